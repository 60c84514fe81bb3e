#include "check_scene.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace {

// A deterministic, irregular displacement (no random generator, so every run and every machine
// checks the same numbers): each vertex and coordinate gets its own phase.
Eigen::MatrixXd wobble_offsets(int rows, double amplitude, double phase) {
  Eigen::MatrixXd offsets(rows, 3);
  for (int i = 0; i < rows; ++i)
    for (int c = 0; c < 3; ++c)
      offsets(i, c) = amplitude * std::sin(1.7 * i + 2.3 * c + phase);
  return offsets;
}

// Fill in the forces and the starting state: displaced from rest (so the springs pull from the
// first step), moving (Uprev ≠ Ucur), pinned vertices held at their targets.
CheckScene make_scene(std::string description, Eigen::MatrixXd V, Eigen::MatrixXi E, double k,
                      Eigen::VectorXd m, Eigen::VectorXi b, double delta_t, double amplitude,
                      int steps) {
  CheckScene scene;
  scene.description = std::move(description);
  // Away from the origin: a pinned vertex at (0, 0, 0) would make the pin term w CᵀC V zero,
  // and a function that leaves it out would pass.
  scene.V = std::move(V);
  scene.V.rowwise() += Eigen::RowVector3d(0.25, 1.5, -0.5);
  scene.E = std::move(E);
  scene.k = k;
  scene.m = std::move(m);
  scene.b = std::move(b);
  scene.delta_t = delta_t;
  scene.fext = gravity_forces(scene.m);
  const int n = static_cast<int>(scene.V.rows());
  scene.Ucur = scene.V + wobble_offsets(n, amplitude, 0.5);
  scene.Uprev = scene.Ucur - wobble_offsets(n, 0.3 * amplitude, 1.1);
  for (Eigen::Index c = 0; c < scene.b.size(); ++c) {
    scene.Ucur.row(scene.b(c)) = scene.V.row(scene.b(c));
    scene.Uprev.row(scene.b(c)) = scene.V.row(scene.b(c));
  }
  scene.steps = steps;
  return scene;
}

// nx by ny vertices in the x-y plane (a hanging cloth), h apart, with structural springs and
// both diagonals of every cell.
void cloth_grid(int nx, int ny, double h, Eigen::MatrixXd& V, Eigen::MatrixXi& E) {
  V.resize(nx * ny, 3);
  std::vector<std::pair<int, int>> springs;
  const auto index = [nx](int x, int y) { return y * nx + x; };
  for (int y = 0; y < ny; ++y) {
    for (int x = 0; x < nx; ++x) {
      V.row(index(x, y)) << h * x, -h * y, 0.0;
      if (x + 1 < nx) springs.emplace_back(index(x, y), index(x + 1, y));
      if (y + 1 < ny) springs.emplace_back(index(x, y + 1), index(x, y));
      if (x + 1 < nx && y + 1 < ny) {
        springs.emplace_back(index(x, y), index(x + 1, y + 1));
        springs.emplace_back(index(x + 1, y), index(x, y + 1));
      }
    }
  }
  E.resize(static_cast<int>(springs.size()), 2);
  for (int e = 0; e < E.rows(); ++e)
    E.row(e) << springs[e].first, springs[e].second;
}

// A chain of n vertices along x, h apart; every other spring written backwards when asked, so
// a function that assumes E(e,0) < E(e,1) is caught.
void chain(int n, double h, bool alternate, Eigen::MatrixXd& V, Eigen::MatrixXi& E) {
  V = Eigen::MatrixXd::Zero(n, 3);
  for (int i = 0; i < n; ++i)
    V(i, 0) = h * i;
  E.resize(n - 1, 2);
  for (int e = 0; e + 1 < n; ++e) {
    if (alternate && e % 2 == 1)
      E.row(e) << e + 1, e;
    else
      E.row(e) << e, e + 1;
  }
}

}  // namespace

Eigen::MatrixXd gravity_forces(const Eigen::VectorXd& m) {
  Eigen::MatrixXd f = Eigen::MatrixXd::Zero(m.size(), 3);
  f.col(1) = -9.8 * m;
  return f;
}

double scene_size(const CheckScene& scene) {
  if (scene.V.rows() == 0) return 1.0;
  Eigen::RowVector3d low = scene.V.colwise().minCoeff(), high = scene.V.colwise().maxCoeff();
  if (scene.Ucur.rows() == scene.V.rows()) {
    low = low.cwiseMin(scene.Ucur.colwise().minCoeff());
    high = high.cwiseMax(scene.Ucur.colwise().maxCoeff());
  }
  return std::max((high - low).norm(), 1e-3);
}

std::vector<CheckScene> generated_scenes() {
  std::vector<CheckScene> scenes;
  Eigen::MatrixXd V;
  Eigen::MatrixXi E;

  V.resize(2, 3);
  V << 0, 0, 0, 1, 0, 0;
  E.resize(1, 2);
  E << 0, 1;
  scenes.push_back(make_scene("a 2-vertex spring E = [0 1], no pins", V, E, 50.0,
                              Eigen::Vector2d(1.0, 2.0), Eigen::VectorXi(0), 0.01, 0.2, 3));
  E << 1, 0;
  scenes.push_back(make_scene("a 2-vertex spring written E = [1 0], vertex 0 pinned", V, E, 50.0,
                              Eigen::Vector2d(1.0, 2.0), Eigen::VectorXi::Zero(1), 0.01, 0.2, 3));

  V.resize(3, 3);
  V << 0, 0, 0, 0.5, 0.5, 0, 1, 0, 0;
  E << 0, 1;
  scenes.push_back(make_scene("3 vertices, one spring E = [0 1], vertex 2 in no spring and pinned",
                              V, E, 80.0, Eigen::Vector3d(1.0, 0.5, 2.0),
                              Eigen::VectorXi::Constant(1, 2), 0.01, 0.1, 3));

  chain(4, 1.0, false, V, E);
  CheckScene seed =
      make_scene("the seed's example E = [0 1; 1 2; 2 3], 4 vertices, vertex 0 pinned", V, E, 100.0,
                 Eigen::VectorXd::Ones(4), Eigen::VectorXi::Zero(1), 0.01, 0.2, 3);
  scenes.push_back(seed);
  seed.description += ", with the outputs passed in already holding values of their shape";
  seed.outputs_prefilled = true;
  scenes.push_back(seed);

  chain(6, 0.3, true, V, E);
  V.col(1) = wobble_offsets(6, 0.1, 2.0).col(1);
  Eigen::VectorXd masses(6);
  for (int i = 0; i < 6; ++i)
    masses(i) = 0.5 + 0.25 * i;
  Eigen::VectorXi ends(2);
  ends << 0, 5;
  scenes.push_back(make_scene(
      "a 6-vertex zigzag chain, springs written both ways, masses 0.5 to 1.75 kg, both ends pinned",
      V, E, 300.0, masses, ends, 0.01, 0.05, 3));

  // Stiff: k Δt²/m = 100, so 50 iterations are far from the step's minimum and one iteration
  // more or less moves the result by much more than the tolerance.
  chain(10, 0.1, false, V, E);
  CheckScene stiff =
      make_scene("a stiff 10-vertex chain (k = 1e6 N/m, 1 kg each, dt = 0.01 s), vertex 0 pinned",
                 V, E, 1e6, Eigen::VectorXd::Ones(10), Eigen::VectorXi::Zero(1), 0.01, 0.0, 4);
  // Stretched by 30% and bent: the springs snap back over the steps.
  const Eigen::ArrayXd along = 1.3 * (stiff.V.col(0).array() - stiff.V(0, 0));
  stiff.Ucur.col(0) = stiff.V(0, 0) + along;
  stiff.Ucur.col(1) = stiff.V.col(1).array() + 0.05 * along.square();
  stiff.Uprev = stiff.Ucur;
  scenes.push_back(stiff);

  cloth_grid(4, 3, 0.2, V, E);
  Eigen::VectorXd grid_masses(12);
  for (int i = 0; i < 12; ++i)
    grid_masses(i) = 0.05 * (1 + i % 3);
  Eigen::VectorXi corners(2);
  corners << 0, 3;
  scenes.push_back(make_scene("a 4 by 3 cloth grid with shear springs, two corners pinned", V, E,
                              500.0, grid_masses, corners, 0.01, 0.03, 3));
  scenes.push_back(make_scene("a 4 by 3 cloth grid with shear springs, no pins (falling)", V, E,
                              500.0, grid_masses, Eigen::VectorXi(0), 0.01, 0.03, 3));

  cloth_grid(5, 5, 0.1, V, E);
  corners << 0, 4;
  scenes.push_back(make_scene(
      "a stiff 5 by 5 cloth grid (k = 1e5 N/m, 1 kg each, dt = 0.01 s), two corners pinned", V, E,
      1e5, Eigen::VectorXd::Ones(25), corners, 0.01, 0.02, 3));
  return scenes;
}

CheckScene large_chain(int vertex_count) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi E;
  chain(vertex_count, 0.01, false, V, E);
  CheckScene scene = make_scene("a " + std::to_string(vertex_count) + "-vertex chain", V, E, 2000.0,
                                Eigen::VectorXd::Constant(vertex_count, 0.01),
                                Eigen::VectorXi::Zero(1), 0.01, 0.001, 2);
  scene.large = true;
  return scene;
}
