#ifndef WOBBLE_APP_HEADLESS_RENDER_OFFSCREEN_H
#define WOBBLE_APP_HEADLESS_RENDER_OFFSCREEN_H

#include <vector>

#include "app/outputs/image_outputs.h"
#include "app/outputs/instrument_csv.h"
#include "app/outputs/obj_sequence.h"
#include "app/outputs/run_statistics.h"
#include "app/viewer/viewer.h"
#include "io/png_image.h"
#include "platform/egl_context.h"

namespace wobble {

struct OffscreenOptions {
  int width = 1280, height = 720;  // pixels
  long frames = 1;                 // one time step each
  bool ui = false;                 // draw the ImGui panel into the images too
};

// What an offscreen run measured. (What each step writes, and its timing, observe the viewer's
// steps: app/outputs/step_outputs.h.)
struct OffscreenReport {
  std::vector<double> render_ms;  // per frame: drawing, UI and read-back (when an image is read)
  std::string context;            // which EGL platform and GL driver drew, on one line
  GlDriver driver;                // the same, field by field
};

// The headless mode's frames: make an EGL context and a framebuffer object, then draw
// `options.frames` frames of `viewer` through draw_frame (app/viewer/frame_loop.h: the window's
// and the page's order, one step a frame) and return the image after the last step. `outputs`, if
// given, receives the frames it wants. Nothing in the images depends on the wall clock, so the same
// inputs give the same pixels. Throws ContextError when EGL cannot give a GL 3.3 context.
RgbaImage render_offscreen(Viewer& viewer, const OffscreenOptions& options,
                           ImageOutputs* outputs = nullptr, OffscreenReport* report = nullptr);

}  // namespace wobble

#endif
