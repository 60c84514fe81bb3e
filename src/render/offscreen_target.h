#ifndef WOBBLE_RENDER_OFFSCREEN_TARGET_H
#define WOBBLE_RENDER_OFFSCREEN_TARGET_H

#include <glad/gl.h>

#include <vector>

namespace wobble {

// A framebuffer object to draw into when there is no window: 4× multisampled colour and depth,
// resolved into a plain colour buffer for reading back, so headless images are antialiased like
// the window's. Needs a current GL context. Throws std::runtime_error when the driver refuses
// the size or the format.
class OffscreenTarget {
 public:
  OffscreenTarget(int width, int height, int samples = 4);
  ~OffscreenTarget();
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;

  // Make it the target of drawing.
  void bind() const;
  // Resolve the samples and read the image: width × height RGBA, first row at the top.
  void read_rgba(std::vector<unsigned char>& rgba) const;

  // Wait until everything drawn so far is done (for honest frame timings).
  void finish() const { glFinish(); }

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  GLuint multisampled_ = 0, resolved_ = 0;
  GLuint renderbuffers_[3] = {0, 0, 0};  // multisampled colour and depth, resolved colour
};

// Read the colour of the bound read framebuffer (a window's back buffer, say): width × height
// RGBA, first row at the top, as image files store it.
void read_framebuffer_rgba(int width, int height, std::vector<unsigned char>& rgba);

}  // namespace wobble

#endif
