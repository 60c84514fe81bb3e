#ifndef WOBBLE_TESTS_BENCHMARK_SOLVER_RACE_H
#define WOBBLE_TESTS_BENCHMARK_SOLVER_RACE_H

namespace wobble::benchmark {

// L-BFGS against local-global on one step of the stiff curtain (81×81, 2 m, pinned along its
// top, k = 1e5, density 0.3, pushed at 1.5 m/s), the 65k cloth (256×256) and a stiff jelly:
// the step energy of 50 local-global iterations, how many L-BFGS iterations reach it, and the
// wall time of each (median of repeats from the same state, in one run), with their ratio.
void print_solver_race();

}  // namespace wobble::benchmark

#endif
