#ifndef WOBBLE_SIM_INSTRUMENTS_STEP_OBSERVER_H
#define WOBBLE_SIM_INSTRUMENTS_STEP_OBSERVER_H

#include <Eigen/Core>
#include <vector>

namespace wobble {

// What watches a step's iterations without changing them: the convergence trace, a teaching
// callback. A step solver calls these once per step and once per iteration, never per vertex.
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  // Whether it wants measured(): the energy and gradient of every iterate cost the solver
  // about one more pass over the springs per iteration.
  virtual bool wants_measures() const { return false; }
  // Before the first iterate. `solver` is the solver's registered name; `accelerated` whether
  // its iterates are extrapolated (Chebyshev) rather than the plain method's.
  virtual void begin_step(const char* /*solver*/, bool /*accelerated*/) {}
  // The step energy E(p) (J, see step_objective.h) and ‖∇E(p)‖ (N) at each iterate in turn:
  // the first iterate, then the iterate after each iteration.
  virtual void measured(double /*energy*/, double /*gradient_norm*/) {}
  // After each iteration (0-based), with the iterate p (#V by 3, m).
  virtual void iterated(int /*iteration*/, const Eigen::MatrixXd& /*p*/) {}
};

// The observers a step reports to, in order. Holds pointers it does not own; set() between
// steps, never during one.
class StepObservers {
 public:
  void set(std::vector<StepObserver*> observers);
  bool wants_measures() const { return wants_measures_; }
  void begin_step(const char* solver, bool accelerated) {
    for (StepObserver* observer : observers_)
      observer->begin_step(solver, accelerated);
  }
  void measured(double energy, double gradient_norm) {
    for (StepObserver* observer : observers_)
      if (observer->wants_measures()) observer->measured(energy, gradient_norm);
  }
  void iterated(int iteration, const Eigen::MatrixXd& p) {
    for (StepObserver* observer : observers_)
      observer->iterated(iteration, p);
  }

 private:
  std::vector<StepObserver*> observers_;
  bool wants_measures_ = false;
};

}  // namespace wobble

#endif
