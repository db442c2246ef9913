#include "render/frame_sink.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ostream>
#include <stdexcept>

namespace collide::render {

FrameSink::FrameSink(int width, int height, FrameSinkOptions options)
    : width_(width), height_(height), options_(std::move(options)) {
    if (width < 1 || height < 1) throw std::invalid_argument("FrameSink: empty frames");
    const int threads = std::max(1, options_.threads);
    const int buffers = std::max(threads + 1, options_.buffers);
    storage_.resize(static_cast<std::size_t>(buffers));
    for (Buffer& b : storage_) {
        b.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
        free_.push_back(&b);
    }
    for (int i = 0; i < threads; ++i) threads_.emplace_back([this] { encode_loop(); });
}

FrameSink::~FrameSink() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        closing_ = true;
    }
    changed_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void FrameSink::rethrow_locked() {
    if (error_) std::rethrow_exception(error_);
}

FrameSink::Buffer* FrameSink::acquire() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return !free_.empty() || error_; });
    rethrow_locked();
    Buffer* b = free_.back();
    free_.pop_back();
    return b;
}

void FrameSink::submit(long index, Buffer* buffer) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (error_) {
            free_.push_back(buffer);
            rethrow_locked();
        }
        queue_.emplace_back(index, buffer);
    }
    changed_.notify_all();
}

void FrameSink::finish() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return (queue_.empty() && busy_ == 0) || error_; });
    rethrow_locked();
}

std::string FrameSink::path_of(long index) const {
    char number[32];
    std::snprintf(number, sizeof number, "%0*ld", options_.digits, index);
    return options_.dir + "/" + options_.prefix + number + ".png";
}

long FrameSink::written() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return written_;
}

void FrameSink::encode_loop() {
    while (true) {
        std::pair<long, Buffer*> job;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            changed_.wait(lock, [this] { return !queue_.empty() || closing_; });
            if (queue_.empty()) return;  // closing, nothing left
            job = queue_.front();
            queue_.pop_front();
            ++busy_;
        }
        std::exception_ptr failure;
        try {
            write_png_atomic(path_of(job.first), width_, height_, job.second->data(), options_.png);
        } catch (...) {
            failure = std::current_exception();
        }
        {
            std::lock_guard<std::mutex> lock(mutex_);
            --busy_;
            free_.push_back(job.second);
            if (failure && !error_) error_ = failure;
            if (!failure) ++written_;
            if (error_) {  // drop what is queued: the run stops
                for (auto& q : queue_) free_.push_back(q.second);
                queue_.clear();
            }
        }
        changed_.notify_all();
    }
}

// ---- ProgressBar ----

namespace {
double now_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

ProgressBar::ProgressBar(std::ostream& out, long total, bool enabled, std::string label)
    : out_(out), total_(std::max(1L, total)), enabled_(enabled), label_(std::move(label)), start_(now_seconds()) {}

void ProgressBar::update(long done) {
    if (!enabled_ || finished_) return;
    const double t = now_seconds();
    if (last_ >= 0.0 && t - last_ < 0.1) return;
    last_ = t;
    draw(done);
}

void ProgressBar::finish() {
    if (!enabled_ || finished_) return;
    draw(last_done_ > total_ ? last_done_ : total_);
    out_ << "\n" << std::flush;
    finished_ = true;
}

void ProgressBar::draw(long done) {
    last_done_ = done;
    constexpr int kWidth = 30;
    const double fraction = std::min(1.0, static_cast<double>(done) / static_cast<double>(total_));
    const int filled = static_cast<int>(fraction * kWidth + 0.5);
    const double elapsed = now_seconds() - start_;
    char line[160];
    std::snprintf(line, sizeof line, "\r%s [%s%s] %ld/%ld %3d %%  %.1f frames/s", label_.c_str(),
                  std::string(static_cast<std::size_t>(filled), '#').c_str(),
                  std::string(static_cast<std::size_t>(kWidth - filled), '-').c_str(), done, total_,
                  static_cast<int>(fraction * 100.0 + 0.5), elapsed > 0.0 ? static_cast<double>(done) / elapsed : 0.0);
    out_ << line << std::flush;
}

}  // namespace collide::render
