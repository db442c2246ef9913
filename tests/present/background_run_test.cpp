// One job at a time on a worker thread (present/background_run.h), as collide gui re-runs a scene:
// a newer start cancels the older job and its result never comes, progress rises to 1, an
// exception in the job is reported, and destroying the runner while a job runs joins cleanly.
// No timing: the test and the jobs hand each other the turn through condition variables
// (Steps below), and a job that must be cancelled waits for it by checking its flag.
#include "present/background_run.h"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "engine/world.h"
#include "tests/scenes/world_scenes.h"

namespace collide {
namespace {

// A count that one thread raises and another waits for (a latch that can be reused).
class Steps {
public:
    void post(int k) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            count_ = k;
        }
        changed_.notify_all();
    }
    void wait_for(int k) {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [&] { return count_ >= k; });
    }

private:
    std::mutex mutex_;
    std::condition_variable changed_;
    int count_ = 0;
};

// A job that says it started, then runs until it is cancelled (checking as a world run does
// between samples) and notes that it stopped.
struct UntilCancelled {
    Steps* started;
    std::atomic<bool>* stopped;
    int operator()(RunControl& c) const {
        struct Note {
            std::atomic<bool>* flag;
            ~Note() { flag->store(true); }
        } note{stopped};
        started->post(1);
        for (;;) {
            c.check();
            std::this_thread::yield();
        }
    }
};

TEST(BackgroundRun, ANewerStartCancelsTheRunningJob) {
    BackgroundRun<int> runs;
    Steps started;
    std::atomic<bool> stopped{false};
    runs.start(UntilCancelled{&started, &stopped});
    started.wait_for(1);
    EXPECT_TRUE(runs.busy());
    EXPECT_FALSE(runs.take_result());  // nothing before the job ended
    runs.start([](RunControl&) { return 2; });
    runs.wait();
    EXPECT_TRUE(stopped);  // one worker: the newer job ran after the older stopped
    const auto out = runs.take_result();
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->result);
    EXPECT_EQ(*out->result, 2);
    EXPECT_FALSE(runs.take_result());  // taken once
    EXPECT_FALSE(runs.busy());
}

// The older job ignores its cancel flag and returns normally: its result is still thrown away.
// A job that was waiting when a newer one came never runs at all.
TEST(BackgroundRun, AStaleResultNeverComesAndAReplacedJobNeverRuns) {
    BackgroundRun<int> runs;
    Steps started, go;
    RunControl* first = nullptr;
    runs.start([&](RunControl& c) {
        first = &c;
        started.post(1);
        go.wait_for(1);
        return 1;
    });
    started.wait_for(1);
    std::atomic<bool> second_ran{false};
    runs.start([&](RunControl&) {
        second_ran = true;
        return 2;
    });
    runs.start([](RunControl&) { return 3; });
    EXPECT_TRUE(first->cancelled());
    go.post(1);
    runs.wait();
    const auto out = runs.take_result();
    ASSERT_TRUE(out && out->result);
    EXPECT_EQ(*out->result, 3);
    EXPECT_FALSE(second_ran);
}

// Progress is the newest job's, as it reports it: 0 before, each step's value, 1 at the end.
TEST(BackgroundRun, ProgressRisesStepByStepToOne) {
    BackgroundRun<int> runs;
    constexpr int kSteps = 5;
    Steps reached, allowed;
    runs.start([&](RunControl& c) {
        for (int k = 1; k <= kSteps; ++k) {
            allowed.wait_for(k);
            c.report(static_cast<double>(k) / (kSteps + 1));  // the job's own last step short of 1
            c.report(0.0);                                    // never lowered
            reached.post(k);
        }
        allowed.wait_for(kSteps + 1);
        return kSteps;
    });
    EXPECT_EQ(runs.progress(), 0.0);
    double last = 0.0;
    for (int k = 1; k <= kSteps; ++k) {
        allowed.post(k);
        reached.wait_for(k);
        const double p = runs.progress();
        EXPECT_GT(p, last);
        EXPECT_DOUBLE_EQ(p, static_cast<double>(k) / (kSteps + 1));
        last = p;
    }
    allowed.post(kSteps + 1);
    runs.wait();
    EXPECT_EQ(runs.progress(), 1.0);  // a job that finished is complete
    ASSERT_TRUE(runs.take_result());
    EXPECT_EQ(runs.progress(), 1.0);  // and stays so once taken
}

// A real world on the worker: a pile of 2D columns advanced in slices of 1/60 s, the cancel
// flag checked between slices. Progress (simulated time reached / run length) never falls and
// ends at 1; the run is the one the same world gives on this thread.
TEST(BackgroundRun, AWorldRunReportsItsProgressAndGivesTheSameRun) {
    scenes::PileSpec spec;
    spec.n = 6;
    spec.per_column = 3;
    const Scene scene = scenes::pile(2, spec);
    constexpr double kLength = 1.0, kSlice = 1.0 / 60;  // s
    struct Ran {
        std::vector<Event2> events;
        std::vector<double> progress;  // after each slice, as the job saw it
    };
    const auto job = [scene](RunControl& c) {
        Ran ran;
        World2 world(scene);
        for (int k = 1; k * kSlice <= kLength + 1e-12; ++k) {
            c.check();
            world.advance_to(k * kSlice, &ran.events);
            c.report(k * kSlice / kLength);
            ran.progress.push_back(c.progress());
        }
        return ran;
    };
    BackgroundRun<Ran> runs;
    runs.start(job);
    runs.wait();
    const auto out = runs.take_result();
    ASSERT_TRUE(out && out->result) << (out ? out->error : "no outcome");
    const Ran& ran = *out->result;
    ASSERT_EQ(ran.progress.size(), 60u);
    for (std::size_t k = 1; k < ran.progress.size(); ++k) EXPECT_GE(ran.progress[k], ran.progress[k - 1]);
    EXPECT_NEAR(ran.progress.back(), 1.0, 1e-12);
    EXPECT_EQ(runs.progress(), 1.0);
    RunControl here;
    const Ran direct = job(here);
    ASSERT_EQ(ran.events.size(), direct.events.size());
    EXPECT_GT(ran.events.size(), 0u);
    for (std::size_t k = 0; k < ran.events.size(); ++k) EXPECT_EQ(ran.events[k].t, direct.events[k].t);
}

TEST(BackgroundRun, AnExceptionInTheJobIsReported) {
    BackgroundRun<int> runs;
    runs.start([](RunControl&) -> int { throw std::runtime_error("the simulation is stuck at t = 0.5 s"); });
    runs.wait();
    const auto out = runs.take_result();
    ASSERT_TRUE(out);
    EXPECT_FALSE(out->result);
    EXPECT_EQ(out->error, "the simulation is stuck at t = 0.5 s");
    // The worker goes on: the next job runs.
    runs.start([](RunControl&) { return 7; });
    runs.wait();
    const auto next = runs.take_result();
    ASSERT_TRUE(next && next->result);
    EXPECT_EQ(*next->result, 7);
}

// cancel(): the newest job stops and nothing of it comes; the runner is idle at once and the
// next job runs once the cancelled one has stopped.
TEST(BackgroundRun, CancelDropsTheNewestJob) {
    BackgroundRun<int> runs;
    Steps started;
    std::atomic<bool> stopped{false};
    runs.start(UntilCancelled{&started, &stopped});
    started.wait_for(1);
    runs.cancel();
    EXPECT_FALSE(runs.busy());
    runs.wait();  // returns at once
    EXPECT_FALSE(runs.take_result());
    EXPECT_EQ(runs.progress(), 0.0);
    runs.start([](RunControl&) { return 5; });
    runs.wait();
    EXPECT_TRUE(stopped);
    const auto out = runs.take_result();
    ASSERT_TRUE(out && out->result);
    EXPECT_EQ(*out->result, 5);
}

// Destroyed while a job runs: the job is cancelled and the worker joined before the destructor
// returns (the job has stopped: its note is written). Under ThreadSanitizer, a worker outliving
// the runner would show.
TEST(BackgroundRun, DestroyingItWhileAJobRunsJoinsCleanly) {
    Steps started;
    std::atomic<bool> stopped{false};
    {
        BackgroundRun<int> runs;
        runs.start(UntilCancelled{&started, &stopped});
        started.wait_for(1);
    }
    EXPECT_TRUE(stopped);
    { BackgroundRun<int> never_started; }  // no worker to join
}

}  // namespace
}  // namespace collide
