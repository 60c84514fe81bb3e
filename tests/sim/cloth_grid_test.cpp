#include "sim/shapes/cloth_grid.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "sim/input_error.h"

namespace {

TEST(ClothGrid, CountsFollowFromTheResolution) {
  for (int n : {2, 3, 7, 40}) {
    wobble::ClothGridOptions options;
    options.resolution = n;
    const wobble::SpringNetwork cloth = wobble::make_cloth_grid(options);
    EXPECT_EQ(cloth.V.rows(), n * n);
    const int structural = 2 * n * (n - 1), shear = 2 * (n - 1) * (n - 1), bend = 2 * n * (n - 2);
    EXPECT_EQ(cloth.E.rows(), structural + shear + bend) << "n = " << n;
    EXPECT_EQ(cloth.F.rows(), 2 * (n - 1) * (n - 1));
  }
}

TEST(ClothGrid, SpringSetsCanBeChosen) {
  wobble::ClothGridOptions options;
  options.resolution = 5;
  options.shear = false;
  options.bend = false;
  const wobble::SpringNetwork cloth = wobble::make_cloth_grid(options);
  EXPECT_EQ(cloth.E.rows(), 2 * 5 * 4);
  const double h = options.size / 4;
  for (Eigen::Index e = 0; e < cloth.E.rows(); ++e) {
    EXPECT_NEAR((cloth.V.row(cloth.E(e, 0)) - cloth.V.row(cloth.E(e, 1))).norm(), h, 1e-12);
  }
}

TEST(ClothGrid, MassesAreSymmetricAndAddUpToDensityTimesArea) {
  wobble::ClothGridOptions options;
  options.resolution = 9;
  options.size = 2.0;
  options.areal_density = 0.3;
  const wobble::SpringNetwork cloth = wobble::make_cloth_grid(options);
  EXPECT_NEAR(cloth.m.sum(), 0.3 * 4.0, 1e-12);
  const int n = options.resolution;
  for (int row = 0; row < n; ++row) {
    for (int column = 0; column < n; ++column) {
      const double m = cloth.m(wobble::cloth_grid_vertex(n, row, column));
      EXPECT_NEAR(m, cloth.m(wobble::cloth_grid_vertex(n, row, n - 1 - column)), 1e-15);
      EXPECT_NEAR(m, cloth.m(wobble::cloth_grid_vertex(n, n - 1 - row, column)), 1e-15);
    }
  }
  // An interior vertex carries four quarter cells, a corner one.
  const double cell = 0.3 * (2.0 / 8) * (2.0 / 8);
  EXPECT_NEAR(cloth.m(wobble::cloth_grid_vertex(n, 4, 4)), cell, 1e-15);
  EXPECT_NEAR(cloth.m(0), cell / 4, 1e-15);
}

TEST(ClothGrid, FacesTileTheSquareFacingUp) {
  wobble::ClothGridOptions options;
  options.resolution = 6;
  const wobble::SpringNetwork cloth = wobble::make_cloth_grid(options);
  double area = 0.0;
  for (Eigen::Index f = 0; f < cloth.F.rows(); ++f) {
    const Eigen::Vector3d a = cloth.V.row(cloth.F(f, 0)), b = cloth.V.row(cloth.F(f, 1)),
                          c = cloth.V.row(cloth.F(f, 2));
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    EXPECT_GT(normal.y(), 0.0);
    area += 0.5 * normal.norm();
  }
  EXPECT_NEAR(area, 1.0, 1e-12);
  EXPECT_NEAR(cloth.V.col(0).minCoeff(), -0.5, 1e-15);
  EXPECT_NEAR(cloth.V.col(2).maxCoeff(), 0.5, 1e-15);
  EXPECT_EQ(cloth.V.col(1).cwiseAbs().maxCoeff(), 0.0);
}

TEST(ClothGrid, RefusesBadOptions) {
  wobble::ClothGridOptions options;
  options.resolution = 1;
  EXPECT_THROW(wobble::make_cloth_grid(options), wobble::InputError);
  options.resolution = 4;
  options.size = 0.0;
  EXPECT_THROW(wobble::make_cloth_grid(options), wobble::InputError);
}

}  // namespace
