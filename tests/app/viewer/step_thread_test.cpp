#include "app/viewer/step_thread.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace {

TEST(StepThread, RunsEachJobOnItsOwnThreadAndWaitSeesItsWrites) {
  std::atomic<int> woken{0};
  wobble::StepThread thread([&woken] { ++woken; });
  const std::thread::id caller = std::this_thread::get_id();
  for (int job = 0; job < 50; ++job) {
    std::thread::id ran_on;
    long sum = 0;  // written by the job, read after wait() with no lock of the test's own
    thread.start([&] {
      ran_on = std::this_thread::get_id();
      for (int i = 1; i <= 1000; ++i)
        sum += i;
    });
    thread.wait();
    EXPECT_NE(ran_on, caller);
    EXPECT_EQ(sum, 500500);
    EXPECT_FALSE(thread.running());
  }
  // The hook ran after every job (on the stepping thread, possibly just after wait returned).
  for (int tries = 0; woken.load() < 50 && tries < 1000; ++tries)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_EQ(woken.load(), 50);
}

TEST(StepThread, RunningUntilTheJobEnds) {
  wobble::StepThread thread;
  std::atomic<bool> release{false};
  thread.start([&release] {
    while (!release.load())
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  });
  EXPECT_TRUE(thread.running());
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_TRUE(thread.running());
  release = true;
  thread.wait();
  EXPECT_FALSE(thread.running());
}

TEST(StepThread, AnExceptionComesOutOfWaitOnce) {
  wobble::StepThread thread;
  thread.start([] { throw std::runtime_error("disk full"); });
  EXPECT_THROW(thread.wait(), std::runtime_error);
  EXPECT_NO_THROW(thread.wait());
  // The thread goes on taking jobs.
  bool ran = false;
  thread.start([&ran] { ran = true; });
  thread.wait();
  EXPECT_TRUE(ran);
}

TEST(StepThread, DestructionWaitsForTheRunningJob) {
  bool finished = false;
  {
    wobble::StepThread thread;
    thread.start([&finished] {
      std::this_thread::sleep_for(std::chrono::milliseconds(30));
      finished = true;
    });
  }
  EXPECT_TRUE(finished);
}

}  // namespace
