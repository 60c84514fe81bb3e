#include "write_obj.h"

#include <charconv>

#include "atomic_file.h"
#include "text_pieces.h"

namespace wobble {

namespace {

void append_indices(std::string& out, const char* tag, const Eigen::MatrixXi& rows) {
  for (Eigen::Index row = 0; row < rows.rows(); ++row) {
    out += tag;
    for (Eigen::Index col = 0; col < rows.cols(); ++col) {
      out += ' ';
      out += std::to_string(rows(row, col) + 1);
    }
    out += '\n';
  }
}

}  // namespace

std::string obj_text(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXi& E) {
  std::string out = "# written by wobble\n";
  out.reserve(out.size() + 64 * V.rows() + 24 * (F.rows() + E.rows()));
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    out += 'v';
    for (Eigen::Index c = 0; c < V.cols(); ++c) {
      out += ' ';
      append_shortest(out, V(i, c));
    }
    out += '\n';
  }
  if (F.rows() > 0) {
    append_indices(out, "f", F);
  } else {
    append_indices(out, "l", E);
  }
  return out;
}

void write_obj(const std::string& path, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
               const Eigen::MatrixXi& E) {
  write_output_file(path, obj_text(V, F, E));
}

}  // namespace wobble
