#include "voronoi_masses.h"

#include <Eigen/Geometry>

namespace wobble {

Eigen::VectorXd voronoi_masses(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  Eigen::VectorXd areas = Eigen::VectorXd::Zero(V.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const int corner[3] = {F(f, 0), F(f, 1), F(f, 2)};
    Eigen::Vector3d x[3];
    for (int c = 0; c < 3; ++c)
      x[c] = V.row(corner[c]).transpose();
    const double twice_area = (x[1] - x[0]).cross(x[2] - x[0]).norm();
    // A zero-area triangle has no Voronoi region, and its cotangents would be infinite.
    if (!(twice_area > 0.0)) continue;
    const double area = 0.5 * twice_area;

    // dot[c] = (x_a − x_c)·(x_b − x_c) for the two other corners a, b: its sign says whether the
    // angle at c is obtuse, and cot θ_c = dot[c] / (2·area) because |(x_a−x_c)×(x_b−x_c)| is
    // twice the area whichever corner it is measured from.
    double dot[3];
    for (int c = 0; c < 3; ++c)
      dot[c] = (x[(c + 1) % 3] - x[c]).dot(x[(c + 2) % 3] - x[c]);

    int obtuse = -1;
    for (int c = 0; c < 3; ++c) {
      if (dot[c] < 0.0) obtuse = c;
    }
    if (obtuse >= 0) {
      for (int c = 0; c < 3; ++c)
        areas(corner[c]) += c == obtuse ? 0.5 * area : 0.25 * area;
      continue;
    }
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const int k = (i + 2) % 3;
      const double cot_j = dot[j] / twice_area;
      const double cot_k = dot[k] / twice_area;
      areas(corner[i]) +=
          ((x[i] - x[j]).squaredNorm() * cot_k + (x[i] - x[k]).squaredNorm() * cot_j) / 8.0;
    }
  }
  return areas;
}

}  // namespace wobble
