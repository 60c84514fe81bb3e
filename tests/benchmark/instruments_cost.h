#ifndef WOBBLE_TESTS_BENCHMARK_INSTRUMENTS_COST_H
#define WOBBLE_TESTS_BENCHMARK_INSTRUMENTS_COST_H

namespace wobble::benchmark {

// What the classroom instruments cost a step: the same scene stepped with the convergence trace
// off and on (plain and Chebyshev), alternating step by step so that both see the same machine,
// and the frame energy of the energy plot; printed as table rows of medians and ratios.
void print_instruments_cost();

}  // namespace wobble::benchmark

#endif
