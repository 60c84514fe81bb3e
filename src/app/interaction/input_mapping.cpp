#include "app/interaction/input_mapping.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>  // key and button codes only: nothing here calls GLFW

namespace wobble {

ViewerCommand command_for_key(int key, bool control) {
  // Esc is what a presenter presses to back out of something: it must never end the demo.
  if (control) {
    if (key == GLFW_KEY_Q) return ViewerCommand::quit;
    return key == GLFW_KEY_S ? ViewerCommand::save_scene : ViewerCommand::none;
  }
  switch (key) {
    case GLFW_KEY_SPACE:
      return ViewerCommand::toggle_pause;
    case GLFW_KEY_S:
      return ViewerCommand::step_once;
    case GLFW_KEY_R:
      return ViewerCommand::reset;
    case GLFW_KEY_E:
      return ViewerCommand::toggle_wireframe;
    case GLFW_KEY_W:
      return ViewerCommand::toggle_wind;
    case GLFW_KEY_C:
      return ViewerCommand::toggle_colliders;
    case GLFW_KEY_P:
      return ViewerCommand::toggle_points;
    case GLFW_KEY_L:
      return ViewerCommand::toggle_springs;
    case GLFW_KEY_V:
      return ViewerCommand::cycle_color_by;
    case GLFW_KEY_H:
      return ViewerCommand::toggle_help;
    case GLFW_KEY_F:
      return ViewerCommand::frame_mesh;
    case GLFW_KEY_O:
      return ViewerCommand::default_view;
    case GLFW_KEY_G:
      return ViewerCommand::toggle_plots;
    case GLFW_KEY_2:
      return ViewerCommand::toggle_split;
    case GLFW_KEY_F12:
      return ViewerCommand::screenshot;
    case GLFW_KEY_TAB:
      return ViewerCommand::toggle_panel;
    case GLFW_KEY_F11:
      return ViewerCommand::export_obj;
    case GLFW_KEY_F9:
      return ViewerCommand::toggle_record;
    case GLFW_KEY_ESCAPE:
      return ViewerCommand::close_overlays;
    default:
      return ViewerCommand::none;
  }
}

MouseGesture gesture_for_press(int button, bool control, bool shift, bool over_ui, bool over_pin,
                               bool over_vertex, bool alt, bool over_collider) {
  if (over_ui) return MouseGesture::none;
  if (button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE) {
    return MouseGesture::pan;
  }
  if (button != GLFW_MOUSE_BUTTON_LEFT) return MouseGesture::none;
  // Alt is only for colliders: a missed Alt+click must not grab the cloth or turn the camera.
  if (alt) return over_collider ? MouseGesture::grab_collider : MouseGesture::none;
  if (control) return over_vertex ? MouseGesture::toggle_pin : MouseGesture::none;
  // Shift+drag pans, for touchpads without a middle or right button.
  if (shift) return MouseGesture::pan;
  if (over_pin) return MouseGesture::grab_pin;
  if (over_vertex) return MouseGesture::grab_free_vertex;
  return MouseGesture::orbit;
}

const std::vector<Binding>& viewer_bindings() {
  static const std::vector<Binding> bindings = {
      {"Space", "pause / play"},
      {"S", "step once"},
      {"R", "reset the scene"},
      {"W", "wind on / off"},
      {"E", "wireframe on / off"},
      {"C", "colliders shown / hidden"},
      {"P", "vertices as points on / off"},
      {"L", "springs as lines on / off"},
      {"V", "colour by material / strain / speed / contacts"},
      {"F", "frame the mesh and the room it moves in"},
      {"O", "the scene's opening view"},
      {"G", "convergence and energy plots on / off"},
      {"2", "split view: the scene twice, the right side with its own settings"},
      {"Tab", "the control panel shown / hidden"},
      {"F12", "screenshot: wobble-SCENE-0001.png, ... in the working folder"},
      {"F11", "export the current positions: wobble-SCENE-0001.obj, ..."},
      {"F9",
       "record on / off: each new state, as PNG frames in wobble-SCENE-frames-0001/ or a "
       "WebM or MP4 video, of the scene alone or the whole window (the panel's record combo)"},
      {"Ctrl+S", "save the scene, its pins and settings: wobble-SCENE-scene-0001.json"},
      {"H", "this help on / off"},
      {"Esc", "close the help (never quits)"},
      {"Ctrl+Q", "quit (or the window's close button)"},
      {"Left-drag a pin", "move the pin; the shape follows"},
      {"Left-drag a vertex", "hold it while dragging; let go to throw"},
      {"Ctrl+click a vertex", "pin / unpin it"},
      {"Alt+left-drag a collider", "move the sphere, box or capsule"},
      {"Left-drag elsewhere", "orbit the camera"},
      {"Right/middle or Shift+left-drag", "pan"},
      {"Wheel", "zoom (stops short of the shape and far from it)"},
  };
  return bindings;
}

std::vector<Binding> page_bindings() {
  std::vector<Binding> bindings;
  for (const Binding& binding : viewer_bindings()) {
    const std::string& input = binding.input;
    if (input == "F12" || input == "F11" || input == "F9" || input == "Ctrl+Q") continue;
    if (input == "H") {
      bindings.push_back({"PNG, OBJ, Save scene",
                          "the panel's buttons: downloads of the picture, "
                          "the positions, the scene and its mesh"});
    }
    if (input == "Ctrl+S") {
      // The page keeps both keys from the browser (index.html): no "Save page" nor "Open file".
      bindings.push_back({"Ctrl+S / Cmd+S",
                          "save the scene, its pins and settings: a download of "
                          "wobble-SCENE-scene-0001.json and its mesh"});
      bindings.push_back({"Ctrl+O / Cmd+O",
                          "open a scene, mesh or texture: the browser's file chooser (or drop "
                          "the files on the page)"});
      continue;
    }
    bindings.push_back(binding);
  }
  return bindings;
}

}  // namespace wobble
