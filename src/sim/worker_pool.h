#ifndef WOBBLE_SIM_WORKER_POOL_H
#define WOBBLE_SIM_WORKER_POOL_H

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace wobble {

// A few helper threads for the stepper's parallel loops, built so that a busy machine costs
// little: an idle helper sleeps (it never spins waiting for work), and the calling thread does
// every task that no helper has taken yet. So a helper that has no core to run on delays nothing
// (the caller does its share), and a step on a machine whose other core is taken by another
// program costs about what it costs on one thread, not the many times more that busy-waiting
// barriers cost there (issue 13: OpenMP's step crawled beside any busy process).
//
// run(count, task) calls task(i) once for every i in [0, count), on the caller and any helpers
// that wake in time, and returns when all calls have returned. Tasks must not throw and must not
// call run on the same pool. run allocates nothing; the helpers start in the constructor.
class WorkerPool {
 public:
  // threads  the caller plus threads − 1 helpers (1: everything runs on the caller).
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // The pool the simulation uses: as many threads as processors this process may run on, at
  // most max_shared_threads. Made on first use (in a simulation's precomputation).
  static WorkerPool& shared();
  static constexpr int max_shared_threads = 4;

  int threads() const { return static_cast<int>(helpers_.size()) + 1; }

  template <typename Task>
  void run(int count, Task& task) {
    run_erased(
        count, [](void* context, int index) { (*static_cast<Task*>(context))(index); }, &task);
  }

 private:
  using Call = void (*)(void* context, int index);
  struct Job {
    Call call = nullptr;
    void* context = nullptr;
    int count = 0;
  };
  void run_erased(int count, Call call, void* context);
  void helper_loop();
  // Takes the next task of generation `generation`, if that job is still the current one and
  // has tasks left.
  bool claim(std::uint64_t generation, int count, int& index);
  void finish_task(int count);

  std::vector<std::thread> helpers_;
  std::mutex mutex_;
  std::condition_variable wake_;      // helpers wait here for a new job
  std::condition_variable finished_;  // the caller waits here for the last task
  Job job_;                           // guarded by mutex_
  std::uint64_t generation_ = 0;      // guarded by mutex_; one per run
  bool stop_ = false;                 // guarded by mutex_
  // generation_ for helpers that look without the lock between two close jobs.
  std::atomic<std::uint64_t> published_generation_{0};
  // The generation in the high 32 bits and the next task in the low ones, so that a helper
  // still holding an old job can never take a task of a newer one.
  std::atomic<std::uint64_t> next_task_{0};
  std::atomic<int> done_{0};
};

// Processors this process may run on (its CPU affinity), at least 1.
int usable_processors();

}  // namespace wobble

#endif
