#ifndef WOBBLE_CHECK_COMPARE_H
#define WOBBLE_CHECK_COMPARE_H

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <string>

// Comparisons of a student's output with the reference's. Each returns "" when they agree and
// otherwise one phrase for a FAIL line: which output, where (row and column, or vertex), the two
// values, by how much and against which tolerance. NaN never agrees.

// `shape` names the expected shape in the assignment's words, e.g. "#E by #V".
std::string compare_dense(const std::string& name, const std::string& shape,
                          const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected,
                          double tolerance);

// The same for a vector, e.g. r: "r(3) is 0.5, expected 0.25 ...".
std::string compare_vector(const std::string& name, const std::string& shape,
                           const Eigen::VectorXd& got, const Eigen::VectorXd& expected,
                           double tolerance);

// #V by 3 positions, compared vertex by vertex (Euclidean distance between the two rows).
std::string compare_vertices(const std::string& name, const Eigen::MatrixXd& got,
                             const Eigen::MatrixXd& expected, double tolerance);

// Sparse matrices, never made dense (the scale check's are 30,000 by 30,000).
std::string compare_sparse(const std::string& name, const std::string& shape,
                           const Eigen::SparseMatrix<double>& got,
                           const Eigen::SparseMatrix<double>& expected, double tolerance);

// The sparse forms' storage rule: no explicitly stored zero, and exactly `nonzeros` entries
// (`count_words` says why, e.g. "2 per spring").
std::string check_sparse_storage(const std::string& name, const Eigen::SparseMatrix<double>& got,
                                 Eigen::Index nonzeros, const std::string& count_words);

// Whether `got` is exactly −`expected` (same shape, not all zero): an incidence matrix of the
// opposite orientation.
bool is_exact_negative(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected);
bool is_exact_negative(const Eigen::SparseMatrix<double>& got,
                       const Eigen::SparseMatrix<double>& expected);

// The FAIL text of an incidence matrix A (#E by #V) that differs, `difference` from
// compare_dense or compare_sparse, with the rule it breaks, or that it is exactly the negative of
// the handout's. "" stays "".
std::string incidence_difference(const std::string& difference, const Eigen::MatrixXd& A,
                                 const Eigen::MatrixXd& expected);
std::string incidence_difference(const std::string& difference,
                                 const Eigen::SparseMatrix<double>& A,
                                 const Eigen::SparseMatrix<double>& expected);

// A number as a FAIL line prints it: 6 significant digits unless told more.
std::string number(double value, int digits = 6);

#endif
