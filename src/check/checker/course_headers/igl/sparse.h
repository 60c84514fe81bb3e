#ifndef WOBBLE_CHECK_COURSE_HEADERS_IGL_SPARSE_H
#define WOBBLE_CHECK_COURSE_HEADERS_IGL_SPARSE_H

// The checker's own stand-in for libigl's <igl/sparse.h> (the handout lists igl::sparse as not
// to be used, but a file that includes it must still compile). Written for Wobble from the
// interface: a sparse matrix from lists of rows I, columns J and values V (repeated entries
// add), its size given or taken from the largest indices, or from a dense matrix's nonzeros.

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <cstddef>
#include <vector>

namespace igl {

template <typename IndexVectorI, typename IndexVectorJ, typename ValueVector, typename T>
void sparse(const IndexVectorI& I, const IndexVectorJ& J, const ValueVector& V, const size_t m,
            const size_t n, Eigen::SparseMatrix<T>& X) {
  std::vector<Eigen::Triplet<T>> entries;
  entries.reserve(static_cast<size_t>(I.size()));
  for (Eigen::Index e = 0; e < I.size(); ++e)
    entries.emplace_back(static_cast<Eigen::Index>(I(e)), static_cast<Eigen::Index>(J(e)),
                         static_cast<T>(V(e)));
  X.resize(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(n));
  X.setFromTriplets(entries.begin(), entries.end());
}

template <typename IndexVector, typename ValueVector, typename T>
void sparse(const IndexVector& I, const IndexVector& J, const ValueVector& V,
            Eigen::SparseMatrix<T>& X) {
  const size_t m = I.size() == 0 ? 0 : static_cast<size_t>(I.maxCoeff()) + 1;
  const size_t n = J.size() == 0 ? 0 : static_cast<size_t>(J.maxCoeff()) + 1;
  sparse(I, J, V, m, n, X);
}

template <typename DerivedD, typename T>
void sparse(const Eigen::PlainObjectBase<DerivedD>& D, Eigen::SparseMatrix<T>& X) {
  std::vector<Eigen::Triplet<T>> entries;
  for (Eigen::Index j = 0; j < D.cols(); ++j)
    for (Eigen::Index i = 0; i < D.rows(); ++i)
      if (D(i, j) != 0) entries.emplace_back(i, j, static_cast<T>(D(i, j)));
  X.resize(D.rows(), D.cols());
  X.setFromTriplets(entries.begin(), entries.end());
}

}  // namespace igl

#endif
