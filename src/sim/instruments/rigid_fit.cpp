#include "sim/instruments/rigid_fit.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>

namespace wobble {

double rigid_fit_rms(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& deformed) {
  const Eigen::Index n = reference.rows();
  if (n == 0) return 0.0;
  const Eigen::RowVector3d reference_center = reference.colwise().mean();
  const Eigen::RowVector3d deformed_center = deformed.colwise().mean();
  const Eigen::MatrixXd a = reference.rowwise() - reference_center;
  const Eigen::MatrixXd b = deformed.rowwise() - deformed_center;
  // The rotation R maximizing trace(Rᵀ bᵀa) is V diag(1, 1, det) Uᵀ for aᵀb = U S Vᵀ.
  const Eigen::Matrix3d covariance = a.transpose() * b;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d flip = Eigen::Matrix3d::Identity();
  if ((svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0) flip(2, 2) = -1.0;
  const Eigen::Matrix3d rotation = svd.matrixV() * flip * svd.matrixU().transpose();
  const Eigen::MatrixXd placed = a * rotation.transpose();
  return std::sqrt((placed - b).squaredNorm() / static_cast<double>(n));
}

double bounding_diagonal(const Eigen::MatrixXd& positions) {
  if (positions.rows() == 0) return 0.0;
  return (positions.colwise().maxCoeff() - positions.colwise().minCoeff()).norm();
}

}  // namespace wobble
