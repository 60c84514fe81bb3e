#ifndef WOBBLE_APP_HEADLESS_RENDER_OFFSCREEN_H
#define WOBBLE_APP_HEADLESS_RENDER_OFFSCREEN_H

#include <vector>

#include "app/outputs/image_outputs.h"
#include "app/outputs/instrument_csv.h"
#include "app/outputs/obj_sequence.h"
#include "app/outputs/run_statistics.h"
#include "app/viewer/viewer.h"
#include "io/png_image.h"

namespace wobble {

struct OffscreenOptions {
  int width = 1280, height = 720;             // pixels
  long frames = 1;                            // one time step each
  bool ui = false;                            // draw the ImGui panel into the images too
  const ObjSequence* obj_sequence = nullptr;  // also write each frame's positions as OBJ
  InstrumentCsv* instruments = nullptr;       // rows of each frame's convergence and energy
};

// What an offscreen run measured.
struct OffscreenReport {
  StepTimes times;                // per frame: the simulation step
  std::vector<double> render_ms;  // per frame: drawing, UI and read-back (when an image is read)
  std::string context;            // which EGL platform and GL renderer drew
};

// The headless mode's frame loop: make an EGL context and a framebuffer object, then run
// `options.frames` frames of `viewer` (UI, one step, render: the window's order) and return the
// image after the last step. `outputs`, if given, receives the frames it wants. Nothing in the
// images depends on the wall clock, so the same inputs give the same pixels. Throws ContextError
// when EGL cannot give a GL 3.3 context.
RgbaImage render_offscreen(Viewer& viewer, const OffscreenOptions& options,
                           ImageOutputs* outputs = nullptr, OffscreenReport* report = nullptr);

}  // namespace wobble

#endif
