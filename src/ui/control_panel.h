#ifndef WOBBLE_UI_CONTROL_PANEL_H
#define WOBBLE_UI_CONTROL_PANEL_H

#include <string>
#include <vector>

namespace wobble {

// What the panel edits. The app compares it with the simulation after each frame's UI and applies
// what changed, so the panel itself touches neither the simulation nor GL.
struct PanelSettings {
  float k = 400.0f;           // N/m
  float dt = 1.0f / 60.0f;    // s
  int iterations = 50;        //
  float gravity = 9.81f;      // m/s², its strength along the scene's own direction
  bool chebyshev = false;     // Chebyshev acceleration of the iterations
  float damping = 0.0f;       // 1/s, mass-proportional
  float friction = 0.0f;      // Coulomb μ against the colliders
  bool wind = false;          // wind on
  float wind_speed = 0.0f;    // m/s (aerodynamic wind only)
  float wind_heading = 0.0f;  // degrees around y the wind blows towards: 0 +x, 90 +z
  bool colliders = true;      // colliders shown
  bool paused = false;
  // Real time: the window takes as many steps before a frame as keep the simulated clock with
  // the wall clock (up to what fits in a frame); off, one step a frame.
  bool real_time = true;
  // Self-collision on, and its thickness in mm (the simulation's is in m).
  bool self_collision = false;
  float self_collision_mm = 10.0f;
  bool surface = true, wireframe = false, springs = false, points = false, ground = true;
  int color_by = 0;  // 0 material, 1 spring strain, 2 vertex speed, 3 contacts (V cycles them)
  int scene = 0;     // index into the scene names
  bool show_help = false;
  char open_path[512] = "";       // the "open" field's text
  bool show_panel = true;         // Tab hides it
  bool recording = false;         // every new state drawn written as a PNG (F9)
  float ui_scale = 1.0f;          // fonts and the panel, times the screen's scale (projectors)
  bool show_convergence = false;  // the last step's convergence plot
  bool show_energy = false;       // the energy-over-time plot
  // The split view and its right side's own settings.
  bool split = false;
  float right_k = 400.0f, right_dt = 1.0f / 60.0f;
  int right_iterations = 5;
  bool right_chebyshev = false;

  static constexpr float min_k = 1.0f, max_k = 1e6f;
  static constexpr float min_dt = 1.0f / 240.0f, max_dt = 1.0f / 15.0f;
  static constexpr int min_iterations = 1, max_iterations = 100;
  static constexpr float max_gravity = 30.0f;
  static constexpr float min_ui_scale = 0.75f, max_ui_scale = 3.0f;
  static constexpr float max_damping = 10.0f, max_friction = 2.0f, max_wind_speed = 30.0f;
  // limits::self_collision_thickness, 1e-5 to 1 m, in mm.
  static constexpr float min_self_collision_mm = 0.01f, max_self_collision_mm = 1000.0f;
};

// Numbers the panel shows.
struct PanelStats {
  // Timings come from the wall clock. Headless images leave them out so that two runs give the
  // same pixels.
  bool show_timings = true;
  float fps = 0.0f;          // frames drawn per second, from the median frame time of the last 15
  float ui_frame_ms = 0.0f;  // the UI's own time for a frame (median of the last 15), no step in it
  float step_ms = 0.0f, local_ms = 0.0f, global_ms = 0.0f;
  float forces_ms = 0.0f, contact_ms = 0.0f;  // wind; collider projection and friction
  // Over about the last second: simulated seconds per wall-clock second (< 1: slow motion), and
  // steps per wall-clock second.
  float real_time_factor = 0.0f, steps_per_second = 0.0f;
  float instruments_ms = 0.0f;  // recording the convergence plot's numbers
  int vertices = 0, springs = 0, pins = 0;
  int threads = 1;  // the solver's threads (--threads, OMP_NUM_THREADS or the processors)
  long steps = 0;
  double simulated_seconds = 0.0;
  bool has_colliders = false;      // friction, the colliders' checkbox and contacts show only then
  bool aerodynamic_wind = true;    // the wind has a speed and heading (the course's has neither)
  int contacts = 0;                // vertices the last step moved out of a collider
  bool student_side = false;       // the right side is a student's step (--student)
  bool course_scene = false;       // the course's format: no Chebyshev, no self-collision offered
  std::vector<std::string> notes;  // what the scene loader chose for the user
  std::string warning;             // why the simulation paused by itself, or empty
  std::string recording;           // while recording: "DIR/ (N frames)"
  // Self-collision on (its row shows only then), the vertices the last step's self-collision
  // moved, and that step's time detecting pairs and pushing them apart (ms).
  bool self_collision = false;
  int self_contacts = 0;
  float self_detection_ms = 0.0f, self_response_ms = 0.0f;
};

// Where the panel lies, in ImGui's display units (the window's, from its top-left corner), so
// that the viewer can frame the shape beside it.
struct PanelPlace {
  bool shown = false;  // drawn and not collapsed to its title bar
  float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;
};

// Buttons pressed this frame, and where the panel was drawn.
struct PanelRequests {
  bool step_once = false;
  bool reset = false;
  bool frame_mesh = false;
  bool default_view = false;      // the scene's opening view
  bool scene_changed = false;     // the picker chose a scene (the current one again: reopen it)
  bool restore_defaults = false;  // the scene as it opened, every setting included
  std::string open_path;          // a scene or mesh file to open (the "open" field), or empty
  bool save_scene = false;        // save the scene with its pins and settings (Ctrl+S)
  bool export_obj = false;        // the current positions as an OBJ (F11)
  bool screenshot = false;        // the window as a PNG (F12)
  PanelPlace place;
};

// The "Wobble" panel: scene picker, play controls, simulation and environment (damping,
// friction, wind, colliders, self-collision) sliders, view toggles and stats. Call between
// ImGui::NewFrame and ImGui::Render. `ui_scale` is the high-DPI factor.
PanelRequests draw_control_panel(PanelSettings& settings, const PanelStats& stats,
                                 const std::vector<std::string>& scene_names, float ui_scale);

// A window at the top of the view saying why the simulation paused by itself; nothing when
// `warning` is empty.
void draw_step_warning(const std::string& warning, float ui_scale);

// A window listing {input, action} pairs, open while `open` is true (its close button clears it).
void draw_help_overlay(const std::vector<std::pair<std::string, std::string>>& bindings,
                       bool& open);

}  // namespace wobble

#endif
