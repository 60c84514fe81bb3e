#include <Eigen/OrderingMethods>
#include <algorithm>
#include <cstdio>

#include "cholesky_solver.h"
#include "sim/input_error.h"
#include "sim/input_limits.h"

// The symbolic analysis: ordering, elimination tree, supernodes and the pattern of L.
namespace wobble {

namespace {

// A factorization's work for a message: "2.4e11 operations".
std::string describe_work(double work) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g operations", work);
  return text;
}

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
  plan_solve(n);
  plan_factorization(Q, parent);
}

}  // namespace wobble
