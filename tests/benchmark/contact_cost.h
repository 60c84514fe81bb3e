#ifndef WOBBLE_TESTS_BENCHMARK_CONTACT_COST_H
#define WOBBLE_TESTS_BENCHMARK_CONTACT_COST_H

namespace wobble::benchmark {

// A 128×128 cloth draped over a sphere on the ground: the median step time and the share of it
// spent in contact (projection and friction) and in wind, printed as a table row.
void print_contact_cost();

}  // namespace wobble::benchmark

#endif
