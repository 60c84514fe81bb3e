#include "sim/volume/tet_rotations.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

namespace wobble {

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__AVX2__)
#define WOBBLE_TET_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define WOBBLE_TET_CLONES
#endif
#define WOBBLE_TET_INLINE __attribute__((always_inline)) inline

using Lane = TetRotations::Lane;
using SingleLane = TetRotations::SingleLane;
typedef float HalfSingle __attribute__((vector_size(16)));

namespace {

// The lanes' arithmetic, for 4 doubles (Lane) or 8 floats (SingleLane): the integer lanes a
// comparison gives (`long` is 32 bits on wasm32, so 64-bit lanes are long long), and the
// exponent's place in the bits.
// A lane's number type (double or float).
template <typename L>
using NumberOf = std::decay_t<decltype(std::declval<L>()[0])>;
template <typename Number>
struct Lanes;
template <>
struct Lanes<double> {
  typedef long long Mask __attribute__((vector_size(32), aligned(32)));
  static constexpr int mantissa = 52, exponent_mask = 0x7ff, bias = 1023;
};
template <>
struct Lanes<float> {
  typedef int Mask __attribute__((vector_size(32), aligned(32)));
  static constexpr int mantissa = 23, exponent_mask = 0xff, bias = 127;
};
template <typename L>
using MaskOf = typename Lanes<NumberOf<L>>::Mask;

template <typename L>
WOBBLE_TET_INLINE L splat(double value) {
  return L{} + static_cast<NumberOf<L>>(value);
}

template <typename M>
WOBBLE_TET_INLINE bool any(M m) {
  auto bits = m[0];
  for (unsigned l = 1; l < sizeof(M) / sizeof(m[0]); ++l)
    bits |= m[l];
  return bits != 0;
}

template <typename L>
WOBBLE_TET_INLINE L absolute(L v) {
  return v < NumberOf<L>(0) ? -v : v;
}

// R (row by row) from the quaternion q = (w, x, y, z), of any length above 0: the rotation of
// q/|q|, so q need not be unit.
template <typename L>
WOBBLE_TET_INLINE void rotation_of(const L* q, L* R) {
  using N = NumberOf<L>;
  const L w = q[0], x = q[1], y = q[2], z = q[3];
  const L ww = w * w, xx = x * x, yy = y * y, zz = z * z;
  const L s = N(2) / ((ww + xx) + (yy + zz));
  const L sx = s * x, sy = s * y, sz = s * z;
  const L sxx = sx * x, syy = sy * y, szz = sz * z;
  const L sxy = sx * y, sxz = sx * z, syz = sy * z, swx = sx * w, swy = sy * w, swz = sz * w;
  R[0] = N(1) - (syy + szz);
  R[1] = sxy - swz;
  R[2] = sxz + swy;
  R[3] = sxy + swz;
  R[4] = N(1) - (sxx + szz);
  R[5] = syz - swx;
  R[6] = sxz - swy;
  R[7] = syz + swx;
  R[8] = N(1) - (sxx + syy);
}

// The power of two c with c²·v in [1, 4), from the exponent's bits (v positive and normal): a
// quaternion of squared length v times c is between 1 and 2 long, and rounds nothing.
template <typename L>
WOBBLE_TET_INLINE L reciprocal_root_power_of_two(L v) {
  using T = Lanes<NumberOf<L>>;
  const MaskOf<L> exponent = (((MaskOf<L>)v >> T::mantissa) & T::exponent_mask) - T::bias;
  return (L)((T::bias - (exponent >> 1)) << T::mantissa);
}

// Turns q (and R, its matrix) toward the rotation nearest F, `most` times or until every lane's
// last Newton update turned by θ with θ² at most `tolerance` (rad): Newton's updates converge
// quadratically, so the next would turn by about Kθ² with K well below 1 (docs/performance.md),
// less than `tolerance`; a lane that stopped keeps its q.
// Turning R by θ (R ← exp([θ])R) changes tr(RᵀF) by θ·τ − ½θᵀHθ to second order, with M = FRᵀ,
// the torque τ = Σ rᵢ × fᵢ (columns of R and F) = (M₂₁ − M₁₂, M₀₂ − M₂₀, M₁₀ − M₀₁) and
// H = tr(M)·I − sym(M): Newton's update is θ = H⁻¹τ, quadratic near the maximum, where H is
// positive definite. Elsewhere (a start far from it) Müller's τ/|tr M|, which ascends. No
// trigonometry: the turn is q + ½(0, θ)q (a turn by 2·atan(|θ|/2) about θ), and q is kept at
// any length, so neither a square root nor a division by H's determinant is needed.
template <typename L>
WOBBLE_TET_INLINE void turn_toward(const L* F, L* q, L* R, int most, double tolerance) {
  using N = NumberOf<L>;
  using Mask = MaskOf<L>;
  Mask active = splat<L>(0.0) == splat<L>(0.0);
  for (int update = 0; update < most; ++update) {
    L M[9];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        M[3 * i + j] =
            F[3 * i] * R[3 * j] + F[3 * i + 1] * R[3 * j + 1] + F[3 * i + 2] * R[3 * j + 2];
    }
    const L t0 = M[7] - M[5], t1 = M[2] - M[6], t2 = M[3] - M[1];
    const L trace = M[0] + M[4] + M[8];
    const L h00 = trace - M[0], h11 = trace - M[4], h22 = trace - M[8];
    const L h01 = N(-0.5) * (M[1] + M[3]), h02 = N(-0.5) * (M[2] + M[6]),
            h12 = N(-0.5) * (M[5] + M[7]);
    // H's cofactors; H is positive definite when its leading minors are.
    const L c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22, c02 = h01 * h12 - h02 * h11;
    const L c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12;
    const L c22 = h00 * h11 - h01 * h01;
    const L det = h00 * c00 + h01 * c01 + h02 * c02;
    const L scale = absolute(trace) + N(1e-9);
    const Mask newton = (h00 > N(0)) & (c22 > N(0)) & (det > N(1e-9) * scale * scale * scale);
    // The turn θ = u/D, u = adj(H)·τ and D = det H (Newton's), or u = τ and D = |tr M| + 1e-9
    // (Müller's); D > 0 either way.
    const L D = newton ? det : scale;
    const L u0 = newton ? c00 * t0 + c01 * t1 + c02 * t2 : t0;
    const L u1 = newton ? c01 * t0 + c11 * t1 + c12 * t2 : t1;
    const L u2 = newton ? c02 * t0 + c12 * t1 + c22 * t2 : t2;
    const L u2sum = u0 * u0 + u1 * u1 + u2 * u2;  // D²|θ|²
    // Not at the rotation already, and F finite (a NaN fails every comparison).
    const Mask moving = active & (u2sum > N(0));
    // D·(q + ½(0, θ)q): the turned q times D > 0, the same rotation.
    const L a0 = N(0.5) * u0, a1 = N(0.5) * u1, a2 = N(0.5) * u2;
    L n[4];
    n[0] = D * q[0] - (a0 * q[1] + a1 * q[2] + a2 * q[3]);
    n[1] = D * q[1] + (q[0] * a0 + (a1 * q[3] - a2 * q[2]));
    n[2] = D * q[2] + (q[0] * a1 + (a2 * q[1] - a0 * q[3]));
    n[3] = D * q[3] + (q[0] * a2 + (a0 * q[2] - a1 * q[1]));
    // Kept between 1 and 2 long by a power of two (rotation_of divides by |q|²).
    const L length2 = (n[0] * n[0] + n[1] * n[1]) + (n[2] * n[2] + n[3] * n[3]);
    const L unit = reciprocal_root_power_of_two(length2);
    for (int c = 0; c < 4; ++c)
      q[c] = moving ? n[c] * unit : q[c];
    rotation_of(q, R);
    active = moving & ((u2sum > N(tolerance) * (D * D)) | ~newton);
    if (update + 1 < most && !any(active)) break;
  }
}

// F = Ds Dm⁻¹ (Fᵢⱼ = Σ_c d_c,ᵢ (Dm⁻¹)_c,ⱼ) from the edges d[3c + i] = (x_{c+1} − x₀)ᵢ.
template <typename L>
WOBBLE_TET_INLINE void deformation_of(const L* d, const L* B, L* F) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      F[3 * i + j] = d[i] * B[j] + d[3 + i] * B[3 + j] + d[6 + i] * B[6 + j];
  }
}

// Corner c ≥ 1 of w G towardᵀ: w Σⱼ (Dm⁻¹)_c,ⱼ toward_ᵢⱼ; corner 0 the negated sum of those,
// as G's rows sum to zero. pull[3c + i]: corner c's coordinate i.
template <typename L>
WOBBLE_TET_INLINE void pull_of(const L* B, L weight, const L* toward, L* pull) {
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < 3; ++i)
      pull[3 * (c + 1) + i] =
          weight * (B[3 * c] * toward[3 * i] + B[3 * c + 1] * toward[3 * i + 1] +
                    B[3 * c + 2] * toward[3 * i + 2]);
  }
  for (int i = 0; i < 3; ++i)
    pull[i] = -(pull[3 + i] + pull[6 + i] + pull[9 + i]);
}

// The edges from corner 0 of 4 tetrahedra, d[3c + i] = (x_{c+1} − x₀)ᵢ, corner c of lane l at
// corner[4c + l].
WOBBLE_TET_INLINE void edges_of(const int* corner, const double* p, long rows, Lane* d) {
  for (int i = 0; i < 3; ++i) {
    const double* column = p + i * rows;
    const Lane x0{column[corner[0]], column[corner[1]], column[corner[2]], column[corner[3]]};
    for (int c = 0; c < 3; ++c) {
      const int* at = corner + 4 * (c + 1);
      d[3 * c + i] = Lane{column[at[0]], column[at[1]], column[at[2]], column[at[3]]} - x0;
    }
  }
}

// One pack in double (see TetRotations::update).
WOBBLE_TET_INLINE void update_pack(TetRotations::Pack& pack, const int* corner, const double* p,
                                   long rows, int most, double tolerance, bool gradient,
                                   TetRotations::Out& out, bool energy) {
  Lane d[9], F[9], R[9];
  edges_of(corner, p, rows, d);
  deformation_of(d, pack.inverse_rest, F);
  for (int e = 0; e < 9; ++e)
    R[e] = pack.R[e];
  turn_toward(F, pack.q, R, most, tolerance);
  for (int e = 0; e < 9; ++e)
    pack.R[e] = R[e];
  Lane toward[9];
  for (int e = 0; e < 9; ++e)
    toward[e] = gradient ? F[e] - R[e] : R[e];
  if (energy) {
    Lane e2 = splat<Lane>(0.0);
    for (int e = 0; e < 9; ++e)
      e2 += (F[e] - R[e]) * (F[e] - R[e]);
    out.energy = 0.5 * pack.weight * e2;
  }
  pull_of(pack.inverse_rest, pack.weight, toward, out.pull);
}

WOBBLE_TET_INLINE SingleLane to_single(Lane low, Lane high) {
  const HalfSingle a = __builtin_convertvector(low, HalfSingle);
  const HalfSingle b = __builtin_convertvector(high, HalfSingle);
  return __builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7);
}
// The local-global iterations' case, 8 tetrahedra in single precision: one update and the pull
// alone (the edges are taken in double, then rounded).
WOBBLE_TET_INLINE void update_single_pack(TetRotations::SinglePack& pack, const int* corner,
                                          const double* p, long rows,
                                          TetRotations::SingleOut& out) {
  Lane d_low[9], d_high[9];
  edges_of(corner, p, rows, d_low);
  edges_of(corner + 16, p, rows, d_high);
  SingleLane d[9], F[9];
  for (int e = 0; e < 9; ++e)
    d[e] = to_single(d_low[e], d_high[e]);
  deformation_of(d, pack.inverse_rest, F);
  turn_toward(F, pack.q, pack.R, 1, 0.0);
  pull_of(pack.inverse_rest, pack.weight, pack.R, out.pull);
}

}  // namespace

// Packs [begin, end) (see TetRotations::update); out of the class so that it can be cloned for
// AVX2.
WOBBLE_TET_CLONES void update_tet_packs(TetRotations::Pack* packs, const int* corners,
                                        const double* p, long rows, long begin, long end, int most,
                                        double tolerance, bool gradient, TetRotations::Out* out,
                                        bool energy) {
  for (long k = begin; k < end; ++k)
    update_pack(packs[k], corners + 16 * k, p, rows, most, tolerance, gradient, out[k], energy);
}

WOBBLE_TET_CLONES void update_single_packs(TetRotations::SinglePack* packs, const int* corners,
                                           const double* p, long rows, long begin, long end,
                                           TetRotations::SingleOut* out) {
  for (long k = begin; k < end; ++k)
    update_single_pack(packs[k], corners + 32 * k, p, rows, out[k]);
}

TetRotations::TetRotations(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T,
                           const Eigen::VectorXd& weight)
    : packs_((T.rows() + 3) / 4),
      single_packs_((packs_.size() + 1) / 2),
      out_(2 * single_packs_.size()),
      single_out_(single_packs_.size()),
      corners_(32 * single_packs_.size()),
      tets_(T.rows()) {
  for (std::size_t k = 0; k < out_.size(); ++k) {
    for (int l = 0; l < 4; ++l) {
      const Eigen::Index t = std::min<Eigen::Index>(4 * k + l, tets_ - 1);
      Eigen::Matrix3d Dm;
      for (int c = 0; c < 3; ++c)
        Dm.col(c) = (V.row(T(t, c + 1)) - V.row(T(t, 0))).transpose();
      const Eigen::Matrix3d inverse = Dm.inverse();
      SinglePack& single = single_packs_[k / 2];
      const int s = 4 * static_cast<int>(k % 2) + l;  // the lane in the single pack
      for (int e = 0; e < 9; ++e)
        single.inverse_rest[e][s] = static_cast<float>(inverse(e / 3, e % 3));
      single.weight[s] = static_cast<float>(weight(t));
      for (int c = 0; c < 4; ++c)
        corners_[16 * k + 4 * c + l] = T(t, c);
      if (k >= packs_.size()) continue;
      for (int e = 0; e < 9; ++e)
        packs_[k].inverse_rest[e][l] = inverse(e / 3, e % 3);
      packs_[k].weight[l] = weight(t);
    }
  }
  reset();
}

void TetRotations::prepare(bool single) {
  if (single == single_current_) return;
  // The last rotations into the other precision's packs.
  for (std::size_t k = 0; k < packs_.size(); ++k) {
    SinglePack& to = single_packs_[k / 2];
    Pack& pack = packs_[k];
    const int offset = 4 * static_cast<int>(k % 2);
    for (int l = 0; l < 4; ++l) {
      for (int c = 0; c < 4; ++c) {
        if (single)
          to.q[c][offset + l] = static_cast<float>(pack.q[c][l]);
        else
          pack.q[c][l] = to.q[c][offset + l];
      }
      for (int e = 0; e < 9; ++e) {
        if (single)
          to.R[e][offset + l] = static_cast<float>(pack.R[e][l]);
        else
          pack.R[e][l] = to.R[e][offset + l];
      }
    }
  }
  single_current_ = single;
}

void TetRotations::update(const Eigen::MatrixXd& p, long begin, long end, int most,
                          double tolerance, bool gradient, bool energy) {
  const long rows = static_cast<long>(p.rows());
  if (single_current_) {
    update_single_packs(single_packs_.data(), corners_.data(), p.data(), rows, begin, end,
                        single_out_.data());
  } else {
    update_tet_packs(packs_.data(), corners_.data(), p.data(), rows, begin, end, most, tolerance,
                     gradient, out_.data(), energy);
  }
}

double TetRotations::energy() const {
  double sum = 0.0;
  for (long t = 0; t < tets_; ++t)
    sum += out_[t / 4].energy[t % 4];
  return sum;
}

void TetRotations::reset() {
  for (Pack& pack : packs_) {
    pack.q[0] = splat<Lane>(1.0);
    for (int c = 1; c < 4; ++c)
      pack.q[c] = splat<Lane>(0.0);
    for (int e = 0; e < 9; ++e)
      pack.R[e] = splat<Lane>(e % 4 == 0 ? 1.0 : 0.0);
  }
  for (SinglePack& pack : single_packs_) {
    pack.q[0] = splat<SingleLane>(1.0);
    for (int c = 1; c < 4; ++c)
      pack.q[c] = splat<SingleLane>(0.0);
    for (int e = 0; e < 9; ++e)
      pack.R[e] = splat<SingleLane>(e % 4 == 0 ? 1.0 : 0.0);
  }
}

Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& F, Eigen::Quaterniond& q, int most,
                                 double tolerance) {
  // One lane of the packs' arithmetic, F in all four.
  Lane lanes_F[9], lanes_q[4], R[9];
  for (int e = 0; e < 9; ++e)
    lanes_F[e] = splat<Lane>(F(e / 3, e % 3));
  lanes_q[0] = splat<Lane>(q.w());
  lanes_q[1] = splat<Lane>(q.x());
  lanes_q[2] = splat<Lane>(q.y());
  lanes_q[3] = splat<Lane>(q.z());
  rotation_of(lanes_q, R);
  turn_toward(lanes_F, lanes_q, R, most, tolerance);
  q = Eigen::Quaterniond(lanes_q[0][0], lanes_q[1][0], lanes_q[2][0], lanes_q[3][0]).normalized();
  Eigen::Matrix3d rotation;
  for (int e = 0; e < 9; ++e)
    rotation(e / 3, e % 3) = R[e][0];
  return rotation;
}

}  // namespace wobble
