#include "worker_pool.h"

#include <algorithm>

#if defined(__linux__)
#include <sched.h>
#endif

namespace wobble {

namespace {

// How long a thread polls before it sleeps: about 256 pause instructions (a few microseconds),
// enough to catch the local step's second loop, which starts right after its first, and far too
// short to matter to another program on the same core.
constexpr int poll_rounds = 256;

inline void cpu_pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

}  // namespace

int usable_processors() {
#if defined(__linux__)
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return std::max(1, CPU_COUNT(&set));
#endif
  return std::max(1u, std::thread::hardware_concurrency());
}

WorkerPool::WorkerPool(int threads) {
  for (int t = 1; t < threads; ++t)
    helpers_.emplace_back([this] { helper_loop(); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& helper : helpers_)
    helper.join();
}

WorkerPool& WorkerPool::shared() {
  static WorkerPool pool(std::min(usable_processors(), max_shared_threads));
  return pool;
}

bool WorkerPool::claim(std::uint64_t generation, int count, int& index) {
  std::uint64_t next = next_task_.load(std::memory_order_relaxed);
  for (;;) {
    if ((next >> 32) != generation) return false;
    const int task = static_cast<int>(next & 0xffffffffu);
    if (task >= count) return false;
    if (next_task_.compare_exchange_weak(next, next + 1, std::memory_order_acquire,
                                         std::memory_order_relaxed)) {
      index = task;
      return true;
    }
  }
}

void WorkerPool::finish_task(int count) {
  if (done_.fetch_add(1, std::memory_order_acq_rel) + 1 == count) {
    // Under the lock, so the caller cannot check done_ and then miss this notification.
    std::lock_guard<std::mutex> lock(mutex_);
    finished_.notify_one();
  }
}

void WorkerPool::run_erased(int count, Call call, void* context) {
  if (count <= 0) return;
  if (helpers_.empty() || count == 1) {
    for (int i = 0; i < count; ++i)
      call(context, i);
    return;
  }
  std::uint64_t generation;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = {call, context, count};
    generation = ++generation_;
    done_.store(0, std::memory_order_relaxed);
    next_task_.store(generation << 32, std::memory_order_release);
    published_generation_.store(generation, std::memory_order_release);
  }
  wake_.notify_all();  // no system call when every helper is still polling

  int index;
  while (claim(generation, count, index)) {
    call(context, index);
    finish_task(count);
  }
  // Only tasks a helper has already started are left: wait for them, briefly polling, then
  // asleep, so that a helper without a core of its own can have the caller's.
  for (int round = 0; round < poll_rounds; ++round) {
    if (done_.load(std::memory_order_acquire) == count) return;
    cpu_pause();
  }
  std::unique_lock<std::mutex> lock(mutex_);
  finished_.wait(lock, [&] { return done_.load(std::memory_order_acquire) == count; });
}

void WorkerPool::helper_loop() {
  std::uint64_t seen = 0;
  for (;;) {
    for (int round = 0; round < poll_rounds; ++round) {
      if (published_generation_.load(std::memory_order_acquire) != seen) break;
      cpu_pause();
    }
    Job job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      job = job_;
    }
    int index;
    while (claim(seen, job.count, index)) {
      job.call(job.context, index);
      finish_task(job.count);
    }
  }
}

}  // namespace wobble
