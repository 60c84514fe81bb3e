#include <algorithm>
#include <cstdint>

#include "cholesky_solver.h"

// The solve: L laid out for it once per analysis, copied after each factorization, and the
// forward and backward substitution for x, y and z side by side.
namespace wobble {

void CholeskySolver::plan_solve(int n) {
  // The copy of L for the solve. A supernode at least block_solve_min_width wide is solved as a
  // block: its columns keep only their rows among its own columns, and its rows below are read
  // row by row for all its columns at once. Every other column keeps all its rows below the
  // diagonal.
  solve_blocks_.clear();
  column_start_.assign(n + 1, 0);
  inverse_diagonal_.assign(n, 0.0);
  long entries = 0, block_entries = 0, block_row_count = 0;
  for (const Supernode& s : supernodes_) {
    const bool block = s.width >= block_solve_min_width && s.rows > s.width;
    for (int c = 0; c < s.width; ++c) {
      column_start_[s.first + c] = static_cast<int>(entries);
      entries += (block ? s.width : s.rows) - c - 1;
    }
    if (block) {
      SolveBlock b;
      b.first = s.first;
      b.width = s.width;
      b.below = s.rows - s.width;
      b.row_start = block_row_count;
      b.value_start = block_entries;
      solve_blocks_.push_back(b);
      block_row_count += b.below;
      block_entries += static_cast<long>(b.below) * b.width;
    }
  }
  column_start_[n] = static_cast<int>(entries);
  column_rows_.resize(entries);
  block_rows_.resize(block_row_count);
  {
    std::size_t next_block = 0;
    for (const Supernode& s : supernodes_) {
      const bool block =
          next_block < solve_blocks_.size() && solve_blocks_[next_block].first == s.first;
      const int kept = block ? s.width : s.rows;
      for (int c = 0; c < s.width; ++c) {
        std::copy(rows_.begin() + s.row_start + c + 1, rows_.begin() + s.row_start + kept,
                  column_rows_.begin() + column_start_[s.first + c]);
      }
      if (block) {
        const SolveBlock& b = solve_blocks_[next_block++];
        std::copy(rows_.begin() + s.row_start + s.width, rows_.begin() + s.row_start + s.rows,
                  block_rows_.begin() + b.row_start);
      }
    }
  }
  single_ = factor_nonzeros_ > single_precision_above_;
  column_values_.assign(single_ ? 0 : column_rows_.size(), 0.0);
  column_values_single_.assign(single_ ? column_rows_.size() : 0, 0.0f);
  block_values_.assign(single_ ? 0 : block_entries, 0.0);
  block_values_single_.assign(single_ ? block_entries : 0, 0.0f);
  // Room to start the lanes on a cache line (see solve).
  work_.assign(4 * static_cast<std::size_t>(n) + 8, 0.0);
}

template <typename Value>
void CholeskySolver::copy_for_solve(Value* columns, Value* blocks) const {
  std::size_t next_block = 0;
  for (const Supernode& node : supernodes_) {
    const double* block = values_.data() + node.value_start;
    const bool is_block =
        next_block < solve_blocks_.size() && solve_blocks_[next_block].first == node.first;
    const int kept = is_block ? node.width : node.rows;
    for (int c = 0; c < node.width; ++c) {
      columns = std::copy(block + c * node.rows + c + 1, block + c * node.rows + kept, columns);
    }
    if (is_block) {
      const SolveBlock& b = solve_blocks_[next_block++];
      Value* out = blocks + b.value_start;
      for (int i = 0; i < b.below; ++i) {
        for (int c = 0; c < node.width; ++c)
          *out++ = static_cast<Value>(block[c * node.rows + node.width + i]);
      }
    }
  }
}

void CholeskySolver::solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& x) {
  const Eigen::Index n = static_cast<Eigen::Index>(permutation_.size());
  // On a 64-byte boundary, so that no lane straddles two cache lines and the step's time does
  // not depend on where the allocator put work_.
  const std::uintptr_t address = reinterpret_cast<std::uintptr_t>(work_.data());
  Lane4* w = reinterpret_cast<Lane4*>(work_.data() + ((64 - address % 64) % 64) / sizeof(double));
  for (Eigen::Index i = 0; i < n; ++i)
    w[permutation_[i]] = Lane4{b(i, 0), b(i, 1), b(i, 2), 0.0};
  if (single_) {
    substitute_lanes(solve_factor(column_values_single_.data(), block_values_single_.data()), w);
  } else {
    substitute_lanes(solve_factor(column_values_.data(), block_values_.data()), w);
  }
  if (x.rows() != n || x.cols() != 3) x.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Lane4& row = w[permutation_[i]];
    x(i, 0) = row[0];
    x(i, 1) = row[1];
    x(i, 2) = row[2];
  }
}

template <typename Value>
SolveFactor<Value> CholeskySolver::solve_factor(const Value* columns, const Value* blocks) const {
  SolveFactor<Value> f;
  f.n = static_cast<int>(permutation_.size());
  f.start = column_start_.data();
  f.rows = column_rows_.data();
  f.values = columns;
  f.inverse_diagonal = inverse_diagonal_.data();
  f.block_count = static_cast<int>(solve_blocks_.size());
  f.blocks = solve_blocks_.data();
  f.block_rows = block_rows_.data();
  f.block_values = blocks;
  return f;
}

template void CholeskySolver::copy_for_solve(double* columns, double* blocks) const;
template void CholeskySolver::copy_for_solve(float* columns, float* blocks) const;

}  // namespace wobble
