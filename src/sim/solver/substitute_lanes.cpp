#include "substitute_lanes.h"

namespace wobble {

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__AVX2__)
#define WOBBLE_LANE_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define WOBBLE_LANE_CLONES
#endif

namespace {

#define WOBBLE_INLINE __attribute__((always_inline)) inline

// Forward substitution along column j: its value is final once the columns left of it are done;
// it then updates the rows below. The updates of one column go to distinct rows, so they do not
// wait on each other. (Lane4 may alias anything, so the bounds are read before w is written.)
template <typename Value>
WOBBLE_INLINE void forward_column(const SolveFactor<Value>& f, int j, Lane4* w) {
  const Lane4 z = w[j] * f.inverse_diagonal[j];
  w[j] = z;
  const int end = f.start[j + 1];
  for (int s = f.start[j]; s < end; ++s)
    w[f.rows[s]] -= static_cast<double>(f.values[s]) * z;
}

// Back substitution of row j of Lᵀ, which is column j of L: a dot product down the column. Two
// running sums take turns, so that each subtraction does not wait for the one before.
template <typename Value>
WOBBLE_INLINE void backward_column(const SolveFactor<Value>& f, int j, Lane4* w) {
  Lane4 even = w[j];
  Lane4 odd = {0.0, 0.0, 0.0, 0.0};
  int s = f.start[j];
  const int end = f.start[j + 1];
  for (; s + 1 < end; s += 2) {
    even -= static_cast<double>(f.values[s]) * w[f.rows[s]];
    odd -= static_cast<double>(f.values[s + 1]) * w[f.rows[s + 1]];
  }
  if (s < end) even -= static_cast<double>(f.values[s]) * w[f.rows[s]];
  w[j] = (even + odd) * f.inverse_diagonal[j];
}

// The block's rows below it, forward: each row takes the dot product of its values with the
// block's finished columns z, read from w[first...] (a few kB, in L1).
template <typename Value>
WOBBLE_INLINE void forward_block(const SolveFactor<Value>& f, const SolveBlock& b, Lane4* w) {
  const Lane4* z = w + b.first;
  const int* rows = f.block_rows + b.row_start;
  const Value* v = f.block_values + b.value_start;
  const int width = b.width;
  for (int i = 0; i < b.below; ++i, v += width) {
    Lane4 even = {0.0, 0.0, 0.0, 0.0};
    Lane4 odd = {0.0, 0.0, 0.0, 0.0};
    int c = 0;
    for (; c + 1 < width; c += 2) {
      even += static_cast<double>(v[c]) * z[c];
      odd += static_cast<double>(v[c + 1]) * z[c + 1];
    }
    if (c < width) even += static_cast<double>(v[c]) * z[c];
    w[rows[i]] -= even + odd;
  }
}

// The block's rows below it, backward: `Chunk` columns at a time, each with its own running
// sum, over the rows below; each row's value of w is loaded once per chunk.
template <int Chunk, typename Value>
WOBBLE_INLINE void backward_block_chunk(const SolveFactor<Value>& f, const SolveBlock& b, int c0,
                                        Lane4* w) {
  Lane4 sum[Chunk];
  for (int c = 0; c < Chunk; ++c)
    sum[c] = Lane4{0.0, 0.0, 0.0, 0.0};
  const int* rows = f.block_rows + b.row_start;
  const Value* v = f.block_values + b.value_start + c0;
  for (int i = 0; i < b.below; ++i, v += b.width) {
    const Lane4 x = w[rows[i]];
    for (int c = 0; c < Chunk; ++c)
      sum[c] += static_cast<double>(v[c]) * x;
  }
  for (int c = 0; c < Chunk; ++c)
    w[b.first + c0 + c] -= sum[c];
}

template <typename Value>
WOBBLE_INLINE void backward_block(const SolveFactor<Value>& f, const SolveBlock& b, Lane4* w) {
  int c0 = 0;
  for (; c0 + 8 <= b.width; c0 += 8)
    backward_block_chunk<8>(f, b, c0, w);
  for (; c0 < b.width; ++c0)
    backward_block_chunk<1>(f, b, c0, w);
}

// Inlined into each public variant, so that every build of those has its own copy.
template <typename Value>
WOBBLE_INLINE void substitute(const SolveFactor<Value>& f, Lane4* w) {
  int next = 0;  // the next block, forward
  for (int j = 0; j < f.n; ++j) {
    if (next < f.block_count && f.blocks[next].first == j) {
      const SolveBlock& b = f.blocks[next++];
      for (int c = 0; c < b.width; ++c)
        forward_column(f, j + c, w);
      forward_block(f, b, w);
      j += b.width - 1;
    } else {
      forward_column(f, j, w);
    }
  }
  int previous = f.block_count - 1;  // the next block, backward
  for (int j = f.n - 1; j >= 0; --j) {
    if (previous >= 0 && f.blocks[previous].first + f.blocks[previous].width - 1 == j) {
      const SolveBlock& b = f.blocks[previous--];
      backward_block(f, b, w);
      for (int c = b.width - 1; c >= 0; --c)
        backward_column(f, b.first + c, w);
      j = b.first;
    } else {
      backward_column(f, j, w);
    }
  }
}

}  // namespace

WOBBLE_LANE_CLONES void substitute_lanes(const SolveFactor<double>& factor, Lane4* w) {
  substitute(factor, w);
}

WOBBLE_LANE_CLONES void substitute_lanes(const SolveFactor<float>& factor, Lane4* w) {
  substitute(factor, w);
}

}  // namespace wobble
