#ifndef WOBBLE_UI_PANEL_SECTIONS_H
#define WOBBLE_UI_PANEL_SECTIONS_H

#include <string>
#include <vector>

namespace wobble {

// The control panel's parts, one function each, with the settings each edits. Each is drawn by
// what owns those settings (the viewer or one of its components), into the place the control
// panel keeps for it (control_panel.h); none touches the simulation or GL. Between
// ImGui::Begin and End, inside the panel's list of sections.

// The scene picker and the "open" field: rows at the top. A page has no paths to type: it shows
// "Open file..." (the browser's file picker) and "Copy link" instead of the field.
struct SceneRowSettings {
  int scene = 0;             // index into the scene names
  char open_path[512] = "";  // the "open" field's text
  bool page = false;         // the page's buttons instead of the field
};
struct SceneRowRequests {
  bool scene_changed = false;  // the picker chose a scene (the current one again: reopen it)
  std::string open_path;       // a scene or mesh file to open (the "open" field), or empty
  bool pick_files = false;     // the page's "Open file..."
  bool copy_link = false;      // the page's "Copy link"
};
// What the picker lists of a scene: the label, what it shows (a tooltip), and whether it is one
// of the course's scenes (listed after Wobble's own, under a heading).
struct SceneChoice {
  std::string name;
  std::string description;
  bool course = false;
};
SceneRowRequests draw_scene_rows(SceneRowSettings& settings,
                                 const std::vector<SceneChoice>& scenes);

// Files into the working folder: Save scene, OBJ, PNG, the record toggle and what it writes
// (`record_format`, a RecordFormat; fixed while recording), and where a recording goes
// ("DIR/ (N frames)", empty when not recording).
struct SaveRowRequests {
  bool save_scene = false;  // save the scene with its pins and settings (Ctrl+S)
  bool export_obj = false;  // the current positions as an OBJ (F11)
  bool screenshot = false;  // the window as a PNG (F12)
};
// What the record toggle writes, the combo beside it: PNG frames in a folder, or one video.
enum RecordFormat : int { record_png_frames = 0, record_webm_video = 1, record_mp4_video = 2 };
// `record_whole_window`: what a recorded frame shows (the scene alone, or the window with its
// panel), the second choice in the same combo. Without `offer_record` (the page, which has no
// folder to record into), the toggle and the combos are left out.
SaveRowRequests draw_save_rows(bool& recording, int& record_format, bool& record_whole_window,
                               const std::string& recording_status, bool offer_record = true);

// Play, Step, Reset, Frame, View and Help, real time, and why the simulation paused by itself
// (`warning`, or empty).
struct PlaySettings {
  bool paused = false;
  // Real time: the window takes as many steps before a frame as keep the simulated clock with
  // the wall clock (up to what fits in a frame); off, one step a frame.
  bool real_time = true;
  bool show_help = false;
};
struct PlayRequests {
  bool step_once = false;
  bool reset = false;
  bool frame_mesh = false;
  bool default_view = false;  // the scene's opening view
};
PlayRequests draw_play_rows(PlaySettings& settings, const std::string& warning);

// The control of one setting in the panel: the app fills a side's from the settings'
// declarations (sim/settings/setting_registry.h), one per setting each side has its own of, in
// their order, and the environment's from those the sides share (app/viewer/side_settings.h).
// Labelled "LABEL (UNIT)", and " right" after it on the right side.
struct SettingControl {
  // heading: a vector as two numbers, its speed (`value`, "LABEL (UNIT)") and its heading around
  // y (`heading`, "LABEL heading", degrees: 0 +x, 90 +z).
  enum class Kind { number, integer, toggle, choice, heading };
  Kind kind = Kind::number;
  std::string name;                       // the setting's: "k", "tether-stiffness"
  std::string label;                      // "k", "tether k"
  std::string unit;                       // "N/m", or "" for a plain factor
  std::string help;                       // a choice's or a switch's tooltip
  float low = 0.0f, high = 1.0f;          // a number's or an integer's range in the panel
  bool log_scale = false;                 // a number moves by a factor a pixel (low > 0)
  std::string format = "%.4g";            // a number's
  float value = 0.0f;                     // a number's, a heading's speed, a strength
  double direction[3] = {0.0, 0.0, 0.0};  // a strength's: the unit vector it scales
  float heading = 0.0f;                   // a heading's, degrees
  int whole = 0;                          // an integer's; a choice's index into `choices`
  bool on = false;                        // a switch's
  std::vector<std::string> choices;       // a choice's labels
  // A switch that applies only with some choices of another control of the side (Chebyshev with
  // the local-global solver): that control's name, and for each of its choices whether it
  // applies; greyed out, with `why_not` as its tooltip, when it does not.
  std::string applies_with;
  std::vector<char> applies_for;
  std::string why_not;
  bool course_locked = false;  // a course scene keeps it as the course has it: greyed out there
  bool shown = true;  // false: it does nothing for the scene shown (a solid's setting on cloth)
  std::string shown_with;  // shown only while the switch of this name, in the same list, is on
};

// What one side of the view steps with: the left side's in SimulationSettings, the right side's
// in SplitSettings::right.
struct SideSliders {
  std::vector<SettingControl> controls;

  // The control of the setting `name`, or null.
  SettingControl* control(const std::string& name);
  const SettingControl* control(const std::string& name) const;
};

// "simulation": a control for each setting of the side (k, dt, iterations, the solver,
// Chebyshev, the added settings) and Restore defaults (returns whether it was pressed). A course
// scene (`course_scene`) keeps the course's plain local-global iterations: the controls
// `course_locked` are greyed out.
struct SimulationSettings : SideSliders {};
bool draw_simulation_section(SimulationSettings& settings, bool course_scene);

// "environment": a control for each setting the two sides share (damping, friction, the wind's
// switch, speed and heading, self-collision and its thickness: each shown where its declaration
// offers it), then the colliders' checkbox where there are colliders. In a course scene those
// `course_locked` are greyed out.
struct EnvironmentSettings {
  SideSliders environment;
  bool colliders = true;  // colliders shown
};
struct EnvironmentOffer {
  bool colliders = false;     // the scene has colliders
  bool course_scene = false;  // the course's format
};
void draw_environment_section(EnvironmentSettings& settings, const EnvironmentOffer& offer);

// "view": the layers, the colouring and the UI scale.
struct ViewSettings {
  bool surface = true, wireframe = false, springs = false, points = false, ground = true;
  int color_by = 0;       // 0 material, 1 spring strain, 2 vertex speed, 3 contacts (V cycles them)
  float ui_scale = 1.0f;  // fonts and the panel, times the screen's scale (projectors)

  static constexpr float min_ui_scale = 0.75f, max_ui_scale = 3.0f;
};
void draw_view_section(ViewSettings& settings);

// "instruments": which plots are open.
struct InstrumentSettings {
  bool show_convergence = false;  // the last step's convergence plot
  bool show_energy = false;       // the energy-over-time plot
};
// Returns whether "CSV" (what the plots show, as files) was pressed.
bool draw_instruments_section(InstrumentSettings& settings);

// "compare": the split view and its right side's own settings (as the simulation section's);
// with a student's step on the right (`student_side`), what it shows instead.
struct SplitSettings {
  bool split = false;
  SideSliders right;
};
void draw_split_section(SplitSettings& settings, bool student_side);

}  // namespace wobble

#endif
