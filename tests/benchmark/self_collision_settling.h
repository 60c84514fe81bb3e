#ifndef WOBBLE_TESTS_BENCHMARK_SELF_COLLISION_SETTLING_H
#define WOBBLE_TESTS_BENCHMARK_SELF_COLLISION_SETTLING_H

namespace wobble::benchmark {

// Whether a pile with self-collision settles, printed as table rows: the shipped
// assets/cloth_pile.json with its iterations and thickness varied (20, 30, 50 iterations; 5 mm
// and 1 cm), 900 steps each: its whole energy at the start, the most it reaches once it has
// fallen (steps 300-899, where a pile that settles only loses energy), its kinetic energy at the
// end, and the median step and searches a step once it lies (steps 700-899).
void print_self_collision_settling();

// Whether a pile that lands harder still settles, printed as table rows: the self-collision
// tests' folding pile (tests/sim/folding_scenes.h; 32 × 32, thickness 1 cm and 5 mm) let go with
// its sideways velocity as it is, 1.6 and 2 times it, and as it is with self-collision switched
// on only after 10 steps (a fall that nothing held back, as free motion would be): the most
// kinetic energy over steps 401-460, where the tests ask for 1e-5 J (1 cm) and 1e-4 J (5 mm).
void print_self_collision_landing();

}  // namespace wobble::benchmark

#endif
