#include "sim/contact/self_contact_term.h"

#include <algorithm>

#include "sim/contact/vertex_row.h"
#include "sim/instruments/stopwatch.h"
#include "sim/value_limits.h"

namespace wobble {

namespace {

// Pairs closer than this many thicknesses in the rest shape are the mesh's own neighbourhood.
constexpr double rest_skip_factor = 2.0;
// A pair that starts closer than the thickness opens by this fraction of it a step: pushed out at
// once it would leave with the whole shortfall as speed.
constexpr double recovery_fraction = 0.1;
// Reaches: this many times a vertex's predicted motion apart from the common motion.
constexpr double reach_factor = 1.5;

std::uint64_t pair_key(const SelfContactPair& pair) {
  std::uint64_t key = pair.vertex_triangle ? 0x9e3779b97f4a7c15ull : 0xc2b2ae3d27d4eb4full;
  for (const int v : pair.vertex) {
    key ^= static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)) + 0x9e3779b97f4a7c15ull +
           (key << 6) + (key >> 2);
    key *= 0xff51afd7ed558ccdull;
  }
  return key;
}

}  // namespace

Eigen::Vector3d SelfContactTerm::common_motion(const Eigen::MatrixXd& p) const {
  // The median of the surface's motion along each axis, of at most max_motion_samples vertices
  // at an even stride (the same every run). Not the mean: where a corner of a lying pile slides,
  // the mean moves, and the clamp dragged every still vertex whose bound is small along with it
  // (the shipped pile popped to 3.4 J in its springs for a few steps). Any common motion keeps
  // the bounds' promise.
  const std::size_t count = surface_.vertices.size();
  if (count == 0) return Eigen::Vector3d::Zero();
  const std::size_t stride = (count + max_motion_samples - 1) / max_motion_samples;
  Eigen::Vector3d median;
  for (int axis = 0; axis < 3; ++axis) {
    motion_samples_.clear();
    for (std::size_t k = 0; k < count; k += stride) {
      const int v = surface_.vertices[k];
      motion_samples_.push_back(p(v, axis) - x_(v, axis));
    }
    const auto middle =
        motion_samples_.begin() + static_cast<std::ptrdiff_t>(motion_samples_.size() / 2);
    std::nth_element(motion_samples_.begin(), middle, motion_samples_.end());
    median(axis) = *middle;
  }
  return median;
}

bool SelfContactTerm::within(const Eigen::MatrixXd& p, double fraction) const {
  // Any common motion keeps the bounds' promise (distances do not change when everything moves
  // alike): the common motion since the epoch started is taken out.
  const Eigen::Vector3d common = common_motion(p);
  for (const int v : surface_.vertices) {
    const double limit = fraction * bounds_(v);
    if (!((vertex_row(p, v) - vertex_row(x_, v) - common).squaredNorm() <= limit * limit))
      return false;
  }
  return true;
}

SelfContactTerm::SelfContactTerm(const SpringNetwork& rest) : rest_(&rest) {}

void SelfContactTerm::build_surface() {
  surface_ = SelfCollisionSurface(*rest_);
  built_ = true;
}

void SelfContactTerm::set(const SelfCollisionParams& params) {
  on_ = params.on;
  if (!on_) {
    reset();
    return;
  }
  if (!built_) build_surface();
  const double kept = thickness_kept(params.thickness);
  if (kept != thickness_) {
    thickness_ = kept;
    rest_neighbours_ = RestNeighbours(surface_, rest_skip_factor * thickness_);
    remembered_.clear();
    epoch_open_ = false;
  }
}

double SelfContactTerm::thickness_kept(double asked) const {
  if (!built_) return asked;
  return std::min(asked, largest_self_collision_thickness(surface_.mean_edge));
}

bool SelfContactTerm::reset() {
  epoch_open_ = false;
  remembered_.clear();
  pairs_.clear();
  std::fill(in_contact_.begin(), in_contact_.end(), 0);
  contact_count_ = clamped_ = repaired_ = epochs_ = 0;
  return false;
}

TermStep SelfContactTerm::begin_step(const StepContext& step, const Eigen::MatrixXd& first) {
  if (!on_) return TermStep{};
  epochs_ = clamped_ = repaired_ = 0;
  detection_ms_ = solve_ms_ = guard_ms_ = 0.0;
  sweep_fresh_ = true;
  step_covered_ = epoch_covered_;  // a kept epoch's; a new one's is ANDed in by start_epoch
  // An epoch outlives the step while the surface stays well within its bounds (a pile at rest,
  // a cloth sliding as a whole): its pairs and bounds still hold, and nothing is found again.
  const bool keep = epoch_open_ && x_.rows() == step.current.rows() &&
                    within(step.current, keep_fraction) && within(first, keep_fraction);
  if (!keep) {
    step_covered_ = true;
    x_ = step.current;
    pack_rows(x_, anchor_);
    start_epoch(step, first);
  }
  TermStep begun;
  begun.in_solve = true;
  begun.touching = contact_count_ > 0;
  return begun;
}

void SelfContactTerm::start_epoch(const StepContext& step, const Eigen::MatrixXd& heading) {
  const Stopwatch stopwatch;
  const Eigen::Index n = x_.rows();
  // A new epoch within the step carries the forces its pairs have reached so far.
  if (epochs_ > 0) end_step();
  const Eigen::Vector3d common = common_motion(heading);
  reach_.setZero(n);
  for (const int v : surface_.vertices) {
    const double wander = (vertex_row(heading, v) - vertex_row(x_, v) - common).norm();
    reach_(v) = std::max(thickness_, reach_factor * wander);
  }
  proximity_.find(surface_, rest_neighbours_, x_, reach_, contact_reach * thickness_, found_,
                  bounds_);
  epoch_open_ = true;
  sweep_fresh_ = true;
  epoch_covered_ = proximity_.covers_every_pair();
  step_covered_ = step_covered_ && epoch_covered_;

  const double mu = step.friction;
  const Eigen::VectorXd* inertia = step.inertia;
  pairs_.resize(found_.size());
  for (std::size_t i = 0; i < found_.size(); ++i) {
    Pair& pair = pairs_[i];
    pair.features = found_[i];
    // The gap to keep: the thickness, or a little more than the pair has if it starts closer.
    pair.features.target = std::min(thickness_, found_[i].depth + recovery_fraction * thickness_);
    double compliance = 0.0;
    for (int k = 0; k < 4; ++k) {
      const int v = pair.features.vertex[k];
      const double beta = pair.features.beta[k];
      if (beta != 0.0 && !step.pinned[v] && inertia && inertia->size() == n)
        compliance += beta * beta / (*inertia)(v);
    }
    pair.stiffness = compliance > 0.0 ? gain / compliance : 0.0;
    pair.key = pair_key(pair.features);
    pair.force = remembered_force(pair.key);
    pair.friction = mu * pair.force;
  }
  ++epochs_;
  detection_ms_ += stopwatch.milliseconds();
}

void SelfContactTerm::project(const StepContext& step, Eigen::MatrixXd& next) {
  if (!on_) return;
  const Stopwatch stopwatch;
  // What the colliders' projection moved stays within the bounds too.
  clamped_ += clamp_to_bounds(x_, common_motion(next), bounds_, next);
  // The forces at the solved positions, for the next step's start (and L-BFGS's λ̄).
  const double mu = step.friction;
  const Eigen::Index n = next.rows();
  in_contact_.assign(n, 0);
  contact_count_ = 0;
  for (Pair& pair : pairs_) {
    pair.friction = mu * pair.force;
    if (!(pair.force > 0.0) && !(violation(pair, next, nullptr) > -0.01 * thickness_)) continue;
    for (int k = 0; k < 4; ++k) {
      const int v = pair.features.vertex[k];
      if (pair.features.beta[k] != 0.0 && !in_contact_[v]) {
        in_contact_[v] = 1;
        ++contact_count_;
      }
    }
  }
  solve_ms_ += stopwatch.milliseconds();
  // The last resort, where the bounds do not keep every pair apart: a search stopped (the pairs
  // among the vertices it froze went unexamined), or a pair was found closer than the floor
  // (where rounding may decide). Elsewhere every vertex now lies within its bound of every epoch
  // this step, so no edge passed through a triangle, and the guard would look for nothing.
  repaired_ = 0;
  guard_ms_ = 0.0;
  if (step_covered_) return;
  const Stopwatch guard;
  inverse_mass_.resize(n);
  for (Eigen::Index v = 0; v < n; ++v)
    inverse_mass_(v) = step.pinned[v] ? 0.0 : 1.0 / step.rest.m(v);
  put_back_.assign(n, 0);
  // While the bounds held every vertex without having to move one and the search left nothing
  // out, a crossing could only start at a listed pair: the guard looks around those alone.
  const std::vector<char>* watched = nullptr;
  if (clamped_ == 0 && !proximity_.saturated()) {
    watched_.assign(n, 0);
    for (const Pair& pair : pairs_) {
      for (const int v : pair.features.vertex)
        watched_[v] = 1;
    }
    watched = &watched_;
  }
  repaired_ =
      guard_.undo_crossings(surface_, step.current, inverse_mass_, next, put_back_, watched);
  guard_ms_ = guard.milliseconds();
}

void SelfContactTerm::end_step() {
  if (!on_) return;
  // An open-addressed table of (key, λ), about half full, probed linearly; a key met twice keeps
  // the smaller λ.
  std::size_t count = 0;
  for (const Pair& pair : pairs_)
    count += pair.force > 0.0;
  std::size_t slots = 16;
  while (slots < 2 * count)
    slots *= 2;
  remembered_.assign(slots, std::make_pair(std::uint64_t{0}, 0.0));  // λ = 0: an empty slot
  for (const Pair& pair : pairs_) {
    if (!(pair.force > 0.0)) continue;
    for (std::size_t slot = remembered_slot(pair.key);; slot = (slot + 1) & (slots - 1)) {
      auto& entry = remembered_[slot];
      if (entry.second == 0.0) {
        entry = {pair.key, pair.force};
        break;
      }
      if (entry.first == pair.key) {
        entry.second = std::min(entry.second, pair.force);
        break;
      }
    }
  }
}

std::size_t SelfContactTerm::remembered_slot(std::uint64_t key) const {
  return static_cast<std::size_t>(key ^ (key >> 29)) & (remembered_.size() - 1);
}

double SelfContactTerm::remembered_force(std::uint64_t key) const {
  if (remembered_.empty()) return 0.0;
  for (std::size_t slot = remembered_slot(key);; slot = (slot + 1) & (remembered_.size() - 1)) {
    const auto& entry = remembered_[slot];
    if (entry.second == 0.0) return 0.0;
    if (entry.first == key) return entry.second;
  }
}

const std::vector<char>& SelfContactTerm::contact_vertices() const {
  static const std::vector<char> none;
  return on_ ? in_contact_ : none;
}

void SelfContactTerm::report(std::vector<TermFigure>& figures) const {
  if (!on_) return;
  const char* term = name();
  figures.push_back(TermFigure{term, "detection", "ms", detection_ms_});
  figures.push_back(TermFigure{term, "solve", "ms", solve_ms_});
  figures.push_back(TermFigure{term, "guard", "ms", guard_ms_});
  figures.push_back(TermFigure{term, "pairs", "", static_cast<double>(pairs_.size())});
  figures.push_back(TermFigure{term, "contacts", "", static_cast<double>(contact_count_)});
  figures.push_back(TermFigure{term, "epochs", "", static_cast<double>(epochs_)});
  figures.push_back(TermFigure{term, "bounded", "", static_cast<double>(clamped_)});
  figures.push_back(TermFigure{term, "guard repairs", "", static_cast<double>(repaired_)});
}

const std::vector<char>& self_contact_vertices(const StepTerms& terms) {
  static const std::vector<char> none;
  const SelfContactTerm* term = terms.find<SelfContactTerm>();
  return term ? term->contact_vertices() : none;
}

double self_collision_thickness_kept(const StepTerms& terms, double asked) {
  const SelfContactTerm* term = terms.find<SelfContactTerm>();
  return term ? term->thickness_kept(asked) : asked;
}

std::size_t SelfContactTerm::memory_bytes() const {
  const auto matrix = [](const Eigen::MatrixXd& m) { return m.size() * sizeof(double); };
  return matrix(surface_.rest) + (surface_.triangles.size() + surface_.edges.size()) * sizeof(int) +
         surface_.vertex_edges.memory_bytes() + surface_.vertex_triangles.memory_bytes() +
         rest_neighbours_.memory_bytes() + proximity_.memory_bytes() + guard_.memory_bytes() +
         matrix(x_) +
         (anchor_.capacity() + rows_.capacity() + last_rows_.capacity() + rhs_rows_.capacity()) *
             sizeof(Eigen::Vector3d) +
         travel_.capacity() * sizeof(double) +
         (reach_.size() + bounds_.size() + inverse_mass_.size()) * sizeof(double) +
         found_.capacity() * sizeof(SelfContactPair) + pairs_.capacity() * sizeof(Pair) +
         remembered_.capacity() * sizeof(std::pair<std::uint64_t, double>) +
         in_contact_.capacity() + put_back_.capacity();
}

}  // namespace wobble
