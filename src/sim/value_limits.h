#ifndef WOBBLE_SIM_VALUE_LIMITS_H
#define WOBBLE_SIM_VALUE_LIMITS_H

#include <Eigen/Core>
#include <string>

namespace wobble {

// The range a value may take, both ends included.
struct ValueRange {
  double low, high;
  const char* unit;  // "N/m", or "" for a plain factor

  // False for NaN, so a range check is also a finiteness check.
  bool contains(double value) const { return value >= low && value <= high; }
};

// One set of limits for every value a scene can set, whichever way it comes in: the command
// line (--k, --dt, --iterations), a Wobble scene file, a course scene file, and the panel
// (Simulation's setters check the same ranges). Each keeps the numbers of a step finite and the
// pins in charge, and each maximum runs on the 2-core development machine in a few seconds
// (docs/scenes.md, "Limits").
namespace limits {

// k: far below the pin weight w = 1e10, so that a pin still holds against its springs (a pin
// gives way by about k/w of its springs' stretch).
inline constexpr ValueRange stiffness{1e-6, 1e8, "N/m"};
// Δt: M/Δt² must stay finite and a step must be a step, not a jump of seconds.
inline constexpr ValueRange time_step{1e-9, 1.0, "s"};
// Local-global iterations per step: 5000 on the built-in cloth are a few seconds a step (tests
// take 3000 for a converged step).
inline constexpr int max_iterations = 5000;
// The work of one step, as iterations x (springs + the Cholesky factor's nonzeros): each
// iteration visits every spring (local step) and every nonzero of the factor twice (forward and
// back substitution). Each limit alone is fine, but not their product: 5,000 iterations of a
// 256x256 cloth (390,658 springs, a factor of 5.85 million nonzeros) are 3.1e10, over a minute
// a frame. 2e9 is about 7 s a frame on a 2-core laptop: 320 iterations of that cloth, and all
// 5,000 of the built-in 40x40 cloth (3.6e8).
inline constexpr double max_step_work = 2e9;
// Gravity and every initial velocity, each component (and the sway's top speed).
inline constexpr ValueRange acceleration{-1000.0, 1000.0, "m/s²"};
inline constexpr ValueRange speed{-1000.0, 1000.0, "m/s"};
// A density (kg/m² for surfaces, kg/m³ for volumes), a total mass, and what each vertex gets:
// masses outside these would make M/Δt² underflow against the springs or outweigh the pins.
inline constexpr ValueRange density{1e-6, 1e6, "kg/m² or kg/m³"};
inline constexpr ValueRange total_mass{1e-6, 1e9, "kg"};
inline constexpr ValueRange vertex_mass{1e-9, 1e6, "kg"};
// A mesh's scale factor, a generator's side length, and every position (offsets, heights,
// camera, vertices after scaling): far from where squared lengths under- or overflow.
inline constexpr ValueRange scale{1e-6, 1e6, ""};
inline constexpr ValueRange size{1e-3, 1e3, "m"};
inline constexpr ValueRange coordinate{-1e6, 1e6, "m"};

// Damping c (1/s): velocities decay as (1 + cΔt)⁻ⁿ; beyond 1000/s everything stops in a step.
inline constexpr ValueRange damping{0.0, 1000.0, "1/s"};
// Coulomb friction coefficient μ (material and colliders).
inline constexpr ValueRange friction{0.0, 10.0, ""};
// Wind: aerodynamic coefficients, relative gust strength, air density.
inline constexpr ValueRange aerodynamic_coefficient{0.0, 100.0, ""};
inline constexpr ValueRange gust_strength{0.0, 1.0, ""};
inline constexpr ValueRange air_density{0.0, 1e4, "kg/m³"};
// Colliders: sizes (radius, box edges) and the contact offset, and how many a scene may have
// (every vertex is tested against every collider each step).
inline constexpr ValueRange collider_size{1e-4, 1e4, "m"};
inline constexpr ValueRange contact_offset{0.0, 10.0, "m"};
inline constexpr int max_colliders = 64;
// Self-collision: the thickness the surface keeps between its own layers.
inline constexpr ValueRange self_collision_thickness{1e-5, 1.0, "m"};

// Generated meshes: the largest of each that loads and takes its first step in a few seconds.
inline constexpr int max_cloth_resolution = 256;  // vertices a side: 65,536 vertices
inline constexpr int max_jelly_resolution = 24;   // cells a side: 15,625 vertices
inline constexpr int max_fill_resolution = 24;    // cells along the longest side
// Filling a surface tests every cell centre against every triangle (tetrahedralize_surface):
// at most this many cell-triangle pairs (blob.obj's 1,280 triangles at resolution 24 are
// 1.8e7 of the 13,824 cells' pairs).
inline constexpr double max_fill_pairs = 2e7;

}  // namespace limits

// A number as limits are shown, in its shortest form that reads back (or rounded to
// `max_digits` significant digits): 1e8, 1e-6, 0.25, 1000.
std::string limit_text(double value, int max_digits = 17);

// "within the limits 1e-6 to 1e8 N/m".
std::string within_text(const ValueRange& range);

// What a value in `range` is, for "expected ..." in a message: "a positive number within the
// limits 1e-6 to 1e8 N/m" (or "a number within ..." for a range that takes negatives).
std::string expected_in(const ValueRange& range);

// Empty when every entry of `values` is within `range`; otherwise what is wrong, for a message:
// "vertex masses from 2e-40 to 5e-40 kg, expected each within the limits 1e-9 to 1e6 kg", with
// `what` = "vertex masses" (or "non-finite vertex masses" when one is NaN or infinite).
std::string outside_limits(const Eigen::Ref<const Eigen::ArrayXd>& values, const ValueRange& range,
                           const std::string& what);

}  // namespace wobble

#endif
