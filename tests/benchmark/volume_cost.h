#ifndef WOBBLE_TESTS_BENCHMARK_VOLUME_COST_H
#define WOBBLE_TESTS_BENCHMARK_VOLUME_COST_H

namespace wobble::benchmark {

// The volume term's cost: the median step of a swaying jelly block (its base pinned) with the
// term off and on, both solvers, at resolutions 8 (the built-in jelly, 3,072 tetrahedra) and 15
// (20,250), and the ratio measured in the same run, printed as table rows.
void print_volume_cost();

}  // namespace wobble::benchmark

#endif
