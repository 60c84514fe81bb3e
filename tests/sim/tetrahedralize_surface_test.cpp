#include "sim/shapes/tetrahedralize_surface.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "sim/input_error.h"
#include "sim/shapes/tet_mesh.h"

namespace {

struct Surface {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
};

// A sphere of `radius` around `centre`: an icosahedron split in four `levels` times, corners
// pushed onto the sphere, counter-clockwise seen from outside.
Surface icosphere(int levels, double radius, const Eigen::RowVector3d& centre) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::RowVector3d> V = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                       {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                       {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& v : V)
    v.normalize();
  std::vector<std::array<int, 3>> F = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoints;
    const auto midpoint = [&](int a, int b) {
      const auto [it, added] =
          midpoints.try_emplace({std::min(a, b), std::max(a, b)}, static_cast<int>(V.size()));
      if (added) V.push_back((V[a] + V[b]).normalized());
      return it->second;
    };
    std::vector<std::array<int, 3>> refined;
    for (const auto& [a, b, c] : F) {
      const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      refined.insert(refined.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    F = refined;
  }
  Surface s;
  s.V.resize(V.size(), 3);
  for (std::size_t i = 0; i < V.size(); ++i)
    s.V.row(i) = centre + radius * V[i];
  s.F.resize(F.size(), 3);
  for (std::size_t f = 0; f < F.size(); ++f)
    s.F.row(f) << F[f][0], F[f][1], F[f][2];
  return s;
}

// The 12-triangle surface of the box [0, size]³, counter-clockwise seen from outside.
Surface cube_surface(double size) {
  Surface s;
  s.V.resize(8, 3);
  for (int v = 0; v < 8; ++v)
    s.V.row(v) << size * (v & 1), size * ((v >> 1) & 1), size * ((v >> 2) & 1);
  s.F.resize(12, 3);
  s.F << 0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6,
      1, 3, 5, 3, 7, 5;
  return s;
}

// Volume enclosed by a closed outward surface (divergence theorem).
double enclosed_volume(const Surface& s) {
  double volume = 0.0;
  for (Eigen::Index f = 0; f < s.F.rows(); ++f) {
    const Eigen::Vector3d a = s.V.row(s.F(f, 0)), b = s.V.row(s.F(f, 1)), c = s.V.row(s.F(f, 2));
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

double tet_volume(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, Eigen::Index t) {
  const Eigen::Vector3d a = V.row(T(t, 0)), b = V.row(T(t, 1)), c = V.row(T(t, 2)),
                        d = V.row(T(t, 3));
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

std::string error_of(const Surface& s, int resolution) {
  Eigen::MatrixXd TV;
  Eigen::MatrixXi TT;
  try {
    wobble::tetrahedralize_surface(s.V, s.F, resolution, TV, TT);
  } catch (const wobble::InputError& error) {
    return error.what();
  }
  return "";
}

TEST(TetrahedralizeSurface, SphereVolumeMatchesEnclosedVolumeAndEveryTetIsPositive) {
  const Surface sphere = icosphere(3, 0.3, Eigen::RowVector3d(0.1, 0.35, -0.2));
  Eigen::MatrixXd TV;
  Eigen::MatrixXi TT;
  wobble::tetrahedralize_surface(sphere.V, sphere.F, 12, TV, TT);
  const double h = 0.6 / 12;
  double volume = 0.0;
  for (Eigen::Index t = 0; t < TT.rows(); ++t) {
    const double v = tet_volume(TV, TT, t);
    // Snapping keeps every tetrahedron at 10% or more of its unsnapped volume h³/6.
    EXPECT_GE(v, 0.1 * h * h * h / 6.0 * (1.0 - 1e-9)) << "tet " << t;
    volume += v;
  }
  const double ratio = volume / enclosed_volume(sphere);
  std::printf("tetrahedralized sphere at resolution 12: %ld tets, volume ratio %.4f\n",
              static_cast<long>(TT.rows()), ratio);
  // Measured 0.987: the snapped boundary's flat faces are chords of the sphere, each a sag of
  // about h²/8r below it. (The unsnapped staircase measured 1.017.)
  EXPECT_NEAR(ratio, 1.0, 0.02);
}

TEST(TetrahedralizeSurface, BoundaryVerticesLieOnTheSurfaceAfterSnapping) {
  const double radius = 0.3;
  const Eigen::RowVector3d centre(0.1, 0.35, -0.2);
  const Surface sphere = icosphere(3, radius, centre);
  Eigen::MatrixXd TV;
  Eigen::MatrixXi TT;
  wobble::tetrahedralize_surface(sphere.V, sphere.F, 12, TV, TT);
  const Eigen::MatrixXi boundary = wobble::tet_mesh_boundary_faces(TV, TT);
  std::vector<bool> on_boundary(TV.rows(), false);
  for (Eigen::Index i = 0; i < boundary.size(); ++i)
    on_boundary[boundary(i)] = true;
  // The level-3 icosphere's flat triangles sag at most ~0.4% of the radius below the sphere.
  const double on_surface = 0.005 * radius, h = 2.0 * radius / 12;
  int count = 0, snapped = 0;
  for (Eigen::Index v = 0; v < TV.rows(); ++v) {
    if (!on_boundary[v]) continue;
    const double off = std::abs((TV.row(v) - centre).norm() - radius);
    // Unsnapped, the staircase's corners are up to 0.87 h away; those stopped short of the
    // surface to keep their tetrahedra from flattening measured up to 0.3 h.
    EXPECT_LT(off, 0.35 * h) << "vertex " << v;
    ++count;
    snapped += off < on_surface;
  }
  std::printf("boundary vertices on the surface: %d of %d\n", snapped, count);
  EXPECT_GE(snapped, 0.8 * count);  // measured 578 of 674 (86%)
}

TEST(TetrahedralizeSurface, InteriorFacesBelongToTwoTetsWithOppositeOrientations) {
  const Surface sphere = icosphere(2, 1.0, Eigen::RowVector3d::Zero());
  Eigen::MatrixXd TV;
  Eigen::MatrixXi TT;
  wobble::tetrahedralize_surface(sphere.V, sphere.F, 7, TV, TT);
  // Sorted corners → (uses, sum of orientation signs relative to the sorted order).
  std::map<std::array<int, 3>, std::pair<int, int>> faces;
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (Eigen::Index t = 0; t < TT.rows(); ++t) {
    for (const auto& face : kFaces) {
      std::array<int, 3> f = {TT(t, face[0]), TT(t, face[1]), TT(t, face[2])};
      // The parity of the sort says whether the outward face agrees with the sorted one.
      int swaps = 0;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j + 1 < 3 - i; ++j) {
          if (f[j] > f[j + 1]) std::swap(f[j], f[j + 1]), ++swaps;
        }
      }
      auto& entry = faces[f];
      ++entry.first;
      entry.second += swaps % 2 == 0 ? 1 : -1;
    }
  }
  int boundary = 0;
  for (const auto& [face, entry] : faces) {
    ASSERT_LE(entry.first, 2);
    if (entry.first == 2) {
      EXPECT_EQ(entry.second, 0);  // a shared face is seen outward from both sides
    } else {
      ++boundary;
    }
  }
  EXPECT_EQ(boundary, wobble::tet_mesh_boundary_faces(TV, TT).rows());
  EXPECT_GT(faces.size(), static_cast<std::size_t>(boundary));
}

TEST(TetrahedralizeSurface, GridAlignedCubeIsFilledExactly) {
  const Surface cube = cube_surface(0.4);
  Eigen::MatrixXd TV;
  Eigen::MatrixXi TT;
  wobble::tetrahedralize_surface(cube.V, cube.F, 3, TV, TT);
  EXPECT_EQ(TV.rows(), 4 * 4 * 4);
  ASSERT_EQ(TT.rows(), 6 * 27);
  double volume = 0.0;
  for (Eigen::Index t = 0; t < TT.rows(); ++t)
    volume += tet_volume(TV, TT, t);
  EXPECT_NEAR(volume, 0.4 * 0.4 * 0.4, 1e-12);  // the grid is the box, nothing to snap
  EXPECT_NEAR(TV.minCoeff(), 0.0, 1e-12);
  EXPECT_NEAR(TV.maxCoeff(), 0.4, 1e-12);
}

TEST(TetrahedralizeSurface, InwardFacingSurfaceGivesTheSameMesh) {
  const Surface outward = icosphere(2, 1.0, Eigen::RowVector3d::Zero());
  Surface inward = outward;
  inward.F.col(1).swap(inward.F.col(2));
  Eigen::MatrixXd TV_out, TV_in;
  Eigen::MatrixXi TT_out, TT_in;
  wobble::tetrahedralize_surface(outward.V, outward.F, 6, TV_out, TT_out);
  wobble::tetrahedralize_surface(inward.V, inward.F, 6, TV_in, TT_in);
  EXPECT_EQ(TT_out, TT_in);
  EXPECT_TRUE(TV_out.isApprox(TV_in, 1e-12));
}

TEST(TetrahedralizeSurface, RefusesOpenMisorientedAndEmptySurfaces) {
  Surface open = icosphere(1, 1.0, Eigen::RowVector3d::Zero());
  open.F.conservativeResize(open.F.rows() - 1, 3);
  EXPECT_EQ(error_of(open, 8), "the surface is not closed: 3 edges belong to one triangle only");

  Surface flipped = icosphere(1, 1.0, Eigen::RowVector3d::Zero());
  std::swap(flipped.F(0, 1), flipped.F(0, 2));
  EXPECT_NE(error_of(flipped, 8).find("not consistently oriented: 3 edges"), std::string::npos);

  // Two triangles back to back: closed and consistent, but enclosing nothing.
  Surface flat;
  flat.V = Eigen::Matrix3d::Identity();
  flat.F.resize(2, 3);
  flat.F << 0, 1, 2, 0, 2, 1;
  EXPECT_NE(error_of(flat, 8).find("no cell centre is inside"), std::string::npos);

  const Surface cube = cube_surface(1.0);
  EXPECT_NE(error_of(cube, 0).find("resolution must be 1 to 1000, got 0"), std::string::npos);
  Surface bad_index = cube;
  bad_index.F(3, 1) = 8;
  EXPECT_NE(error_of(bad_index, 4).find("triangle 3 refers to vertex 8"), std::string::npos);
  EXPECT_EQ(error_of(cube, 1), "");
}

}  // namespace

namespace {

// The work estimate counts the very grid the fill uses: cells along each side times triangles.
TEST(TetrahedralizeSurface, PairsAreTheGridsCellsTimesTheTriangles) {
  Eigen::MatrixXd box(2, 3);
  box << 0, 0, 0, 2, 1, 0.5;
  EXPECT_EQ(wobble::tetrahedralize_surface_pairs(box, 10, 4), 4.0 * 2 * 1 * 10);
  Eigen::MatrixXd cube(2, 3);
  cube << 0, 0, 0, 1, 1, 1;
  EXPECT_EQ(wobble::tetrahedralize_surface_pairs(cube, 12, 24), 24.0 * 24 * 24 * 12);
  EXPECT_EQ(wobble::tetrahedralize_surface_pairs(Eigen::MatrixXd(0, 3), 12, 24), 0.0);
}

}  // namespace
