#ifndef WOBBLE_APP_INTERACTION_INPUT_MAPPING_H
#define WOBBLE_APP_INTERACTION_INPUT_MAPPING_H

#include <string>
#include <vector>

namespace wobble {

// What a key does in the viewer.
enum class ViewerCommand {
  none,
  toggle_pause,
  step_once,
  reset,
  toggle_wireframe,
  toggle_wind,
  toggle_colliders,
  toggle_points,
  toggle_springs,
  cycle_color_by,  // material → strain → speed → contacts → material
  toggle_help,
  toggle_plots,    // the convergence and energy plots
  toggle_split,    // the split view: the scene twice, side by side
  screenshot,      // the window as a PNG in the working folder
  toggle_panel,    // Tab: the control panel shown / hidden
  export_obj,      // the current positions as an OBJ in the working folder
  save_scene,      // Ctrl+S: the scene, its pins and settings as a Wobble scene file
  toggle_record,   // F9: write every new state drawn as a PNG, into a new folder
  frame_mesh,      // frame the shape and the room it moves in, beside the panel
  default_view,    // back to the view the scene opened with
  close_overlays,  // Esc: the help overlay (ImGui closes its own menus and edits)
  quit,            // Ctrl+Q (and the window's close button)
};

// The command for a GLFW key code (GLFW_KEY_*); none for keys without one.
// With Ctrl held only Ctrl+Q (quit) and Ctrl+S (save the scene) mean something; Esc never
// quits, it closes the help.
ViewerCommand command_for_key(int key, bool control = false);

// What pressing a mouse button starts, given what is under the cursor.
enum class MouseGesture {
  none,              // ImGui has the mouse, or the button does nothing
  grab_pin,          // drag a pinned vertex's target
  grab_free_vertex,  // pin a free vertex for the length of the drag, then let it go
  toggle_pin,        // Ctrl+click: pin or unpin the vertex under the cursor
  grab_collider,     // Alt+drag: move the sphere, box or capsule under the cursor
  orbit,             // turn the camera about its target
  pan,               // slide the camera and its target
};

// `button` is a GLFW mouse button. `over_ui` is ImGui's io.WantCaptureMouse; `over_pin` and
// `over_vertex` say whether a pinned (or any) vertex is within the picking radius;
// `over_collider` whether the cursor ray meets a collider that can be grabbed.
MouseGesture gesture_for_press(int button, bool control, bool shift, bool over_ui, bool over_pin,
                               bool over_vertex, bool alt = false, bool over_collider = false);

// Every key and mouse action, for the help overlay and docs/viewer.md ("Mouse and keys"): {input,
// what it does}.
struct Binding {
  std::string input;
  std::string action;
};
const std::vector<Binding>& viewer_bindings();
// What of them works in a page (the help a page shows): the desktop's keys but those the browser
// keeps for itself (F12, F11, Ctrl+Q) and recording (F9, no folder to write into), the panel's
// buttons that download files in their place, Ctrl+S as a download and Ctrl+O, the browser's
// file chooser (the page keeps both from the browser).
std::vector<Binding> page_bindings();

}  // namespace wobble

#endif
