#include "offscreen_target.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace wobble {

namespace {

void check_complete(const char* which, int width, int height) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return;
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", status);
  throw std::runtime_error(std::string("the GL driver refused a ") + which + " framebuffer of " +
                           std::to_string(width) + "x" + std::to_string(height) + " (status " +
                           code + ")");
}

}  // namespace

OffscreenTarget::OffscreenTarget(int width, int height, int samples)
    : width_(width), height_(height) {
  GLint max_size = 0, max_samples = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (width < 1 || height < 1 || width > max_size || height > max_size) {
    throw std::runtime_error("an image of " + std::to_string(width) + "x" + std::to_string(height) +
                             " is beyond this GL driver's limit of " + std::to_string(max_size) +
                             " pixels a side");
  }
  samples = std::min(samples, static_cast<int>(max_samples));

  glGenRenderbuffers(3, renderbuffers_);
  glGenFramebuffers(1, &multisampled_);
  glGenFramebuffers(1, &resolved_);

  glBindFramebuffer(GL_FRAMEBUFFER, multisampled_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            renderbuffers_[0]);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                            renderbuffers_[1]);
  check_complete("multisampled", width, height);

  glBindFramebuffer(GL_FRAMEBUFFER, resolved_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[2]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            renderbuffers_[2]);
  check_complete("resolve", width, height);
  bind();
}

OffscreenTarget::~OffscreenTarget() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &multisampled_);
  glDeleteFramebuffers(1, &resolved_);
  glDeleteRenderbuffers(3, renderbuffers_);
}

void OffscreenTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, multisampled_);
}

void OffscreenTarget::read_rgba(std::vector<unsigned char>& rgba) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_);
  read_framebuffer_rgba(width_, height_, rgba);
  bind();
}

void read_framebuffer_rgba(int width, int height, std::vector<unsigned char>& rgba) {
  const std::size_t row = 4 * static_cast<std::size_t>(width);
  rgba.resize(row * height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  // GL's first row is the bottom one.
  for (int y = 0; y < height / 2; ++y) {
    std::swap_ranges(rgba.begin() + y * row, rgba.begin() + (y + 1) * row,
                     rgba.begin() + (height - 1 - y) * row);
  }
  // The alpha channel holds whatever blending left there; an image of the screen is opaque.
  for (std::size_t i = 3; i < rgba.size(); i += 4)
    rgba[i] = 255;
}

}  // namespace wobble
