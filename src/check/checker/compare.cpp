#include "compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace {

std::string shape_of(Eigen::Index rows, Eigen::Index cols) {
  return std::to_string(rows) + " by " + std::to_string(cols);
}

// |a − b|, infinite when either is NaN, so a NaN always counts as the worst difference.
double difference(double a, double b) {
  const double d = std::abs(a - b);
  return std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
}

// Enough significant digits for two values `difference` apart to print differently: a step
// off by 1.5e-5 m at 1.55 m needs 7, not the default 6.
int digits_to_show(double magnitude, double difference) {
  if (!(difference > 0) || !std::isfinite(difference) || !std::isfinite(magnitude)) return 6;
  const int digits = 2 + static_cast<int>(std::ceil(std::log10(std::abs(magnitude) / difference)));
  return std::clamp(digits, 6, 17);
}

template <typename Matrix>
std::string explain_incidence(const std::string& difference, const Matrix& A,
                              const Matrix& expected) {
  if (difference.empty()) return difference;
  if (A.rows() != expected.rows() || A.cols() != expected.cols()) return difference;
  if (is_exact_negative(A, expected))
    return difference +
           ": A is exactly the negative of the handout's, a consistent opposite orientation; the "
           "handout's row e holds +1 at column E(e,0) and -1 at column E(e,1), the orientation of "
           "the step's d_e = r_e (p_i − p_j)/‖p_i − p_j‖ for E(e,:) = [i j]";
  return difference + " (row e holds +1 at column E(e,0) and -1 at column E(e,1))";
}

std::string off_by(double worst, Eigen::Index others, double tolerance) {
  std::string text = ": off by " + number(worst, 3) + ", tolerance " + number(tolerance, 3);
  if (others > 0)
    text +=
        "; " + std::to_string(others) + " more entr" + (others == 1 ? "y differs" : "ies differ");
  return text;
}

}  // namespace

std::string number(double value, int digits) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

std::string compare_dense(const std::string& name, const std::string& shape,
                          const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected,
                          double tolerance) {
  if (got.rows() != expected.rows() || got.cols() != expected.cols())
    return name + " is " + shape_of(got.rows(), got.cols()) + ", expected " +
           shape_of(expected.rows(), expected.cols()) + " (" + shape + ")";
  Eigen::Index worst_row = 0, worst_col = 0, count = 0;
  double worst = -1;
  for (Eigen::Index j = 0; j < got.cols(); ++j) {
    for (Eigen::Index i = 0; i < got.rows(); ++i) {
      const double d = difference(got(i, j), expected(i, j));
      if (!(d <= tolerance)) ++count;
      if (d > worst) worst = d, worst_row = i, worst_col = j;
    }
  }
  if (count == 0) return "";
  const int digits = digits_to_show(expected(worst_row, worst_col), worst);
  return name + "(" + std::to_string(worst_row) + "," + std::to_string(worst_col) + ") is " +
         number(got(worst_row, worst_col), digits) + ", expected " +
         number(expected(worst_row, worst_col), digits) + off_by(worst, count - 1, tolerance);
}

std::string compare_vector(const std::string& name, const std::string& shape,
                           const Eigen::VectorXd& got, const Eigen::VectorXd& expected,
                           double tolerance) {
  if (got.size() != expected.size())
    return name + " has " + std::to_string(got.size()) + " entries, expected " +
           std::to_string(expected.size()) + " (" + shape + ")";
  Eigen::Index worst_index = 0, count = 0;
  double worst = -1;
  for (Eigen::Index i = 0; i < got.size(); ++i) {
    const double d = difference(got(i), expected(i));
    if (!(d <= tolerance)) ++count;
    if (d > worst) worst = d, worst_index = i;
  }
  if (count == 0) return "";
  const int digits = digits_to_show(expected(worst_index), worst);
  return name + "(" + std::to_string(worst_index) + ") is " + number(got(worst_index), digits) +
         ", expected " + number(expected(worst_index), digits) +
         off_by(worst, count - 1, tolerance);
}

std::string compare_vertices(const std::string& name, const Eigen::MatrixXd& got,
                             const Eigen::MatrixXd& expected, double tolerance) {
  if (got.rows() != expected.rows() || got.cols() != expected.cols())
    return name + " is " + shape_of(got.rows(), got.cols()) + ", expected " +
           shape_of(expected.rows(), expected.cols()) + " (#V by 3)";
  Eigen::Index worst_vertex = 0, count = 0;
  double worst = -1;
  for (Eigen::Index i = 0; i < got.rows(); ++i) {
    double d = (got.row(i) - expected.row(i)).norm();
    if (std::isnan(d)) d = std::numeric_limits<double>::infinity();
    if (!(d <= tolerance)) ++count;
    if (d > worst) worst = d, worst_vertex = i;
  }
  if (count == 0) return "";
  const int digits = digits_to_show(expected.row(worst_vertex).cwiseAbs().maxCoeff(), worst);
  const auto row = [&](const Eigen::MatrixXd& U) {
    return "(" + number(U(worst_vertex, 0), digits) + ", " + number(U(worst_vertex, 1), digits) +
           ", " + number(U(worst_vertex, 2), digits) + ")";
  };
  std::string text = name + " vertex " + std::to_string(worst_vertex) + " is " + row(got) +
                     ", expected " + row(expected) + ": off by " + number(worst, 3) +
                     " m, tolerance " + number(tolerance, 3) + " m";
  if (count > 1)
    text += "; " + std::to_string(count - 1) + " more vert" +
            (count == 2 ? "ex differs" : "ices differ");
  return text;
}

std::string compare_sparse(const std::string& name, const std::string& shape,
                           const Eigen::SparseMatrix<double>& got,
                           const Eigen::SparseMatrix<double>& expected, double tolerance) {
  if (got.rows() != expected.rows() || got.cols() != expected.cols())
    return name + " is " + shape_of(got.rows(), got.cols()) + ", expected " +
           shape_of(expected.rows(), expected.cols()) + " (" + shape + ")";
  const Eigen::SparseMatrix<double> difference_matrix = got - expected;
  Eigen::Index worst_row = 0, worst_col = 0, count = 0;
  double worst = -1;
  for (int j = 0; j < difference_matrix.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(difference_matrix, j); it; ++it) {
      double d = std::abs(it.value());
      if (std::isnan(d)) d = std::numeric_limits<double>::infinity();
      if (!(d <= tolerance)) ++count;
      if (d > worst) worst = d, worst_row = it.row(), worst_col = it.col();
    }
  }
  if (count == 0) return "";
  const int digits = digits_to_show(expected.coeff(worst_row, worst_col), worst);
  return name + "(" + std::to_string(worst_row) + "," + std::to_string(worst_col) + ") is " +
         number(got.coeff(worst_row, worst_col), digits) + ", expected " +
         number(expected.coeff(worst_row, worst_col), digits) + off_by(worst, count - 1, tolerance);
}

std::string check_sparse_storage(const std::string& name, const Eigen::SparseMatrix<double>& got,
                                 Eigen::Index nonzeros, const std::string& count_words) {
  for (int j = 0; j < got.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(got, j); it; ++it) {
      if (it.value() == 0.0)
        return name + " stores an explicit zero at (" + std::to_string(it.row()) + "," +
               std::to_string(it.col()) + "): a sparse matrix must store only its nonzeros";
    }
  }
  if (got.nonZeros() != nonzeros)
    return name + " stores " + std::to_string(got.nonZeros()) + " entries, expected " +
           std::to_string(nonzeros) + " (" + count_words + ")";
  return "";
}

bool is_exact_negative(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected) {
  return got.rows() == expected.rows() && got.cols() == expected.cols() && expected.size() > 0 &&
         !expected.isZero(0.0) && got == -expected;
}

bool is_exact_negative(const Eigen::SparseMatrix<double>& got,
                       const Eigen::SparseMatrix<double>& expected) {
  if (got.rows() != expected.rows() || got.cols() != expected.cols()) return false;
  if (expected.nonZeros() == 0) return false;
  Eigen::SparseMatrix<double> sum = got + expected;
  sum.prune(0.0, 0.0);
  return sum.nonZeros() == 0;
}

std::string incidence_difference(const std::string& difference, const Eigen::MatrixXd& A,
                                 const Eigen::MatrixXd& expected) {
  return explain_incidence(difference, A, expected);
}

std::string incidence_difference(const std::string& difference,
                                 const Eigen::SparseMatrix<double>& A,
                                 const Eigen::SparseMatrix<double>& expected) {
  return explain_incidence(difference, A, expected);
}
