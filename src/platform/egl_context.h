#ifndef WOBBLE_PLATFORM_EGL_CONTEXT_H
#define WOBBLE_PLATFORM_EGL_CONTEXT_H

#include <string>

#include "context_error.h"

namespace wobble {

// The headless mode's context: a GL 3.3 core context made current through EGL with no surface
// at all, loaded through glad. Drawing goes to an OffscreenTarget. No DISPLAY is needed.
//
// It tries EGL's device platform first (what works on NVIDIA's driver), then Mesa's surfaceless
// platform. WOBBLE_EGL_PLATFORM=device or =surfaceless in the environment allows only that one.
// libEGL.so.1 is opened at run time, so the program starts without it (the window needs none).
// What drew a headless picture, for a CI log beside a failing image.
struct GlDriver {
  std::string platform;                   // EGL's: "device" or "surfaceless"
  std::string vendor, renderer, version;  // GL_VENDOR, GL_RENDERER, GL_VERSION
};

class EglContext {
 public:
  // Throws ContextError with one line naming each EGL call that failed and what to install.
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // Which platform worked and the GL driver on one line, e.g. "EGL surfaceless, Mesa, llvmpipe
  // (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
  const std::string& description() const { return description_; }
  const GlDriver& driver() const { return driver_; }

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  std::string description_;
  GlDriver driver_;
};

}  // namespace wobble

#endif
