#include "sim/contact/self_contact_response.h"

#include <algorithm>
#include <cmath>

#include "sim/contact/vertex_row.h"

namespace wobble {

namespace {

// Moves the pair's vertices so that Σβₖxₖ moves by `amount` (m) along `direction`, each vertex
// by wₖβₖλ; returns λ. No vertex moves farther than `amount`: when the only vertex free to move
// has a small weight βₖ (a triangle's corner far from the contact, the others pinned), the
// full correction would throw it amount/βₖ away; the pair then gets only part of it.
double push(const SelfContactPair& pair, double amount, const Eigen::Vector3d& direction,
            const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next) {
  double weight = 0.0, largest = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double w = inverse_mass(pair.vertex[k]);
    weight += pair.beta[k] * pair.beta[k] * w;
    largest = std::max(largest, w * std::abs(pair.beta[k]));
  }
  if (!(weight > 0.0)) return 0.0;  // nothing can move
  const double lambda = std::min(amount / weight, amount / largest);
  for (int k = 0; k < 4; ++k) {
    const int i = pair.vertex[k];
    next.row(i) += (inverse_mass(i) * pair.beta[k] * lambda) * direction.transpose();
  }
  return lambda;
}

}  // namespace

double SelfContactResponse::sweep(std::vector<SelfContactPair>& pairs,
                                  const Eigen::VectorXd& inverse_mass, int number,
                                  Eigen::MatrixXd& next) {
  double worst = 0.0;
  moved_list_.clear();
  const auto visit = [&](SelfContactPair& pair) {
    double gap = 0.0;
    for (int k = 0; k < 4; ++k) {
      const int i = pair.vertex[k];
      gap += pair.beta[k] * (next(i, 0) * pair.normal(0) + next(i, 1) * pair.normal(1) +
                             next(i, 2) * pair.normal(2));
    }
    const double violation = pair.target - gap;
    if (!(violation > 0.0)) return;
    if (push(pair, violation, pair.normal, inverse_mass, next) > 0.0) {
      pair.depth += violation;
      for (int k = 0; k < 4; ++k) {
        const int i = pair.vertex[k];
        if (pair.beta[k] != 0.0 && inverse_mass(i) > 0.0 && moved_[i] != number) {
          moved_[i] = number;
          moved_list_.push_back(i);
        }
      }
    }
    worst = std::max(worst, violation);
  };
  if (number == 0) {
    for (SelfContactPair& pair : pairs)
      visit(pair);
    return worst;
  }
  // Only the pairs of a vertex the sweep before pushed can have lost their gap; they come in the
  // order the pushes found them, which the pairs' order fixes (the same sweeps on any machine).
  for (const int p : active_)
    visit(pairs[p]);
  return worst;
}

void SelfContactResponse::gather_active(int number) {
  active_.clear();
  for (const int v : moved_list_) {
    for (int s = pair_start_[v]; s < pair_start_[v + 1]; ++s) {
      const int p = pair_ids_[s];
      if (pair_seen_[p] == number) continue;
      pair_seen_[p] = number;
      active_.push_back(p);
    }
  }
}

void SelfContactResponse::index_pairs(const std::vector<SelfContactPair>& pairs, int vertex_count) {
  pair_start_.assign(vertex_count + 1, 0);
  for (const SelfContactPair& pair : pairs) {
    for (int k = 0; k < 4; ++k)
      ++pair_start_[pair.vertex[k] + 1];
  }
  for (int v = 0; v < vertex_count; ++v)
    pair_start_[v + 1] += pair_start_[v];
  pair_ids_.resize(pair_start_[vertex_count]);
  fill_.assign(pair_start_.begin(), pair_start_.end() - 1);
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    for (int k = 0; k < 4; ++k)
      pair_ids_[fill_[pairs[p].vertex[k]]++] = static_cast<int>(p);
  }
  pair_seen_.assign(pairs.size(), -1);
}

void SelfContactResponse::separate(std::vector<SelfContactPair>& pairs,
                                   const Eigen::VectorXd& inverse_mass, double thickness,
                                   Eigen::MatrixXd& next) {
  const int vertex_count = static_cast<int>(next.rows());
  moved_.assign(vertex_count, -1);
  index_pairs(pairs, vertex_count);
  // However the pairs jam (a dense pile whose layers the solve pressed through each other), the
  // sweeps visit at most sweep_budget times as many pairs as there are: a few contacts get
  // their max_sweeps, a pile pays about what sweep_budget full sweeps cost.
  const std::size_t budget = sweep_budget * pairs.size() + max_sweeps * 64;
  std::size_t visited = pairs.size();
  for (int number = 0; number < max_sweeps; ++number) {
    if (number > 0) {
      gather_active(number);
      visited += active_.size();
      if (visited > budget) break;
    }
    if (sweep(pairs, inverse_mass, number, next) <= settled_fraction * thickness) break;
  }
}

void SelfContactResponse::apply_friction(std::vector<SelfContactPair>& pairs,
                                         const Eigen::MatrixXd& current,
                                         const Eigen::VectorXd& inverse_mass, double friction,
                                         Eigen::MatrixXd& next) {
  for (const SelfContactPair& pair : pairs) {
    // Only a vertex over a triangle's face (its closest point inside): there the normal is the
    // face's, and what is tangential slides along the layer. Friction on edge-edge pairs too
    // kept a 32×32 pile on the ground bouncing (0.1–0.8 J six seconds in), and on a vertex
    // beside a triangle (an oblique normal, so motion across the layer counted as sliding) a
    // settled pile crept and came back to life (10⁻⁷ J to 0.03 J from 4 s to 8 s).
    if (!(pair.depth > 0.0) || !pair.vertex_triangle) continue;
    if (!(pair.beta[1] < 0.0 && pair.beta[2] < 0.0 && pair.beta[3] < 0.0)) continue;
    // The pair's relative motion over the step, less its normal part.
    Eigen::Vector3d relative = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k)
      relative +=
          pair.beta[k] * (vertex_row(next, pair.vertex[k]) - vertex_row(current, pair.vertex[k]));
    const Eigen::Vector3d tangential = relative - relative.dot(pair.normal) * pair.normal;
    const double slide = tangential.norm();
    if (!(slide > 0.0)) continue;
    // Coulomb: the slide shrinks by μ times the depth the pair was pushed out, at most to rest.
    push(pair, std::min(slide, friction * pair.depth), -tangential / slide, inverse_mass, next);
  }
}

void SelfContactResponse::respond(std::vector<SelfContactPair>& pairs,
                                  const Eigen::MatrixXd& current,
                                  const Eigen::VectorXd& inverse_mass, double friction,
                                  double thickness, Eigen::MatrixXd& next) {
  separate(pairs, inverse_mass, thickness, next);
  if (friction > 0.0) {
    apply_friction(pairs, current, inverse_mass, friction, next);
    separate(pairs, inverse_mass, thickness, next);
  }
}

}  // namespace wobble
