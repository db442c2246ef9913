// One job at a time on a worker thread, for a window that must keep drawing while a scene is
// re-run (`collide gui`): the newest job wins. Starting a job cancels the one running (it
// stops at its next check and its result is thrown away) and replaces one still waiting to
// run (which then never runs); the window meanwhile reads the job's progress and, once it has
// finished, takes its result or its error.
//
//   UI thread                         worker thread
//   start(job) ---- job, control ---> job(control): control.report(f), control.check()
//   progress()  <--- control (atomics)
//   take_result() <-- Outcome, under the mutex, only from the newest job not cancelled
//
// Who owns what: a job owns everything it computes with (the world it advances, copies of its
// inputs); it shares only its RunControl (atomics) with the UI thread, and hands its result
// over under the mutex. No knowledge of windows or of the engine.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

namespace collide {

// What a job sees of its run: whether to stop, and where to say how far it got.
class RunControl {
public:
    // Thrown by check() once the job is cancelled (a job may also just return: a cancelled
    // job's result is never handed over either way).
    struct Cancelled : std::exception {
        const char* what() const noexcept override { return "cancelled"; }
    };

    bool cancelled() const { return cancel_.load(std::memory_order_acquire); }
    void check() const {
        if (cancelled()) throw Cancelled{};
    }
    // How far the job got, from 0 to 1; clamped into [0, 1] and never lowered.
    void report(double fraction);
    double progress() const { return progress_.load(std::memory_order_acquire); }

    void cancel() { cancel_.store(true, std::memory_order_release); }

private:
    std::atomic<bool> cancel_{false};
    std::atomic<double> progress_{0.0};
};

template <class Result>
class BackgroundRun {
public:
    using Job = std::function<Result(RunControl&)>;
    // How the newest job ended: its result, or the message of what it threw.
    struct Outcome {
        std::optional<Result> result;
        std::string error;  // when result is empty
    };

    BackgroundRun() = default;
    BackgroundRun(const BackgroundRun&) = delete;
    BackgroundRun& operator=(const BackgroundRun&) = delete;
    // Cancels the job running, drops one waiting, and joins the worker.
    ~BackgroundRun() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
            pending_.reset();
            if (running_) running_->cancel();
        }
        wake_.notify_all();
        if (worker_.joinable()) worker_.join();
    }

    // Runs `job` on the worker once the job running (if any, now cancelled) has stopped. An
    // outcome of an older job not yet taken is dropped: only this job's can come.
    void start(Job job) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (running_) running_->cancel();
            latest_ = std::make_shared<RunControl>();
            pending_ = Task{std::move(job), latest_};
            outcome_.reset();
            if (!worker_.joinable()) worker_ = std::thread([this] { work(); });
        }
        wake_.notify_all();
    }

    // Cancels the newest job: it stops at its next check, and nothing of it is handed over.
    void cancel() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (latest_) latest_->cancel();
            pending_.reset();
            latest_.reset();
            outcome_.reset();
        }
        done_.notify_all();
    }

    // True from start() until the newest job has ended (its outcome may wait to be taken).
    bool busy() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return busy_locked();
    }
    // The newest job's progress, 0 to 1 (0 while it waits for the older one to stop).
    double progress() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return latest_ ? latest_->progress() : 0.0;
    }
    // The newest job's outcome, once, after it has ended; nothing before, or if it was
    // cancelled.
    std::optional<Outcome> take_result() {
        std::lock_guard<std::mutex> lock(mutex_);
        std::optional<Outcome> out = std::move(outcome_);
        outcome_.reset();
        return out;
    }
    // Blocks until the newest job has ended (at once when there is none).
    void wait() {
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [&] { return !busy_locked(); });
    }

private:
    struct Task {
        Job job;
        std::shared_ptr<RunControl> control;
    };

    bool busy_locked() const { return pending_ || (running_ && running_ == latest_); }

    void work() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            wake_.wait(lock, [&] { return stop_ || pending_; });
            if (stop_) return;
            Task task = std::move(*pending_);
            pending_.reset();
            running_ = task.control;
            lock.unlock();
            Outcome out;
            bool ended = true;  // false: cancelled
            try {
                task.control->check();
                out.result.emplace(task.job(*task.control));
            } catch (const RunControl::Cancelled&) {
                ended = false;
            } catch (const std::exception& e) {
                out.error = e.what();
            } catch (...) {
                out.error = "unknown error";
            }
            task.job = nullptr;  // what the job holds goes on this thread, outside the lock
            lock.lock();
            running_.reset();
            if (ended && !task.control->cancelled() && task.control == latest_) {
                if (out.result) task.control->report(1.0);
                outcome_ = std::move(out);
            }
            done_.notify_all();
        }
    }

    mutable std::mutex mutex_;
    std::condition_variable wake_;         // the worker: a job to run, or stop
    std::condition_variable done_;         // wait(): a job ended
    std::optional<Task> pending_;          // the next job to run (the newest, when set)
    std::shared_ptr<RunControl> running_;  // the job on the worker
    std::shared_ptr<RunControl> latest_;   // the newest job started and not cancelled
    std::optional<Outcome> outcome_;       // the newest job's, until taken
    bool stop_ = false;
    std::thread worker_;  // started by the first start(); last, so the rest exists before it
};

}  // namespace collide
