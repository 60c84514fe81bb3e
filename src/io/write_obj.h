#ifndef WOBBLE_IO_WRITE_OBJ_H
#define WOBBLE_IO_WRITE_OBJ_H

#include <Eigen/Core>
#include <string>

namespace wobble {

// The text of a Wobble OBJ file: one `v x y z` line per vertex in the order of V, written with
// the shortest decimal form that reads back to the same double, then one `f a b c` line per
// face (1-based). A mesh without faces gets one `l a b` line per spring instead, so that a
// spring network without faces still exports something a viewer can show.
//
// Inputs:
//   V  #V by 3 list of vertex positions
//   F  #F by 3 list of triangles, indices into rows of V (may be empty)
//   E  #E by 2 list of springs, used only when F is empty (may be empty)
std::string obj_text(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                     const Eigen::MatrixXi& E = Eigen::MatrixXi());

// Write obj_text(V, F, E) to `path` atomically. Throws OutputError if it cannot.
void write_obj(const std::string& path, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
               const Eigen::MatrixXi& E = Eigen::MatrixXi());

}  // namespace wobble

#endif
