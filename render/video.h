// MP4 and GIF from a PNG frame sequence, through ffmpeg when it is installed (Debian's
// ffmpeg 5.1; the arguments are those of ../shared/STACK.md). The video is written under a
// temporary name and renamed, like every other output: complete or absent.
#pragma once

#include <string>

namespace collide::render {

enum class VideoFormat { mp4, gif };

// The full path of `program` found on $PATH, or "" when it is not there.
std::string find_program(const std::string& program);

// Encodes dir/frame_00000.png, ... (consecutive, all the same size) at `fps` frames per second
// into `out_path`. MP4: H.264, yuv420p (what players expect), odd sizes rounded down to even.
// GIF: at most 30 frames/s and 640 pixels wide, with a palette made for the frames.
// Throws std::runtime_error with ffmpeg's own message when it fails; nothing is left behind.
void encode_video(const std::string& ffmpeg, const std::string& frames_dir, double fps,
                  VideoFormat format, const std::string& out_path);

}  // namespace collide::render
