#ifndef WOBBLE_APP_INTERACTION_DRAG_SCRIPT_H
#define WOBBLE_APP_INTERACTION_DRAG_SCRIPT_H

#include <Eigen/Core>
#include <string>
#include <vector>

#include "sim/simulation.h"
#include "sim/value_limits.h"

namespace wobble {

// One drag from the command line, `--drag VERTEX:DX,DY,DZ@FRAME` or `...@FRAME-LAST`: vertex
// VERTEX is taken hold of before the step of frame FRAME (1-based) and its pin target moved by
// (DX, DY, DZ) metres, in equal parts over frames FRAME to LAST (default FRAME + 29: half a
// second at 60 frames a second). Like a mouse drag, a free vertex is pinned for the drag and let
// go before the step of frame LAST + 1, keeping its velocity; a pinned one stays where it was
// taken.
struct ScriptedDrag {
  int vertex = 0;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  long first_frame = 1, last_frame = 1;
  std::string text;  // as typed, for messages

  static constexpr long default_frames = 30;
  static constexpr double max_offset = limits::coordinate.high;  // m, per coordinate
};

// Parse one --drag value. Throws InputError naming --drag, the value and the expected form.
ScriptedDrag parse_drag(const std::string& text, long max_frame);

// Scripted drags applied frame by frame to a simulation, as the viewer's mouse would.
class DragScript {
 public:
  DragScript() = default;
  // Throws InputError when a drag names a vertex the scene does not have.
  DragScript(std::vector<ScriptedDrag> drags, long vertex_count);

  // Call before the step of `frame` (1-based; steps_taken() + 1). Calling it twice for one frame
  // (a rolled-back step is taken again) does no harm.
  void before_step(Simulation& simulation, long frame);
  // Forget every drag in progress; the simulation was reset or replaced.
  void restart();
  bool empty() const { return drags_.empty(); }
  // Whether a scripted drag holds a vertex now.
  bool holds_vertex() const;

 private:
  struct Hold {
    bool held = false;
    bool was_free = false;
    Eigen::Vector3d start = Eigen::Vector3d::Zero();
  };
  std::vector<ScriptedDrag> drags_;
  std::vector<Hold> holds_;
};

}  // namespace wobble

#endif
