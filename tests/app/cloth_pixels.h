#ifndef WOBBLE_TESTS_APP_CLOTH_PIXELS_H
#define WOBBLE_TESTS_APP_CLOTH_PIXELS_H

namespace wobble::testing {

// Whether an RGBA pixel has the colour of the cloth's lit front (orange: red well above green,
// green well above blue), which neither the background nor the ground grid has.
inline bool is_cloth_front(const unsigned char* pixel) {
  return pixel[0] > pixel[1] + 30 && pixel[1] > pixel[2] + 20;
}

}  // namespace wobble::testing

#endif
