#ifndef WOBBLE_SIM_SUBSTITUTE_LANES_H
#define WOBBLE_SIM_SUBSTITUTE_LANES_H

namespace wobble {

// Four doubles handled as one value (GCC and Clang vector extension): x, y, z and a padding
// lane, so that one pass over L serves all three coordinates. Aligned like a double and allowed
// to alias one, so that it can be laid over an array of doubles.
typedef double Lane4 __attribute__((vector_size(32), aligned(8), may_alias));

// Solve L Lᵀ u = w in place, for the four lanes of each row of w side by side: forward
// substitution L z = w, then back substitution Lᵀ u = z. L is n by n, lower triangular, held by
// columns: column j's entries below the diagonal are at rows[s], values[s] for s in
// [start[j], start[j + 1]), and its diagonal entry is 1 / inverse_diagonal[j].
//
// Where the compiler can, it is built twice, for plain x86-64 and for x86-64-v3 (AVX2, whole
// 256-bit lanes), and the processor picks at load time. The two give the same results, bit for
// bit: the file is compiled without contracting a·b + c into FMA.
void substitute_lanes(int n, const int* start, const int* rows, const double* values,
                      const double* inverse_diagonal, Lane4* w);
// The same with L's values below the diagonal rounded to float; the arithmetic is double.
void substitute_lanes(int n, const int* start, const int* rows, const float* values,
                      const double* inverse_diagonal, Lane4* w);

}  // namespace wobble

#endif
