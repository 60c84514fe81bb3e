#ifndef WOBBLE_TESTS_BENCHMARK_SOLVE_COST_H
#define WOBBLE_TESTS_BENCHMARK_SOLVE_COST_H

namespace wobble::benchmark {

// The global step's solver alone, Wobble's supernodal Cholesky against Eigen's SimplicialLLT
// on each benchmark scene's Q = k AᵀA + M/Δt² + w CᵀC, printed as table rows: one solve of
// the #V by 3 right-hand side, and one numeric factorization (Wobble's on one thread and on the
// shared pool), median milliseconds of runs taken in turn, and the ratios. The step table's
// speed-ups are for whole steps, where the local step gains too.
void print_solve_cost();

}  // namespace wobble::benchmark

#endif
