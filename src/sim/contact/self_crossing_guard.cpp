#include "sim/contact/self_crossing_guard.h"

#include <algorithm>
#include <initializer_list>

#include "sim/contact/vertex_row.h"

namespace wobble {

namespace {

constexpr int chunks = 32;
// The most triangles a round looks at for one edge, and edges for one triangle.
constexpr int max_met = 1024;

// Whether segment pq passes through triangle abc: p and q strictly on opposite sides of its
// plane, and the line pq inside or on all three of its edges (signed volumes).
bool segment_crosses_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                              const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector3d& c) {
  const auto volume = [](const Eigen::Vector3d& w, const Eigen::Vector3d& x,
                         const Eigen::Vector3d& y,
                         const Eigen::Vector3d& z) { return (x - w).dot((y - w).cross(z - w)); };
  const double side_p = volume(a, b, c, p), side_q = volume(a, b, c, q);
  if (!((side_p > 0.0 && side_q < 0.0) || (side_p < 0.0 && side_q > 0.0))) return false;
  const double u = volume(p, q, a, b), v = volume(p, q, b, c), w = volume(p, q, c, a);
  return (u >= 0.0 && v >= 0.0 && w >= 0.0) || (u <= 0.0 && v <= 0.0 && w <= 0.0);
}

}  // namespace

bool SelfCrossingGuard::crosses(const SelfCollisionSurface& surface, int edge, int triangle,
                                const Eigen::MatrixXd& current, const Eigen::MatrixXd& next) const {
  const int p = surface.edges(edge, 0), q = surface.edges(edge, 1);
  const int a = surface.triangles(triangle, 0), b = surface.triangles(triangle, 1),
            c = surface.triangles(triangle, 2);
  if (p == a || p == b || p == c || q == a || q == b || q == c) return false;
  if (!segment_crosses_triangle(vertex_row(next, p), vertex_row(next, q), vertex_row(next, a),
                                vertex_row(next, b), vertex_row(next, c))) {
    return false;
  }
  // A crossing the step started with (a tangle from before) is not this step's doing.
  return !segment_crosses_triangle(vertex_row(current, p), vertex_row(current, q),
                                   vertex_row(current, a), vertex_row(current, b),
                                   vertex_row(current, c));
}

void SelfCrossingGuard::build_grids(const SelfCollisionSurface& surface,
                                    const Eigen::MatrixXd& next, const std::vector<char>* watched) {
  const auto watching = [&](std::initializer_list<int> vertices) {
    if (watched == nullptr) return true;
    for (const int v : vertices) {
      if ((*watched)[v]) return true;
    }
    return false;
  };
  triangle_boxes_.resize(surface.triangles.rows());
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    const int a = surface.triangles(t, 0), b = surface.triangles(t, 1), c = surface.triangles(t, 2);
    Eigen::AlignedBox3d box;  // empty: not filed
    if (watching({a, b, c})) {
      box.extend(vertex_row(next, a));
      box.extend(vertex_row(next, b));
      box.extend(vertex_row(next, c));
    }
    triangle_boxes_[t] = box;
  }
  edge_boxes_.resize(surface.edges.rows());
  for (Eigen::Index e = 0; e < surface.edges.rows(); ++e) {
    const int p = surface.edges(e, 0), q = surface.edges(e, 1);
    Eigen::AlignedBox3d box;
    if (watching({p, q})) {
      box.extend(vertex_row(next, p));
      box.extend(vertex_row(next, q));
    }
    edge_boxes_[e] = box;
  }
  const double cell = surface.mean_edge > 0.0 ? 1.5 * surface.mean_edge : 1.0;
  triangle_grid_.build(triangle_boxes_, cell);
  edge_grid_.build(edge_boxes_, cell);
}

int SelfCrossingGuard::undo_crossings(const SelfCollisionSurface& surface,
                                      const Eigen::MatrixXd& current,
                                      const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next,
                                      std::vector<char>& put_back,
                                      const std::vector<char>* watched) {
  if (watched != nullptr &&
      std::find(watched->begin(), watched->end(), char{1}) == watched->end()) {
    return 0;  // nothing came near anything
  }
  frozen_.assign(next.rows(), 0);
  edge_checked_.assign(surface.edges.rows(), -1);
  triangle_checked_.assign(surface.triangles.rows(), -1);
  int undone = 0;
  const int edge_count = static_cast<int>(surface.edges.rows());
  // A crossing with a pinned vertex is not undone with the others: the pin follows its target,
  // and putting ever more of the cloth back would only hold it still in the pin's way. It is
  // listed, and tried once at the end (resolve_pinned).
  pinned_crossings_.clear();
  const auto add_crossing = [&](int e, int t, std::vector<int>& crossed) {
    const int vertices[5] = {surface.edges(e, 0), surface.edges(e, 1), surface.triangles(t, 0),
                             surface.triangles(t, 1), surface.triangles(t, 2)};
    for (const int v : vertices) {
      if (!(inverse_mass(v) > 0.0)) {
        // Marked by a negative edge id, so the lists of free vertices stay flat.
        crossed.push_back(-1 - e);
        crossed.push_back(t);
        return;
      }
    }
    crossed.insert(crossed.end(), vertices, vertices + 5);
  };
  const auto sort_out = [&](const std::vector<int>& found) {
    for (std::size_t k = 0; k < found.size();) {
      if (found[k] < 0) {
        pinned_crossings_.emplace_back(-1 - found[k], found[k + 1]);
        k += 2;
      } else {
        crossed_.insert(crossed_.end(), found.begin() + k, found.begin() + k + 5);
        k += 5;
      }
    }
  };
  for (int round = 0;; ++round) {
    build_grids(surface, next, round == 0 ? watched : nullptr);
    crossed_.clear();
    if (round == 0) {
      // Every edge against every triangle near it.
      chunk_crossed_.resize(chunks);
      auto task = [&](int chunk) {
        std::vector<int>& crossed = chunk_crossed_[chunk];
        crossed.clear();
        const int first = static_cast<int>(static_cast<long long>(edge_count) * chunk / chunks);
        const int last =
            static_cast<int>(static_cast<long long>(edge_count) * (chunk + 1) / chunks);
        for (int e = first; e < last; ++e) {
          // An edge that is not watched has an empty box: it overlaps nothing. At most
          // max_met triangles an edge (a pile of coincident triangles stays bounded).
          int met = 0;
          triangle_grid_.for_each_overlapping(edge_boxes_[e], [&](int t) {
            if (crosses(surface, e, t, current, next)) add_crossing(e, t, crossed);
            return ++met < max_met;
          });
        }
      };
      WorkerPool::shared().run(chunks, task, &payoff_);
      for (const std::vector<int>& crossed : chunk_crossed_)
        sort_out(crossed);
    } else {
      // Only what touches a vertex just put back can cross anything new.
      found_.clear();
      for (const int v : changed_) {
        for (int s = surface.vertex_edges.begin(v); s < surface.vertex_edges.end(v); ++s) {
          const int e = surface.vertex_edges.ids[s];
          if (edge_checked_[e] == round) continue;
          edge_checked_[e] = round;
          int met = 0;
          triangle_grid_.for_each_overlapping(edge_boxes_[e], [&](int t) {
            if (crosses(surface, e, t, current, next)) add_crossing(e, t, found_);
            return ++met < max_met;
          });
        }
        for (int s = surface.vertex_triangles.begin(v); s < surface.vertex_triangles.end(v); ++s) {
          const int t = surface.vertex_triangles.ids[s];
          if (triangle_checked_[t] == round) continue;
          triangle_checked_[t] = round;
          int met = 0;
          edge_grid_.for_each_overlapping(triangle_boxes_[t], [&](int e) {
            if (crosses(surface, e, t, current, next)) add_crossing(e, t, found_);
            return ++met < max_met;
          });
        }
      }
      sort_out(found_);
    }
    // The crossing vertices and their neighbours go back to where they started (a pinned
    // neighbour stays with its target).
    changed_.clear();
    const auto undo = [&](int v) {
      if (frozen_[v] || !(inverse_mass(v) > 0.0)) return;
      frozen_[v] = 1;
      next.row(v) = current.row(v);
      put_back[v] = 1;
      changed_.push_back(v);
    };
    for (const int v : crossed_) {
      undo(v);
      for (int s = surface.vertex_edges.begin(v); s < surface.vertex_edges.end(v); ++s) {
        const int e = surface.vertex_edges.ids[s];
        undo(surface.edges(e, 0) == v ? surface.edges(e, 1) : surface.edges(e, 0));
      }
    }
    undone += static_cast<int>(changed_.size());
    // Every vertex that could move has gone back: the step ends where it started, but for pins.
    if (changed_.empty()) break;
  }
  return undone + resolve_pinned(surface, current, inverse_mass, next, put_back);
}

int SelfCrossingGuard::resolve_pinned(const SelfCollisionSurface& surface,
                                      const Eigen::MatrixXd& current,
                                      const Eigen::VectorXd& inverse_mass, Eigen::MatrixXd& next,
                                      std::vector<char>& put_back) {
  int undone = 0;
  std::sort(pinned_crossings_.begin(), pinned_crossings_.end());
  pinned_crossings_.erase(std::unique(pinned_crossings_.begin(), pinned_crossings_.end()),
                          pinned_crossings_.end());
  for (const auto& [e, t] : pinned_crossings_) {
    if (!crosses(surface, e, t, current, next)) continue;
    // The crossing's free vertices and their free neighbours back where they started; kept only
    // if that ends this crossing and makes no other around them.
    changed_.clear();
    saved_.clear();
    const auto undo = [&](int v) {
      if (frozen_[v] || !(inverse_mass(v) > 0.0)) return;
      frozen_[v] = 1;
      saved_.emplace_back(v, Eigen::Vector3d(next.row(v).transpose()));
      next.row(v) = current.row(v);
      changed_.push_back(v);
    };
    const int vertices[5] = {surface.edges(e, 0), surface.edges(e, 1), surface.triangles(t, 0),
                             surface.triangles(t, 1), surface.triangles(t, 2)};
    for (const int v : vertices) {
      if (!(inverse_mass(v) > 0.0)) continue;
      undo(v);
      for (int s = surface.vertex_edges.begin(v); s < surface.vertex_edges.end(v); ++s) {
        const int f = surface.vertex_edges.ids[s];
        undo(surface.edges(f, 0) == v ? surface.edges(f, 1) : surface.edges(f, 0));
      }
    }
    if (changed_.empty()) continue;
    build_grids(surface, next);
    bool crossing = crosses(surface, e, t, current, next);
    for (std::size_t k = 0; k < changed_.size() && !crossing; ++k) {
      const int v = changed_[k];
      for (int s = surface.vertex_edges.begin(v); s < surface.vertex_edges.end(v) && !crossing;
           ++s) {
        const int f = surface.vertex_edges.ids[s];
        triangle_grid_.for_each_overlapping(edge_boxes_[f], [&](int u) {
          crossing = crosses(surface, f, u, current, next);
          return !crossing;
        });
      }
      for (int s = surface.vertex_triangles.begin(v);
           s < surface.vertex_triangles.end(v) && !crossing; ++s) {
        const int u = surface.vertex_triangles.ids[s];
        edge_grid_.for_each_overlapping(triangle_boxes_[u], [&](int f) {
          crossing = crosses(surface, f, u, current, next);
          return !crossing;
        });
      }
    }
    if (crossing) {
      for (const auto& [v, position] : saved_) {
        next.row(v) = position.transpose();
        frozen_[v] = 0;
      }
      continue;
    }
    for (const int v : changed_)
      put_back[v] = 1;
    undone += static_cast<int>(changed_.size());
  }
  return undone;
}

std::size_t SelfCrossingGuard::memory_bytes() const {
  std::size_t bytes =
      (triangle_boxes_.capacity() + edge_boxes_.capacity()) * sizeof(Eigen::AlignedBox3d) +
      triangle_grid_.memory_bytes() + edge_grid_.memory_bytes() +
      (crossed_.capacity() + changed_.capacity() + edge_checked_.capacity() +
       triangle_checked_.capacity() + found_.capacity()) *
          sizeof(int) +
      frozen_.capacity() + saved_.capacity() * sizeof(saved_[0]) +
      pinned_crossings_.capacity() * sizeof(pinned_crossings_[0]);
  for (const std::vector<int>& crossed : chunk_crossed_)
    bytes += crossed.capacity() * sizeof(int);
  return bytes;
}

}  // namespace wobble
