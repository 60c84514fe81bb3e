#include "cholesky_solver.h"

#include <Eigen/Cholesky>
#include <Eigen/OrderingMethods>
#include <algorithm>
#include <cstdio>

#include "sim/input_error.h"
#include "sim/input_limits.h"

namespace wobble {

namespace {

// A factorization's work for a message: "2.4e11 operations".
std::string describe_work(double work) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g operations", work);
  return text;
}

using ColumnBlock = Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>>;

// Column counts of L (entries below the diagonal), from the rows of Q's lower triangle (row i's
// columns left of the diagonal at left[left_start[i]...]) and the elimination tree. Row i of L
// is the subtree of the tree reached from row i's entries of Q by walking up towards i: each
// column passed on the way has an entry in row i.
std::vector<int> column_counts(const std::vector<int>& left_start, const std::vector<int>& left,
                               const std::vector<int>& parent) {
  const int n = static_cast<int>(parent.size());
  std::vector<int> mark(n, -1), count(n, 0);
  for (int i = 0; i < n; ++i) {
    mark[i] = i;
    for (int s = left_start[i]; s < left_start[i + 1]; ++s) {
      for (int j = left[s]; mark[j] != i; j = parent[j]) {
        mark[j] = i;
        ++count[j];
      }
    }
  }
  return count;
}

// The pattern of Q's lower triangle once permuted (entry (i, j) of Q at (permutation[i],
// permutation[j])), as flat lists (like CSR): by rows, each row's columns left of the diagonal;
// or by columns, each column's rows below it. In no particular order within a list.
void permuted_lower_triangle(const Eigen::SparseMatrix<double>& Q,
                             const std::vector<int>& permutation, bool by_rows,
                             std::vector<int>& start, std::vector<int>& entries) {
  const int n = static_cast<int>(Q.rows());
  const auto visit = [&](auto&& entry) {
    for (int j = 0; j < n; ++j) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(Q, j); it; ++it) {
        const int a = permutation[it.row()], b = permutation[j];
        if (a > b) by_rows ? entry(a, b) : entry(b, a);
      }
    }
  };
  start.assign(n + 1, 0);
  visit([&](int list, int) { ++start[list + 1]; });
  for (int i = 0; i < n; ++i)
    start[i + 1] += start[i];
  entries.resize(start[n]);
  std::vector<int> next(n);
  std::copy_n(start.begin(), n, next.begin());
  visit([&](int list, int value) { entries[next[list]++] = value; });
}

}  // namespace

void CholeskySolver::analyze(const Eigen::SparseMatrix<double>& Q) {
  const int n = static_cast<int>(Q.rows());
  // The fill-reducing ordering: Eigen's AMD, as SimplicialLLT would use it, without the
  // symbolic factorization SimplicialLLT::analyzePattern would do after it. AMD gives the
  // elimination order; row i of Q becomes row permutation_[i] of L.
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  Eigen::AMDOrdering<int>()(Q, order);
  permutation_.resize(n);
  for (int k = 0; k < n; ++k)
    permutation_[order.indices()(k)] = k;

  // The permuted lower triangle's pattern by rows: for each row, the columns left of the
  // diagonal.
  std::vector<int> left_start, left;
  permuted_lower_triangle(Q, permutation_, true, left_start, left);
  // Elimination tree (Liu's algorithm with path compression).
  std::vector<int> parent(n, -1), ancestor(n, -1);
  for (int i = 0; i < n; ++i) {
    for (int s = left_start[i]; s < left_start[i + 1]; ++s) {
      int r = left[s];
      while (ancestor[r] != -1 && ancestor[r] != i) {
        const int next = ancestor[r];
        ancestor[r] = i;
        r = next;
      }
      if (ancestor[r] == -1) {
        ancestor[r] = i;
        parent[r] = i;
      }
    }
  }
  const std::vector<int> count = column_counts(left_start, left, parent);
  // Supernodes: column j + 1 joins j's when it is j's parent and its pattern is j's minus itself
  // (it holds that pattern, so equal counts mean equal patterns).
  supernodes_.clear();
  supernode_of_.assign(n, 0);
  for (int j = 0; j < n; ++j) {
    const bool joins = j > 0 && parent[j - 1] == j && count[j - 1] == count[j] + 1;
    if (!joins) {
      Supernode s;
      s.first = j;
      supernodes_.push_back(s);
    }
    ++supernodes_.back().width;
    supernode_of_[j] = static_cast<int>(supernodes_.size()) - 1;
  }
  // Each supernode's rows below its columns, without listing any column's whole pattern: a
  // column's pattern is its entries of Q below the diagonal and its children's patterns, less
  // the rows above it. So a supernode's rows are those of its columns in Q and of its child
  // supernodes, past its last column; children come first in the order, so theirs are ready.
  std::vector<int> below_start, below;  // Q's lower triangle by columns
  permuted_lower_triangle(Q, permutation_, false, below_start, below);
  const int supernode_count = static_cast<int>(supernodes_.size());
  std::vector<int> child_head(supernode_count, -1), child_next(supernode_count, -1);
  for (int t = supernode_count - 1; t >= 0; --t) {
    const int up = parent[supernodes_[t].first + supernodes_[t].width - 1];
    if (up < 0) continue;
    child_next[t] = child_head[supernode_of_[up]];
    child_head[supernode_of_[up]] = t;
  }
  std::vector<int> mark(n, -1), gathered;
  rows_.clear();
  long values = 0;
  factor_nonzeros_ = 0;
  factorization_work_ = 0.0;
  for (int index = 0; index < supernode_count; ++index) {
    Supernode& s = supernodes_[index];
    const int last = s.first + s.width - 1;
    gathered.clear();
    const auto gather = [&](int row) {
      if (row > last && mark[row] != index) {
        mark[row] = index;
        gathered.push_back(row);
      }
    };
    for (int c = s.first; c <= last; ++c) {
      for (int k = below_start[c]; k < below_start[c + 1]; ++k)
        gather(below[k]);
    }
    for (int t = child_head[index]; t >= 0; t = child_next[t]) {
      const Supernode& child = supernodes_[t];
      for (long k = child.row_start + child.width; k < child.row_start + child.rows; ++k)
        gather(rows_[k]);
    }
    std::sort(gathered.begin(), gathered.end());
    s.row_start = static_cast<long>(rows_.size());
    s.value_start = values;
    for (int c = 0; c < s.width; ++c)
      rows_.push_back(s.first + c);
    rows_.insert(rows_.end(), gathered.begin(), gathered.end());
    s.rows = s.width + static_cast<int>(gathered.size());
    values += static_cast<long>(s.rows) * s.width;
    factor_nonzeros_ += static_cast<long>(s.rows) * s.width - s.width * (s.width - 1) / 2;
    factorization_work_ += static_cast<double>(s.width) * s.rows * s.rows;
  }
  // Before the factor's memory is taken: springs that join far-apart vertices fill L far beyond
  // what their count suggests (a 1.3 MB OBJ of random triangles: 52 million nonzeros, 30 s).
  if (factor_nonzeros_ > max_factor_nonzeros || factorization_work_ > max_factorization_work) {
    throw InputError("the springs join the vertices so that the Cholesky factor of Q would hold " +
                     with_thousands_separators(factor_nonzeros_) + " nonzeros and take " +
                     describe_work(factorization_work_) +
                     " to factorize, above Wobble's limits of " +
                     with_thousands_separators(max_factor_nonzeros) + " and " +
                     describe_work(max_factorization_work) +
                     " (springs between nearby vertices keep the factor small)");
  }
  values_.assign(values, 0.0);
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
  work_.assign(4 * static_cast<std::size_t>(n), 0.0);
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
  Lane4* w = reinterpret_cast<Lane4*>(work_.data());
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

}  // namespace wobble
