#ifndef WOBBLE_CHECK_COURSE_HEADERS_IGL_DIAG_H
#define WOBBLE_CHECK_COURSE_HEADERS_IGL_DIAG_H

// The checker's own stand-in for libigl's <igl/diag.h> (the handout lists igl::diag as not to
// be used, but a file that includes it must still compile). Written for Wobble from the
// interface: the diagonal of a sparse matrix as a vector, or a sparse diagonal matrix from one.

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <algorithm>
#include <vector>

namespace igl {

template <typename T, typename DerivedV>
void diag(const Eigen::SparseMatrix<T>& X, Eigen::PlainObjectBase<DerivedV>& V) {
  V = X.diagonal();
}

template <typename DerivedV, typename T>
void diag(const Eigen::MatrixBase<DerivedV>& V, Eigen::SparseMatrix<T>& X) {
  const Eigen::Index n = V.size();
  std::vector<Eigen::Triplet<T>> entries;
  entries.reserve(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i)
    entries.emplace_back(i, i, static_cast<T>(V(i)));
  X.resize(n, n);
  X.setFromTriplets(entries.begin(), entries.end());
}

}  // namespace igl

#endif
