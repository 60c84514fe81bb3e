#include "sim/volume/volume_term.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "sim/settings/setting_registry.h"
#include "sim/terms/term_registry.h"

namespace wobble {

namespace {

// The setting that turns the term on: off (0) unless a scene or the user sets it.
const SettingRegistration volume_stiffness{
    {"volume-stiffness",
     "volume k",
     "stiffness of the volume term that keeps each tetrahedron of a solid near a rotation of its "
     "rest shape (0: off)",
     {0.0, 1e7, "Pa"},
     0.0,
     SettingCost::refactorize,
     /*log_scale=*/false,
     /*solids_only=*/true}};

// A fixed count of pieces, so that the order of every sum is the same for any thread count.
constexpr int pieces = 16;

// One update of q toward the rotation nearest F, from R = q's matrix: returns the angle turned.
// Turning R by θ (R ← exp([θ])R) changes tr(RᵀF) by θ·τ − ½θᵀHθ to second order, with the
// torque τ = Σ rᵢ × fᵢ (columns of R and F), M = FRᵀ and H = tr(M)·I − sym(M): Newton's step is
// θ = H⁻¹τ, quadratic near the maximum, where H is positive definite. Elsewhere (a start far
// from it) Müller's step τ/|tr M| (Müller et al. 2016), which ascends. No trigonometry: the
// turn is q + ½(0, θ)q, normalized (a turn by 2·atan(|θ|/2) about θ).
inline double turn_toward(const Eigen::Matrix3d& F, Eigen::Matrix3d& R, Eigen::Quaterniond& q) {
  const Eigen::Vector3d torque =
      R.col(0).cross(F.col(0)) + R.col(1).cross(F.col(1)) + R.col(2).cross(F.col(2));
  const Eigen::Matrix3d M = F * R.transpose();
  const double trace = M.trace();
  const double h00 = trace - M(0, 0), h11 = trace - M(1, 1), h22 = trace - M(2, 2);
  const double h01 = -0.5 * (M(0, 1) + M(1, 0)), h02 = -0.5 * (M(0, 2) + M(2, 0)),
               h12 = -0.5 * (M(1, 2) + M(2, 1));
  // H's cofactors; H is positive definite when its leading minors are.
  const double c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22,
               c02 = h01 * h12 - h02 * h11;
  const double minor2 = h00 * h11 - h01 * h01;
  const double det = h00 * c00 + h01 * c01 + h02 * c02;
  const double scale = std::abs(trace) + 1e-9;
  Eigen::Vector3d theta;
  if (h00 > 0.0 && minor2 > 0.0 && det > 1e-9 * scale * scale * scale) {
    const double c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12;
    const double c22 = minor2;
    theta << c00 * torque(0) + c01 * torque(1) + c02 * torque(2),
        c01 * torque(0) + c11 * torque(1) + c12 * torque(2),
        c02 * torque(0) + c12 * torque(1) + c22 * torque(2);
    theta /= det;
  } else {
    theta = torque / scale;
  }
  const double angle = theta.norm();
  if (!(angle > 0.0)) return 0.0;  // at the rotation, or F is not finite
  const Eigen::Quaterniond turn(0.0, 0.5 * theta(0), 0.5 * theta(1), 0.5 * theta(2));
  q.coeffs() += (turn * q).coeffs();
  q.normalize();
  R = q.toRotationMatrix();
  return angle;
}

}  // namespace

Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& F, Eigen::Quaterniond& q, int most,
                                 double tolerance) {
  Eigen::Matrix3d R = q.toRotationMatrix();
  for (int update = 0; update < most; ++update) {
    if (!(turn_toward(F, R, q) > tolerance)) break;
  }
  return R;
}

VolumeTerm::VolumeTerm(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, double stiffness,
                       WorkerPool& pool)
    : T_(T), G_(T.rows()), weight_(T.rows()), pool_(&pool) {
  const Eigen::Index tets = T.rows();
  for (Eigen::Index t = 0; t < tets; ++t) {
    Eigen::Matrix3d Dm;
    for (int c = 0; c < 3; ++c)
      Dm.col(c) = (V.row(T(t, c + 1)) - V.row(T(t, 0))).transpose();
    const double volume = std::abs(Dm.determinant()) / 6.0;
    // F = Ds Dm⁻¹ = Pᵀ G with G = [−1ᵀ; I] Dm⁻¹: the corners' rows of G sum to zero.
    const Eigen::Matrix3d inverse = Dm.inverse();
    G_[t].row(0) = -inverse.colwise().sum();
    G_[t].bottomRows<3>() = inverse;
    weight_(t) = stiffness * volume;
  }
  // Each vertex's slots, in increasing order.
  const Eigen::Index n = V.rows();
  incident_start_.assign(n + 1, 0);
  for (Eigen::Index t = 0; t < tets; ++t) {
    for (int c = 0; c < 4; ++c)
      ++incident_start_[T(t, c) + 1];
  }
  for (Eigen::Index i = 0; i < n; ++i)
    incident_start_[i + 1] += incident_start_[i];
  incident_.resize(4 * tets);
  std::vector<int> next(incident_start_.begin(), incident_start_.end() - 1);
  for (Eigen::Index t = 0; t < tets; ++t) {
    for (int c = 0; c < 4; ++c)
      incident_[next[T(t, c)]++] = static_cast<int>(4 * t + c);
  }
  rotation_.assign(tets, Eigen::Quaterniond::Identity());
  pull_.resize(4 * tets, 3);
  energy_.resize(tets);
}

void VolumeTerm::add_matrix(std::vector<Eigen::Triplet<double>>& K) const {
  K.reserve(K.size() + 16 * T_.rows());
  for (Eigen::Index t = 0; t < T_.rows(); ++t) {
    const Eigen::Matrix4d block = weight_(t) * G_[t] * G_[t].transpose();
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b)
        K.emplace_back(T_(t, a), T_(t, b), block(a, b));
    }
  }
}

Eigen::Matrix3d VolumeTerm::deformation(const Eigen::MatrixXd& p, Eigen::Index t) const {
  // F = Pᵀ G: column b of F is Σ_c x_c G(c, b).
  const Eigen::Matrix<double, 4, 3>& G = G_[t];
  Eigen::Matrix<double, 3, 4> X;
  for (int c = 0; c < 4; ++c) {
    const int i = T_(t, c);
    X.col(c) << p(i, 0), p(i, 1), p(i, 2);
  }
  return X * G;
}

void VolumeTerm::local_step(const Eigen::MatrixXd& p, int most, double tolerance, bool gradient,
                            bool energy) const {
  const auto tets = [&](Eigen::Index begin, Eigen::Index end) {
    for (Eigen::Index t = begin; t < end; ++t) {
      const Eigen::Matrix3d F = deformation(p, t);
      Eigen::Quaterniond& q = rotation_[t];
      Eigen::Matrix3d R = q.toRotationMatrix();
      for (int update = 0; update < most; ++update) {
        if (!(turn_toward(F, R, q) > tolerance)) break;
      }
      if (energy) energy_(t) = 0.5 * weight_(t) * (F - R).squaredNorm();
      // The pull w v G Rᵀ of the right-hand side, or the gradient w v G (F − R)ᵀ.
      const Eigen::Matrix3d toward = gradient ? Eigen::Matrix3d(F - R) : R;
      const Eigen::Matrix<double, 4, 3> pull = weight_(t) * (G_[t] * toward.transpose());
      double* out = pull_.data() + 12 * t;
      for (int c = 0; c < 4; ++c) {
        out[3 * c] = pull(c, 0);
        out[3 * c + 1] = pull(c, 1);
        out[3 * c + 2] = pull(c, 2);
      }
    }
  };
  const Eigen::Index count = T_.rows();
  if (count < min_tets_for_threads || pool_->threads() == 1) {
    tets(0, count);
    return;
  }
  auto piece = [&](int k) { tets(count * k / pieces, count * (k + 1) / pieces); };
  pool_->run(pieces, piece, &payoff_);
}

void VolumeTerm::add_targets(const StepContext& /*step*/, const Eigen::MatrixXd& p,
                             Eigen::MatrixXd& rhs, double* energy) {
  // One update of each rotation an iteration: warm-started from the last iteration's, the
  // rotations converge along with the iterations.
  local_step(p, 1, 0.0, /*gradient=*/false, /*energy=*/energy != nullptr);
  const Eigen::Index n = rhs.rows();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int s = incident_start_[i]; s < incident_start_[i + 1]; ++s) {
      const int slot = incident_[s];
      rhs(i, 0) += pull_(slot, 0);
      rhs(i, 1) += pull_(slot, 1);
      rhs(i, 2) += pull_(slot, 2);
    }
  }
  if (energy) *energy += energy_.sum();
}

double VolumeTerm::add_energy(const StepContext& /*step*/, const Eigen::MatrixXd& p,
                              Eigen::MatrixXd* gradient) const {
  local_step(p, 20, 1e-12, /*gradient=*/true, /*energy=*/true);
  if (gradient) {
    for (Eigen::Index i = 0; i < gradient->rows(); ++i) {
      for (int s = incident_start_[i]; s < incident_start_[i + 1]; ++s) {
        const int slot = incident_[s];
        (*gradient)(i, 0) += pull_(slot, 0);
        (*gradient)(i, 1) += pull_(slot, 1);
        (*gradient)(i, 2) += pull_(slot, 2);
      }
    }
  }
  return energy_.sum();
}

void VolumeTerm::project(const StepContext& /*step*/, Eigen::MatrixXd& next) {
  inverted_ = 0;
  // det F ≤ 0: turned inside out (F = I at rest, whichever way the corners are numbered).
  for (Eigen::Index t = 0; t < T_.rows(); ++t) {
    if (!(deformation(next, t).determinant() > 0.0)) ++inverted_;
  }
}

bool VolumeTerm::reset() {
  rotation_.assign(T_.rows(), Eigen::Quaterniond::Identity());
  inverted_ = 0;
  return false;
}

void VolumeTerm::report(std::vector<TermFigure>& figures) const {
  figures.push_back({"volume", "inverted", "", static_cast<double>(inverted_)});
}

std::unique_ptr<StepTerm> make_volume_term(const TermSetup& setup) {
  const double stiffness = setting_value(setup.params, "volume-stiffness");
  if (!(stiffness > 0.0) || setup.rest.T.rows() == 0) return nullptr;
  return std::make_unique<VolumeTerm>(setup.rest.V, setup.rest.T, stiffness);
}

}  // namespace wobble
