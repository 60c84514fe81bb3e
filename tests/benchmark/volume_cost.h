#ifndef WOBBLE_TESTS_BENCHMARK_VOLUME_COST_H
#define WOBBLE_TESTS_BENCHMARK_VOLUME_COST_H

namespace wobble::benchmark {

// The volume term's cost: the median step of a swaying jelly block (its base pinned) with the
// term off and on, stepped in turn, both solvers, at resolutions 8 (the built-in jelly, 3,072
// tetrahedra), 11 (7,986) and 15 (20,250), the ratio, the factor's nonzeros and whether the step
// keeps up with dt, printed as table rows.
void print_volume_cost();
// At resolution 15, the step's time and how much of its motion is left undone at 10 to 50
// iterations, plain and with Chebyshev, with the term off and on, printed as table rows.
void print_volume_iterations();

}  // namespace wobble::benchmark

#endif
