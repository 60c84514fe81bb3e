// The thread setting: decided from --threads, OMP_NUM_THREADS and OMP_THREAD_LIMIT as documented,
// and obeyed: a simulation of the curtain's size run with one thread starts no second thread.
#include <dirent.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "sim/parallel/worker_pool.h"
#include "sim/shapes/cloth_grid.h"
#include "sim/simulation.h"

namespace {

using wobble::decide_thread_setting;
using wobble::ThreadSetting;

TEST(ThreadSetting, TheFlagWinsThenTheVariableThenTheProcessors) {
  EXPECT_EQ(decide_thread_setting(3, "2", nullptr, 8).threads, 3);
  EXPECT_EQ(decide_thread_setting(3, "2", nullptr, 8).source, "--threads");
  EXPECT_EQ(decide_thread_setting(0, "2", nullptr, 8).threads, 2);
  EXPECT_EQ(decide_thread_setting(0, "2", nullptr, 8).source, "OMP_NUM_THREADS");
  // The flag and the variable are obeyed beyond the processors (as OpenMP does); the default is
  // the processors, at most max_shared_threads.
  EXPECT_EQ(decide_thread_setting(0, "16", nullptr, 2).threads, 16);
  EXPECT_EQ(decide_thread_setting(0, nullptr, nullptr, 2).threads, 2);
  EXPECT_EQ(decide_thread_setting(0, nullptr, nullptr, 2).source, "processors");
  EXPECT_EQ(decide_thread_setting(0, nullptr, nullptr, 64).threads,
            wobble::WorkerPool::max_shared_threads);
  EXPECT_EQ(decide_thread_setting(0, nullptr, nullptr, 1).threads, 1);
}

TEST(ThreadSetting, TheVariableIsReadAsOpenMpReadsIt) {
  EXPECT_EQ(decide_thread_setting(0, " 3 ", nullptr, 8).threads, 3);
  EXPECT_EQ(decide_thread_setting(0, "3,2,1", nullptr, 8).threads, 3) << "nested levels";
  for (const char* bad : {"", "0", "-2", "two", "2.5", "65", "99999999999"}) {
    const ThreadSetting setting = decide_thread_setting(0, bad, nullptr, 2);
    EXPECT_EQ(setting.source, "processors") << bad;
    EXPECT_EQ(setting.warning, std::string("OMP_NUM_THREADS='") + bad +
                                   "' is not a whole number of threads from 1 to 64, so it is "
                                   "not obeyed");
  }
  // With --threads given, a bad variable is irrelevant and not reported.
  EXPECT_EQ(decide_thread_setting(2, "two", nullptr, 2).warning, "");
}

TEST(ThreadSetting, TheLimitCapsEverySource) {
  EXPECT_EQ(decide_thread_setting(8, nullptr, "2", 8).threads, 2);
  EXPECT_EQ(decide_thread_setting(8, nullptr, "2", 8).source, "OMP_THREAD_LIMIT");
  EXPECT_EQ(decide_thread_setting(0, "8", "3", 8).threads, 3);
  EXPECT_EQ(decide_thread_setting(0, nullptr, "1", 8).threads, 1);
  EXPECT_EQ(decide_thread_setting(0, nullptr, "6", 8).threads,
            wobble::WorkerPool::max_shared_threads)
      << "a limit above the default changes nothing";
  EXPECT_EQ(decide_thread_setting(0, nullptr, "6", 8).source, "processors");
  EXPECT_NE(decide_thread_setting(0, nullptr, "none", 8).warning, "");
}

// The threads this process has now (/proc/self/task), or -1 where that cannot be read.
int live_threads() {
  DIR* tasks = opendir("/proc/self/task");
  if (tasks == nullptr) return -1;
  int count = 0;
  while (const dirent* entry = readdir(tasks))
    count += entry->d_name[0] != '.';
  closedir(tasks);
  return count;
}

// In a fresh process (the caller is a death test): OMP_NUM_THREADS=`threads`, then the curtain's
// system (81 × 81 vertices, its top edge pinned: a factor of 417,470 nonzeros, above the size
// that is factorized on two threads), factorized and stepped, a re-factorization included.
// Exits with the process's thread count, and 100 + it when a helper ran a task with one thread.
[[noreturn]] void run_the_curtain(const char* threads) {
  setenv("OMP_NUM_THREADS", threads, 1);
  unsetenv("OMP_THREAD_LIMIT");  // a CI's limit would cap the count this test expects
  wobble::ClothGridOptions options;
  options.resolution = 81;
  options.size = 2.0;
  wobble::SpringNetwork cloth = wobble::make_cloth_grid(options);
  std::vector<int> pins;
  for (int column = 0; column < 81; ++column)
    pins.push_back(wobble::cloth_grid_vertex(81, 0, column));
  wobble::SimulationParams params;
  params.k = 2000.0;
  params.iterations = 30;
  wobble::Simulation simulation(cloth, pins, params);
  for (int step = 0; step < 5; ++step)
    simulation.step();
  simulation.apply(
      wobble::with_setting(simulation.params(), "k", 1500.0));  // a second factorization
  for (int step = 0; step < 5; ++step)
    simulation.step();
  const int count = live_threads();
  const bool helper_ran = wobble::WorkerPool::shared().helper_tasks() > 0;
  std::fprintf(stderr, "factor nonzeros %ld, threads %d\n", simulation.factor_nonzeros(), count);
  std::_Exit(std::string(threads) == "1" && helper_ran ? 100 + count : count);
}

TEST(ThreadSetting, OneThreadRunsTheCurtainWithNoSecondThread) {
  if (live_threads() < 0) GTEST_SKIP() << "no /proc/self/task on this system";
  // "threadsafe" death tests run the test in a new process of this program, so the shared pool
  // is made there, after the variable is set.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(run_the_curtain("1"), ::testing::ExitedWithCode(1),
              "factor nonzeros 417470, threads 1");
  // The same check sees the second thread when there is one, so it can fail.
  EXPECT_EXIT(run_the_curtain("2"), ::testing::ExitedWithCode(2), "threads 2");
}

}  // namespace
