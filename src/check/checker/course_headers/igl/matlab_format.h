#ifndef WOBBLE_CHECK_COURSE_HEADERS_IGL_MATLAB_FORMAT_H
#define WOBBLE_CHECK_COURSE_HEADERS_IGL_MATLAB_FORMAT_H

// The checker's own stand-in for libigl's <igl/matlab_format.h>, which the course's template
// includes on the second line of both step files (the course builds with libigl; Debian has no
// package of it). Written for Wobble from the interface alone: the same names, arguments and
// return types, so any call a student makes compiles; what it prints is a MATLAB literal in
// Wobble's own layout, and the checker never reads it.
//
//   igl::matlab_format()                  an Eigen::IOFormat:  std::cout << M.format(it)
//   igl::matlab_format(M, "name")         dense M, streamable: name = [ rows ];
//   igl::matlab_format(S, "name")         sparse S, a string of 1-based triplets and sparse()
//   igl::matlab_format(x, "name")         a double or float, a string: name = x;
//   igl::matlab_format_index(M, "name")   dense indices, printed 1-based as MATLAB counts

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <sstream>
#include <string>

namespace igl {

namespace matlab_format_detail {

inline Eigen::IOFormat literal(const std::string& name) {
  const std::string opening = name.empty() ? "[\n" : name + " = [\n";
  return Eigen::IOFormat(Eigen::FullPrecision, Eigen::DontAlignCols, " ", "\n", "  ", "", opening,
                         "\n];");
}

template <typename Scalar>
std::string scalar(Scalar value, const std::string& name) {
  std::ostringstream text;
  text.precision(17);
  if (!name.empty()) text << name << " = ";
  text << value << ';';
  return text.str();
}

}  // namespace matlab_format_detail

inline Eigen::IOFormat matlab_format() {
  return matlab_format_detail::literal("");
}

template <typename DerivedM>
const Eigen::WithFormat<DerivedM> matlab_format(const Eigen::DenseBase<DerivedM>& M,
                                                const std::string name = "") {
  return M.format(matlab_format_detail::literal(name));
}

template <typename DerivedS>
std::string matlab_format(const Eigen::SparseMatrixBase<DerivedS>& S, const std::string name = "") {
  const std::string matrix = name.empty() ? std::string("S") : name;
  std::ostringstream text;
  text.precision(17);
  text << matrix << "_ijv = [\n";
  const typename DerivedS::PlainObject plain = S.derived();
  for (Eigen::Index outer = 0; outer < plain.outerSize(); ++outer)
    for (typename DerivedS::PlainObject::InnerIterator it(plain, outer); it; ++it)
      text << "  " << it.row() + 1 << ' ' << it.col() + 1 << ' ' << it.value() << '\n';
  text << "];\n"
       << matrix << " = sparse(" << matrix << "_ijv(:,1)," << matrix << "_ijv(:,2)," << matrix
       << "_ijv(:,3)," << plain.rows() << ',' << plain.cols() << ");";
  return text.str();
}

inline std::string matlab_format(const double value, const std::string name = "") {
  return matlab_format_detail::scalar(value, name);
}

inline std::string matlab_format(const float value, const std::string name = "") {
  return matlab_format_detail::scalar(value, name);
}

template <typename DerivedM>
std::string matlab_format_index(const Eigen::MatrixBase<DerivedM>& M, const std::string name = "") {
  std::ostringstream text;
  text << (M.array() + 1).matrix().format(matlab_format_detail::literal(name));
  return text.str();
}

}  // namespace igl

#endif
