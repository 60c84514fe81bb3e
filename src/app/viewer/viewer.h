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
#include "app/interaction/collider_mesh.h"
#include "app/interaction/input_mapping.h"
#include "app/student/student_step.h"
#include "app/viewer/instruments.h"
#include "app/viewer/moving_median.h"
#include "app/viewer/notices.h"
#include "app/viewer/pick_and_drag.h"
#include "app/viewer/quantity_colors.h"
#include "app/viewer/right_side.h"
#include "app/viewer/save_and_record.h"
#include "app/viewer/simulation_host.h"
#include "app/viewer/view_camera.h"
#include "io/missing_texture.h"
#include "io/png_image.h"
#include "platform/input_event.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "sim/instruments/frame_energy.h"
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
};

// The start-up settings a command line asks for.
ViewerSettings viewer_settings(const CommandLine& command);

// Everything the window, the page and the headless mode share: the scene and its simulation, the
// camera, the mouse and keys, the ImGui panel, and the renderer. One frame is draw_frame's
// (app/viewer/frame_loop.h), in this order, each mode a FrameHost under it:
//   handle_events → build_ui → advance (headless) or exchange (window, page) → build_legend →
//   render
//
// Its components each own their state and draw their own part, called by the viewer in that
// order: ViewCamera (the camera), PickAndDrag (the mouse), SaveAndRecord (the files), Instruments
// (the plots), RightSide (the split view's right side), Notices, and SimulationHost (the
// simulation's side, below). The viewer hands them what they act on; none reaches into another.
//
// The simulation's side and the UI's: the simulation and its scripted drags (SimulationHost), the
// split view's right side and the student's step are touched by one batch of steps at a time. In
// the window a batch runs on a thread of its own (step_on_thread) while the UI goes on drawing
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
  // Throws, leaving the viewer as it was, when
  // the scene's texture cannot be read or its simulation cannot be built. A mesh without faces
  // starts with its springs and vertices shown, since there is no surface to see; the layers
  // chosen for meshes with faces come back with the next mesh that has them.
  void load(Scene scene);
  // The scene as it opened (with the command line's settings): k, dt, iterations, gravity,
  // environment, pins, colliders, the start and the split view's right side. The panel's
  // "Restore defaults", and the picker choosing the current scene again.
  void restore_defaults();
  // Open a scene or mesh file (dropped on the window, or typed into the panel's "open" field),
  // as load_scene reads it. A file that does not load leaves the current scene running, the
  // reason shown in the panel's notes, `hidden_folder` (and its '/') taken out of it: the page's
  // own folder for dropped files. Returns whether it loaded.
  bool open_file(const std::string& path, const std::string& hidden_folder = "");
  // Files dropped or picked together: the scene file among them (the last .json) opens, its mesh
  // and texture beside it; with no scene file, the last one. Returns whether it loaded.
  bool open_files(const std::vector<std::string>& paths);
  // The page's own: its file picker and its link (the panel shows "Open file..." and "Copy link"
  // instead of the path field), and scene files that open without a texture they lack (noted).
  struct PageActions {
    std::function<void()> pick_files;
    std::function<void()> copy_link;
  };
  void set_page_actions(PageActions actions);
  // The on-screen confirmations of what was written, and what a scene does as it opens (its
  // wind blowing, and the key that turns it off).
  const Notices& notices() const { return notices_; }
  // Draw the notices (the window); headless images never show them, so that they do not
  // depend on the wall clock.
  void show_notices(bool on) { show_notices_ = on; }
  // Each file a save writes from then on (F12 or PNG, F11 or OBJ, Ctrl+S or Save scene: the scene
  // and its mesh), as its path: the page offers each as a download.
  void set_file_written(std::function<void(const std::string& path)> written) {
    save_and_record_.set_written(std::move(written));
  }
  // What the help (H) lists: viewer_bindings(), or a page's page_bindings().
  void set_help(std::vector<Binding> bindings) { help_ = std::move(bindings); }
  // Tells the user one line: on screen for a few seconds (while notices show) and among the
  // panel's notes (a page's refused address key, a file written).
  void tell(const std::string& what) { saved(what); }
  // What the scene picker lists, in its order.
  const std::vector<std::string>& scene_labels() const { return scene_labels_; }
  // The window: the panel's "record" (F9) records into new folders in `folder`, `progress`
  // told of each (headless images never record from the panel).
  void record_window_into(std::string folder, std::ostream& progress) {
    save_and_record_.record_into(std::move(folder), progress);
  }
  // The window, after drawing a frame: the screenshot F12 asked for, and while recording the
  // new state. `read_frame` reads the frame drawn, when `drawn` (a minimized window draws
  // none). What was written, or why not, shows as notices.
  void write_window_files(bool drawn, const std::function<RgbaImage()>& read_frame);
  // The scene drawn, before the panel goes over it: a recording of the scene alone reads it now.
  void scene_drawn(const std::function<RgbaImage()>& read_frame) {
    save_and_record_.scene_drawn(read_frame);
  }
  // The simulated time of the state shown and the step it is taken with, for a video's frames.
  FrameTime shown_time() const;

  // Create the renderer. Needs the GL context current until detach_renderer or destruction.
  void attach_renderer();
  // Free the renderer's GL objects while their context is still current.
  void detach_renderer() { renderer_.reset(); }

  // Mouse and keys since the last frame. `ui_wants_mouse`/`ui_wants_keyboard` are ImGui's
  // io.WantCaptureMouse/WantCaptureKeyboard: what the panel takes, the 3-D view ignores.
  void handle_events(const std::vector<InputEvent>& events, bool ui_wants_mouse,
                     bool ui_wants_keyboard, const Eigen::Vector2f& window_size);
  // The panel and the help overlay (ImGui, between NewFrame and Render). Applies what changed.
  void build_ui(const PanelStats& timings, float ui_scale);
  // One time step, unless paused, finished before it returns (headless, tests). A step the
  // simulation rolls back pauses the viewer and sets step_warning(). Then, paused or not, the
  // state to be drawn, with the colours of color_by().
  void advance();
  // The window's frame: if a batch of steps still runs, nothing (the UI draws the last state;
  // returns false). Otherwise take the finished batch's results, hand over what the user did
  // since, in order, take the state to be drawn, and start the next batch: one step if one was
  // asked for; while playing, in real-time mode as many as keep up with the wall clock `now`
  // (s) but fit in `frame_seconds` (StepPacer), otherwise one. Returns true.
  bool exchange(double now, double frame_seconds);
  // Run batches on a thread of their own from now on (the window). `wake` runs on that thread
  // after each batch.
  void step_on_thread(std::function<void()> wake);
  // Wait for a running batch and take its results (before the window closes, and at the end of
  // a --frames run).
  void finish_steps();
  // Wait for a running batch and drop its results and any error it met (a run that failed
  // elsewhere, before it writes what it has).
  void stop_stepping() noexcept;
  // Whether a batch of steps runs on the stepping thread now.
  bool stepping() const { return host_.stepping(); }
  // Never step beyond this many steps in all (the window's --frames).
  // Step at most `steps` steps in all; once there (exchange), paused, and Play goes on.
  void set_step_limit(long steps) { host_.set_step_limit(steps); }
  // Called after each good step, on the thread that took it, with the simulation (the CSV rows
  // and OBJ sequences of the window).
  void set_step_observer(std::function<void(const Simulation&)> observer) {
    host_.set_step_observer(std::move(observer));
  }
  // The steps taken as of the state drawn.
  long shown_steps() const { return shown_stats_.steps; }
  // viewer_colors.cpp: the colour bar of color_by() (ImGui, after advance so that it shows the
  // range this frame is drawn with, and before ImGui::Render); nothing for material.
  void build_legend(float ui_scale);
  ColorQuantity color_by() const { return static_cast<ColorQuantity>(panel_.color_by); }
  // The colours the last advance() computed (empty while coloured by material).
  const QuantityColors& quantity_colors() const { return quantity_colors_; }
  // Draw into the bound framebuffer. `window_size` is in the units of the mouse events;
  // `pixel_ratio` is framebuffer pixels per window unit; `mark_scale` is framebuffer pixels per
  // pixel of a mark's size (pin dots, the held vertex, bands of springs): the pixel ratio where
  // window units are the screen's points (unset: `pixel_ratio`), the page's device pixel ratio
  // in the page. Without `draw`, only what drawing would change besides the pixels: the camera's
  // framing, the drawn positions and marks (a frame no one sees still frames the shape as one seen
  // would).
  void render(int framebuffer_width, int framebuffer_height, const Eigen::Vector2f& window_size,
              float pixel_ratio, std::optional<float> mark_scale = std::nullopt, bool draw = true);

  // Keep the simulation recording its convergence whether or not the plot shows it (for
  // --convergence-csv), through scene changes too.
  void set_convergence_required(bool required);

  // What ImGui draws besides the panel: the convergence and energy plots when open, the split
  // view's corner labels. build_ui draws them too; headless images without the panel draw only
  // these. Between ImGui's NewFrame and Render.
  void draw_overlays(float ui_scale);
  // Whether draw_overlays has anything to draw.
  bool has_overlays() const { return right_.simulation() || instruments_.column_open(); }
  // The convergence and energy plots, and what they show.
  const Instruments& instruments() const { return instruments_; }
  // The split view's right side, or null when the view is not split.
  const Simulation* right_side() const { return right_.simulation(); }
  // Why the right side stopped (a student's step that crashed or hung, a failed step), or empty.
  const std::string& right_side_warning() const { return shown_twin_warning_; }
  // With a student's step on the right: its largest distance from Wobble's positions after the
  // last step (m).
  double student_distance() const { return shown_student_distance_; }

  bool quit_requested() const { return quit_; }
  bool real_time() const { return panel_.real_time; }
  bool paused() const { return panel_.paused; }
  bool help_shown() const { return panel_.show_help; }
  bool panel_shown() const { return show_panel_; }
  // Shown and not folded to its title bar, when it was last drawn.
  bool panel_open() const { return show_panel_ && panel_place_.shown; }
  // Where build_ui last drew the panel (window units); not shown when hidden or folded.
  PanelPlace panel_place() const { return show_panel_ ? panel_place_ : PanelPlace(); }
  // #V by 3 positions as the last render() drew them (a paused drag draws the held vertex at its
  // target).
  const std::vector<float>& drawn_positions() const { return positions_; }
  // Whether the next frames change without input: playing, a step asked for, or the mouse
  // holding something or turning the camera. A paused viewer with none of these can wait for
  // input instead of redrawing the same picture.
  bool animating() const {
    return !panel_.paused || step_requested_ || pick_and_drag_.busy() || host_.batch_started() ||
           host_.changes_waiting();
  }
  // Why the last step was rolled back (shown in the view until the next good step), or empty.
  const std::string& step_warning() const { return step_warning_; }
  const Simulation& simulation() const { return host_.simulation(); }
  const Scene& scene() const { return scene_; }
  // What the current scene was opened from: a built-in scene's name, or the file's path (as the
  // picker's sources name them, or a file opened or dropped); empty when not known.
  const std::string& scene_source() const { return scene_source_; }
  const OrbitCamera& camera() const { return view_camera_.camera(); }
  // The camera as the command line's angles and zoom give it back (the page's Copy link).
  ViewCamera::Angles camera_angles() const { return view_camera_.angles(); }
  // A scene without faces, which shows its springs and points unasked; the plots open.
  bool faceless() const { return faceless_; }
  bool plots_open() const { return instruments_.column_open(); }
  // How far the mouse may take the camera, for this scene's shape and ground.
  const CameraLimits& camera_limits() const { return view_camera_.limits(); }
  // Panel figures that do not come from the wall clock, as of the state drawn.
  PanelStats stats() const;
  // The layers render() draws, as the panel's checkboxes show them.
  ViewLayers layers() const;
  // The ground grid under the scene (see ground_grid_height), set when a scene loads.
  const GroundGrid& ground() const { return ground_; }
  // The colliders' triangles as the last render() drew them (empty while they are hidden).
  const ColliderTriangles& collider_mesh() const { return collider_mesh_; }

 private:
  // The simulation's side (see the class comment).
  // Do `what` now when no batch runs, else once the running batch finished, after what was
  // asked before it.
  void change(std::function<void()> what);
  void hand_over_changes();
  // Headless (no `now`): one step, unless paused.
  int steps_to_start(std::optional<double> now, double frame_seconds);
  void start_batch(int steps);
  // The finished batch's figures, plots and warning, taken into the UI.
  void finish_batch();
  // Copy what the UI draws and shows out of the simulation's side.
  void refresh_shown_state();
  // The panel's figures, the right side's warning and the student's distance and colours.
  void copy_shown_figures();
  PanelStats simulation_stats() const;

  void apply(ViewerCommand command);
  // Ctrl+S (SaveAndRecord), the picker offering the file from then on.
  void save_scene();
  // Tell the user that a file was written or why not: on screen for a few seconds (Notices),
  // and among the panel's notes.
  void saved(const std::string& what) {
    scene_.notes.push_back(what);
    notices_.post(what, notice_clock());
  }
  // The panel's settings to the simulation, as one settings value (Simulation::apply).
  void apply_panel_settings();
  // viewer_environment.cpp: the environment section's controls from the simulation's settings.
  void show_environment_in_panel();
  // viewer_instruments.cpp: the convergence and energy plots.
  void update_recording();
  void show_instruments(float ui_scale);
  // viewer_compare.cpp: the split view.
  void start_split(const CompareSettings& settings);
  void stop_split();
  void apply_split_settings();
  // The split view's corner labels for the state drawn.
  void describe_sides();
  // A student's step on the right.
  void start_student();
  void draw_student_legend(float ui_scale);
  // Split, the part of a window `window` wide that the two sides share (window units): what
  // the panel and the plots leave, in two halves of `half` from `left`; the whole window when
  // that part is too narrow to see anything in.
  struct SplitArea {
    float left = 0.0f, half = 0.0f;
  };
  SplitArea split_area(float window) const;
  void place_ground();
  void update_collider_mesh();
  void update_vertex_arrays();
  // viewer_colors.cpp
  void update_quantity_colors();
  void add_quantity_colors(const QuantityColors& colors, MeshFrame& frame) const;
  // The picture as the last render() drew it, for the mouse in a window `window_size` big.
  PointerView pointer_view(const Eigen::Vector2f& window_size) const;

  Scene scene_;
  std::vector<std::string> scene_sources_, scene_labels_;  // the picker: what to load, as shown
  std::string scene_source_;                // what the current scene was opened from (scene_source)
  std::vector<SceneChoice> scene_choices_;  // the picker's labels, descriptions and groups
  // The panel's settings that the viewer draws and applies itself (the components keep theirs).
  struct OwnPanelSettings : SceneRowSettings,
                            PlaySettings,
                            SimulationSettings,
                            EnvironmentSettings,
                            ViewSettings {};
  OwnPanelSettings panel_;
  bool show_panel_ = true;  // Tab hides the panel
  // Whether the scene has no faces, and the springs and points layers chosen for scenes with
  // faces while such a scene shows both.
  bool faceless_ = false;
  bool chosen_springs_ = false, chosen_points_ = false;
  ViewCamera view_camera_;          // the camera, its opening view and framing (a component)
  PanelPlace panel_place_;          // where build_ui last drew the panel; not shown without a panel
  float instruments_left_ = -1.0f;  // the plots' left edge (window units); < 0 while closed
  bool framed_with_plots_ = false;  // the plots were open when the view was last framed
  bool framed_with_panel_ = false;  // ... and the panel shown
  float framed_panel_bottom_ = 0.0f;  // ... and the bottom of a panel as wide as it (0: none)
  std::vector<Binding> help_ = viewer_bindings();
  PageActions page_actions_;
  bool paused_at_limit_ = false;  // paused by the step limit, not by the user
  MissingTexture missing_texture_ = MissingTexture::refuse;
  // What the UI shows of the simulation's side, as of the last refresh_shown_state.
  PanelStats shown_stats_;
  std::string shown_twin_warning_;
  std::string shown_left_label_, shown_right_label_;  // the split view's settings
  double shown_student_distance_ = 0.0;
  std::vector<float> shown_student_colors_;
  bool quit_ = false;
  Notices notices_;
  bool show_notices_ = false;
  SaveAndRecord save_and_record_;  // the record toggle, recordings and saves (a component)
  MovingMedian step_ms_, local_ms_, global_ms_;  // the panel's step times
  StepTiming last_timing_;                       // the last good step's
  bool step_requested_ = false;
  std::string step_warning_;
  Instruments instruments_;  // the convergence and energy plots (a component)
  // The split view's right side, or a student's step there (a component), and the arrays the
  // renderer draws it from.
  RightSide right_;
  std::vector<float> twin_positions_, twin_normals_;
  PickAndDrag pick_and_drag_;  // the mouse's gesture in progress and what it holds (a component)

  // What the renderer draws, as plain arrays refreshed between batches. Stale after a change
  // the last refresh did not see (render then refreshes them).
  bool arrays_stale_ = false;
  std::vector<unsigned> triangles_, springs_;
  std::vector<float> positions_, normals_;
  std::vector<unsigned char> marks_, pinned_flags_;
  std::vector<float> uv_;  // #V by 2, or empty
  RgbaImage texture_;
  GroundGrid ground_;
  ColliderTriangles collider_mesh_;
  QuantityColors quantity_colors_;  // empty while coloured by material
  QuantityColors twin_colors_;      // the split view's right side, in the same range
  Eigen::Matrix4f view_ = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f projection_ = Eigen::Matrix4f::Identity();
  std::unique_ptr<Renderer> renderer_;
  // The simulation, its scripted drags and the batches of steps (a component). Last, so that a
  // batch still running finishes before the members it reads go.
  SimulationHost host_;
};

// The viewer of the scene the command line names, with its start-up settings and the scene
// picker's catalogue. An InputError from starting its simulation names the scene.
Viewer open_viewer(const CommandLine& command);

}  // namespace wobble

#endif
