#ifndef WOBBLE_TESTS_BENCHMARK_SELF_COLLISION_SETTLING_H
#define WOBBLE_TESTS_BENCHMARK_SELF_COLLISION_SETTLING_H

namespace wobble::benchmark {

// Whether a pile with self-collision settles, printed as table rows: the shipped
// assets/cloth_pile.json with its iterations and thickness varied (20, 30, 50 iterations; 5 mm
// and 1 cm), 900 steps each: its whole energy at the start, the most it reaches once it has
// fallen (steps 300-899, where a pile that settles only loses energy), its kinetic energy at the
// end, and the median step and searches a step once it lies (steps 700-899).
void print_self_collision_settling();

}  // namespace wobble::benchmark

#endif
