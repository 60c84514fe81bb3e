#include "app/viewer/step_thread.h"

#include <utility>

namespace wobble {

StepThread::StepThread(std::function<void()> finished_hook)
    : finished_hook_(std::move(finished_hook)), thread_([this] { loop(); }) {}

StepThread::~StepThread() {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    finished_.wait(lock, [this] { return !running_; });
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void StepThread::start(std::function<void()> job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = std::move(job);
    running_ = true;
  }
  wake_.notify_one();
}

bool StepThread::running() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return running_;
}

void StepThread::wait() {
  std::exception_ptr error;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    finished_.wait(lock, [this] { return !running_; });
    std::swap(error, error_);
  }
  if (error) std::rethrow_exception(error);
}

void StepThread::loop() {
  for (;;) {
    std::function<void()> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return stop_ || job_; });
      if (stop_) return;
      std::swap(job, job_);
    }
    std::exception_ptr error;
    try {
      job();
    } catch (...) {
      error = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      error_ = error;
      running_ = false;
    }
    finished_.notify_all();
    if (finished_hook_) finished_hook_();
  }
}

}  // namespace wobble
