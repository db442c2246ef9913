// `collide material -o DIR [LESSON ...]`: a self-contained static HTML site of lessons that
// works offline (docs/commands/material.md; present/site.h lists its files). The site is built
// in a temporary directory beside DIR and renamed into place at the end (present/staged_dir.h):
// DIR is complete or untouched.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace collide {

struct MaterialOptions {
    std::string out_dir;               // -o DIR
    std::vector<std::string> lessons;  // ids or lesson files; empty: every bundled lesson
    std::string size = "720p";         // as collide render
    double fps = 30.0;
    std::string quality = "medium";
    bool quiet = false;  // no progress, no summary
    bool force = false;  // replace a DIR that is not empty
};

// Where `collide material` finds the WebAssembly module collide-engine.js for the Try-it
// panels, the first of: $COLLIDE_ENGINE_JS when set (InputError when it is not a file); `installed` when it is a file (an
// installed program's share/collide/collide-engine.js); the build tree's BUILD/wasm/
// collide-engine.js (scripts/build-wasm.sh, or the build itself when emscripten is
// installed). "" when there is none: the pages have no panel and the summary says how to
// build it.
std::string engine_js_path(const std::string& installed);
// The same for the running program (installed: its directory/../share/collide/).
std::string engine_js_path();
// Where `collide material` finds three.min.js (three.js, Debian's libjs-three), which draws the
// 3D lessons' Try-it panels: $COLLIDE_THREE_JS when set, else COLLIDE_THREE_JS_PATH (CMake's,
// /usr/share/javascript/three/three.min.js). "" when the file is not there; `looked` (if
// given) receives the place looked at, for the warning that says so.
std::string three_js_path(std::string* looked = nullptr);

// Returns the exit code: 0 done, 2 bad input (nothing written), 1 any other failure.
int run_material(const MaterialOptions& options, std::ostream& out, std::ostream& err);

}  // namespace collide
