// The inspector's one background-job type (ui/gui/background_job.h): Done, Cancelled and Failed
// as the work ends, progress and stage seen from the UI thread, start refused while running.
#include "ui/gui/background_job.h"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <thread>

namespace pvs::gui {
namespace {

JobStatus wait_for_end(BackgroundJob<int>& job)
{
    while (job.poll() == JobStatus::Running)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return job.status();
}

const auto positive = [](const int& value) { return value > 0; };

TEST(BackgroundJob, DoneHoldsTheOutput)
{
    BackgroundJob<int> job;
    EXPECT_EQ(job.status(), JobStatus::Idle);
    ASSERT_TRUE(job.start([](JobControl&) { return 7; }, positive));
    EXPECT_EQ(wait_for_end(job), JobStatus::Done);
    ASSERT_TRUE(job.output());
    EXPECT_EQ(*job.output(), 7);
}

TEST(BackgroundJob, CancelEndsCancelledAndStartIsRefusedWhileRunning)
{
    BackgroundJob<int> job;
    std::atomic<bool> started{false};
    ASSERT_TRUE(job.start(
        [&](JobControl& control) {
            control.set_stage("waiting");
            control.set_progress(0.5);
            started = true;
            while (!control.cancel_requested())
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            return -1;
        },
        positive));
    while (!started)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    EXPECT_EQ(job.stage(), "waiting");
    EXPECT_EQ(job.progress(), 0.5);
    EXPECT_FALSE(job.start([](JobControl&) { return 1; }, positive)) << "one job at a time";
    job.cancel();
    EXPECT_EQ(wait_for_end(job), JobStatus::Cancelled);
    ASSERT_TRUE(job.output()) << "a cancelled job's output is kept (reports)";
    EXPECT_EQ(*job.output(), -1);
    ASSERT_TRUE(job.start([](JobControl&) { return 2; }, positive)) << "and again once it has ended";
    EXPECT_EQ(wait_for_end(job), JobStatus::Done);
}

TEST(BackgroundJob, AnExceptionFailsTheJobWithItsMessage)
{
    BackgroundJob<int> job;
    ASSERT_TRUE(job.start([](JobControl&) -> int { throw std::runtime_error("zone.bsp: offset 12: bad lump"); },
                          positive));
    EXPECT_EQ(wait_for_end(job), JobStatus::Failed);
    EXPECT_EQ(job.error(), "zone.bsp: offset 12: bad lump");
    EXPECT_FALSE(job.output());
}

TEST(BackgroundJob, DestroyingARunningJobStopsIt)
{
    std::atomic<bool> saw_cancel{false};
    {
        BackgroundJob<int> job;
        job.start(
            [&](JobControl& control) {
                while (!control.cancel_requested())
                    std::this_thread::sleep_for(std::chrono::milliseconds(1));
                saw_cancel = true;
                return 0;
            },
            positive);
    }
    EXPECT_TRUE(saw_cancel);
}

} // namespace
} // namespace pvs::gui
