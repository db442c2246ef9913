// The fuzzers' entry points (fuzz/*_fuzz.cpp), shared with the regression test that replays
// tests/fuzz-regressions/ in the normal build (tests/fuzz/regressions_test.cpp).
//
// Each takes the bytes of one input file, first read as the commands read a file or stdin
// (scenario/toml_reader.h read_bounded: what it accepts must be those bytes, and it must
// accept every text under the limit), then parsed whatever that says. Bad input is expected and must be refused with an
// InputError, which the entry point swallows; anything else escapes: another exception (the
// fuzzer aborts on it, the regression test fails), or a crash, a hang or undefined behaviour
// (the sanitizers and libFuzzer's -timeout report those).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace collide::fuzz {

// A scenario file: parse_scene_text with its [view] table.
void scene(const std::string& text);
// A `collide solve` file: parse_solve_text, solve, and the three reports.
void solve(const std::string& text);
// A lesson file: parse_lesson_text (its scene, questions, variants, [penalty]).
void lesson(const std::string& text);
// A scenario parsed and then stepped like `collide step`, cut short so one input stays well
// under a second: at most kMaxBodies bodies, kMaxOutputSteps output instants, kMaxEvents
// collisions and (2D, 3D) kMaxSubsteps substeps of the world (a resting body costs one solve
// per millisecond of simulated time: World::kRestStep), checked every 10 ms of simulated time;
// and, last, about half a second of the clock (a fast spin's free rotation is neither).
// Besides an InputError, the world may refuse a run with a RunError (beyond the scene's work
// budget, or a state no longer finite: named, exit 2 in the commands) or std::runtime_error (a
// stuck simulation: step.h); every state it reports must be finite.
inline constexpr std::size_t kMaxBodies = 8;
inline constexpr std::size_t kMaxOutputSteps = 40;
inline constexpr std::size_t kMaxEvents = 2000;
inline constexpr std::uint64_t kMaxSubsteps = 300;
void step(const std::string& text);

// The entry points by name ("scene", "solve", "lesson", "step"); nullptr for another name.
using EntryPoint = void (*)(const std::string&);
EntryPoint entry_point(const std::string& name);

}  // namespace collide::fuzz
