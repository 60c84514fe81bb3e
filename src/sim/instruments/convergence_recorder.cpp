#include "convergence_recorder.h"

namespace wobble {

void ConvergenceRecorder::reserve(int max_iterations) {
  trace_.energy.reserve(max_iterations + 1);
  trace_.gradient_norm.reserve(max_iterations + 1);
}

void ConvergenceRecorder::begin_step(const char* solver, bool accelerated) {
  trace_.energy.clear();
  trace_.gradient_norm.clear();
  trace_.chebyshev = accelerated;
  trace_.solver = solver;  // a registered name: static storage
  trace_.force_scale = force_scale_;
}

void ConvergenceRecorder::measured(double energy, double gradient_norm) {
  trace_.gradient_norm.push_back(gradient_norm);
  trace_.energy.push_back(energy);
}

}  // namespace wobble
