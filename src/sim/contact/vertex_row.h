#ifndef WOBBLE_SIM_CONTACT_VERTEX_ROW_H
#define WOBBLE_SIM_CONTACT_VERTEX_ROW_H

#include <Eigen/Core>
#include <vector>

namespace wobble {

// Vertex i of a #V by 3 position matrix, as a fixed-size vector.
inline Eigen::Vector3d vertex_row(const Eigen::MatrixXd& m, int i) {
  return Eigen::Vector3d(m(i, 0), m(i, 1), m(i, 2));
}

// Every row of a #V by 3 matrix into `rows`, packed: a column-major matrix costs three cache
// lines a vertex where a loop reads vertices out of order.
inline void pack_rows(const Eigen::MatrixXd& m, std::vector<Eigen::Vector3d>& rows) {
  rows.resize(m.rows());
  for (Eigen::Index v = 0; v < m.rows(); ++v)
    rows[v] = vertex_row(m, static_cast<int>(v));
}

// The inverse: `rows` back into the rows of m (#V by 3, already sized).
inline void unpack_rows(const std::vector<Eigen::Vector3d>& rows, Eigen::MatrixXd& m) {
  for (Eigen::Index v = 0; v < m.rows(); ++v)
    m.row(v) = rows[v].transpose();
}

}  // namespace wobble

#endif
