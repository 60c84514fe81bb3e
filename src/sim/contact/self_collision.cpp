#include "sim/contact/self_collision.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "sim/contact/closest_points.h"
#include "sim/contact/vertex_row.h"
#include "sim/input_error.h"
#include "sim/value_limits.h"

namespace wobble {

namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The motion detection allows beyond the solve's, as a fraction of the thickness, and how often
// the pairs are found again when the response pushed a vertex farther.
constexpr double margin_fraction = 0.25;
constexpr int max_rounds = 3;
// The pairs of a slow step are kept while no vertex strays farther than half this fraction of
// the thickness from where they were found.
constexpr double skin_fraction = 0.5;
// Pairs closer than this many thicknesses in the rest shape are the mesh's own neighbourhood.
constexpr double rest_skip_factor = 2.0;
// The largest thickness, in mean rest edges (see largest_self_collision_thickness).
constexpr double largest_thickness_in_edges = 1.5;

}  // namespace

void validate_self_collision(const SelfCollisionParams& params) {
  if (!limits::self_collision_thickness.contains(params.thickness)) {
    throw InputError("self-collision thickness: expected " +
                     expected_in(limits::self_collision_thickness) + ", got " +
                     limit_text(params.thickness));
  }
}

namespace {

double largest_thickness(const SelfCollisionSurface& surface) {
  return std::max(limits::self_collision_thickness.low,
                  largest_thickness_in_edges * surface.mean_edge);
}

}  // namespace

double largest_self_collision_thickness(const SpringNetwork& network) {
  return largest_thickness(SelfCollisionSurface(network));
}

SelfCollision::SelfCollision(const SpringNetwork& rest, const SelfCollisionParams& params)
    : params_(params), surface_(rest) {
  in_contact_.assign(rest.V.rows(), 0);
  largest_thickness_ = largest_thickness(surface_);
  thickness_ = -1.0;
  set_thickness(params.thickness);
}

void SelfCollision::set_thickness(double thickness) {
  params_.thickness = thickness;
  const double used = std::min(thickness, largest_thickness_);
  if (used == thickness_) return;
  thickness_ = used;
  listed_ = false;
  rest_neighbours_.find(surface_, rest_skip_factor * thickness_);
}

void SelfCollision::clear() {
  listed_ = false;
  pairs_.clear();
  listed_pairs_.clear();
  std::fill(in_contact_.begin(), in_contact_.end(), 0);
  contact_count_ = 0;
  pair_count_ = 0;
}

bool SelfCollision::near_reference(const Eigen::MatrixXd& positions, double reach) const {
  return within_of_common_motion(reference_, positions, reach);
}

bool SelfCollision::within_of_common_motion(const Eigen::MatrixXd& from, const Eigen::MatrixXd& to,
                                            double reach) const {
  // Distances between vertices do not change when all of them move alike: only what each moves
  // apart from the mean counts.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const int v : surface_.vertices)
    mean += vertex_row(to, v) - vertex_row(from, v);
  if (!surface_.vertices.empty()) mean /= static_cast<double>(surface_.vertices.size());
  const double reach2 = reach * reach;
  for (const int v : surface_.vertices) {
    if (!((vertex_row(to, v) - vertex_row(from, v) - mean).squaredNorm() <= reach2)) return false;
  }
  return true;
}

bool SelfCollision::near_segments(const Eigen::MatrixXd& current, const Eigen::MatrixXd& end,
                                  const Eigen::MatrixXd& positions, double reach) const {
  for (const int v : surface_.vertices) {
    const Eigen::Vector3d from = vertex_row(current, v), along = vertex_row(end, v) - from;
    const Eigen::Vector3d p = vertex_row(positions, v);
    const double length2 = along.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((p - from).dot(along) / length2, 0.0, 1.0) : 0.0;
    if (!((p - from - t * along).norm() <= reach)) return false;
  }
  return true;
}

void SelfCollision::refresh_pairs(const Eigen::MatrixXd& current) {
  const double h = thickness_;
  pairs_.resize(listed_pairs_.size());
  std::size_t kept = 0;
  for (SelfContactPair pair : listed_pairs_) {
    const Eigen::Vector3d p0 = vertex_row(current, pair.vertex[0]),
                          p1 = vertex_row(current, pair.vertex[1]);
    const Eigen::Vector3d p2 = vertex_row(current, pair.vertex[2]),
                          p3 = vertex_row(current, pair.vertex[3]);
    // The closest points of the two features where the step starts.
    if (pair.vertex_triangle) {
      const Eigen::Vector3d alpha = closest_on_triangle(p0, p1, p2, p3);
      pair.beta[1] = -alpha(0);
      pair.beta[2] = -alpha(1);
      pair.beta[3] = -alpha(2);
    } else {
      const Eigen::Vector2d su = closest_on_segments(p0, p1, p2, p3);
      pair.beta[0] = 1.0 - su(0);
      pair.beta[1] = su(0);
      pair.beta[2] = -(1.0 - su(1));
      pair.beta[3] = -su(1);
    }
    const Eigen::Vector3d start =
        pair.beta[0] * p0 + pair.beta[1] * p1 + pair.beta[2] * p2 + pair.beta[3] * p3;
    const double distance = start.norm();
    if (distance > 1e-9 * h) pair.normal = start / distance;  // else the last step's normal
    pair.target = std::min(h, distance + SelfContactDetection::recovery_fraction * h);
    pair.depth = 0.0;
    pairs_[kept++] = pair;
  }
  pairs_.resize(kept);
}

void SelfCollision::respond(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass,
                            double friction, Eigen::MatrixXd& next) {
  response_.respond(pairs_, current, inverse_mass, friction, thickness_, next);
  for (const SelfContactPair& pair : pairs_) {
    if (!(pair.depth > 0.0)) continue;
    ++pair_count_;
    for (int k = 0; k < 4; ++k) {
      if (pair.beta[k] != 0.0) in_contact_[pair.vertex[k]] = 1;
    }
  }
}

void SelfCollision::project(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass,
                            double friction, Eigen::MatrixXd& next) {
  std::fill(in_contact_.begin(), in_contact_.end(), 0);
  contact_count_ = pair_count_ = undone_ = 0;
  detection_ms_ = response_ms_ = 0.0;
  const double h = thickness_;
  const double skin = skin_fraction * h;
  const double margin = margin_fraction * h;
  solved_ = next;

  // At rest (a settled pile), the pairs found around where the surface rests serve step after
  // step: every pair left out was at least the thickness plus the skin apart there, so it
  // cannot come within the thickness while no vertex strays half the skin from there.
  if (listed_ && near_reference(current, 0.5 * skin)) {
    const auto detection_start = Clock::now();
    refresh_pairs(current);
    detection_ms_ += milliseconds_since(detection_start);
    const auto response_start = Clock::now();
    respond(current, inverse_mass, friction, next);
    response_ms_ += milliseconds_since(response_start);
    if (near_reference(next, 0.5 * skin)) {
      path_end_ = nullptr;
      saturated_ = listed_saturated_;
      return;
    }
    next = solved_;
    std::fill(in_contact_.begin(), in_contact_.end(), 0);
    pair_count_ = 0;
  }
  listed_ = false;

  // Otherwise the pairs the step's motion can bring within the thickness, with a margin for the
  // response's pushes; when a push takes a vertex farther from its path than the margin, the
  // pairs are found again along the pushed path.
  const Eigen::MatrixXd* end = &solved_;
  for (int round = 0; round < max_rounds; ++round) {
    const auto detection_start = Clock::now();
    if (round > 0) {
      pushed_ = next;
      next = solved_;
      end = &pushed_;
    }
    detection_.detect(surface_, rest_neighbours_, current, *end, h, margin, pairs_);
    saturated_ = detection_.saturated();
    path_end_ = end;
    detection_ms_ += milliseconds_since(detection_start);
    const auto response_start = Clock::now();
    respond(current, inverse_mass, friction, next);
    response_ms_ += milliseconds_since(response_start);
    if (near_segments(current, *end, next, margin)) break;
  }

  // A step that hardly moved: the pairs around where it ends, for the next steps.
  if (within_of_common_motion(current, next, 0.25 * skin)) {
    const auto detection_start = Clock::now();
    detection_.detect(surface_, rest_neighbours_, next, next, h, 0.5 * skin, listed_pairs_);
    listed_saturated_ = detection_.saturated();
    reference_ = next;
    listed_ = true;
    detection_ms_ += milliseconds_since(detection_start);
  }
}

void SelfCollision::project_again(const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next) {
  const auto start = Clock::now();
  response_.separate(pairs_, inverse_mass, thickness_, next);
  response_ms_ += milliseconds_since(start);
}

void SelfCollision::finish(const Eigen::MatrixXd& current, const Eigen::VectorXd& inverse_mass,
                           Eigen::MatrixXd& next) {
  const auto start = Clock::now();
  // A crossing starts as a vertex and a triangle, or two edges, coming within the thickness.
  // While every vertex ends on the path the pairs were found along (within the margin) and no
  // feature had pairs left out, the pairs list every such meeting, and the guard need only look
  // at the features with a vertex in a pair; else it looks everywhere.
  const bool on_path = path_end_ == nullptr
                           ? near_reference(next, 0.5 * skin_fraction * thickness_)
                           : near_segments(current, *path_end_, next, margin_fraction * thickness_);
  const std::vector<char>* watched = nullptr;
  if (on_path && !saturated_) {
    watched_.assign(next.rows(), 0);
    for (const SelfContactPair& pair : pairs_) {
      for (const int v : pair.vertex)
        watched_[v] = 1;
    }
    watched = &watched_;
  }
  undone_ = guard_.undo_crossings(surface_, current, inverse_mass, next, in_contact_, watched);
  response_ms_ += milliseconds_since(start);
  contact_count_ = 0;
  for (const char flag : in_contact_)
    contact_count_ += flag;
}

std::size_t SelfCollision::memory_bytes() const {
  const auto matrix = [](const Eigen::MatrixXd& m) { return m.size() * sizeof(double); };
  return matrix(surface_.rest) + (surface_.triangles.size() + surface_.edges.size()) * sizeof(int) +
         surface_.vertices.capacity() * sizeof(int) + surface_.vertex_edges.memory_bytes() +
         surface_.vertex_triangles.memory_bytes() + rest_neighbours_.memory_bytes() +
         detection_.memory_bytes() + response_.memory_bytes() + guard_.memory_bytes() +
         (pairs_.capacity() + listed_pairs_.capacity()) * sizeof(SelfContactPair) +
         matrix(solved_) + matrix(pushed_) + matrix(reference_) + in_contact_.capacity();
}

}  // namespace wobble
