#include "app/interaction/collider_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace {

using wobble::Collider;
using wobble::ColliderTriangles;
using wobble::ColliderType;

Eigen::Vector3f row(const std::vector<float>& values, int i) {
  return Eigen::Vector3f(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
}

// Every vertex lies on the collider's surface (signed distance 0, float rounding: 1e-5 m on
// shapes of a metre), its normal is the surface's outward normal there, and every triangle
// winds counter-clockwise seen from outside (its face normal agrees with the vertex normals).
void expect_on_surface_and_outward(const Collider& collider, const ColliderTriangles& mesh) {
  ASSERT_GT(mesh.triangle_count(), 0);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    const wobble::ColliderSurface surface =
        wobble::collider_surface(collider, row(mesh.positions, i).cast<double>());
    EXPECT_NEAR(surface.distance, 0.0, 1e-5) << "vertex " << i;
    EXPECT_NEAR(row(mesh.normals, i).norm(), 1.0f, 1e-5f);
  }
  int checked = 0;
  for (int f = 0; f < mesh.triangle_count(); ++f) {
    const Eigen::Vector3f a = row(mesh.positions, mesh.triangles[3 * f]);
    const Eigen::Vector3f b = row(mesh.positions, mesh.triangles[3 * f + 1]);
    const Eigen::Vector3f c = row(mesh.positions, mesh.triangles[3 * f + 2]);
    const Eigen::Vector3f face = (b - a).cross(c - a);
    if (face.norm() < 1e-9f) continue;  // the collapsed triangles at a sphere's poles
    const Eigen::Vector3f centroid = (a + b + c) / 3.0f;
    const Eigen::Vector3d outward =
        wobble::collider_surface(collider, centroid.cast<double>()).normal;
    EXPECT_GT(face.normalized().dot(outward.cast<float>()), 0.9f) << "triangle " << f;
    ++checked;
  }
  EXPECT_GT(checked, mesh.triangle_count() / 2);
}

TEST(ColliderMesh, SphereVerticesLieOnItAndFacesPointOut) {
  Collider sphere;
  sphere.type = ColliderType::sphere;
  sphere.center = Eigen::Vector3d(1.0, 2.0, -0.5);
  sphere.radius = 0.4;
  ColliderTriangles mesh;
  wobble::append_collider_triangles(sphere, Eigen::Vector3f::Zero(), 1.0f, mesh, 16);
  expect_on_surface_and_outward(sphere, mesh);
  // The tessellation reaches the sphere's extremes (its poles and equator).
  float top = -1e9f, bottom = 1e9f;
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    top = std::max(top, mesh.positions[3 * i + 1]);
    bottom = std::min(bottom, mesh.positions[3 * i + 1]);
  }
  EXPECT_NEAR(top, 2.4f, 1e-5f);
  EXPECT_NEAR(bottom, 1.6f, 1e-5f);
}

TEST(ColliderMesh, CapsuleAlongATiltedAxis) {
  Collider capsule;
  capsule.type = ColliderType::capsule;
  capsule.from = Eigen::Vector3d(-1.0, 0.2, 0.3);
  capsule.to = Eigen::Vector3d(0.5, 1.0, -0.4);
  capsule.radius = 0.25;
  ColliderTriangles mesh;
  wobble::append_collider_triangles(capsule, Eigen::Vector3f::Zero(), 1.0f, mesh);
  expect_on_surface_and_outward(capsule, mesh);
}

TEST(ColliderMesh, BoxHasSixFlatFacesAtItsFullEdges) {
  Collider box;
  box.type = ColliderType::box;
  box.center = Eigen::Vector3d(0.0, 1.0, 0.0);
  box.size = Eigen::Vector3d(2.0, 0.5, 1.0);  // full edges
  ColliderTriangles mesh;
  wobble::append_collider_triangles(box, Eigen::Vector3f::Zero(), 1.0f, mesh);
  EXPECT_EQ(mesh.triangle_count(), 12);
  EXPECT_EQ(mesh.vertex_count(), 24);
  expect_on_surface_and_outward(box, mesh);
  Eigen::Vector3f lower = row(mesh.positions, 0), upper = lower;
  for (int i = 1; i < mesh.vertex_count(); ++i) {
    lower = lower.cwiseMin(row(mesh.positions, i));
    upper = upper.cwiseMax(row(mesh.positions, i));
  }
  EXPECT_TRUE(lower.isApprox(Eigen::Vector3f(-1.0f, 0.75f, -0.5f)));
  EXPECT_TRUE(upper.isApprox(Eigen::Vector3f(1.0f, 1.25f, 0.5f)));
}

TEST(ColliderMesh, PlaneIsASquareAroundTheFocusAndTheGroundIsNotMeshed) {
  Collider plane;
  plane.type = ColliderType::plane;
  plane.center = Eigen::Vector3d(0.0, 0.0, -1.0);
  plane.normal = Eigen::Vector3d(0.0, 0.0, 1.0);  // a wall facing +z
  ColliderTriangles mesh;
  wobble::append_collider_triangles(plane, Eigen::Vector3f(3.0f, 1.0f, 5.0f), 2.0f, mesh);
  ASSERT_EQ(mesh.vertex_count(), 4);
  EXPECT_EQ(mesh.triangle_count(), 2);
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(mesh.positions[3 * i + 2], -1.0f, 1e-6f);
    EXPECT_NEAR((row(mesh.positions, i) - Eigen::Vector3f(3, 1, -1)).norm(), 2.0f * std::sqrt(2.0f),
                1e-5f);
    centroid += row(mesh.positions, i) / 4.0f;
  }
  EXPECT_TRUE(centroid.isApprox(Eigen::Vector3f(3.0f, 1.0f, -1.0f), 1e-5f));

  Collider ground;  // the viewer draws it as the grid
  ColliderTriangles none = wobble::collider_triangles({ground}, Eigen::Vector3f::Zero(), 1.0f);
  EXPECT_EQ(none.vertex_count(), 0);
  EXPECT_EQ(none.triangle_count(), 0);
}

TEST(ColliderMesh, SeveralCollidersIndexTheirOwnVertices) {
  Collider sphere, box;
  sphere.type = ColliderType::sphere;
  box.type = ColliderType::box;
  box.center = Eigen::Vector3d(3.0, 0.0, 0.0);
  const ColliderTriangles mesh =
      wobble::collider_triangles({sphere, box}, Eigen::Vector3f::Zero(), 1.0f);
  ColliderTriangles sphere_only;
  wobble::append_collider_triangles(sphere, Eigen::Vector3f::Zero(), 1.0f, sphere_only);
  // The box's triangles come after the sphere's and point at the box's vertices.
  for (std::size_t k = sphere_only.triangles.size(); k < mesh.triangles.size(); ++k) {
    EXPECT_GE(mesh.triangles[k], static_cast<unsigned>(sphere_only.vertex_count()));
    EXPECT_LT(mesh.triangles[k], static_cast<unsigned>(mesh.vertex_count()));
  }
}

}  // namespace
