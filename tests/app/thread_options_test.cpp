// --threads and the thread variables: the solver's pool obeys them, --stats says how many threads
// it ran and what decided it, and a value that cannot be obeyed is refused (--threads) or
// reported (a variable) on one line.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "run_wobble.h"
#include "sim/parallel/worker_pool.h"

namespace {

using wobble::testing::Result;
using wobble::testing::run_wobble;

const char* const short_run = "cloth --headless --frames 2 --stats";

// The variables this test sets, and none from the environment it runs in (a CI's
// OMP_THREAD_LIMIT would cap every count).
std::string only(const std::string& assignments = "") {
  return "env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT " + assignments;
}

// The --stats line (the last line of stdout).
nlohmann::json stats_of(const Result& result) {
  const std::string out = result.out.substr(0, result.out.find_last_not_of('\n') + 1);
  return nlohmann::json::parse(out.substr(out.rfind('\n') + 1));
}

TEST(ThreadOptions, TheFlagSetsTheSolversThreads) {
  for (const int threads : {1, 3}) {
    const Result result =
        run_wobble(std::string(short_run) + " --threads " + std::to_string(threads),
                   only("OMP_NUM_THREADS=2"));
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const nlohmann::json stats = stats_of(result);
    EXPECT_EQ(stats["threads"], threads);
    EXPECT_EQ(stats["threads_from"], "--threads") << "the flag wins over the variable";
  }
}

TEST(ThreadOptions, OmpNumThreadsIsObeyedAndCappedByTheLimit) {
  Result result = run_wobble(short_run, only("OMP_NUM_THREADS=1"));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(stats_of(result)["threads"], 1);
  EXPECT_EQ(stats_of(result)["threads_from"], "OMP_NUM_THREADS");
  EXPECT_EQ(result.err, "");

  result = run_wobble(short_run, only("OMP_NUM_THREADS=3,1"));  // a nested list: the first level
  EXPECT_EQ(stats_of(result)["threads"], 3);

  result = run_wobble(short_run, only("OMP_NUM_THREADS=3 OMP_THREAD_LIMIT=2"));
  EXPECT_EQ(stats_of(result)["threads"], 2);
  EXPECT_EQ(stats_of(result)["threads_from"], "OMP_THREAD_LIMIT");
}

TEST(ThreadOptions, WithoutASettingTheProcessorsDecide) {
  const Result result = run_wobble(short_run, only());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(stats_of(result)["threads_from"], "processors");
  EXPECT_EQ(stats_of(result)["threads"],
            std::min(wobble::usable_processors(), wobble::WorkerPool::max_shared_threads));
}

TEST(ThreadOptions, AVariableThatCannotBeObeyedIsReportedOnOneLine) {
  const Result result = run_wobble(short_run, only("OMP_NUM_THREADS=lots"));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err,
            "wobble: warning: OMP_NUM_THREADS='lots' is not a whole number of threads from 1 to " +
                std::to_string(wobble::max_setting_threads) + ", so it is not obeyed\n");
  EXPECT_EQ(stats_of(result)["threads_from"], "processors");
}

TEST(ThreadOptions, AValueWithALineBreakStaysOnOneLine) {
  const Result result = run_wobble(short_run, only("OMP_NUM_THREADS=\"$(printf '2\\nx')\""));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err,
            "wobble: warning: OMP_NUM_THREADS='2\\nx' is not a whole number of threads from 1 to " +
                std::to_string(wobble::max_setting_threads) + ", so it is not obeyed\n");
}

TEST(ThreadOptions, TheFlagRefusesWhatItCannotObey) {
  for (const char* value : {"0", "65", "two", "1.5", "-1"}) {
    const Result result = run_wobble(std::string("cloth --headless --frames 1 --threads ") + value);
    EXPECT_EQ(result.exit_code, 2) << value;
    EXPECT_EQ(result.err, "wobble: --threads: expected a whole number from 1 to " +
                              std::to_string(wobble::max_setting_threads) + ", got '" + value +
                              "'\n");
  }
}

}  // namespace
