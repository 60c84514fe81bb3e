#ifndef WOBBLE_CHECK_COURSE_HEADERS_IGL_EDGE_LENGTHS_H
#define WOBBLE_CHECK_COURSE_HEADERS_IGL_EDGE_LENGTHS_H

// The checker's own stand-in for libigl's <igl/edge_lengths.h> (the handout lists it as not to
// be used, but a file that uses it must still compile and run). Written for Wobble from the
// interface:
//   F  #F by 2 edges: L  #F list of their lengths
//   F  #F by 3 triangles: L  #F by 3, column c the length of the edge opposite corner c

#include <Eigen/Core>
#include <stdexcept>

namespace igl {

template <typename DerivedV, typename DerivedF, typename DerivedL>
void edge_lengths(const Eigen::MatrixBase<DerivedV>& V, const Eigen::MatrixBase<DerivedF>& F,
                  Eigen::PlainObjectBase<DerivedL>& L) {
  const auto length = [&](Eigen::Index f, Eigen::Index a, Eigen::Index b) {
    return (V.row(F(f, a)) - V.row(F(f, b))).norm();
  };
  if (F.cols() == 2) {
    L.resize(F.rows(), 1);
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      L(f, 0) = length(f, 0, 1);
  } else if (F.cols() == 3) {
    L.resize(F.rows(), 3);
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
      L(f, 0) = length(f, 1, 2);
      L(f, 1) = length(f, 2, 0);
      L(f, 2) = length(f, 0, 1);
    }
  } else {
    throw std::invalid_argument(
        "igl::edge_lengths: the checker's stand-in takes edges or triangles");
  }
}

}  // namespace igl

#endif
