#include "app/interaction/drag_script.h"

#include <cmath>
#include <optional>

#include "sim/parse_number.h"
#include "sim/input_error.h"

namespace wobble {

ScriptedDrag parse_drag(const std::string& text, long max_frame) {
  const auto refuse = [&text](const std::string& why) {
    return InputError("--drag: expected VERTEX:DX,DY,DZ@FRAME or VERTEX:DX,DY,DZ@FRAME-LAST, " +
                      why + ", got '" + text + "'");
  };
  const std::size_t colon = text.find(':');
  const std::size_t at = text.find('@');
  if (colon == std::string::npos || at == std::string::npos || at < colon) {
    throw refuse("with a ':' and then an '@'");
  }
  ScriptedDrag drag;
  drag.text = text;
  const std::optional<int> vertex = parse_number<int>(text.substr(0, colon));
  if (!vertex || *vertex < 0) throw refuse("VERTEX a vertex index from 0");
  drag.vertex = *vertex;

  const std::string offset = text.substr(colon + 1, at - colon - 1);
  std::size_t begin = 0;
  for (int c = 0; c < 3; ++c) {
    const std::size_t comma = c < 2 ? offset.find(',', begin) : offset.size();
    if (comma == std::string::npos) throw refuse("three offsets DX,DY,DZ in metres");
    const std::optional<double> value = parse_number<double>(offset.substr(begin, comma - begin));
    if (!value || !std::isfinite(*value) || std::abs(*value) > ScriptedDrag::max_offset) {
      throw refuse("offsets DX,DY,DZ " + within_text(limits::coordinate));
    }
    drag.offset(c) = *value;
    begin = comma + 1;
  }
  if (begin != offset.size() + 1) throw refuse("three offsets DX,DY,DZ in metres");

  const std::string frames = text.substr(at + 1);
  const std::size_t dash = frames.find('-');
  const std::optional<long> first = parse_number<long>(frames.substr(0, dash));
  if (!first || *first < 1 || *first > max_frame) {
    throw refuse("FRAME a frame from 1 to " + std::to_string(max_frame));
  }
  drag.first_frame = *first;
  if (dash == std::string::npos) {
    drag.last_frame = *first + ScriptedDrag::default_frames - 1;
  } else {
    const std::optional<long> last = parse_number<long>(frames.substr(dash + 1));
    if (!last || *last < *first || *last > max_frame) {
      throw refuse("LAST a frame from FRAME to " + std::to_string(max_frame));
    }
    drag.last_frame = *last;
  }
  return drag;
}

DragScript::DragScript(std::vector<ScriptedDrag> drags, long vertex_count)
    : drags_(std::move(drags)), holds_(drags_.size()) {
  for (const ScriptedDrag& drag : drags_) {
    if (drag.vertex >= vertex_count) {
      throw InputError("--drag: vertex " + std::to_string(drag.vertex) +
                       " is out of range: the scene has " + std::to_string(vertex_count) +
                       " vertices, 0 to " + std::to_string(vertex_count - 1) + " (in '" +
                       drag.text + "')");
    }
  }
}

void DragScript::before_step(Simulation& simulation, long frame) {
  for (std::size_t d = 0; d < drags_.size(); ++d) {
    const ScriptedDrag& drag = drags_[d];
    Hold& hold = holds_[d];
    if (frame == drag.first_frame && !hold.held) {
      hold.held = true;
      hold.was_free = !simulation.is_pinned(drag.vertex);
      if (hold.was_free) simulation.pin(drag.vertex);
      hold.start = simulation.pin_target(drag.vertex);
    }
    if (!hold.held) continue;
    // Someone else (the mouse, another drag) let go of the vertex: this drag is over.
    if (!simulation.is_pinned(drag.vertex)) {
      hold = Hold();
      continue;
    }
    if (frame > drag.last_frame) {
      if (hold.was_free) simulation.unpin(drag.vertex);
      hold = Hold();
      continue;
    }
    const double done = static_cast<double>(frame - drag.first_frame + 1) /
                        static_cast<double>(drag.last_frame - drag.first_frame + 1);
    simulation.set_pin_target(drag.vertex, hold.start + done * drag.offset);
  }
}

bool DragScript::holds_vertex() const {
  for (const Hold& hold : holds_) {
    if (hold.held) return true;
  }
  return false;
}

void DragScript::restart() {
  for (Hold& hold : holds_)
    hold = Hold();
}

}  // namespace wobble
