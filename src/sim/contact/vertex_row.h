#ifndef WOBBLE_SIM_CONTACT_VERTEX_ROW_H
#define WOBBLE_SIM_CONTACT_VERTEX_ROW_H

#include <Eigen/Core>

namespace wobble {

// Vertex i of a #V by 3 position matrix, as a fixed-size vector.
inline Eigen::Vector3d vertex_row(const Eigen::MatrixXd& m, int i) {
  return Eigen::Vector3d(m(i, 0), m(i, 1), m(i, 2));
}

}  // namespace wobble

#endif
