#ifndef WOBBLE_TESTS_BENCHMARK_SELF_COLLISION_MOTION_H
#define WOBBLE_TESTS_BENCHMARK_SELF_COLLISION_MOTION_H

namespace wobble::benchmark {

// Whether self-contact leaves free motion free, printed as table rows:
// - two 96×96 sheets, one falling 0.5 m onto the other (tests/sim/motion_scenes.h): the upper
//   sheet's centroid with self-contact against without, frame by frame until they meet, and
//   the median step while they are apart, with and without;
// - the 128×128 pile (self_collision_cost.h's): how far its top row has dropped by frames 45 and
//   90 with self-contact, as a share of the drop without, for both solvers;
// - a small sheet on a sheet sloped 10°, frictionless and with friction 0.4, against the same
//   sheet on a plane collider of that slope: how far it slid in 1 s;
// and for each, how often self-contact held a vertex's motion back a step, per vertex.
void print_self_collision_motion();

}  // namespace wobble::benchmark

#endif
