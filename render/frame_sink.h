// Frame sequences: frames rendered on the calling thread are PNG-encoded and written on
// encoder threads beside it, through a bounded pool of frame buffers.
//
//   render thread:   acquire() a free buffer (waits while every buffer is queued or being
//                    encoded), read the frame into it, submit(index, buffer);
//   encoder threads: take the next submitted frame, write DIR/frame_00042.png atomically
//                    (render/png.h), give the buffer back.
// Memory is `buffers` frames whatever the length of the sequence. The first write error
// (disk full, permissions) stops the sink: later submit() and finish() calls rethrow it.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <iosfwd>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "render/png.h"

namespace collide::render {

struct FrameSinkOptions {
    std::string dir;  // existing directory
    std::string prefix = "frame_";
    int digits = 5;  // frame_00000.png
    PngOptions png;
    int threads = 1;  // encoder threads (>= 1)
    int buffers = 3;  // frames in flight (>= threads + 1 keeps rendering busy)
};

class FrameSink {
public:
    FrameSink(int width, int height, FrameSinkOptions options);
    ~FrameSink();  // waits for queued frames (errors are dropped here: call finish() to see them)
    FrameSink(const FrameSink&) = delete;
    FrameSink& operator=(const FrameSink&) = delete;

    using Buffer = std::vector<std::uint8_t>;  // width * height * 4 bytes, RGBA, top row first

    Buffer* acquire();
    void submit(long index, Buffer* buffer);
    // Waits until every submitted frame is written; rethrows the first error.
    void finish();

    std::string path_of(long index) const;                        // DIR/frame_00042.png
    long written() const;                                         // frames written so far
    std::size_t buffer_count() const { return storage_.size(); }  // frames in memory, at most

private:
    void encode_loop();
    void rethrow_locked();

    int width_, height_;
    FrameSinkOptions options_;
    std::vector<Buffer> storage_;
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::vector<Buffer*> free_;
    std::deque<std::pair<long, Buffer*>> queue_;
    int busy_ = 0;  // frames being encoded
    long written_ = 0;
    bool closing_ = false;
    std::exception_ptr error_;
    std::vector<std::thread> threads_;
};

// A one-line progress bar, redrawn in place ("\r"), at most about 10 times a second:
//   frames [##########----------]  120/301   40 %   52.1 frames/s
// Disabled, it prints nothing at all.
class ProgressBar {
public:
    ProgressBar(std::ostream& out, long total, bool enabled, std::string label = "frames");
    void update(long done);
    void finish();  // the final state and a newline (once)

private:
    void draw(long done);
    std::ostream& out_;
    long total_;
    bool enabled_;
    std::string label_;
    double start_ = 0.0, last_ = -1.0;
    bool finished_ = false;
    long last_done_ = 0;
};

}  // namespace collide::render
