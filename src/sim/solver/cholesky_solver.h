#ifndef WOBBLE_SIM_CHOLESKY_SOLVER_H
#define WOBBLE_SIM_CHOLESKY_SOLVER_H

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "sim/parallel/worker_pool.h"
#include "substitute_lanes.h"

namespace wobble {

// Supernodal sparse Cholesky factorization Q = Pᵀ L Lᵀ P (AMD ordering) with a solve for the
// three coordinates of a #V by 3 right-hand side in one pass over L.
//
// Columns of L with the same pattern below the diagonal are grouped into supernodes and stored
// as dense blocks, so the factorization works with dense products (left-looking; a large factor
// on two threads). The solve uses a copy of L laid out for it (by columns, and the rows below
// each supernode at least block_solve_min_width wide row by row), and treats x, y and z side by
// side: Eigen's solve on a #V by 3 right-hand side makes one pass over L per column; this one
// makes one pass in all.
//
// analyze once per sparsity pattern, factorize after every change of values, solve as often as
// needed: solve allocates nothing. Their sources: cholesky_analysis.cpp, cholesky_factorization.cpp
// and cholesky_solve.cpp.
class CholeskySolver {
 public:
  // Ordering, elimination tree, the pattern of L and its supernodes, for the pattern of the
  // symmetric positive definite Q (both triangles stored; only the lower one is read). Throws
  // InputError, before taking the factor's memory, when L would hold more than
  // max_factor_nonzeros nonzeros or take more than max_factorization_work to factorize.
  void analyze(const Eigen::SparseMatrix<double>& Q);
  // Measured on the 2-core development machine: the largest regular meshes the file limits admit
  // stay below both (a 44³ block of tetrahedra: 65 million nonzeros, work 2.4e11, 12 s and
  // 1.4 GB to analyze and factorize; a 660×660 OBJ grid: 27 million, 1.8e10, 1.6 s), while a
  // 1.3 MB OBJ of 40,000 random triangles (52 million, 1.0e12: 27 s and 2.9 GB) is refused.
  static constexpr long max_factor_nonzeros = 70'000'000;
  static constexpr double max_factorization_work = 3e11;
  // Numeric factorization of Q, which must have the analyzed pattern. False if Q is not
  // positive definite.
  bool factorize(const Eigen::SparseMatrix<double>& Q);
  // The threads factorize may use (by default the shared pool).
  void set_pool(WorkerPool& pool) { pool_ = &pool; }
  // x = Q⁻¹ b, b and x #V by 3. x is resized only if its shape differs.
  void solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& x);

  // Nonzeros of L, the diagonal included: exactly those of Eigen's L with the same ordering.
  long factor_nonzeros() const { return factor_nonzeros_; }
  // The work of one numeric factorization, estimated as the sum over supernodes of their width
  // times their rows squared (about twice the multiply-adds).
  double factorization_work() const { return factorization_work_; }

  // A factor with more nonzeros than this no longer fits in cache, and the solve is bound by
  // reading it from memory: it then reads L's values rounded to float (the diagonal, and all
  // arithmetic, stay double), a third less to read. A solve then agrees with the double one to
  // about 1e-7 relative instead of 1e-15. Takes effect at the next analyze. The default,
  // 2,000,000 (24 MB of values and rows in double), keeps double up to the 128×128 cloth.
  void set_single_precision_above(long nonzeros) { single_precision_above_ = nonzeros; }
  bool solves_in_single_precision() const { return single_; }
  static constexpr long default_single_precision_above = 2'000'000;
  // Supernodes at least this wide are solved as blocks. Measured (global step, 10 iterations,
  // ms): curtain 7.2 with no blocks, 4.5 from width 3, 4.9 from width 8; 128×128 cloth 22, 13
  // and 16; 256×256 158, 98 and 93 (within the noise of each other).
  static constexpr int block_solve_min_width = 3;
  // A factor with more nonzeros is factorized in two parts side by side on the pool's threads,
  // each a set of subtrees of the elimination tree, then the rest on the caller. The result does
  // not depend on which thread takes which part.
  static constexpr long parallel_factorization_above = 200'000;

 private:
  // The parts of analyze() after the pattern of L (cholesky_analysis.cpp): the layout of L for
  // the solve and its scratch (cholesky_solve.cpp), and where Q's values go in the blocks, the
  // threads' parts and their scratch (cholesky_factorization.cpp). `parent`: the elimination tree.
  void plan_solve(int n);
  void plan_factorization(const Eigen::SparseMatrix<double>& Q, const std::vector<int>& parent);
  template <typename Value>
  void copy_for_solve(Value* columns, Value* blocks) const;
  // Fills parts_ from the elimination tree (parent of each column).
  void split_for_threads(const std::vector<int>& parent);
  // Factorizes supernode s with part `part`'s scratch. False if not positive definite.
  bool factorize_supernode(int s, int part);
  template <typename Value>
  SolveFactor<Value> solve_factor(const Value* columns, const Value* blocks) const;

  struct Supernode {
    int first = 0;         // first column
    int width = 0;         // number of columns
    int rows = 0;          // rows of its block: its own columns, then the rows below
    long row_start = 0;    // into rows_
    long value_start = 0;  // into values_: rows × width, column-major
  };

  std::vector<int> permutation_;  // row i of Q is row permutation_[i] of L
  std::vector<Supernode> supernodes_;
  std::vector<int> rows_;          // every supernode's rows, in order
  std::vector<int> supernode_of_;  // the supernode holding each column
  std::vector<long> value_slot_;   // for each stored value of Q: where it goes, or -1
  std::vector<double> values_;     // the blocks of L
  // L as the solve reads it (see SolveFactor): by columns, and the rows below each supernode at
  // least block_solve_min_width wide as a row-major block. Narrow supernodes are faster to solve
  // column by column; wide ones as blocks, which read their row numbers and update each row of
  // the right-hand side once for all their columns.
  std::vector<int> column_start_, column_rows_;
  std::vector<double> column_values_, inverse_diagonal_;
  std::vector<SolveBlock> solve_blocks_;
  std::vector<int> block_rows_;
  std::vector<double> block_values_;
  // Instead of column_values_ and block_values_ for a large factor.
  std::vector<float> column_values_single_, block_values_single_;
  long factor_nonzeros_ = 0;
  double factorization_work_ = 0.0;
  long single_precision_above_ = default_single_precision_above;
  bool single_ = false;

  // Factorization: the supernodes each of two threads takes (subtrees, closed under
  // descendants), then those left for one thread afterwards, all in increasing order.
  std::vector<int> parts_[3];
  // Per part: relative row positions, the heads of the update lists, the dense update.
  struct Scratch {
    std::vector<int> relative, link_head;
    std::vector<double> update;
  };
  Scratch scratch_[2];
  std::vector<int> link_next_, cursor_;  // by supernode: next in its list, rows already used
  std::vector<double> work_;  // solve scratch: #V by 4 (x, y, z, padding), seen as Lane4s
  WorkerPool* pool_ = &WorkerPool::shared();
};

}  // namespace wobble

#endif
