// Scenario files (TOML): a [scene] table and [[body]] tables. Format: README.md.
#pragma once

#include <string>

#include "engine/scene.h"

namespace collide {

// Parses and validates; throws InputError naming file, line, column and key. Beyond the
// per-key checks: unique names, static bodies at rest, no two bodies overlapping at the start.
Scene parse_scene_file(const std::string& path);
Scene parse_scene_text(const std::string& text, const std::string& name);

}  // namespace collide
