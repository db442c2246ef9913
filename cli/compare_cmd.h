// `collide compare FILE`: runs a 2D scenario through collide's World<2> and through Box2D 2.4.1
// (compare/box2d_world.h), matches their collision events by pair and order (compare/match.h),
// and prints each pair's velocities before and after side by side with the difference and the
// reason where they differ (docs/commands/compare.md).
//
//   text (default)  a header with the settings, one block per event, a summary;
//   --json          {"events": [{"a": .., "b": .., "t": {"collide": .., "box2d": ..},
//                    "collide": {"a": {"v": .., "w": ..}, "b": {..}}, "box2d": {..},
//                    "difference": .., "reason": ".."}], "settings": {..}, "summary": {..}}
//                   with the velocities after each event (null for a side without the event);
//   --samples       also both trajectories side by side at the scene's output_dt.
#pragma once

#include <iosfwd>
#include <string>

namespace collide {

struct CompareOptions {
    std::string file;  // scenario file (TOML), 2D
    bool json = false;
    bool samples = false;
    bool box2d_defaults = false;  // Box2D's threshold (1 m/s) and mixing; else collide's rules
    double dt = 1.0 / 600.0;      // s: Box2D's step
    int velocity_iterations = 8;
    int position_iterations = 3;
};

// Runs the command. Returns the exit code: 0 done; 2 bad input (one "collide: error: FILE:LINE:
// COL: key: message" line on err, nothing on out): a malformed scenario, a scene that is not 2D
// or that Box2D cannot represent, options out of range; 1 any other failure.
int run_compare(const CompareOptions& options, std::ostream& out, std::ostream& err);

}  // namespace collide
