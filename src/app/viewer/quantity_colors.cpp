#include "app/viewer/quantity_colors.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim/contact/collider_contact_term.h"
#include "sim/contact/self_contact_term.h"
#include "sim/shapes/tet_mesh.h"
#include "sim/simulation.h"

namespace wobble {

namespace {

// Control colours of the maps, linear RGB. The diverging halves have about the same luminance at
// the same |t| (tints 0.63 and 0.66, ends 0.20 and 0.23), so neither side looks stronger.
const Eigen::Vector3f neutral(0.93f, 0.91f, 0.88f);
const Eigen::Vector3f stretch_tint(0.95f, 0.55f, 0.45f), stretch_end(0.70f, 0.06f, 0.10f);
const Eigen::Vector3f compression_tint(0.50f, 0.68f, 0.95f), compression_end(0.08f, 0.22f, 0.70f);
// Luminances 0.02, 0.15, 0.47, 0.95: increasing control points make a monotonic cubic.
const Eigen::Vector3f sequential_points[4] = {
    {0.02f, 0.01f, 0.08f}, {0.45f, 0.02f, 0.55f}, {1.0f, 0.35f, 0.05f}, {1.0f, 0.97f, 0.55f}};

void put(std::vector<float>& rgb, Eigen::Index row, const Eigen::Vector3f& color) {
  rgb[3 * row] = color.x();
  rgb[3 * row + 1] = color.y();
  rgb[3 * row + 2] = color.z();
}

}  // namespace

// Magenta and cyan-blue stand apart from each other, from the grey and from the orange and blue
// of the material's two sides.
Eigen::Vector3f self_contact_color() {
  return {0.85f, 0.08f, 0.55f};
}

Eigen::Vector3f collider_contact_color() {
  return {0.05f, 0.55f, 0.95f};
}

Eigen::Vector3f contact_free_color() {
  return {0.55f, 0.55f, 0.55f};
}

void contact_colors(const std::vector<char>& self, const std::vector<char>& collider,
                    int vertex_count, std::vector<float>& colors) {
  const auto size = static_cast<std::size_t>(vertex_count);
  const bool has_self = self.size() == size, has_collider = collider.size() == size;
  colors.resize(3 * size);
  for (int i = 0; i < vertex_count; ++i) {
    const Eigen::Vector3f color = has_self && self[i]           ? self_contact_color()
                                  : has_collider && collider[i] ? collider_contact_color()
                                                                : contact_free_color();
    put(colors, i, color);
  }
}

void spring_strains(const Eigen::MatrixXd& V, const Eigen::MatrixXi& E, const Eigen::VectorXd& r,
                    Eigen::VectorXf& strain) {
  strain.resize(E.rows());
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    const double length = (V.row(E(e, 0)) - V.row(E(e, 1))).norm();
    strain[e] = static_cast<float>((length - r[e]) / r[e]);
  }
}

void vertex_mean_of_springs(const Eigen::MatrixXi& E, const Eigen::VectorXf& spring_values,
                            int vertex_count, Eigen::VectorXf& vertex_values,
                            Eigen::VectorXf& counts) {
  vertex_values.setZero(vertex_count);
  counts.setZero(vertex_count);
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    for (int end = 0; end < 2; ++end) {
      vertex_values[E(e, end)] += spring_values[e];
      counts[E(e, end)] += 1.0f;
    }
  }
  vertex_values = (counts.array() > 0.0f).select(vertex_values.array() / counts.array(), 0.0f);
}

void vertex_speeds(const Eigen::MatrixXd& current, const Eigen::MatrixXd& previous, double dt,
                   Eigen::VectorXf& speed) {
  // A loop rather than one expression: (current − previous) would allocate a #V by 3 temporary
  // every frame.
  speed.resize(current.rows());
  for (Eigen::Index i = 0; i < current.rows(); ++i)
    speed[i] = static_cast<float>((current.row(i) - previous.row(i)).norm() / dt);
}

std::string two_significant_digits(float value) {
  if (!(value > 0.0f)) return "0";
  const int decimals = std::max(0, 1 - static_cast<int>(std::floor(std::log10(value))));
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, static_cast<double>(value));
  return text;
}

float robust_maximum(const Eigen::VectorXf& values, std::vector<float>& scratch) {
  if (values.size() == 0) return 0.0f;
  scratch.resize(values.size());
  for (Eigen::Index i = 0; i < values.size(); ++i)
    scratch[i] = std::abs(values[i]);
  // nth_element is linear on average: about a millisecond for the 128 × 128 cloth's springs.
  const std::size_t at = static_cast<std::size_t>(0.99 * static_cast<double>(scratch.size() - 1));
  std::nth_element(scratch.begin(), scratch.begin() + at, scratch.end());
  return scratch[at];
}

Eigen::Vector3f diverging_color(float t) {
  t = std::clamp(t, -1.0f, 1.0f);
  const float s = std::abs(t);
  const Eigen::Vector3f& tint = t < 0.0f ? compression_tint : stretch_tint;
  const Eigen::Vector3f& end = t < 0.0f ? compression_end : stretch_end;
  return (1.0f - s) * (1.0f - s) * neutral + 2.0f * s * (1.0f - s) * tint + s * s * end;
}

Eigen::Vector3f sequential_color(float t) {
  const float s = std::clamp(t, 0.0f, 1.0f), u = 1.0f - s;
  return u * u * u * sequential_points[0] + 3.0f * u * u * s * sequential_points[1] +
         3.0f * u * s * s * sequential_points[2] + s * s * s * sequential_points[3];
}

void vertex_volume_changes(const Eigen::MatrixXd& V, const Eigen::MatrixXd& rest,
                           const Eigen::MatrixXi& T, Eigen::VectorXf& vertex_values,
                           Eigen::VectorXf& counts) {
  vertex_values.setZero(V.rows());
  counts.setZero(V.rows());
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    const double before = tet_signed_volume(rest, T, t);
    if (before == 0.0) continue;
    const auto change = static_cast<float>(tet_signed_volume(V, T, t) / before - 1.0);
    for (int c = 0; c < 4; ++c) {
      vertex_values[T(t, c)] += change;
      counts[T(t, c)] += 1.0f;
    }
  }
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    if (counts[i] > 0.0f) vertex_values[i] /= counts[i];
  }
}

float SmoothedRange::update(float maximum) {
  const float target = std::isfinite(maximum) ? std::max(maximum, floor_) : floor_;
  if (value_ <= 0.0f) {
    value_ = target;
  } else {
    value_ += (target > value_ ? rise : fall) * (target - value_);
  }
  return value_;
}

float QuantityColors::measured_range() const {
  switch (quantity_) {
    case ColorQuantity::strain:
      return strain_range_.value();
    case ColorQuantity::speed:
      return speed_range_.value();
    case ColorQuantity::volume:
      return volume_range_.value();
    case ColorQuantity::material:
    case ColorQuantity::contacts:
      break;
  }
  return 0.0f;
}

void QuantityColors::update(ColorQuantity quantity, const Simulation& simulation,
                            bool with_springs) {
  measure(quantity, simulation);
  paint(simulation, measured_range(), with_springs);
}

void QuantityColors::measure(ColorQuantity quantity, const Simulation& simulation) {
  // A quantity chosen afresh starts from its own maximum rather than an old one.
  if (quantity != quantity_) {
    strain_range_.restart();
    speed_range_.restart();
    volume_range_.restart();
  }
  quantity_ = quantity;
  const Eigen::MatrixXi& E = simulation.rest().E;
  if (quantity == ColorQuantity::strain) {
    spring_strains(simulation.positions(), E, simulation.rest_lengths(), spring_values_);
    strain_range_.update(robust_maximum(spring_values_, scratch_));
    vertex_mean_of_springs(E, spring_values_, static_cast<int>(simulation.positions().rows()),
                           vertex_values_, counts_);
  } else if (quantity == ColorQuantity::speed) {
    vertex_speeds(simulation.positions(), simulation.previous_positions(), simulation.params().dt,
                  vertex_values_);
    speed_range_.update(robust_maximum(vertex_values_, scratch_));
  } else if (quantity == ColorQuantity::volume) {
    vertex_volume_changes(simulation.positions(), simulation.rest().V, simulation.rest().T,
                          vertex_values_, counts_);
    volume_range_.update(robust_maximum(vertex_values_, scratch_));
  } else if (quantity == ColorQuantity::contacts) {
    // Nothing to measure; paint takes the vertex count from these values' length.
    vertex_values_.resize(simulation.positions().rows());
  }
}

void QuantityColors::paint(const Simulation& simulation, float range, bool with_springs) {
  painted_range_ =
      quantity_ == ColorQuantity::material || quantity_ == ColorQuantity::contacts ? 0.0f : range;
  if (quantity_ == ColorQuantity::material) {
    vertex_colors_.clear();
    spring_colors_.clear();
    return;
  }
  const Eigen::MatrixXi& E = simulation.rest().E;
  const Eigen::Index vertex_count = vertex_values_.size();
  const Eigen::Index colored_springs = with_springs ? E.rows() : 0;
  vertex_colors_.resize(3 * vertex_count);
  spring_colors_.resize(3 * colored_springs);
  if (quantity_ == ColorQuantity::strain) {
    for (Eigen::Index e = 0; e < colored_springs; ++e)
      put(spring_colors_, e, diverging_color(spring_values_[e] / range));
    for (Eigen::Index i = 0; i < vertex_count; ++i)
      put(vertex_colors_, i, diverging_color(vertex_values_[i] / range));
    return;
  }
  if (quantity_ == ColorQuantity::volume) {
    for (Eigen::Index i = 0; i < vertex_count; ++i)
      put(vertex_colors_, i, diverging_color(vertex_values_[i] / range));
    for (Eigen::Index e = 0; e < colored_springs; ++e) {
      const float mean = 0.5f * (vertex_values_[E(e, 0)] + vertex_values_[E(e, 1)]);
      put(spring_colors_, e, diverging_color(mean / range));
    }
    return;
  }
  if (quantity_ == ColorQuantity::contacts) {
    const std::vector<char>& self = self_contact_vertices(simulation.terms());
    const std::vector<char>& collider = collider_contact_vertices(simulation.terms());
    contact_colors(self, collider, static_cast<int>(vertex_count), vertex_colors_);
    const auto size = static_cast<std::size_t>(vertex_count);
    const auto touching = [&](Eigen::Index i) {
      return (self.size() == size && self[i]) || (collider.size() == size && collider[i]);
    };
    // A spring takes the colour of its first end in contact, if either is.
    for (Eigen::Index e = 0; e < colored_springs; ++e) {
      const Eigen::Index end = touching(E(e, 0)) ? E(e, 0) : E(e, 1);
      for (int k = 0; k < 3; ++k)
        spring_colors_[3 * e + k] = vertex_colors_[3 * end + k];
    }
    return;
  }
  for (Eigen::Index i = 0; i < vertex_count; ++i)
    put(vertex_colors_, i, sequential_color(vertex_values_[i] / range));
  for (Eigen::Index e = 0; e < colored_springs; ++e) {
    const float mean = 0.5f * (vertex_values_[E(e, 0)] + vertex_values_[E(e, 1)]);
    put(spring_colors_, e, sequential_color(mean / range));
  }
}

}  // namespace wobble
