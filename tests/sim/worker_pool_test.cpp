#include "sim/parallel/worker_pool.h"

#include <gtest/gtest.h>
#include <time.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

namespace {

double process_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

TEST(WorkerPool, EveryTaskRunsExactlyOnceRunAfterRun) {
  // Runs alternate between two tasks with counters of their own, so a helper that woke late and
  // ran a task of the earlier run in the later one shows up. More threads than this machine's
  // cores too, so that helpers often wake late. (Without the generation check in claim, this
  // failed in 2 of 5 runs: a race is caught often, not always.)
  for (int threads : {1, 2, 3, 8}) {
    wobble::WorkerPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    std::vector<std::atomic<int>> calls[2] = {std::vector<std::atomic<int>>(64),
                                              std::vector<std::atomic<int>>(64)};
    auto first = [&](int index) { calls[0][index].fetch_add(1); };
    auto second = [&](int index) { calls[1][index].fetch_add(1); };
    for (int run = 0; run < 30000; ++run) {
      const int count = 1 + run % 37, which = run % 2;
      for (auto& counters : calls) {
        for (std::atomic<int>& counter : counters)
          counter.store(0);
      }
      if (which == 0) {
        pool.run(count, first);
      } else {
        pool.run(count, second);
      }
      for (int i = 0; i < 64; ++i) {
        ASSERT_EQ(calls[which][i].load(), i < count ? 1 : 0)
            << threads << " threads, run " << run << ", task " << i;
        ASSERT_EQ(calls[1 - which][i].load(), 0)
            << threads << " threads, run " << run << ": a task of the run before, " << i;
      }
    }
  }
}

TEST(WorkerPool, RunsOnPastTwoToThe32Runs) {
  // The task counter keeps the run's number in 32 bits. Comparing it with the full number hung
  // the first run past 2³² (some eight days of stepping): the loop runs on a thread of its own,
  // so that a hang fails this test instead of stopping the suite.
  std::atomic<bool> finished{false}, right{true};
  std::thread([&] {
    wobble::WorkerPool pool(3, (std::uint64_t{1} << 32) - 50);
    std::vector<std::atomic<int>> calls(8);
    auto task = [&](int index) { calls[index].fetch_add(1); };
    for (int run = 0; run < 200; ++run) {
      for (std::atomic<int>& call : calls)
        call.store(0);
      pool.run(8, task);
      for (std::atomic<int>& call : calls)
        right = right && call.load() == 1;
    }
    finished = true;
  }).detach();
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!finished && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (!finished) {
    std::fprintf(stderr, "a run past 2^32 runs never finished\n");
    std::_Exit(1);
  }
  EXPECT_TRUE(right);
}

TEST(WorkerPool, NoTasksIsNothingToDo) {
  wobble::WorkerPool pool(2);
  int calls = 0;
  auto task = [&](int) { ++calls; };
  pool.run(0, task);
  EXPECT_EQ(calls, 0);
}

TEST(WorkerPool, HelpersRunTasksAtTheSameTimeAsTheCaller) {
  // Task 0 waits for task 1 to start: only a second thread can let it finish. The wait is
  // bounded, so a pool that runs everything on one thread fails instead of hanging.
  wobble::WorkerPool pool(2);
  std::atomic<bool> second_started{false};
  std::atomic<bool> overlapped{false};
  auto task = [&](int index) {
    if (index == 1) {
      second_started = true;
      return;
    }
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!second_started && std::chrono::steady_clock::now() < until)
      std::this_thread::yield();
    overlapped = second_started.load();
  };
  pool.run(2, task);
  EXPECT_TRUE(overlapped);
}

TEST(WorkerPool, IdleHelpersSleepInsteadOfSpinning) {
  // After a burst of work, three helpers that busy-waited for the next job would burn about
  // 0.6 s of processor time in these 0.2 s (OpenMP's default did); sleeping ones burn none.
  wobble::WorkerPool pool(4);
  std::vector<double> data(1 << 16, 1.0);
  auto task = [&](int index) {
    for (std::size_t i = index; i < data.size(); i += 16)
      data[i] = data[i] * 1.0000001 + 1e-9;
  };
  for (int run = 0; run < 200; ++run)
    pool.run(16, task);
  const double before = process_cpu_seconds();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const double used = process_cpu_seconds() - before;
  EXPECT_LT(used, 0.02) << "processor seconds used by an idle pool in 0.2 s";
}

}  // namespace
