#include "sim/volume/volume_term.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "sim/settings/setting_registry.h"
#include "sim/shapes/tet_mesh.h"
#include "sim/terms/term_registry.h"

namespace wobble {

namespace {

// The panel's switch and its stiffness: the term acts when the switch is on and the stiffness is
// above 0. Off unless a scene or the user turns it on (the shipped jellies do; the course's scenes
// never), so every other scene steps exactly as without the term.
const SettingRegistration volume_switch{{"volume",
                                         "volume term",
                                         "Keep each tetrahedron of a solid near a rotation of its "
                                         "rest shape, so that a jelly turned inside out comes back "
                                         "(the shipped jellies: on)",
                                         {0.0, 1.0, ""},
                                         0.0,
                                         SettingCost::refactorize,
                                         /*log_scale=*/false,
                                         /*solids_only=*/true,
                                         SettingType::toggle}};

SettingSpec stiffness_spec() {
  SettingSpec spec{"volume-stiffness",
                   "volume k",
                   "Stiffness of the volume term (0 leaves it out too)",
                   {0.0, 1e7, "Pa"},
                   volume_default_stiffness,
                   SettingCost::refactorize,
                   /*log_scale=*/true,
                   /*solids_only=*/true};
  // Giving a stiffness (the command line, the page's address, a scene file) turns the term on,
  // unless the switch is given too.
  spec.implies = "volume";
  // The panel's drag spans four decades around the shipped jellies' 2e4 Pa.
  spec.panel_range = {100.0, 1e6, ""};
  spec.panel_format = "%.0f";
  return spec;
}
const SettingRegistration volume_stiffness{stiffness_spec()};

// A fixed count of pieces, so that the work of each is the same for any thread count.
constexpr int pieces = 16;

// w vₜ of every tetrahedron (#T, N·m).
Eigen::VectorXd weights(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, double stiffness) {
  Eigen::VectorXd weight(T.rows());
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    weight(t) = stiffness * std::abs(tet_signed_volume(V, T, t));
  return weight;
}

}  // namespace

VolumeTerm::VolumeTerm(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, double stiffness,
                       WorkerPool& pool)
    : T_(T),
      G_(T.rows()),
      weight_(weights(V, T, stiffness)),
      rotations_(V, T, weight_),
      pool_(&pool) {
  const Eigen::Index tets = T.rows();
  for (Eigen::Index t = 0; t < tets; ++t) {
    Eigen::Matrix3d Dm;
    for (int c = 0; c < 3; ++c)
      Dm.col(c) = (V.row(T(t, c + 1)) - V.row(T(t, 0))).transpose();
    // F = Ds Dm⁻¹ = Pᵀ G with G = [−1ᵀ; I] Dm⁻¹: the corners' rows of G sum to zero.
    const Eigen::Matrix3d inverse = Dm.inverse();
    G_[t].row(0) = -inverse.colwise().sum();
    G_[t].bottomRows<3>() = inverse;
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
  incident_single_.resize(4 * tets);
  std::vector<int> next(incident_start_.begin(), incident_start_.end() - 1);
  for (Eigen::Index t = 0; t < tets; ++t) {
    for (int c = 0; c < 4; ++c) {
      incident_single_[next[T(t, c)]] = static_cast<int>(TetRotations::single_at(t, c));
      incident_[next[T(t, c)]++] = static_cast<int>(TetRotations::at(t, c));
    }
  }
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
  const bool single = TetRotations::single_precision(most, gradient, energy);
  rotations_.prepare(single);
  const long count = rotations_.packs(single);
  if (T_.rows() < min_tets_for_threads || pool_->threads() == 1) {
    rotations_.update(p, 0, count, most, tolerance, gradient, energy);
    return;
  }
  auto piece = [&](int k) {
    rotations_.update(p, count * k / pieces, count * (k + 1) / pieces, most, tolerance, gradient,
                      energy);
  };
  pool_->run(pieces, piece, &tet_payoff_);
}

namespace {

// out (#V by 3) += for each vertex in [begin, end) the sum of its pulls, in the order of its
// slots: pulls[incident[s] + stride·i] for coordinate i.
template <typename Pull>
void sum_pulls(const Pull* pulls, long stride, const int* incident_start, const int* incident,
               Eigen::Index begin, Eigen::Index end, Eigen::MatrixXd& out) {
  for (Eigen::Index i = begin; i < end; ++i) {
    double x = 0.0, y = 0.0, z = 0.0;
    for (int s = incident_start[i]; s < incident_start[i + 1]; ++s) {
      const Pull* pull = pulls + incident[s];
      x += static_cast<double>(pull[0]);
      y += static_cast<double>(pull[stride]);
      z += static_cast<double>(pull[2 * stride]);
    }
    out(i, 0) += x;
    out(i, 1) += y;
    out(i, 2) += z;
  }
}

}  // namespace

void VolumeTerm::gather(Eigen::MatrixXd& out) const {
  // After a single-precision update the pulls are floats, half the bytes to read; each is
  // exactly the double it would have been rounded to before.
  const bool single = rotations_.single_current();
  const auto vertices = [&](Eigen::Index begin, Eigen::Index end) {
    if (single) {
      sum_pulls(rotations_.single_out(), 8, incident_start_.data(), incident_single_.data(), begin,
                end, out);
    } else {
      sum_pulls(rotations_.out(), 4, incident_start_.data(), incident_.data(), begin, end, out);
    }
  };
  const Eigen::Index n = out.rows();
  if (T_.rows() < min_tets_for_threads || pool_->threads() == 1) {
    vertices(0, n);
    return;
  }
  auto piece = [&](int k) { vertices(n * k / pieces, n * (k + 1) / pieces); };
  pool_->run(pieces, piece, &vertex_payoff_);
}

void VolumeTerm::add_targets(const StepContext& /*step*/, const Eigen::MatrixXd& p,
                             Eigen::MatrixXd& rhs, double* energy) {
  // One update of each rotation an iteration: warm-started from the last iteration's, the
  // rotations converge along with the iterations.
  local_step(p, 1, 0.0, /*gradient=*/false, /*energy=*/energy != nullptr);
  gather(rhs);
  if (energy) *energy += rotations_.energy();
}

double VolumeTerm::add_energy(const StepContext& /*step*/, const Eigen::MatrixXd& p,
                              Eigen::MatrixXd* gradient) const {
  // Warm-started from the last evaluation's, the rotations are found in one to three Newton
  // updates, stopping once the next would turn by less than 1e-7 rad: an error far below what
  // the energy and the gradient can show (the energy's is of the order of its square).
  local_step(p, 20, 1e-7, /*gradient=*/true, /*energy=*/true);
  if (gradient) gather(*gradient);
  return rotations_.energy();
}

void VolumeTerm::project(const StepContext& /*step*/, Eigen::MatrixXd& next) {
  inverted_ = 0;
  // det F ≤ 0: turned inside out (F = I at rest, whichever way the corners are numbered).
  for (Eigen::Index t = 0; t < T_.rows(); ++t) {
    if (!(deformation(next, t).determinant() > 0.0)) ++inverted_;
  }
}

bool VolumeTerm::reset() {
  rotations_.reset();
  inverted_ = 0;
  return false;
}

void VolumeTerm::report(std::vector<TermFigure>& figures) const {
  figures.push_back({"volume", "inverted", "", static_cast<double>(inverted_)});
}

std::unique_ptr<StepTerm> make_volume_term(const TermSetup& setup) {
  const double stiffness = setting_value(setup.params, "volume-stiffness");
  if (setting_value(setup.params, "volume") == 0.0 || !(stiffness > 0.0) ||
      setup.rest.T.rows() == 0)
    return nullptr;
  return std::make_unique<VolumeTerm>(setup.rest.V, setup.rest.T, stiffness);
}

}  // namespace wobble
