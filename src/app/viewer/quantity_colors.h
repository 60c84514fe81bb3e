#ifndef WOBBLE_APP_VIEWER_QUANTITY_COLORS_H
#define WOBBLE_APP_VIEWER_QUANTITY_COLORS_H

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/color_quantity.h"

namespace wobble {

class Simulation;

// Colouring the shape by a quantity a student can read: how far each spring is stretched or
// compressed, how fast each vertex moves, or which vertices are in contact. Pure functions on Eigen
// arrays, and QuantityColors, which turns a simulation state into colours for the renderer's plain
// arrays. No GL.

// Engineering strain of every spring, strain_e = (‖p_i − p_j‖ − r_e)/r_e: > 0 stretched,
// < 0 compressed, −1 when both ends meet.
//   V       #V by 3 positions (m)
//   E       #E by 2 spring end indices into rows of V
//   r       #E rest lengths (m), each > 0
//   strain  #E, resized (dimensionless)
void spring_strains(const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, const Eigen::VectorXd& r,
                    Eigen::VectorXf& strain);

// The mean of the values of the springs at each vertex (0 where no spring ends).
//   E              #E by 2 spring end indices
//   spring_values  #E
//   vertex_values  vertex_count, resized; `counts` is scratch of the same length
void vertex_mean_of_springs(const Eigen::MatrixXi& E, const Eigen::VectorXf& spring_values,
                            int vertex_count, Eigen::VectorXf& vertex_values,
                            Eigen::VectorXf& counts);

// Speed of every vertex over the last step, ‖pᵗ − pᵗ⁻ᐞᵗ‖/Δt (m/s).
//   current, previous  #V by 3 positions (m) at the current and previous steps
//   dt                 the step (s), > 0
//   speed              #V, resized
void vertex_speeds(const Eigen::MatrixXd& current, const Eigen::MatrixXd& previous, double dt,
                   Eigen::VectorXf& speed);

// The volume change of every tetrahedron, volume/rest volume − 1 (det F − 1): > 0 swollen, < 0
// squashed, below −1 turned inside out; each vertex gets the mean of its tetrahedra's (0 where it
// has none, and everywhere for a network without tetrahedra).
//   V, rest  #V by 3 positions now and at rest (m)
//   T        #T by 4 tetrahedra, indices into rows of V
//   vertex_values  #V, resized; `counts` is scratch of the same length
void vertex_volume_changes(const Eigen::MatrixXd& V, const Eigen::MatrixXd& rest,
                           const Eigen::MatrixXi& T, Eigen::VectorXf& vertex_values,
                           Eigen::VectorXf& counts);

// Colouring by contacts: linear RGB of a vertex the last step's self-collision moved, of one on a
// collider, and of one in neither.
Eigen::Vector3f self_contact_color();
Eigen::Vector3f collider_contact_color();
Eigen::Vector3f contact_free_color();

// Colours of the vertices by contact: self_contact_color() where `self` is set (a vertex in both
// kinds of contact shows the self contact), collider_contact_color() where `collider` is set,
// contact_free_color() elsewhere. A list of flags that is not vertex_count long (empty: before
// the first step, self-collision off or no collider) counts as none set.
//   self, collider  #V flags, non-zero: in contact
//   vertex_count    #V
//   colors          3·#V linear RGB, row-major, resized
void contact_colors(const std::vector<char>& self, const std::vector<char>& collider,
                    int vertex_count, std::vector<float>& colors);

// `value` (≥ 0) with two significant digits and no exponent, for a legend: 0.021 → "0.021",
// 2.14 → "2.1", 123 → "123", 0 → "0".
std::string two_significant_digits(float value);

// The 99th percentile of |values| (0 for none). The top 1% saturates the colour map, so a few
// springs torn at a dragged pin do not wash out the rest of the shape. `scratch` keeps its
// memory between calls.
float robust_maximum(const Eigen::VectorXf& values, std::vector<float>& scratch);

// Diverging map for t in [−1, 1] (clamped): −1 deep blue (compression), 0 a warm near-white,
// +1 deep red (stretch). Each half is a quadratic Bézier curve in linear RGB from the neutral
// colour through a lighter tint to the saturated end, so it is smooth within a half and
// symmetric in lightness.
Eigen::Vector3f diverging_color(float t);
// Sequential map for t in [0, 1] (clamped): a cubic Bézier curve in linear RGB from near-black
// indigo through purple and orange to pale yellow; lightness rises monotonically.
Eigen::Vector3f sequential_color(float t);

// A colour-map range that follows a noisy per-frame maximum without flicker: it takes the first
// value as it is, then moves towards each new one by a share per frame, quickly up (so nothing
// stays saturated for long) and slowly down. Counted in frames, not seconds, so headless images
// do not depend on the wall clock.
class SmoothedRange {
 public:
  static constexpr float rise = 0.3f, fall = 0.05f;  // share of the gap closed per frame
  explicit SmoothedRange(float floor) : floor_(floor) {}
  // Feed this frame's maximum; returns the smoothed range, never below the floor.
  float update(float maximum);
  void restart() { value_ = 0.0f; }
  float value() const { return value_; }

 private:
  float floor_;
  float value_ = 0.0f;  // 0: no frame seen yet
};

// Per-frame colours of a simulation for one quantity. Strain: the springs by their own strain,
// the surface by the mean strain of each vertex's springs, over a symmetric range ±range().
// Speed: the vertices by their speed over 0 … range() m/s, each spring by the mean of its ends'
// speeds. The range is the smoothed robust maximum, with a floor so a resting shape is not
// coloured by noise. Contacts: the vertices by contact_colors() of the simulation's self contact
// and collider contact flags, each spring as its first end in contact (or as a free one), no
// range. Allocates only when the shape's size changes.
class QuantityColors {
 public:
  static constexpr float strain_floor = 1e-4f;  // 0.01%
  static constexpr float speed_floor = 0.01f;   // m/s
  static constexpr float volume_floor = 1e-4f;  // 0.01%

  // Recompute from the simulation's current state. material clears the colours and the range.
  // Without `with_springs` (the springs are not drawn) spring_colors() stays empty: on the
  // 128 × 128 cloth their 97,000 colours are half the cost.
  void update(ColorQuantity quantity, const Simulation& simulation, bool with_springs = true);

  // update in two halves, for shapes shown side by side in one range (the split view): measure
  // each, then paint each with the larger of their measured ranges, so that a colour means the
  // same on both sides. paint needs the simulation that was measured, unchanged since.
  void measure(ColorQuantity quantity, const Simulation& simulation);
  void paint(const Simulation& simulation, float range, bool with_springs);
  // This shape's own smoothed range, from the last measure.
  float measured_range() const;

  ColorQuantity quantity() const { return quantity_; }
  // The range of the colours: strain and volume −range … +range (dimensionless), speed 0 …
  // range (m/s);
  // 0 for material and contacts.
  float range() const { return painted_range_; }
  // #V by 3 and #E by 3 linear RGB, row-major; empty for material (and the springs' without
  // with_springs).
  const std::vector<float>& vertex_colors() const { return vertex_colors_; }
  const std::vector<float>& spring_colors() const { return spring_colors_; }

 private:
  ColorQuantity quantity_ = ColorQuantity::material;
  SmoothedRange strain_range_{strain_floor}, speed_range_{speed_floor}, volume_range_{volume_floor};
  float painted_range_ = 0.0f;
  Eigen::VectorXf spring_values_, vertex_values_, counts_;
  std::vector<float> scratch_, vertex_colors_, spring_colors_;
};

}  // namespace wobble

#endif
