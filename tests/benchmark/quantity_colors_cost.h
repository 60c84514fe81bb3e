#ifndef WOBBLE_TESTS_BENCHMARK_QUANTITY_COLORS_COST_H
#define WOBBLE_TESTS_BENCHMARK_QUANTITY_COLORS_COST_H

namespace wobble::benchmark {

// What colouring by a quantity costs a frame on the 128×128 cloth hanging from its top corners
// (as assets/large_cloth.json): the median of QuantityColors::update for strain and speed, with
// and without the springs' colours, beside the median step, printed as table rows.
void print_quantity_colors_cost();

}  // namespace wobble::benchmark

#endif
