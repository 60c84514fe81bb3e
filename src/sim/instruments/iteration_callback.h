#ifndef WOBBLE_SIM_INSTRUMENTS_ITERATION_CALLBACK_H
#define WOBBLE_SIM_INSTRUMENTS_ITERATION_CALLBACK_H

#include <Eigen/Core>
#include <functional>
#include <utility>

#include "step_observer.h"

namespace wobble {

// Calls a function after every iteration of every step with the iteration number (0-based) and
// the iterate p (#V by 3, m): for teaching and tests (Simulation::set_iteration_observer).
class IterationCallback : public StepObserver {
 public:
  using Function = std::function<void(int, const Eigen::MatrixXd&)>;
  void set(Function function) { function_ = std::move(function); }
  bool empty() const { return !function_; }
  void iterated(int iteration, const Eigen::MatrixXd& p) override { function_(iteration, p); }

 private:
  Function function_;
};

}  // namespace wobble

#endif
