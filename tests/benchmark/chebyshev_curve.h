#ifndef WOBBLE_TESTS_BENCHMARK_CHEBYSHEV_CURVE_H
#define WOBBLE_TESTS_BENCHMARK_CHEBYSHEV_CURVE_H

#include "benchmark_scenes.h"

namespace wobble::benchmark {

// Error against the converged step versus time, for plain and Chebyshev-accelerated iterations
// on `scene`, printed as a table, then how soon Chebyshev reaches the error of 10 plain
// iterations.
void print_chebyshev_curve(const BenchmarkScene& scene);

}  // namespace wobble::benchmark

#endif
