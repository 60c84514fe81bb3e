#ifndef WOBBLE_RENDER_PIN_MARK_SIZES_H
#define WOBBLE_RENDER_PIN_MARK_SIZES_H

#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

namespace wobble {

// How large a pin's marker is drawn (pixels), from how close the next pin is on screen.
struct PinMarkRule {
  float largest = 10.0f;       // pins far apart: today's markers
  float smallest = 3.0f;       // never smaller, however dense (they may then touch)
  float spacing_share = 0.8f;  // at most this share of the distance to the nearest other pin
};

// Marker diameters that keep dense pins (a curtain's rail of 81) apart as separate dots instead
// of merging into one bar, while sparse pins (a cloth's two corners) keep the largest size.
// Needs no GL. Keeps its buffers, so calling it every frame allocates nothing once they have
// grown to the pins' number.
class PinMarkSizes {
 public:
  // screen     #P by 2 positions of the pins on screen (pixels), row-major
  // returns    #P diameters (pixels): rule.largest, or rule.spacing_share × the distance to the
  //            nearest other pin where that is smaller, but not below rule.smallest
  // Neighbours are looked up in a grid of cells rule.largest / rule.spacing_share wide (beyond
  // that a neighbour changes nothing), so the cost grows as #P log #P, not #P².
  const std::vector<float>& compute(const float* screen, int pin_count, const PinMarkRule& rule);

 private:
  std::vector<std::pair<std::uint64_t, int>> cells_;  // (cell key, pin), sorted by key
  std::vector<float> diameters_;
};

// The pins of a mesh and their markers' diameters under a view, a vertex at a time, as the
// renderer uploads them: PinMarkSizes over the pins in front of the eye (only they are drawn, so
// only they can crowd one another). Needs no GL.
class PinMarks {
 public:
  // A mesh of `vertex_count` vertices: no pins until taken, every diameter 0 until sized.
  void reset(int vertex_count) {
    pin_vertices_.clear();
    pin_positions_.clear();
    vertex_diameters_.assign(vertex_count, 0.0f);
  }
  // The diameters as last sized (#V).
  const std::vector<float>& diameters() const { return vertex_diameters_; }
  // This frame's pins: the vertices whose mark is not 0, and where they are (#V by 3).
  void take(const unsigned char* marks, const float* positions);
  // Each vertex's marker diameter (pixels, #V; read for pins only) under `view_projection` in a
  // viewport `width` x `height` pixels; sizes scaled by `pixel_ratio`. A pin behind the eye or
  // well off screen keeps the diameter it had. Empty of pins: no work.
  const std::vector<float>& size(const Eigen::Matrix4f& view_projection, int width, int height,
                                 float pixel_ratio);
  bool empty() const { return pin_vertices_.empty(); }

 private:
  std::vector<float> vertex_diameters_, pin_positions_, pin_screen_;
  std::vector<int> pin_vertices_, pins_in_front_;
  PinMarkSizes sizes_;
};

}  // namespace wobble

#endif
