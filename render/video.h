// MP4 and GIF from a PNG frame sequence, through ffmpeg when it is installed (Debian's
// ffmpeg 5.1; the arguments are those of ../shared/STACK.md). The video is written under a
// temporary name and renamed, like every other output: complete or absent.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace collide::render {

enum class VideoFormat { mp4, gif };

// The full path of `program` found on $PATH, or "" when it is not there.
std::string find_program(const std::string& program);

// Runs a program to its end: args[0] is its full path (find_program), args the whole argv; its
// standard output is discarded and its standard error goes to the file `log`. Says whether it
// started and how it exited (ffmpeg here, weasyprint for `collide worksheet`).
// `stop` (the command's interrupt flag, present/stop.h) is asked while the program runs, every
// 20 ms: once it says true the program is ended (SIGTERM, then SIGKILL after 2 s) and waited
// for, and the run is `stopped` (also when the program died of the same Ctrl-C first). The
// program never outlives the call.
struct ProgramRun {
    bool started = false;
    int exit = -1;         // its exit status; -1 when it did not exit normally
    bool stopped = false;  // ended because `stop` asked (its exit says nothing then)
    bool ok() const { return started && exit == 0 && !stopped; }
};
ProgramRun run_program(const std::vector<std::string>& args, const std::string& log,
                       const std::function<bool()>& stop = nullptr);

// Encodes dir/frame_00000.png, ... (consecutive, all the same size) at `fps` frames per second
// into `out_path`. MP4: H.264, yuv420p (what players expect), odd sizes rounded down to even.
// GIF: at most 30 frames/s and 640 pixels wide, with a palette made for the frames.
// Throws std::runtime_error with ffmpeg's own message when it fails; nothing is left behind.
// Returns false, leaving nothing behind, when `stop` ended ffmpeg (run_program).
bool encode_video(const std::string& ffmpeg, const std::string& frames_dir, double fps, VideoFormat format,
                  const std::string& out_path, const std::function<bool()>& stop = nullptr);

}  // namespace collide::render
