#ifndef WOBBLE_APP_VIEWER_VIEWER_H
#define WOBBLE_APP_VIEWER_VIEWER_H

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/command_line.h"
#include "app/cli/compare_settings.h"
#include "app/interaction/input_mapping.h"
#include "app/viewer/draw_state.h"
#include "app/viewer/pick_and_drag.h"
#include "app/viewer/quantity_colors.h"
#include "app/viewer/viewer_files.h"
#include "app/viewer/viewer_panel.h"
#include "app/viewer/viewer_session.h"
#include "platform/input_event.h"
#include "render/renderer.h"
#include "sim/shapes/builtin_scenes.h"
#include "sim/simulation.h"
#include "ui/control_panel.h"

namespace wobble {

// How the viewer starts: overrides of the scene's parameters, and what to show.
struct ViewerSettings {
  // What the command line changes of the first scene's settings (k, dt, iterations, solver,
  // Chebyshev, added settings).
  SettingsOverrides settings;
  ViewLayers layers;
  std::optional<float> camera_yaw_degrees, camera_pitch_degrees;
  float camera_zoom = 1.0f;         // times nearer than the framing (--camera-zoom)
  std::vector<ScriptedDrag> drags;  // applied to the first scene, from frame 1
  ColorQuantity color_by = ColorQuantity::material;
  std::optional<CompareSettings> compare;  // open in the split view with this right side
  bool plots = false;                      // open the convergence and energy plots
  // wobble --student: the step server built from the student's folder (student_server.h), or
  // empty. The split view then shows the student's sparse step on the right.
  std::string student_server;
  // Where the first scene came from (a built-in scene's name or a file), as scene_source says.
  std::string scene_source;
  // What the help (H) lists: viewer_bindings(), or a page's page_bindings().
  std::vector<Binding> help = viewer_bindings();
  // The page's own: its file picker and its link (the panel shows "Open file..." and "Copy
  // link" instead of the path field, and scene files open without a texture they lack, noted).
  // None in the window and headless.
  PageActions page;
  bool panel_folded = false;  // the panel opens folded to its title bar (a phone's screen)
};

// The start-up settings a command line asks for.
ViewerSettings viewer_settings(const CommandLine& command);

// Everything the window, the page and the headless mode share, as the wiring of components that
// each own their state (libigl's viewer plugins), called in a fixed order by one frame
// (draw_frame, app/viewer/frame_loop.h):
//   handle_events → build_ui → advance (headless) or exchange (window, page) → build_legend →
//   render
//
//   ViewerSession   the scene, the picker's catalogue, the simulation's side (SimulationHost),
//                   the split view's right side and the plots, and what the UI shows of them
//   ViewerPanel     the panel's own settings, where it lies, help, quit
//   DrawState       the camera, the arrays and colours drawn, the ground, the renderer
//   ViewerFiles     opening files, saving and recording, the notices told
//   PickAndDrag     the mouse's gesture in progress
// Callers reach a component through its accessor (viewer.session().simulation()); the viewer
// hands each what it acts on, and none reaches into another.
//
// The simulation's side and the UI's: the simulation and its scripted drags, the split view's
// right side and the student's step are touched by one batch of steps at a time. In the window a
// batch runs on a thread of its own (ViewerSession::step_on_thread) while the UI goes on drawing
// the state the last batch left, at the display's rate; what the user does meanwhile (drags,
// clicks, slider changes, Reset, a new scene) is kept, in order, and handed to the simulation
// once the batch finished, before the next one starts. Each step still has its fixed dt, so the
// results do not depend on the thread: N steps give the same positions as headless.
class Viewer {
 public:
  // `scene_sources` are what the scene picker offers (built-in names and scene files, as
  // load_scene takes them); `scene` is already built. No GL needed yet.
  Viewer(Scene scene, const ViewerSettings& settings, std::vector<std::string> scene_sources);
  ~Viewer();

  // Replace the scene (what the scene picker does), once a running batch of steps finished.
  // Throws, leaving the viewer as it was, when the scene's texture cannot be read or its
  // simulation cannot be built.
  void load(Scene scene);
  // Mouse and keys since the last frame. `ui_wants_mouse`/`ui_wants_keyboard` are ImGui's
  // io.WantCaptureMouse/WantCaptureKeyboard: what the panel takes, the 3-D view ignores.
  void handle_events(const std::vector<InputEvent>& events, bool ui_wants_mouse,
                     bool ui_wants_keyboard, const Eigen::Vector2f& window_size);
  // The panel, the help overlay, the notices and what ImGui draws over the scene (the plots, the
  // split view's corner labels), between ImGui's NewFrame and Render; applies what changed.
  // Without `whole_panel`, only what ImGui draws over the scene (headless images without --ui).
  void build_ui(const PanelStats& timings, float ui_scale, bool whole_panel = true);
  // One time step, unless paused, finished before it returns (headless, tests). A step the
  // simulation rolls back pauses the viewer and sets the session's step_warning. Then, paused or
  // not, the state to be drawn, with the panel's colours.
  void advance();
  // The window's and the page's frame: if a batch of steps still runs, nothing (the UI draws the
  // last state; returns false). Otherwise take the finished batch's results, hand over what the
  // user did since, in order, take the state to be drawn, and start the next batch: one step if
  // one was asked for; while playing, in real-time mode as many as keep up with the wall clock
  // `now` (s) but fit in `frame_seconds` (StepPacer), otherwise one. Returns true.
  bool exchange(double now, double frame_seconds);
  // Wait for a running batch and take its results (before the window closes, and at the end of
  // a --frames run).
  void finish_steps();
  // The colour bar of the panel's colouring (ImGui, after advance so that it shows the range this
  // frame is drawn with, and before ImGui::Render); nothing for material.
  void build_legend(float ui_scale);
  // Draw into the bound framebuffer. `window_size` is in the units of the mouse events;
  // `pixel_ratio` is framebuffer pixels per window unit; `mark_scale` is framebuffer pixels per
  // pixel of a mark's size (pin dots, the held vertex, bands of springs): the pixel ratio where
  // window units are the screen's points (unset: `pixel_ratio`), the page's device pixel ratio
  // in the page. Without `draw`, only what drawing would change besides the pixels: the camera's
  // framing, the drawn positions and marks (a frame no one sees still frames the shape as one seen
  // would).
  void render(int framebuffer_width, int framebuffer_height, const Eigen::Vector2f& window_size,
              float pixel_ratio, std::optional<float> mark_scale = std::nullopt, bool draw = true);
  // Whether the next frames change without input: playing, a step asked for, the mouse holding
  // something or turning the camera, a batch running or changes waiting for one. A paused viewer
  // with none of these can wait for input instead of redrawing the same picture.
  bool animating() const;

  // The components.
  ViewerSession& session() { return session_; }
  const ViewerSession& session() const { return session_; }
  const ViewerPanel& panel() const { return panel_state_; }
  DrawState& drawing() { return drawing_; }
  const DrawState& drawing() const { return drawing_; }
  ViewerFiles& files() { return files_; }

 private:
  // The scene as it opened, again (the panel's "Restore defaults", the picker choosing the
  // current scene again).
  void restore_defaults();
  // Do `what` to the simulation now when no batch runs, else once the running batch finished,
  // after what was asked before it.
  void change(std::function<void()> what);
  void hand_over_changes();
  void start_batch(int steps);
  void finish_batch();
  // Copy what the UI draws and shows out of the simulation's side.
  void refresh_shown_state();
  void update_vertex_arrays();
  void update_quantity_colors();
  void apply(ViewerCommand command);
  // Ctrl+S (SaveAndRecord), the picker offering the file from then on.
  void save_scene();
  // Tell the user that a file was written or why not (ViewerFiles::tell).
  void saved(const std::string& what) { files_.tell(what); }
  // The panel's settings to the simulation, as one settings value (Simulation::apply).
  void apply_panel_settings();
  // viewer_environment.cpp: the environment section's controls from the simulation's settings.
  void show_environment_in_panel();
  void place_ground();
  void update_collider_mesh();
  // viewer_compare.cpp: the split view.
  void draw_overlays(float ui_scale);
  void start_split(const CompareSettings& settings);
  void stop_split();
  void apply_split_settings();
  void start_student();
  void draw_student_legend(float ui_scale);
  bool split() const { return session_.right_side() != nullptr; }

  ViewerSession session_;  // first: the others' batches finish before it goes
  ViewerPanel panel_state_;
  DrawState drawing_;
  ViewerFiles files_;
  PickAndDrag pick_and_drag_;     // the mouse's gesture in progress and what it holds
  bool paused_at_limit_ = false;  // paused by the step limit, not by the user

  // viewer_environment.cpp reads the components' state under the names it had as the viewer's
  // own members: these refer to it.
  ViewerPanel::Settings& panel_;
  SimulationHost& host_;
  const Scene& scene_;
  GroundGrid& ground_;
  ColliderTriangles& collider_mesh_;
};

// The viewer of the scene the command line names, with its start-up settings and the scene
// picker's catalogue. An InputError from starting its simulation names the scene.
// `page` sets ViewerSettings' page, help and panel_folded (the browser's).
struct PageSettings {
  PageActions actions;
  std::vector<Binding> help;
  bool panel_folded = false;
};
Viewer open_viewer(const CommandLine& command, const std::optional<PageSettings>& page = {});

}  // namespace wobble

#endif
