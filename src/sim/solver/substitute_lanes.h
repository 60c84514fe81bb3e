#ifndef WOBBLE_SIM_SUBSTITUTE_LANES_H
#define WOBBLE_SIM_SUBSTITUTE_LANES_H

namespace wobble {

// Four doubles handled as one value (GCC and Clang vector extension): x, y, z and a padding
// lane, so that one pass over L serves all three coordinates. Aligned like a double and allowed
// to alias one, so that it can be laid over an array of doubles.
typedef double Lane4 __attribute__((vector_size(32), aligned(8), may_alias));

// A supernode that the solve treats as a block: columns [first, first + width) of L share the
// same rows below the supernode, `below` of them, listed at block_rows[row_start...]. Their
// values there are row by row (width values per row) at block_values[value_start...].
struct SolveBlock {
  int first = 0;
  int width = 0;
  int below = 0;
  long row_start = 0;
  long value_start = 0;
};

// The Cholesky factor L (n by n, lower triangular) as the solve reads it, with values of type
// Value (double, or float for a large factor; the diagonal is always double).
//
// Column j's entries below the diagonal are at rows[s], values[s] for s in
// [start[j], start[j + 1]), and its diagonal entry is 1 / inverse_diagonal[j]. For a column in a
// block, those are only its entries among the block's own columns: the rows below the block are
// in the block, read once for all its columns rather than once per column.
template <typename Value>
struct SolveFactor {
  int n = 0;
  const int* start = nullptr;
  const int* rows = nullptr;
  const Value* values = nullptr;
  const double* inverse_diagonal = nullptr;
  int block_count = 0;
  const SolveBlock* blocks = nullptr;  // in increasing order of first column
  const int* block_rows = nullptr;
  const Value* block_values = nullptr;
};

// Solve L Lᵀ u = w in place, for the four lanes of each row of w side by side: forward
// substitution L z = w, then back substitution Lᵀ u = z.
//
// Where the compiler can, it is built twice, for plain x86-64 and for x86-64-v3 (AVX2, whole
// 256-bit lanes), and the processor picks at load time. The two give the same results, bit for
// bit: the file is compiled without contracting a·b + c into FMA.
void substitute_lanes(const SolveFactor<double>& factor, Lane4* w);
// The same with L's values rounded to float; the arithmetic is double.
void substitute_lanes(const SolveFactor<float>& factor, Lane4* w);

}  // namespace wobble

#endif
