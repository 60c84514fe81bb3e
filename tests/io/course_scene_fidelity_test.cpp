// Fidelity: a course scene loaded by Wobble and run by wobble::Simulation moves exactly as the
// course's reference program would move it, which is the assignment's dense seed functions fed
// with the course's rules. The springs and masses fed to the seed are built here, by brute
// force and by geometry, not by the code under test.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>

#include "io/course_scene.h"
#include "sim/seed/fast_mass_springs_precomputation_dense.h"
#include "sim/seed/fast_mass_springs_step_dense.h"
#include "sim/simulation.h"
#include "temporary_folder.h"

namespace {

using Faces = std::vector<std::vector<int>>;  // 1-based, as written in the OBJ

struct CourseCase {
  std::string name;
  std::vector<Eigen::RowVector3d> vertices;
  Faces faces;            // `f` lines
  Faces lines;            // `l` lines (polylines)
  std::vector<int> pins;  // 1-based, as in "b"
  double k;
  std::optional<double> m;
};

// The course's fixed settings, written out again rather than taken from the loader.
constexpr double course_dt = 1.0 / 30.0;
constexpr int frames = 30;

std::vector<CourseCase> course_cases() {
  std::vector<CourseCase> cases;
  {  // A horizontal chain held at one end, as one polyline and one extra `l`.
    CourseCase chain{"chain", {}, {}, {{1, 2, 3, 4}, {4, 5, 6}, {6, 7}}, {1}, 50.0, 0.1};
    for (int i = 0; i < 7; ++i)
      chain.vertices.emplace_back(0.2 * i, 0.05 * (i % 2), 0.0);
    cases.push_back(chain);
  }
  {  // A 4×4 horizontal sheet of quads held at two corners, masses from areas.
    CourseCase sheet{"quad_sheet", {}, {}, {}, {1, 4}, 200.0, std::nullopt};
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c)
        sheet.vertices.emplace_back(0.25 * c, 0.0, 0.25 * r);
    }
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        const int v = 4 * r + c + 1;
        sheet.faces.push_back({v, v + 1, v + 5, v + 4});
      }
    }
    cases.push_back(sheet);
  }
  {  // A sheared strip of flat triangles, many of them obtuse, masses from areas.
    CourseCase strip{"obtuse_sheet", {}, {}, {}, {1, 5}, 100.0, std::nullopt};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 5; ++c)
        strip.vertices.emplace_back(0.3 * c + 0.15 * r, 0.02 * r * c, 0.1 * r);
    }
    for (int r = 0; r < 2; ++r) {
      for (int c = 0; c < 4; ++c) {
        const int v = 5 * r + c + 1;
        strip.faces.push_back({v, v + 1, v + 5});
        strip.faces.push_back({v + 1, v + 6, v + 5});
      }
    }
    cases.push_back(strip);
  }
  {  // A pentagon and a hexagon sharing an edge, plus a quad, slightly bent out of plane.
    CourseCase polygons{"polygons", {}, {}, {}, {1, 5}, 300.0, std::nullopt};
    polygons.faces = {{1, 2, 3, 4, 5}, {2, 6, 7, 8, 9, 3}, {6, 10, 11, 7}};
    const double xy[11][2] = {{0, 0},      {1, 0},    {1.2, 0.9}, {0.5, 1.4},
                              {-0.2, 0.9}, {2, -0.3}, {2.6, 0.5}, {2.4, 1.4},
                              {1.8, 1.9},  {3, -0.6}, {3.5, 0.2}};
    for (int i = 0; i < 11; ++i)
      polygons.vertices.emplace_back(0.5 * xy[i][0], 0.5 * xy[i][1], 0.03 * xy[i][0] * xy[i][1]);
    cases.push_back(polygons);
  }
  {  // A small truss of two-vertex faces, held at one vertex.
    CourseCase truss{"two_vertex_faces", {}, {}, {}, {1}, 80.0, 0.05};
    truss.faces = {{1, 2}, {2, 3}, {3, 1}, {1, 4}, {2, 4}, {3, 4}, {4, 5}, {3, 5}, {2, 1}};
    truss.vertices = {{0, 0, 0}, {0.4, 0, 0}, {0.2, 0, 0.35}, {0.2, 0.3, 0.1}, {0.6, 0.35, 0.3}};
    cases.push_back(truss);
  }
  {  // A hanging chain of two-vertex faces whose second spring is written twice: the course's
     // E = F makes it two springs, twice as stiff as the others.
    CourseCase chain{"repeated_spring", {}, {}, {}, {1}, 40.0, 0.1};
    chain.faces = {{1, 2}, {2, 3}, {3, 4}, {2, 3}, {4, 5}, {5, 6}};
    for (int i = 0; i < 6; ++i)
      chain.vertices.emplace_back(0.15 * i, -0.02 * i, 0.01 * (i % 2));
    cases.push_back(chain);
  }
  {  // Polylines whose segment 2–3 is written twice (once each way) beside a triangle sharing it:
     // Wobble takes every `l` segment as written, like a two-vertex face.
    CourseCase lines{"repeated_line_segment", {}, {{1, 2, 3}}, {{3, 4, 5}, {3, 2}}, {1}, 60.0, 0.2};
    lines.vertices = {
        {0, 0, 0}, {0.3, 0, 0}, {0.2, 0.05, 0.25}, {0.5, -0.05, 0.35}, {0.8, -0.1, 0.3}};
    cases.push_back(lines);
  }
  return cases;
}

// Write name.obj and name.json into `folder` and return the JSON's path.
std::string write_case(const CourseCase& c, const wobble::testing::TemporaryFolder& folder) {
  std::ofstream obj(folder.file(c.name + ".obj"));
  obj << std::setprecision(17);
  for (const auto& v : c.vertices)
    obj << "v " << v(0) << " " << v(1) << " " << v(2) << "\n";
  for (const auto& [tag, elements] : {std::pair{"f", &c.faces}, std::pair{"l", &c.lines}}) {
    for (const auto& element : *elements) {
      obj << tag;
      for (int v : element)
        obj << " " << v;
      obj << "\n";
    }
  }
  std::ofstream json(folder.file(c.name + ".json"));
  json << std::setprecision(17) << "{\"obj\": \"" << c.name << ".obj\", \"k\": " << c.k
       << ", \"b\": [";
  for (std::size_t i = 0; i < c.pins.size(); ++i)
    json << (i ? ", " : "") << c.pins[i];
  json << "]";
  if (c.m) json << ", \"m\": " << *c.m;
  json << "}\n";
  return folder.file(c.name + ".json");
}

// The springs by the course's rules, built by brute force: every pair of vertices of the faces
// of 3 or more vertices once, sorted (the course's igl::edges); then every two-vertex face and
// every `l` segment as written, repeats kept (the course's E = F). 0-based.
Eigen::MatrixXi course_springs(const CourseCase& c) {
  std::set<std::pair<int, int>> pairs;
  std::vector<std::pair<int, int>> written;
  for (const auto& face : c.faces) {
    if (face.size() == 2) written.emplace_back(face[0] - 1, face[1] - 1);
    for (int a : face) {
      for (int b : face) {
        if (a < b && face.size() > 2) pairs.insert({a - 1, b - 1});
      }
    }
  }
  for (const auto& line : c.lines) {
    for (std::size_t i = 1; i < line.size(); ++i)
      written.emplace_back(line[i - 1] - 1, line[i] - 1);
  }
  Eigen::MatrixXi E(static_cast<Eigen::Index>(pairs.size() + written.size()), 2);
  Eigen::Index e = 0;
  for (const auto& [a, b] : pairs)
    E.row(e++) << a, b;
  for (const auto& [a, b] : written)
    E.row(e++) << a, b;
  return E;
}

// The same springs with every pair once: what Wobble did before it kept repeated springs.
Eigen::MatrixXi merged_springs(const Eigen::MatrixXi& E) {
  std::set<std::pair<int, int>> pairs;
  for (Eigen::Index e = 0; e < E.rows(); ++e)
    pairs.insert({std::min(E(e, 0), E(e, 1)), std::max(E(e, 0), E(e, 1))});
  Eigen::MatrixXi merged(static_cast<Eigen::Index>(pairs.size()), 2);
  Eigen::Index e = 0;
  for (const auto& [a, b] : pairs)
    merged.row(e++) << a, b;
  return merged;
}

// `frames` steps of the dense seed from rest, with the course's gravity (9.8 down y on every
// vertex, not m·g); every frame's positions.
std::vector<Eigen::MatrixXd> seed_frames(const Eigen::MatrixXd& V, const Eigen::MatrixXi& E,
                                         double k, const Eigen::VectorXd& m,
                                         const Eigen::VectorXi& b) {
  const Eigen::MatrixXd fext = Eigen::RowVector3d(0, -9.8, 0).replicate(V.rows(), 1);
  Eigen::VectorXd r;
  Eigen::MatrixXd M, A, C;
  Eigen::LLT<Eigen::MatrixXd> llt;
  EXPECT_TRUE(fast_mass_springs_precomputation_dense(V, E, k, m, b, course_dt, r, M, A, C, llt));
  std::vector<Eigen::MatrixXd> positions;
  Eigen::MatrixXd previous = V, current = V, next;
  for (int frame = 0; frame < frames; ++frame) {
    fast_mass_springs_step_dense(V, E, k, b, course_dt, fext, r, M, A, C, llt, previous, current,
                                 next);
    previous = current;
    current = next;
    positions.push_back(current);
  }
  return positions;
}

double area(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

// Voronoi masses by geometry rather than cotangents: a corner's region in a non-obtuse
// triangle is the quadrilateral corner, edge midpoint, circumcenter, other edge midpoint.
Eigen::VectorXd geometric_masses(const CourseCase& c, int& obtuse_count) {
  Eigen::VectorXd m = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(c.vertices.size()));
  for (const auto& face : c.faces) {
    for (std::size_t j = 1; j + 1 < face.size(); ++j) {
      const int t[3] = {face[0] - 1, face[j] - 1, face[j + 1] - 1};
      Eigen::Vector3d x[3];
      for (int i = 0; i < 3; ++i)
        x[i] = c.vertices[t[i]].transpose();
      const double whole = area(x[0], x[1], x[2]);
      int obtuse = -1;
      for (int i = 0; i < 3; ++i) {
        if ((x[(i + 1) % 3] - x[i]).dot(x[(i + 2) % 3] - x[i]) < 0) obtuse = i;
      }
      if (obtuse >= 0) {
        ++obtuse_count;
        for (int i = 0; i < 3; ++i)
          m(t[i]) += whole * (i == obtuse ? 0.5 : 0.25);
        continue;
      }
      const Eigen::Vector3d a = x[0] - x[2], b = x[1] - x[2], n = a.cross(b);
      const Eigen::Vector3d o =
          x[2] + (a.squaredNorm() * b - b.squaredNorm() * a).cross(n) / (2 * n.squaredNorm());
      for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d mid_j = (x[i] + x[(i + 1) % 3]) / 2;
        const Eigen::Vector3d mid_k = (x[i] + x[(i + 2) % 3]) / 2;
        m(t[i]) += area(x[i], mid_j, o) + area(x[i], o, mid_k);
      }
    }
  }
  return m;
}

TEST(CourseSceneFidelity, SimulationMatchesTheDenseSeedFrameByFrame) {
  wobble::testing::TemporaryFolder folder;
  for (const CourseCase& c : course_cases()) {
    SCOPED_TRACE(c.name);
    const wobble::Scene scene = wobble::load_course_scene(write_case(c, folder));

    const Eigen::Index n = static_cast<Eigen::Index>(c.vertices.size());
    Eigen::MatrixXd V(n, 3);
    for (Eigen::Index i = 0; i < n; ++i)
      V.row(i) = c.vertices[i];
    const Eigen::MatrixXi E = course_springs(c);
    int obtuse = 0;
    const Eigen::VectorXd m =
        c.m ? Eigen::VectorXd::Constant(n, *c.m).eval() : geometric_masses(c, obtuse);
    if (c.name == "obtuse_sheet") {
      EXPECT_GE(obtuse, 4) << "the obtuse rule must be exercised";
    }
    ASSERT_EQ(scene.network.E, E);
    ASSERT_EQ(scene.network.m.size(), n);
    // Two constructions of the same areas in double precision: 1e-12 relative.
    EXPECT_LE((scene.network.m - m).cwiseAbs().maxCoeff(), 1e-12 * m.maxCoeff());

    Eigen::VectorXi b(static_cast<Eigen::Index>(c.pins.size()));
    for (Eigen::Index i = 0; i < b.size(); ++i)
      b(i) = c.pins[static_cast<std::size_t>(i)] - 1;
    const std::vector<Eigen::MatrixXd> seed = seed_frames(V, E, c.k, m, b);
    ASSERT_EQ(seed.size(), static_cast<std::size_t>(frames));

    wobble::Simulation simulation(scene.network, scene.pins, scene.params, scene.initial_velocity);
    const double diagonal = (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
    double worst = 0.0;
    for (int frame = 0; frame < frames; ++frame) {
      simulation.step();
      worst =
          std::max(worst, (simulation.positions() - seed[frame]).cwiseAbs().maxCoeff() / diagonal);
    }
    const Eigen::MatrixXd& current = seed.back();
    // The scene must actually move, or matching would prove nothing: more than 1% of its size.
    EXPECT_GT((current - V).cwiseAbs().maxCoeff(), 0.01 * diagonal);
    // Sparse and dense Cholesky solve the same system: their difference is rounding, ~1e-12.
    EXPECT_LE(worst, 1e-6);

    // Where a pair is repeated, the repeat must matter: the seed with every pair once moves
    // measurably otherwise, far beyond the 1e-6 above, so merging the repeat fails this test.
    const Eigen::MatrixXi merged = merged_springs(E);
    if (merged.rows() < E.rows()) {
      const Eigen::MatrixXd once = seed_frames(V, merged, c.k, m, b).back();
      const double apart = (once - current).cwiseAbs().maxCoeff() / diagonal;
      EXPECT_GT(apart, 1e-3);
      std::cout << "[ fidelity ] " << c.name << ": " << E.rows() - merged.rows()
                << " repeated springs; merging them moves the last frame by " << std::scientific
                << std::setprecision(2) << apart << std::defaultfloat << " of the diagonal\n";
    }
    std::cout << "[ fidelity ] " << c.name << ": " << n << " vertices, " << E.rows() << " springs, "
              << frames << " frames, max |p_wobble - p_seed| / diagonal = " << std::scientific
              << std::setprecision(2) << worst << std::defaultfloat << "\n";
  }
}

}  // namespace

namespace {

// With the course's wind on (its W key, Wobble's --wind), a course scene moves as the dense seed
// does when fed the program's wind formula each frame, with φ = x_i/bbd + t and t the simulated
// time at the start of the step.
TEST(CourseSceneFidelity, CourseWindMatchesTheProgramsFormula) {
  wobble::testing::TemporaryFolder folder;
  const CourseCase c = course_cases()[1];  // the 4×4 quad sheet held at two corners
  wobble::Scene scene = wobble::load_course_scene(write_case(c, folder));
  ASSERT_EQ(scene.params.wind.model, wobble::WindModel::course);
  ASSERT_FALSE(scene.params.wind.on) << "off until --wind or W";
  scene.params.wind.on = true;

  const Eigen::Index n = static_cast<Eigen::Index>(c.vertices.size());
  Eigen::MatrixXd V(n, 3);
  for (Eigen::Index i = 0; i < n; ++i)
    V.row(i) = c.vertices[i];
  const double bbd = (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
  const Eigen::MatrixXi E = course_springs(c);
  int obtuse = 0;
  const Eigen::VectorXd m = geometric_masses(c, obtuse);
  Eigen::VectorXi b(2);
  b << c.pins[0] - 1, c.pins[1] - 1;
  Eigen::VectorXd r;
  Eigen::MatrixXd M, A, C;
  Eigen::LLT<Eigen::MatrixXd> llt;
  ASSERT_TRUE(fast_mass_springs_precomputation_dense(V, E, c.k, m, b, course_dt, r, M, A, C, llt));

  wobble::Simulation simulation(scene.network, scene.pins, scene.params, scene.initial_velocity);
  wobble::Scene calm_scene = scene;
  calm_scene.params.wind.on = false;
  wobble::Simulation calm(calm_scene.network, calm_scene.pins, calm_scene.params);
  Eigen::MatrixXd previous = V, current = V, next;
  double worst = 0.0;
  for (int frame = 0; frame < frames; ++frame) {
    Eigen::MatrixXd fext = Eigen::RowVector3d(0, -9.8, 0).replicate(n, 1);
    const double t = frame * course_dt;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double phi = current(i, 0) / bbd + t;
      fext(i, 0) = 3.0 + 1.5 * (1.0 + std::cos(5.0 * phi));
      fext(i, 2) = std::sin(phi);
      fext(i, 1) += 1.0 + std::cos(0.3 + phi);
    }
    fast_mass_springs_step_dense(V, E, c.k, b, course_dt, fext, r, M, A, C, llt, previous, current,
                                 next);
    previous = current;
    current = next;
    simulation.step();
    calm.step();
    worst = std::max(worst, (simulation.positions() - current).cwiseAbs().maxCoeff() / bbd);
  }
  EXPECT_LE(worst, 1e-6);
  // The wind must matter, or matching would prove nothing.
  EXPECT_GT((calm.positions() - current).cwiseAbs().maxCoeff() / bbd, 0.01);
  std::cout << "[ fidelity ] course wind: max |p_wobble - p_seed| / diagonal = " << worst << "\n";
}

}  // namespace
