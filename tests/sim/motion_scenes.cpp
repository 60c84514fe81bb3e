#include "motion_scenes.h"

#include <cmath>

#include "sim/shapes/cloth_grid.h"
#include "test_colliders.h"

namespace wobble::testing {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double thickness = 0.005;

// Appends `part` to `whole` (vertices, springs, triangles and masses renumbered after it).
void append(SpringNetwork& whole, const SpringNetwork& part) {
  const auto shift = [](Eigen::MatrixXi indices, Eigen::Index by) {
    indices.array() += static_cast<int>(by);
    return indices;
  };
  const Eigen::Index offset = whole.V.rows();
  SpringNetwork joined;
  joined.V.resize(offset + part.V.rows(), 3);
  joined.V << whole.V, part.V;
  joined.E.resize(whole.E.rows() + part.E.rows(), 2);
  joined.E << whole.E, shift(part.E, offset);
  joined.F.resize(whole.F.rows() + part.F.rows(), 3);
  joined.F << whole.F, shift(part.F, offset);
  joined.m.resize(offset + part.m.rows());
  joined.m << whole.m, part.m;
  whole = std::move(joined);
}

SpringNetwork sheet(int n, double size) {
  ClothGridOptions options;
  options.resolution = n;
  options.size = size;
  options.bend = false;
  return make_cloth_grid(options);
}

// Rotates the rows of V by `degrees` about the x axis.
void tilt(Eigen::MatrixXd& V, double degrees) {
  const double angle = degrees * pi / 180.0, c = std::cos(angle), s = std::sin(angle);
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    const double y = V(i, 1), z = V(i, 2);
    V(i, 1) = c * y - s * z;
    V(i, 2) = s * y + c * z;
  }
}

}  // namespace

MotionScene falling_sheets_scene(int n, bool self_collision) {
  MotionScene scene;
  scene.network = sheet(n, 1.0);
  SpringNetwork upper = sheet(n, 1.0);
  tilt(upper.V, 5.0);
  upper.V.col(1).array() += 0.5;
  const int first = static_cast<int>(scene.network.V.rows());
  append(scene.network, upper);
  for (int v = first; v < scene.network.V.rows(); ++v)
    scene.moving.push_back(v);
  scene.params.k = 1000.0;
  scene.params.iterations = 15;
  scene.params.contact.colliders = {ground_collider()};
  scene.params.contact.friction = 0.4;
  scene.params.self_collision.on = self_collision;
  scene.params.self_collision.thickness = thickness;
  return scene;
}

Eigen::Vector3d slope_direction(double angle_degrees) {
  const double angle = angle_degrees * pi / 180.0;
  // tilt() takes +z to (0, −sin, cos): down the slope, as the sheets start at −z.
  return Eigen::Vector3d(0.0, -std::sin(angle), std::cos(angle));
}

MotionScene sliding_sheet_scene(double angle_degrees, double friction, bool on_plane) {
  const double angle = angle_degrees * pi / 180.0;
  const Eigen::Vector3d normal(0.0, std::cos(angle), std::sin(angle));
  MotionScene scene;
  // The small sheet, 0.9 m up the slope and a thickness above it.
  SpringNetwork small = sheet(10, 0.3);
  small.V.col(2).array() -= 0.9;
  tilt(small.V, angle_degrees);
  small.V.rowwise() += thickness * normal.transpose();
  if (on_plane) {
    scene.network = small;
    Collider plane;
    plane.type = ColliderType::plane;
    plane.center = Eigen::Vector3d::Zero();
    plane.normal = normal;
    scene.params.contact.colliders = {plane};
    scene.params.contact.offset = thickness;
  } else {
    scene.network = sheet(26, 2.5);
    tilt(scene.network.V, angle_degrees);
    for (int v = 0; v < scene.network.V.rows(); ++v)
      scene.pins.push_back(v);
    scene.params.self_collision.on = true;
    scene.params.self_collision.thickness = thickness;
  }
  // The small sheet is the whole network on the plane, and follows the slope's sheet otherwise.
  const int first = on_plane ? 0 : static_cast<int>(scene.network.V.rows());
  if (!on_plane) append(scene.network, small);
  for (int v = first; v < scene.network.V.rows(); ++v)
    scene.moving.push_back(v);
  scene.params.k = 1000.0;
  scene.params.iterations = 30;
  scene.params.contact.friction = friction;
  return scene;
}

Eigen::Vector3d centroid(const Eigen::MatrixXd& positions, const std::vector<int>& vertices) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const int v : vertices)
    sum += positions.row(v).transpose();
  return vertices.empty() ? sum : Eigen::Vector3d(sum / static_cast<double>(vertices.size()));
}

}  // namespace wobble::testing
