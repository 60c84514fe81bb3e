#include "substitute_lanes.h"

namespace wobble {

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__AVX2__)
#define WOBBLE_LANE_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define WOBBLE_LANE_CLONES
#endif

namespace {

// Inlined into each public variant, so that every build of those has its own copy.
template <typename Value>
__attribute__((always_inline)) inline void substitute(int n, const int* start, const int* rows,
                                                      const Value* values,
                                                      const double* inverse_diagonal, Lane4* w) {
  // Forward: column j's value is final once the columns left of it are done; it then updates
  // the rows below. The updates of one column go to distinct rows, so they do not wait on each
  // other.
  // (Lane4 may alias anything, so the loop bounds are read once, before w is written.)
  for (int j = 0; j < n; ++j) {
    const Lane4 z = w[j] * inverse_diagonal[j];
    w[j] = z;
    const int end = start[j + 1];
    for (int s = start[j]; s < end; ++s)
      w[rows[s]] -= static_cast<double>(values[s]) * z;
  }
  // Backward: row j of Lᵀ is column j of L, so each entry is a dot product down a column. Two
  // running sums take turns, so that each subtraction does not wait for the one before.
  for (int j = n - 1; j >= 0; --j) {
    Lane4 even = w[j];
    Lane4 odd = {0.0, 0.0, 0.0, 0.0};
    int s = start[j];
    const int end = start[j + 1];
    for (; s + 1 < end; s += 2) {
      even -= static_cast<double>(values[s]) * w[rows[s]];
      odd -= static_cast<double>(values[s + 1]) * w[rows[s + 1]];
    }
    if (s < end) even -= static_cast<double>(values[s]) * w[rows[s]];
    w[j] = (even + odd) * inverse_diagonal[j];
  }
}

}  // namespace

WOBBLE_LANE_CLONES void substitute_lanes(int n, const int* start, const int* rows,
                                         const double* values, const double* inverse_diagonal,
                                         Lane4* w) {
  substitute(n, start, rows, values, inverse_diagonal, w);
}

WOBBLE_LANE_CLONES void substitute_lanes(int n, const int* start, const int* rows,
                                         const float* values, const double* inverse_diagonal,
                                         Lane4* w) {
  substitute(n, start, rows, values, inverse_diagonal, w);
}

}  // namespace wobble
