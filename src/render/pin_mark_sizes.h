#ifndef WOBBLE_RENDER_PIN_MARK_SIZES_H
#define WOBBLE_RENDER_PIN_MARK_SIZES_H

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

}  // namespace wobble

#endif
