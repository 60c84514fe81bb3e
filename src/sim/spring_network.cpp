#include "spring_network.h"

#include <cmath>
#include <string>

#include "input_error.h"
#include "value_limits.h"

namespace wobble {

namespace {

void check_indices(const Eigen::MatrixXi& indices, Eigen::Index columns, const char* what,
                   Eigen::Index vertex_count) {
  if (indices.rows() > 0 && indices.cols() != columns) {
    throw InputError(std::string(what) + " must have " + std::to_string(columns) +
                     " columns, got " + std::to_string(indices.cols()));
  }
  for (Eigen::Index row = 0; row < indices.rows(); ++row) {
    for (Eigen::Index col = 0; col < indices.cols(); ++col) {
      const int index = indices(row, col);
      if (index < 0 || index >= vertex_count) {
        throw InputError(std::string(what) + " " + std::to_string(row) + " refers to vertex " +
                         std::to_string(index) + ", expected 0 to " +
                         std::to_string(vertex_count - 1));
      }
    }
  }
}

}  // namespace

void validate_spring_network(const SpringNetwork& network) {
  const Eigen::Index n = network.V.rows();
  if (n == 0) throw InputError("the mesh has no vertices");
  if (network.V.cols() != 3) {
    throw InputError("vertex positions must have 3 columns, got " +
                     std::to_string(network.V.cols()));
  }
  if (!network.V.allFinite()) throw InputError("a vertex position is not finite");
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      if (!limits::coordinate.contains(network.V(i, c))) {
        throw InputError("vertex " + std::to_string(i) + " has the coordinate " +
                         limit_text(network.V(i, c)) + ", expected coordinates " +
                         within_text(limits::coordinate));
      }
    }
  }
  check_indices(network.E, 2, "spring", n);
  check_indices(network.F, 3, "face", n);
  check_indices(network.T, 4, "tetrahedron", n);
  for (Eigen::Index e = 0; e < network.E.rows(); ++e) {
    if (network.E(e, 0) == network.E(e, 1)) {
      throw InputError("spring " + std::to_string(e) + " joins vertex " +
                       std::to_string(network.E(e, 0)) + " to itself");
    }
  }
  if (network.m.size() != n) {
    throw InputError("expected " + std::to_string(n) + " masses, got " +
                     std::to_string(network.m.size()));
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!limits::vertex_mass.contains(network.m(i))) {
      throw InputError("vertex " + std::to_string(i) + " has mass " + limit_text(network.m(i)) +
                       " kg, expected " + expected_in(limits::vertex_mass));
    }
  }
}

}  // namespace wobble
