// `collide gui [LESSON|SCENARIO]`: a window with the frame `collide render` would draw at the
// playback time, and Dear ImGui panels to change the scene and play it (present/gui_model.h holds
// what it shows and changes; the window is render/window.h).
#pragma once

#include <iosfwd>
#include <string>

namespace collide {

struct GuiOptions {
    std::string scenario = "catch-up";  // a lesson id, a lesson file or a scenario file
    std::string size = "960x540";       // the frame: WxH or a preset (as collide render)
    double fps = 30.0;                  // frames per simulated second (as collide render)
    std::string view;                   // 2d or 3d; empty: 2d for 1D and 2D scenes, 3d for 3D
    std::string script;                 // --script FILE: actions run one per window frame
    std::string out_dir = ".";          // where "save frame" and "save figure" write
};

// Returns the exit code: 0, 2 for bad input (file, line, key on stderr; no window opened when
// the options or the script are wrong), 1 when no window can be opened (the reason).
int run_gui(const GuiOptions& options, std::ostream& out, std::ostream& err);

}  // namespace collide
