#include "app/interaction/ground_placement.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace wobble {

double ground_grid_height(const Eigen::MatrixXd& V, const Eigen::MatrixXi& E,
                          const std::vector<int>& pins, const std::vector<Collider>& colliders) {
  double ground = -std::numeric_limits<double>::infinity();
  for (const Collider& collider : colliders) {
    if (collider.type == ColliderType::ground) ground = std::max(ground, collider.height);
  }
  if (ground > -std::numeric_limits<double>::infinity()) return ground;
  const int n = static_cast<int>(V.rows());
  if (n == 0) return 0.0;
  const double rest_lowest = V.col(1).minCoeff();
  const double margin =
      ground_margin_share *
      std::max((V.colwise().maxCoeff() - V.colwise().minCoeff()).maxCoeff(), 1e-3);
  if (pins.empty()) return rest_lowest - margin;

  // One Dijkstra from every pin at once. cost(v) = min over pins of (1.1·d(v, pin) − pin_y), so
  // that −cost(v) is the highest of the hanging bounds: a vertex cannot hang below any of them.
  std::vector<std::vector<std::pair<int, double>>> neighbours(n);
  for (Eigen::Index e = 0; e < E.rows(); ++e) {
    const int a = E(e, 0), b = E(e, 1);
    const double length = hanging_stretch * (V.row(a) - V.row(b)).norm();
    neighbours[a].emplace_back(b, length);
    neighbours[b].emplace_back(a, length);
  }
  const double unreached = std::numeric_limits<double>::infinity();
  std::vector<double> cost(n, unreached);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int pin : pins) {
    if (pin < 0 || pin >= n) continue;
    const double start = -V(pin, 1);
    if (start < cost[pin]) {
      cost[pin] = start;
      queue.emplace(start, pin);
    }
  }
  while (!queue.empty()) {
    const auto [c, v] = queue.top();
    queue.pop();
    if (c > cost[v]) continue;
    for (const auto& [w, length] : neighbours[v]) {
      if (c + length < cost[w]) {
        cost[w] = c + length;
        queue.emplace(cost[w], w);
      }
    }
  }
  // Vertices no pin holds fall freely; like a scene without pins, they count at rest.
  double lowest = rest_lowest;
  for (int v = 0; v < n; ++v) {
    if (cost[v] < unreached) lowest = std::min(lowest, -cost[v]);
  }
  return lowest - margin;
}

}  // namespace wobble
