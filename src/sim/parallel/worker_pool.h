#ifndef WOBBLE_SIM_PARALLEL_WORKER_POOL_H
#define WOBBLE_SIM_PARALLEL_WORKER_POOL_H

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace wobble {

// A few helper threads for the stepper's parallel loops, built for a machine whose cores are
// not all free (a browser, a screen share or a build beside Wobble):
// - the calling thread takes part, and does every task that no helper has started, so a helper
//   that has no core to run on delays nothing; the caller waits only for a task a helper is
//   running, and then asleep, so that a helper which lost its core can have the caller's;
// - between runs a helper polls for the next one only while runs come under 300 µs apart (the
//   local step's iterations on a mid-sized cloth: waking a sleeping thread costs tens of
//   microseconds) and while no other program wants the cores (the runnable threads in
//   /proc/loadavg, looked at every 20 ms); otherwise it sleeps;
// - a loop whose sharing does not pay is kept on the caller (SharingPayoff).
// Busy-waiting barriers (OpenMP's) instead made every thread spin while waiting for one with
// no core: beside one busy process a step took many times what it takes on one thread.
//
// run(count, task) calls task(i) once for every i in [0, count), on the caller and any helpers
// that wake in time, and returns when all calls have returned. Tasks must not throw and must not
// call run on the same pool; runs from several threads take turns. run allocates nothing; the
// helpers start in the constructor.
class WorkerPool;

// Whether sharing one loop with the pool's helpers pays off, learned from the loop's own runs:
// a moving average of its wall time shared and of its wall time on the caller alone. Each run
// takes the faster way, and every explore_every-th run the other one, to keep both averages
// current. So on a quiet machine a large loop is shared; when every core is taken (a helper
// would wake late, or take the caller's core) it stays on the caller, and helpers sleep.
// Results never depend on it.
class SharingPayoff {
 public:
  static constexpr int explore_every = 16;
  // Runs shared since construction, and runs kept on the caller; for benchmarks and tests.
  long shared_runs() const { return shared_runs_; }
  long runs_on_caller() const { return runs_on_caller_; }

 private:
  friend class WorkerPool;
  // Whether the next run is to be shared; try_sharing also counts it.
  bool next_is_shared() const;
  bool try_sharing();
  void record(bool shared, double wall_seconds);
  double shared_seconds_ = 0.0, alone_seconds_ = 0.0;  // moving averages; 0: not measured yet
  long shared_runs_ = 0, runs_on_caller_ = 0;
};

class WorkerPool {
 public:
  // threads  the caller plus threads − 1 helpers (1: everything runs on the caller).
  // first_generation  the count of runs to start from (tests: the counter's wrap-around).
  explicit WorkerPool(int threads, std::uint64_t first_generation = 0);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // The pool the simulation uses, with shared_thread_setting().threads threads. Made on first
  // use (in a simulation's precomputation).
  static WorkerPool& shared();
  static constexpr int max_shared_threads = 4;

  int threads() const { return static_cast<int>(helpers_.size()) + 1; }
  // Tasks the helpers have run since construction (not the caller's); for tests.
  long helper_tasks() const { return helper_tasks_.load(std::memory_order_relaxed); }

  // With a payoff, the run is shared only while sharing this loop pays (see SharingPayoff).
  template <typename Task>
  void run(int count, Task& task, SharingPayoff* payoff = nullptr) {
    run_erased(
        count, [](void* context, int index) { (*static_cast<Task*>(context))(index); }, &task,
        payoff);
  }

 private:
  using Call = void (*)(void* context, int index);
  struct Job {
    Call call = nullptr;
    void* context = nullptr;
    int count = 0;
  };
  void run_erased(int count, Call call, void* context, SharingPayoff* payoff);
  void run_shared(int count, Call call, void* context);
  void helper_loop();
  // Takes the next task of generation `generation`, if that job is still the current one and
  // has tasks left.
  bool claim(std::uint64_t generation, int count, int& index);
  void finish_task(int count);

  std::vector<std::thread> helpers_;
  std::mutex caller_mutex_;  // one run at a time, whichever thread calls
  std::mutex mutex_;
  std::condition_variable wake_;      // helpers wait here for a new job
  std::condition_variable finished_;  // the caller waits here for the last task
  Job job_;                           // guarded by mutex_
  std::uint64_t generation_ = 0;      // guarded by mutex_; one per run
  bool stop_ = false;                 // guarded by mutex_
  std::uint64_t wake_calls_ = 0;      // guarded by mutex_; a call to poll for a coming job
  // generation_ for helpers that look without the lock between two close jobs.
  std::atomic<std::uint64_t> published_generation_{0};
  // The generation in the high 32 bits and the next task in the low ones, so that a helper
  // still holding an old job can never take a task of a newer one.
  std::atomic<std::uint64_t> next_task_{0};
  std::atomic<int> done_{0};
  // How long an idle helper polls before it sleeps, from the recent gaps between runs.
  std::atomic<double> poll_budget_seconds_{0.0};
  std::chrono::steady_clock::time_point last_run_end_;  // guarded by caller_mutex_
  double gap_seconds_ = 0.0;                            // guarded by caller_mutex_
  // Whether, at the last look, other threads wanted every core this pool could poll on.
  std::chrono::steady_clock::time_point last_contention_check_;  // guarded by caller_mutex_
  bool contended_ = false;                                       // guarded by caller_mutex_
  std::atomic<int> polling_helpers_{0};
  std::atomic<long> helper_tasks_{0};
  const int usable_processors_;
};

// Processors this process may run on (its CPU affinity), at least 1.
int usable_processors();

// How many threads the shared pool runs, and what decided it.
struct ThreadSetting {
  int threads = 1;
  std::string source;   // "--threads", "OMP_NUM_THREADS", "OMP_THREAD_LIMIT" or "processors"
  std::string warning;  // a setting that was not obeyed as written, and why; "" when none
};
// The most threads a setting may ask for.
constexpr int max_setting_threads = 64;

// A user's or CI's setting wins over the default: `requested` (the command line's --threads;
// 0 when not given), else OMP_NUM_THREADS (the variable CI systems and users set to cap every
// parallel program; Wobble uses no OpenMP, but obeys it; of a list "4,2" the first number),
// either capped by OMP_THREAD_LIMIT. With neither, the processors this process may run on
// (`processors`), at most WorkerPool::max_shared_threads, and at most OMP_THREAD_LIMIT. A value
// that is not a whole number from 1 to max_setting_threads is not obeyed, and `warning` says so
// (the variables are null when unset).
ThreadSetting decide_thread_setting(int requested, const char* omp_num_threads,
                                    const char* omp_thread_limit, int processors);

// Ask for `threads` threads in the shared pool (the command line's --threads), before the pool
// is first used; throws std::logic_error once the pool exists.
void request_shared_threads(int threads);

// The setting the shared pool is (or will be) made with: decided once, from the request and the
// environment at the first call.
const ThreadSetting& shared_thread_setting();

}  // namespace wobble

#endif
