#include "sim/parallel/worker_pool.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "sim/input_error.h"

#if defined(__linux__)
#include <fcntl.h>
#include <sched.h>
#include <unistd.h>
#endif
#if defined(__unix__)
#include <pthread.h>
#include <signal.h>
#endif

namespace wobble {

namespace {

// How long the caller polls for a helper's last task before it sleeps: about 256 pause
// instructions, a few microseconds.
constexpr int poll_rounds = 256;
// A helper polls for the next job for twice the recent gap between jobs, at least
// min_poll_seconds (enough to catch the local step's second loop, which starts right after its
// first), and only while that gap is under max_poll_seconds: waking a sleeping thread takes some
// 20 to 50 µs, which matters between iterations 100 µs apart and not between ones 2 ms apart.
constexpr double min_poll_seconds = 5e-6, max_poll_seconds = 300e-6;
constexpr double max_counted_gap_seconds = 1e-3;

inline void cpu_pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

// How often the caller looks whether another program wants the processors.
constexpr double contention_check_seconds = 0.02;

// Threads runnable on the whole machine right now (the 4th field of /proc/loadavg, "R/total"),
// or -1 where that cannot be read. Reads into the stack: no allocation.
int runnable_threads() {
#if defined(__linux__)
  const int file = open("/proc/loadavg", O_RDONLY | O_CLOEXEC);
  if (file < 0) return -1;
  char text[128];
  const ssize_t size = read(file, text, sizeof(text) - 1);
  close(file);
  if (size <= 0) return -1;
  text[size] = '\0';
  const char* at = text;
  for (int field = 0; field < 3; ++field) {
    while (*at && *at != ' ')
      ++at;
    while (*at == ' ')
      ++at;
  }
  int runnable = 0;
  for (; *at >= '0' && *at <= '9'; ++at)
    runnable = 10 * runnable + (*at - '0');
  return *at == '/' ? runnable : -1;
#else
  return -1;
#endif
}

double seconds_between(std::chrono::steady_clock::time_point start,
                       std::chrono::steady_clock::time_point end) {
  return std::chrono::duration<double>(end - start).count();
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return seconds_between(start, std::chrono::steady_clock::now());
}

}  // namespace

bool SharingPayoff::next_is_shared() const {
  if (shared_seconds_ == 0.0) return true;
  if (alone_seconds_ == 0.0) return false;
  // A margin, so that sharing that gains next to nothing is left alone.
  const bool faster = shared_seconds_ < 0.95 * alone_seconds_;
  return (shared_runs_ + runs_on_caller_) % explore_every == 0 ? !faster : faster;
}

bool SharingPayoff::try_sharing() {
  const bool share = next_is_shared();
  ++(share ? shared_runs_ : runs_on_caller_);
  return share;
}

void SharingPayoff::record(bool shared, double wall_seconds) {
  double& average = shared ? shared_seconds_ : alone_seconds_;
  // A run that was interrupted (another program took the core for a while) counts at most
  // twice the average, so one stall cannot flip the choice for long.
  average =
      average == 0.0 ? wall_seconds : 0.8 * average + 0.2 * std::min(wall_seconds, 2.0 * average);
}

int usable_processors() {
#if defined(__linux__)
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return std::max(1, CPU_COUNT(&set));
#endif
  return std::max(1u, std::thread::hardware_concurrency());
}

WorkerPool::WorkerPool(int threads, std::uint64_t first_generation)
    : generation_(first_generation),
      published_generation_(first_generation),
      usable_processors_(usable_processors()) {
#if defined(__unix__)
  // Helpers start with every signal blocked (they inherit the mask), so that signals go to the
  // program's own threads: a handler, such as the one that removes a temporary file on SIGTERM,
  // never runs on a helper while the main thread holds the signal back.
  sigset_t all, previous;
  sigfillset(&all);
  pthread_sigmask(SIG_SETMASK, &all, &previous);
#endif
  for (int t = 1; t < threads; ++t)
    helpers_.emplace_back([this] { helper_loop(); });
#if defined(__unix__)
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
#endif
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

namespace {

int requested_shared_threads = 0;  // 0: none requested
std::atomic<bool> shared_pool_made{false};

// The whole number `text` holds (spaces around it allowed), or 0 when it holds none in
// 1..max_setting_threads. With `first_of_list`, only the text before a comma counts.
int parse_threads(std::string text, bool first_of_list) {
  if (first_of_list) text = text.substr(0, text.find(','));
  const auto begin = text.find_first_not_of(" \t");
  const auto end = text.find_last_not_of(" \t");
  if (begin == std::string::npos) return 0;
  text = text.substr(begin, end - begin + 1);
  if (text.empty() || text.size() > 3 ||
      text.find_first_not_of("0123456789") != std::string::npos) {
    return 0;
  }
  const int value = std::stoi(text);
  return value >= 1 && value <= max_setting_threads ? value : 0;
}

}  // namespace

ThreadSetting decide_thread_setting(int requested, const char* omp_num_threads,
                                    const char* omp_thread_limit, int processors) {
  ThreadSetting setting;
  std::string ignored;
  const auto not_obeyed = [&](const char* name, const char* value) {
    // The value is quoted escaped: a line break in it must not split the warning's line.
    ignored += std::string(ignored.empty() ? "" : "; ") + name + "='" +
               escape_control_characters(value) + "' is not a whole number of threads from 1 to " +
               std::to_string(max_setting_threads) + ", so it is not obeyed";
  };
  int limit = max_setting_threads;
  if (omp_thread_limit != nullptr) {
    const int value = parse_threads(omp_thread_limit, false);
    if (value > 0) {
      limit = value;
    } else {
      not_obeyed("OMP_THREAD_LIMIT", omp_thread_limit);
    }
  }
  const int from_variable =
      omp_num_threads == nullptr ? 0 : parse_threads(omp_num_threads, /*first_of_list=*/true);
  if (omp_num_threads != nullptr && from_variable == 0 && requested == 0) {
    not_obeyed("OMP_NUM_THREADS", omp_num_threads);
  }
  if (requested > 0) {
    setting = {requested, "--threads", ""};
  } else if (from_variable > 0) {
    setting = {from_variable, "OMP_NUM_THREADS", ""};
  } else {
    setting = {std::max(1, std::min(processors, WorkerPool::max_shared_threads)), "processors", ""};
  }
  if (setting.threads > limit) {
    setting.threads = limit;
    setting.source = "OMP_THREAD_LIMIT";
  }
  setting.warning = ignored;
  return setting;
}

void request_shared_threads(int threads) {
  if (shared_pool_made.load()) {
    throw std::logic_error("request_shared_threads: the shared pool is already made");
  }
  requested_shared_threads = threads;
}

const ThreadSetting& shared_thread_setting() {
  static const ThreadSetting setting =
      decide_thread_setting(requested_shared_threads, std::getenv("OMP_NUM_THREADS"),
                            std::getenv("OMP_THREAD_LIMIT"), usable_processors());
  return setting;
}

WorkerPool& WorkerPool::shared() {
  static WorkerPool pool((shared_pool_made.store(true), shared_thread_setting().threads));
  return pool;
}

bool WorkerPool::claim(std::uint64_t generation, int count, int& index) {
  std::uint64_t next = next_task_.load(std::memory_order_relaxed);
  for (;;) {
    // The counter holds the generation's low 32 bits: compare those (after 2³² runs, some
    // eight days of stepping, the full number no longer fits).
    if ((next >> 32) != (generation & 0xffffffffu)) return false;
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

void WorkerPool::run_erased(int count, Call call, void* context, SharingPayoff* payoff) {
  if (count <= 0) return;
  std::lock_guard<std::mutex> one_caller(caller_mutex_);
  const auto start = std::chrono::steady_clock::now();
  // The gaps between runs set how long helpers poll before they sleep. A slowly decaying
  // maximum: the local step's gaps alternate between next to nothing (its second loop) and a
  // global step's length, and a poll must outlast the longer one.
  // A gap is counted at most as max_counted_gap_seconds, so that a pause (or the first run)
  // does not stop the polling for long after it.
  gap_seconds_ = std::max(std::min(seconds_between(last_run_end_, start), max_counted_gap_seconds),
                          0.875 * gap_seconds_);
  // A polling helper with no core of its own takes turns with the caller, and slows what the
  // caller does between runs (the global step): poll only while a core is free.
  if (!helpers_.empty() &&
      seconds_between(last_contention_check_, start) >= contention_check_seconds) {
    last_contention_check_ = start;
    const int runnable = runnable_threads();
    const int others = runnable - 1 - polling_helpers_.load(std::memory_order_relaxed);
    contended_ = runnable >= 0 && others + threads() > usable_processors_;
  }
  poll_budget_seconds_.store(!contended_ && gap_seconds_ < max_poll_seconds
                                 ? std::max(2.0 * gap_seconds_, min_poll_seconds)
                                 : min_poll_seconds,
                             std::memory_order_relaxed);
  const bool share = !helpers_.empty() && count > 1 && (!payoff || payoff->try_sharing());
  if (share) {
    run_shared(count, call, context);
  } else {
    for (int i = 0; i < count; ++i)
      call(context, i);
  }
  last_run_end_ = std::chrono::steady_clock::now();
  if (payoff) {
    payoff->record(share, seconds_between(start, last_run_end_));
    // A shared run coming after one on the caller alone: have the helpers poll for it now, so
    // that what it measures is sharing, not waking sleeping threads.
    if (!share && !helpers_.empty() && payoff->next_is_shared()) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        ++wake_calls_;
      }
      wake_.notify_all();
    }
  }
}

void WorkerPool::run_shared(int count, Call call, void* context) {
  std::uint64_t generation;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = {call, context, count};
    generation = ++generation_;
    done_.store(0, std::memory_order_relaxed);
    next_task_.store((generation & 0xffffffffu) << 32, std::memory_order_release);
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
  std::uint64_t seen = 0, seen_wake_calls = 0;
  for (;;) {
    // Poll for the next job while jobs have lately come that soon after each other (the local
    // step's iterations), then sleep until a job or a call to poll comes.
    const auto poll_start = std::chrono::steady_clock::now();
    const double poll_seconds = poll_budget_seconds_.load(std::memory_order_relaxed);
    polling_helpers_.fetch_add(1, std::memory_order_relaxed);
    for (int round = 1; published_generation_.load(std::memory_order_acquire) == seen; ++round) {
      if (round % 64 == 0 && seconds_since(poll_start) >= poll_seconds) break;
      cpu_pause();
    }
    polling_helpers_.fetch_sub(1, std::memory_order_relaxed);
    Job job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock,
                 [&] { return stop_ || generation_ != seen || wake_calls_ != seen_wake_calls; });
      if (stop_) return;
      seen_wake_calls = wake_calls_;
      if (generation_ == seen) continue;  // called to poll: no job yet
      seen = generation_;
      job = job_;
    }
    int index;
    while (claim(seen, job.count, index)) {
      job.call(job.context, index);
      helper_tasks_.fetch_add(1, std::memory_order_relaxed);
      finish_task(job.count);
    }
  }
}

}  // namespace wobble
