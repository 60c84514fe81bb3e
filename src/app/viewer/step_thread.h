#ifndef WOBBLE_APP_VIEWER_STEP_THREAD_H
#define WOBBLE_APP_VIEWER_STEP_THREAD_H

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace wobble {

// The thread the window's simulation steps on, so that the UI never waits for a step: the UI
// starts a job (a few steps), goes on drawing the last finished state and taking input, and
// takes the job's results once it finished. One job at a time. Between jobs the thread sleeps
// on a condition variable: it never spins.
//
// Everything the job writes is the UI's to read once finished() said so (or wait() returned):
// the mutex orders the job's writes before the UI's reads.
class StepThread {
 public:
  // `finished_hook` runs on the stepping thread after each job (the window posts an empty event
  // with it, so that a UI waiting for input wakes for the new state).
  explicit StepThread(std::function<void()> finished_hook = {});
  // Waits for a running job, then ends the thread.
  ~StepThread();
  StepThread(const StepThread&) = delete;
  StepThread& operator=(const StepThread&) = delete;

  // Run `job` on the stepping thread. Only while no job runs (running() is false).
  void start(std::function<void()> job);
  // A job started and not yet finished.
  bool running() const;
  // Until the running job finished (at once when none runs). An exception the job threw comes
  // out here, once.
  void wait();

 private:
  void loop();

  std::function<void()> finished_hook_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;      // the stepping thread waits here for a job
  std::condition_variable finished_;  // wait() waits here for the job's end
  std::function<void()> job_;         // guarded by mutex_; empty when none waits
  bool running_ = false;              // guarded by mutex_
  bool stop_ = false;                 // guarded by mutex_
  std::exception_ptr error_;          // guarded by mutex_
  std::thread thread_;                // last: starts once the rest is built
};

}  // namespace wobble

#endif
