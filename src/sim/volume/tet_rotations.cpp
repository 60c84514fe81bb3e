#include "sim/volume/tet_rotations.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace wobble {

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__AVX2__)
#define WOBBLE_TET_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define WOBBLE_TET_CLONES
#endif
#define WOBBLE_TET_INLINE __attribute__((always_inline)) inline

using Lane = TetRotations::Lane;
// Lanes of 64-bit integers, as a comparison of Lanes gives (`long` is 32 bits on wasm32).
typedef long long Mask __attribute__((vector_size(32), aligned(32)));

namespace {

WOBBLE_TET_INLINE Lane splat(double value) {
  return Lane{value, value, value, value};
}

WOBBLE_TET_INLINE bool any(Mask m) {
  return (m[0] | m[1] | m[2] | m[3]) != 0;
}

WOBBLE_TET_INLINE Lane absolute(Lane v) {
  return v < 0.0 ? -v : v;
}

// R (row by row) from the unit quaternion q = (w, x, y, z).
WOBBLE_TET_INLINE void rotation_of(const Lane* q, Lane* R) {
  const Lane w = q[0], x = q[1], y = q[2], z = q[3];
  const Lane xx = x * x, yy = y * y, zz = z * z;
  const Lane xy = x * y, xz = x * z, yz = y * z, wx = w * x, wy = w * y, wz = w * z;
  R[0] = 1.0 - 2.0 * (yy + zz);
  R[1] = 2.0 * (xy - wz);
  R[2] = 2.0 * (xz + wy);
  R[3] = 2.0 * (xy + wz);
  R[4] = 1.0 - 2.0 * (xx + zz);
  R[5] = 2.0 * (yz - wx);
  R[6] = 2.0 * (xz - wy);
  R[7] = 2.0 * (yz + wx);
  R[8] = 1.0 - 2.0 * (xx + yy);
}

// Turns q (and R, its matrix) toward the rotation nearest F, `most` times or until every lane's
// last Newton update turned by at most `tolerance`; a lane that stopped keeps its q.
// Turning R by θ (R ← exp([θ])R) changes tr(RᵀF) by θ·τ − ½θᵀHθ to second order, with M = FRᵀ,
// the torque τ = Σ rᵢ × fᵢ (columns of R and F) = (M₂₁ − M₁₂, M₀₂ − M₂₀, M₁₀ − M₀₁) and
// H = tr(M)·I − sym(M): Newton's update is θ = H⁻¹τ, quadratic near the maximum, where H is
// positive definite. Elsewhere (a start far from it) Müller's τ/|tr M|, which ascends. No
// trigonometry: the turn is q + ½(0, θ)q, normalized (a turn by 2·atan(|θ|/2) about θ).
WOBBLE_TET_INLINE void turn_toward(const Lane* F, Lane* q, Lane* R, int most, double tolerance) {
  Mask active = splat(0.0) == splat(0.0);
  for (int update = 0; update < most; ++update) {
    Lane M[9];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        M[3 * i + j] =
            F[3 * i] * R[3 * j] + F[3 * i + 1] * R[3 * j + 1] + F[3 * i + 2] * R[3 * j + 2];
    }
    const Lane t0 = M[7] - M[5], t1 = M[2] - M[6], t2 = M[3] - M[1];
    const Lane trace = M[0] + M[4] + M[8];
    const Lane h00 = trace - M[0], h11 = trace - M[4], h22 = trace - M[8];
    const Lane h01 = -0.5 * (M[1] + M[3]), h02 = -0.5 * (M[2] + M[6]), h12 = -0.5 * (M[5] + M[7]);
    // H's cofactors; H is positive definite when its leading minors are.
    const Lane c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22,
               c02 = h01 * h12 - h02 * h11;
    const Lane c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12;
    const Lane c22 = h00 * h11 - h01 * h01;
    const Lane det = h00 * c00 + h01 * c01 + h02 * c02;
    const Lane scale = absolute(trace) + 1e-9;
    const Mask newton = (h00 > 0.0) & (c22 > 0.0) & (det > 1e-9 * scale * scale * scale);
    const Lane inverse = 1.0 / (newton ? det : scale);
    const Lane theta0 = inverse * (newton ? c00 * t0 + c01 * t1 + c02 * t2 : t0);
    const Lane theta1 = inverse * (newton ? c01 * t0 + c11 * t1 + c12 * t2 : t1);
    const Lane theta2 = inverse * (newton ? c02 * t0 + c12 * t1 + c22 * t2 : t2);
    const Lane angle2 = theta0 * theta0 + theta1 * theta1 + theta2 * theta2;
    // Not at the rotation already, and F finite (a NaN fails every comparison).
    const Mask moving = active & (angle2 > 0.0);
    const Lane a0 = 0.5 * theta0, a1 = 0.5 * theta1, a2 = 0.5 * theta2;
    Lane n[4];
    n[0] = q[0] - (a0 * q[1] + a1 * q[2] + a2 * q[3]);
    n[1] = q[1] + (q[0] * a0 + (a1 * q[3] - a2 * q[2]));
    n[2] = q[2] + (q[0] * a1 + (a2 * q[1] - a0 * q[3]));
    n[3] = q[3] + (q[0] * a2 + (a0 * q[2] - a1 * q[1]));
    const Lane length2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2] + n[3] * n[3];
    Lane length;
    for (int l = 0; l < 4; ++l)
      length[l] = std::sqrt(length2[l]);
    const Lane unit = 1.0 / length;
    for (int c = 0; c < 4; ++c)
      q[c] = moving ? n[c] * unit : q[c];
    rotation_of(q, R);
    active = moving & ((angle2 > tolerance * tolerance) | ~newton);
    if (update + 1 < most && !any(active)) break;
  }
}

// One pack (see TetRotations::update). `pull_only`: one update and the pull alone, the
// local-global iterations' case, compiled apart so that F is dropped once M is formed.
template <bool pull_only>
WOBBLE_TET_INLINE void update_pack(TetRotations::Pack& pack, const int* corner, const double* p,
                                   long rows, int most, double tolerance, bool gradient,
                                   TetRotations::Out& out, bool energy) {
  // The edges from corner 0, d[3c + i] = (x_{c+1} − x₀)ᵢ.
  Lane d[9];
  for (int i = 0; i < 3; ++i) {
    const double* column = p + i * rows;
    const Lane x0{column[corner[0]], column[corner[1]], column[corner[2]], column[corner[3]]};
    for (int c = 0; c < 3; ++c) {
      const int* at = corner + 4 * (c + 1);
      d[3 * c + i] = Lane{column[at[0]], column[at[1]], column[at[2]], column[at[3]]} - x0;
    }
  }
  // F = Ds Dm⁻¹: Fᵢⱼ = Σ_c d_c,ᵢ (Dm⁻¹)_c,ⱼ.
  const Lane* B = pack.inverse_rest;
  Lane F[9];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      F[3 * i + j] = d[i] * B[j] + d[3 + i] * B[3 + j] + d[6 + i] * B[6 + j];
  }
  Lane R[9];
  for (int e = 0; e < 9; ++e)
    R[e] = pack.R[e];
  turn_toward(F, pack.q, R, pull_only ? 1 : most, tolerance);
  for (int e = 0; e < 9; ++e)
    pack.R[e] = R[e];
  Lane toward[9];
  for (int e = 0; e < 9; ++e)
    toward[e] = !pull_only && gradient ? F[e] - R[e] : R[e];
  if (!pull_only && energy) {
    Lane e2 = splat(0.0);
    for (int e = 0; e < 9; ++e)
      e2 += (F[e] - R[e]) * (F[e] - R[e]);
    out.energy = 0.5 * pack.weight * e2;
  }
  // Corner c ≥ 1 of w G towardᵀ: w Σⱼ (Dm⁻¹)_c,ⱼ toward_ᵢⱼ; corner 0 the negated sum of those,
  // as G's rows sum to zero.
  Lane* pull = out.pull;
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < 3; ++i)
      pull[3 * (c + 1) + i] =
          pack.weight * (B[3 * c] * toward[3 * i] + B[3 * c + 1] * toward[3 * i + 1] +
                         B[3 * c + 2] * toward[3 * i + 2]);
  }
  for (int i = 0; i < 3; ++i)
    pull[i] = -(pull[3 + i] + pull[6 + i] + pull[9 + i]);
}

}  // namespace

// Packs [begin, end) (see TetRotations::update); out of the class so that it can be cloned for
// AVX2.
WOBBLE_TET_CLONES void update_tet_packs(TetRotations::Pack* packs, const int* corners,
                                        const double* p, long rows, long begin, long end, int most,
                                        double tolerance, bool gradient, TetRotations::Out* out,
                                        bool energy) {
  if (most == 1 && !gradient && !energy) {
    for (long k = begin; k < end; ++k)
      update_pack<true>(packs[k], corners + 16 * k, p, rows, 1, tolerance, false, out[k], false);
  } else {
    for (long k = begin; k < end; ++k)
      update_pack<false>(packs[k], corners + 16 * k, p, rows, most, tolerance, gradient, out[k],
                         energy);
  }
}

TetRotations::TetRotations(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T,
                           const Eigen::VectorXd& weight)
    : packs_((T.rows() + 3) / 4),
      out_(packs_.size()),
      corners_(16 * packs_.size()),
      tets_(T.rows()) {
  for (long k = 0; k < packs(); ++k) {
    for (int l = 0; l < 4; ++l) {
      const Eigen::Index t = std::min<Eigen::Index>(4 * k + l, tets_ - 1);
      Eigen::Matrix3d Dm;
      for (int c = 0; c < 3; ++c)
        Dm.col(c) = (V.row(T(t, c + 1)) - V.row(T(t, 0))).transpose();
      const Eigen::Matrix3d inverse = Dm.inverse();
      for (int e = 0; e < 9; ++e)
        packs_[k].inverse_rest[e][l] = inverse(e / 3, e % 3);
      packs_[k].weight[l] = weight(t);
      for (int c = 0; c < 4; ++c)
        corners_[16 * k + 4 * c + l] = T(t, c);
    }
  }
  reset();
}

void TetRotations::update(const Eigen::MatrixXd& p, long begin, long end, int most,
                          double tolerance, bool gradient, bool energy) {
  update_tet_packs(packs_.data(), corners_.data(), p.data(), static_cast<long>(p.rows()), begin,
                   end, most, tolerance, gradient, out_.data(), energy);
}

double TetRotations::energy() const {
  double sum = 0.0;
  for (long t = 0; t < tets_; ++t)
    sum += out_[t / 4].energy[t % 4];
  return sum;
}

void TetRotations::reset() {
  for (Pack& pack : packs_) {
    pack.q[0] = splat(1.0);
    for (int c = 1; c < 4; ++c)
      pack.q[c] = splat(0.0);
    for (int e = 0; e < 9; ++e)
      pack.R[e] = splat(e % 4 == 0 ? 1.0 : 0.0);
  }
}

Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& F, Eigen::Quaterniond& q, int most,
                                 double tolerance) {
  // One lane of the packs' arithmetic, F in all four.
  Lane lanes_F[9], lanes_q[4], R[9];
  for (int e = 0; e < 9; ++e)
    lanes_F[e] = splat(F(e / 3, e % 3));
  lanes_q[0] = splat(q.w());
  lanes_q[1] = splat(q.x());
  lanes_q[2] = splat(q.y());
  lanes_q[3] = splat(q.z());
  rotation_of(lanes_q, R);
  turn_toward(lanes_F, lanes_q, R, most, tolerance);
  q = Eigen::Quaterniond(lanes_q[0][0], lanes_q[1][0], lanes_q[2][0], lanes_q[3][0]);
  Eigen::Matrix3d rotation;
  for (int e = 0; e < 9; ++e)
    rotation(e / 3, e % 3) = R[e][0];
  return rotation;
}

}  // namespace wobble
