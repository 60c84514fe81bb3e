#include <Eigen/Cholesky>
#include <algorithm>

#include "cholesky_solver.h"

// The numeric factorization: Q's values into the supernodes' blocks, then left-looking dense
// updates, two sets of subtrees side by side on the pool's threads.
namespace wobble {

namespace {

using ColumnBlock = Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>>;

}  // namespace

void CholeskySolver::plan_factorization(const Eigen::SparseMatrix<double>& Q,
                                        const std::vector<int>& parent) {
  const int n = static_cast<int>(Q.rows());
  // Where each stored value of Q lands in the blocks (its lower-triangle twin, once permuted).
  std::vector<int> position(n, -1);
  value_slot_.assign(Q.nonZeros(), -1);
  std::vector<int> inverse(n);
  for (int i = 0; i < n; ++i)
    inverse[permutation_[i]] = i;
  for (const Supernode& s : supernodes_) {
    for (int r = 0; r < s.rows; ++r)
      position[rows_[s.row_start + r]] = r;
    for (int c = 0; c < s.width; ++c) {
      const int column = inverse[s.first + c];  // the column of Q that becomes s.first + c
      for (long k = Q.outerIndexPtr()[column]; k < Q.outerIndexPtr()[column + 1]; ++k) {
        const int row = permutation_[Q.innerIndexPtr()[k]];
        if (row < s.first + c) continue;  // upper triangle: its twin is counted instead
        value_slot_[k] = s.value_start + static_cast<long>(c) * s.rows + position[row];
      }
    }
    for (int r = 0; r < s.rows; ++r)
      position[rows_[s.row_start + r]] = -1;
  }

  split_for_threads(parent);
  link_next_.assign(supernodes_.size(), -1);
  cursor_.assign(supernodes_.size(), 0);
  // An update is (rows of the source below its cursor) × (columns of the target).
  int tallest = 1, widest = 1;
  for (const Supernode& s : supernodes_) {
    tallest = std::max(tallest, s.rows);
    widest = std::max(widest, s.width);
  }
  for (Scratch& scratch : scratch_) {
    scratch.relative.assign(n, -1);
    scratch.link_head.assign(supernodes_.size(), -1);
    scratch.update.resize(static_cast<std::size_t>(tallest) * widest);
  }
}

bool CholeskySolver::factorize(const Eigen::SparseMatrix<double>& Q) {
  std::fill(values_.begin(), values_.end(), 0.0);
  const double* q = Q.valuePtr();
  for (std::size_t k = 0; k < value_slot_.size(); ++k) {
    if (value_slot_[k] >= 0) values_[value_slot_[k]] += q[k];
  }
  for (Scratch& scratch : scratch_)
    std::fill(scratch.link_head.begin(), scratch.link_head.end(), -1);
  // Two disjoint sets of subtrees side by side (each needs only its own descendants), then the
  // rest, which they both update, on one thread.
  // Each part has its own scratch, so whichever thread takes it, the result is the same; the
  // caller takes both if no helper wakes in time.
  bool ok[2] = {true, true};
  auto factorize_part = [&](int part) {
    for (int s : parts_[part]) {
      if (!factorize_supernode(s, part)) {
        ok[part] = false;
        return;
      }
    }
  };
  pool_->run(parts_[1].empty() ? 1 : 2, factorize_part);
  if (!ok[0] || !ok[1]) return false;
  for (int s : parts_[2]) {
    if (!factorize_supernode(s, 0)) return false;
  }
  // L for the solve, in the order the supernodes and their columns come: by columns, and the
  // rows below a block row by row. (Rounded to float for a large factor: see
  // solves_in_single_precision.)
  if (single_) {
    copy_for_solve(column_values_single_.data(), block_values_single_.data());
  } else {
    copy_for_solve(column_values_.data(), block_values_.data());
  }
  return true;
}

void CholeskySolver::split_for_threads(const std::vector<int>& parent) {
  for (std::vector<int>& part : parts_)
    part.clear();
  const int count = static_cast<int>(supernodes_.size());
  if (factor_nonzeros_ <= parallel_factorization_above) {
    for (int s = 0; s < count; ++s)
      parts_[0].push_back(s);
    return;
  }
  // The tree of supernodes, and the work below each: a supernode's own work grows as its width
  // times its rows squared (its updates of others and its factorization).
  std::vector<int> up(count, -1), child_head(count, -1), child_next(count, -1), roots;
  std::vector<double> work(count), subtree(count, 0.0);
  double total = 0.0;
  for (int s = 0; s < count; ++s) {
    const Supernode& node = supernodes_[s];
    const int p = parent[node.first + node.width - 1];
    work[s] = static_cast<double>(node.width) * node.rows * node.rows;
    total += work[s];
    subtree[s] += work[s];  // its children, all earlier, are in already
    if (p < 0) {
      roots.push_back(s);
      continue;
    }
    up[s] = supernode_of_[p];
    subtree[up[s]] += subtree[s];
    child_next[s] = child_head[up[s]];
    child_head[up[s]] = s;
  }
  // Split the heaviest subtree into its children (its root joins the shared rest) until the
  // subtrees fall into two piles within 10% of each other, heaviest first into the lighter pile.
  std::vector<int> frontier = roots, owner(count, -1);
  double shared = 0.0;
  for (;;) {
    std::sort(frontier.begin(), frontier.end(),
              [&](int a, int b) { return subtree[a] > subtree[b]; });
    double pile[2] = {0.0, 0.0};
    for (int root : frontier) {
      const int lighter = pile[0] <= pile[1] ? 0 : 1;
      pile[lighter] += subtree[root];
      owner[root] = lighter;
    }
    if (frontier.size() >= 2 && std::max(pile[0], pile[1]) <= 0.55 * (pile[0] + pile[1])) break;
    if (frontier.empty() || shared > 0.5 * total) {  // no useful split: one thread for all
      for (int s = 0; s < count; ++s)
        parts_[0].push_back(s);
      return;
    }
    const int heaviest = frontier.front();
    frontier.erase(frontier.begin());
    owner[heaviest] = 2;
    shared += work[heaviest];
    for (int c = child_head[heaviest]; c >= 0; c = child_next[c])
      frontier.push_back(c);
  }
  // Everything below a pile's subtree root goes with it (parents come later in the order).
  for (int s = count - 1; s >= 0; --s) {
    if (owner[s] < 0) owner[s] = owner[up[s]];
  }
  for (int s = 0; s < count; ++s)
    parts_[owner[s]].push_back(s);
}

bool CholeskySolver::factorize_supernode(int s, int part) {
  Scratch& mine = scratch_[part];
  const auto link = [&](int d, int target) {
    link_next_[d] = mine.link_head[target];
    mine.link_head[target] = d;
  };
  const Supernode& node = supernodes_[s];
  const int* rows = rows_.data() + node.row_start;
  for (int r = 0; r < node.rows; ++r)
    mine.relative[rows[r]] = r;
  ColumnBlock block(values_.data() + node.value_start, node.rows, node.width,
                    Eigen::OuterStride<>(node.rows));
  // Left-looking: every earlier supernode with rows in this one's columns updates it. They wait
  // in the lists of both threads: a supernode of the shared rest hears from both sides.
  for (Scratch& list : scratch_) {
    int d = list.link_head[s];
    list.link_head[s] = -1;
    while (d >= 0) {
      const int next_d = link_next_[d];
      const Supernode& source = supernodes_[d];
      const int* source_rows = rows_.data() + source.row_start;
      const int p = cursor_[d];
      int q_end = p;
      while (q_end < source.rows && source_rows[q_end] < node.first + node.width)
        ++q_end;
      const int m = source.rows - p, k = q_end - p;
      const ColumnBlock L(values_.data() + source.value_start, source.rows, source.width,
                          Eigen::OuterStride<>(source.rows));
      Eigen::Map<Eigen::MatrixXd> C(mine.update.data(), m, k);
      C.noalias() = L.bottomRows(m) * L.middleRows(p, k).transpose();
      for (int jj = 0; jj < k; ++jj) {
        const int column = source_rows[p + jj] - node.first;
        for (int ii = jj; ii < m; ++ii)
          block(mine.relative[source_rows[p + ii]], column) -= C(ii, jj);
      }
      cursor_[d] = q_end;
      if (q_end < source.rows) link(d, supernode_of_[source_rows[q_end]]);
      d = next_d;
    }
  }
  // The dense diagonal block, then the rows below it: B ← B L_diag⁻ᵀ.
  using DiagonalRef = Eigen::Ref<Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
  DiagonalRef diagonal_block(block.topRows(node.width));
  const Eigen::LLT<DiagonalRef> diagonal(diagonal_block);  // in place
  if (diagonal.info() != Eigen::Success) return false;
  if (node.rows > node.width) {
    auto lower = block.topRows(node.width).triangularView<Eigen::Lower>();
    lower.adjoint().solveInPlace<Eigen::OnTheRight>(block.bottomRows(node.rows - node.width));
    cursor_[s] = node.width;
    link(s, supernode_of_[rows[node.width]]);
  }
  for (int c = 0; c < node.width; ++c)
    inverse_diagonal_[node.first + c] = 1.0 / block(c, c);
  return true;
}

}  // namespace wobble
