#include "sim/shapes/tet_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace {

Eigen::MatrixXd unit_tet_vertices() {
  Eigen::MatrixXd V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  return V;
}

Eigen::Vector3d face_normal(const Eigen::MatrixXd& V, const Eigen::RowVector3i& f) {
  const Eigen::Vector3d a = V.row(f(0)), b = V.row(f(1)), c = V.row(f(2));
  return (b - a).cross(c - a);
}

TEST(TetMesh, OneTetrahedronHasSixEdgesAndFourOutwardFaces) {
  const Eigen::MatrixXd V = unit_tet_vertices();
  // Both orientations of the same tetrahedron must give outward faces.
  for (const Eigen::RowVector4i& tet :
       {Eigen::RowVector4i(0, 1, 2, 3), Eigen::RowVector4i(0, 2, 1, 3)}) {
    const Eigen::MatrixXi T = tet;
    EXPECT_EQ(wobble::tet_mesh_edges(T).rows(), 6);
    const Eigen::MatrixXi F = wobble::tet_mesh_boundary_faces(V, T);
    ASSERT_EQ(F.rows(), 4);
    const Eigen::Vector3d centroid = V.colwise().mean();
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
      const Eigen::Vector3d on_face = V.row(F(f, 0));
      EXPECT_GT(face_normal(V, F.row(f)).dot(on_face - centroid), 0.0) << "face " << f;
    }
  }
}

TEST(TetMesh, SharedFaceIsNotBoundaryAndSharedEdgesCountOnce) {
  Eigen::MatrixXd V(5, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1;
  Eigen::MatrixXi T(2, 4);
  T << 0, 1, 2, 3, 1, 2, 3, 4;  // glued along face (1, 2, 3)
  EXPECT_EQ(wobble::tet_mesh_edges(T).rows(), 9);
  const Eigen::MatrixXi F = wobble::tet_mesh_boundary_faces(V, T);
  EXPECT_EQ(F.rows(), 6);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    Eigen::RowVector3i sorted = F.row(f);
    std::sort(sorted.data(), sorted.data() + 3);
    EXPECT_NE(sorted, Eigen::RowVector3i(1, 2, 3));
  }
}

TEST(TetMesh, LumpedMassesAddUpToDensityTimesVolume) {
  const Eigen::MatrixXd V = unit_tet_vertices();
  const Eigen::MatrixXi T = Eigen::RowVector4i(0, 2, 1, 3);  // negative orientation
  const Eigen::VectorXd m = wobble::tet_mesh_lumped_masses(V, T, 600.0);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(m(i), 600.0 / 6.0 / 4.0, 1e-12);
}

}  // namespace
