#include "sim/shapes/face_springs.h"

#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "sim/input_error.h"

namespace {

using Faces = std::vector<std::vector<int>>;

std::vector<std::pair<int, int>> rows(const Eigen::MatrixXi& E) {
  std::vector<std::pair<int, int>> pairs;
  for (Eigen::Index e = 0; e < E.rows(); ++e)
    pairs.emplace_back(E(e, 0), E(e, 1));
  return pairs;
}

TEST(FaceSprings, TriangleGivesItsThreeEdges) {
  const Eigen::MatrixXi E = wobble::face_springs({{2, 0, 1}});
  ASSERT_EQ(E.cols(), 2);
  EXPECT_EQ(rows(E), (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 2}}));
}

TEST(FaceSprings, QuadGivesFourEdgesAndBothDiagonals) {
  const Eigen::MatrixXi E = wobble::face_springs({{0, 1, 2, 3}});
  EXPECT_EQ(rows(E),
            (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}));
}

TEST(FaceSprings, PolygonOfNGivesEveryPairOnce) {
  for (int n = 3; n <= 9; ++n) {  // n = 2 is a spring as written (below)
    std::vector<int> face;
    for (int i = 0; i < n; ++i)
      face.push_back(10 - i);  // any order: the springs come out sorted
    const Eigen::MatrixXi E = wobble::face_springs({face});
    EXPECT_EQ(E.rows(), n * (n - 1) / 2) << n;
    for (Eigen::Index e = 0; e < E.rows(); ++e)
      EXPECT_LT(E(e, 0), E(e, 1));
  }
}

TEST(FaceSprings, PairSharedByTwoFacesIsOneSpring) {
  // Two triangles sharing the edge 1–2, one wound each way: 5 springs, not 6.
  const Eigen::MatrixXi E = wobble::face_springs({{0, 1, 2}, {2, 1, 3}});
  EXPECT_EQ(rows(E), (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 2}, {1, 3}, {2, 3}}));
}

TEST(FaceSprings, TwoVertexFacesAreTheSpringListAsWritten) {
  // The course's E = F: file order, each face's own order, and a repeat (either way round) is a
  // second spring.
  const Faces faces = {{3, 1}, {1, 3}, {0, 2}, {3, 1}};
  EXPECT_EQ(rows(wobble::face_springs(faces)),
            (std::vector<std::pair<int, int>>{{3, 1}, {1, 3}, {0, 2}, {3, 1}}));
}

TEST(FaceSprings, TwoVertexFacesBesidePolygonsAreAddedAsWrittenAfterThePolygonsPairs) {
  // The triangle's edge 0–1 once from the triangle, then the two-vertex faces as written,
  // including 1–0 which repeats that edge: a spring of its own, as a two-vertex face always is.
  const Faces faces = {{4, 2}, {0, 1, 2}, {1, 0}, {2, 3}};
  EXPECT_EQ(rows(wobble::face_springs(faces)),
            (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 2}, {4, 2}, {1, 0}, {2, 3}}));
}

TEST(FaceSprings, PolygonPairsOrderDoesNotDependOnTheFaceOrder) {
  const Faces faces = {{0, 1, 2, 3}, {3, 2, 4}, {4, 5}, {5, 6, 7, 8, 9}};
  const Faces reversed(faces.rbegin(), faces.rend());
  EXPECT_EQ(wobble::face_springs(faces), wobble::face_springs(reversed));
}

TEST(FaceSprings, MatchesABruteForceSetOfPairs) {
  const Faces faces = {{0, 1, 2, 3, 4}, {4, 3, 5, 6, 7, 8}, {8, 9}, {2, 1, 10}, {0, 4, 11}};
  std::set<std::pair<int, int>> expected;
  for (const auto& face : faces) {
    for (int a : face) {
      for (int b : face) {
        if (a < b) expected.insert({a, b});
      }
    }
  }
  const auto got = rows(wobble::face_springs(faces));
  const std::set<std::pair<int, int>> got_set(got.begin(), got.end());
  EXPECT_EQ(got_set, expected);
  EXPECT_EQ(got.size(), expected.size()) << "no pair twice";
}

TEST(FaceSprings, RefusesFacesThatCannotBeSprings) {
  EXPECT_THROW(wobble::face_springs({{0, 1, 2}, {4}}), wobble::InputError);
  EXPECT_THROW(wobble::face_springs({{0, 1, 1}}), wobble::InputError);
  EXPECT_THROW(wobble::face_springs({{0, -1, 2}}), wobble::InputError);
  EXPECT_EQ(wobble::face_springs({}).rows(), 0);
}

TEST(FanTriangles, TriangleStaysAsItIs) {
  const Eigen::MatrixXi F = wobble::fan_triangles({{4, 2, 7}});
  ASSERT_EQ(F.rows(), 1);
  EXPECT_EQ(F.row(0), Eigen::RowVector3i(4, 2, 7));
}

TEST(FanTriangles, PolygonsFanFromTheirFirstVertexKeepingWinding) {
  const Eigen::MatrixXi F = wobble::fan_triangles({{0, 1, 2, 3}, {5, 6}, {9, 8, 7, 6, 5}});
  ASSERT_EQ(F.rows(), 2 + 3);
  ASSERT_EQ(F.cols(), 3);
  Eigen::MatrixXi expected(5, 3);
  expected << 0, 1, 2, 0, 2, 3, 9, 8, 7, 9, 7, 6, 9, 6, 5;
  EXPECT_EQ(F, expected);
}

TEST(FanTriangles, SpringOnlyMeshHasNoTriangles) {
  const Eigen::MatrixXi F = wobble::fan_triangles({{0, 1}, {1, 2}});
  EXPECT_EQ(F.rows(), 0);
  EXPECT_EQ(F.cols(), 3);
}

}  // namespace
