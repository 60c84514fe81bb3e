#ifndef WOBBLE_SIM_INSTRUMENTS_RIGID_FIT_H
#define WOBBLE_SIM_INSTRUMENTS_RIGID_FIT_H

#include <Eigen/Core>

namespace wobble {

// How far a shape is from a rigid motion of another: the root-mean-square distance (m) between
// the rows of `deformed` and those of `reference` after the rotation and translation that bring
// `reference` closest to `deformed` (least squares, Kabsch's method; a reflection is never
// used). Zero when `deformed` is `reference` moved rigidly.
//   reference  #V by 3 positions (m), for example a body's first frame
//   deformed   #V by 3 positions of the same vertices (m)
double rigid_fit_rms(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& deformed);

// The diagonal of the bounding box of `positions` (#V by 3, m).
double bounding_diagonal(const Eigen::MatrixXd& positions);

}  // namespace wobble

#endif
