#ifndef WOBBLE_UI_CONTROL_PANEL_H
#define WOBBLE_UI_CONTROL_PANEL_H

#include <functional>
#include <string>
#include <vector>

#include "panel_sections.h"

namespace wobble {

// Numbers the panel shows.
struct PanelStats {
  // Timings come from the wall clock. Headless images leave them out so that two runs give the
  // same pixels.
  bool show_timings = true;
  float fps = 0.0f;          // frames drawn per second, from the median frame time of the last 15
  float ui_frame_ms = 0.0f;  // the UI's own time for a frame (median of the last 15), no step in it
  float step_ms = 0.0f, local_ms = 0.0f, global_ms = 0.0f;
  float forces_ms = 0.0f;  // the terms' forces (wind)
  // Over about the last second: simulated seconds per wall-clock second (< 1: slow motion), and
  // steps per wall-clock second.
  float real_time_factor = 0.0f, steps_per_second = 0.0f;
  float instruments_ms = 0.0f;  // recording the convergence plot's numbers
  int vertices = 0, springs = 0, pins = 0;
  int threads = 1;  // the solver's threads (--threads, OMP_NUM_THREADS or the processors)
  long steps = 0;
  double simulated_seconds = 0.0;
  bool has_colliders = false;      // the colliders' checkbox and contacts show only then
  int contacts = 0;                // vertices the last step moved out of a collider
  bool student_side = false;       // the right side is a student's step (--student)
  bool course_scene = false;       // the course's format: what it keeps as the course has it greyed
  std::vector<std::string> notes;  // what the scene loader chose for the user
  std::string warning;             // why the simulation paused by itself, or empty
  std::string recording;           // while recording: "DIR/ (N frames)"
  // The label of the solver stepping the simulation ("L-BFGS"), which the stats name.
  std::string solver;
  // Self-collision on (its row shows only then), and the vertices the last step's self-collision
  // held or moved.
  bool self_collision = false;
  int self_contacts = 0;
  // Each figure the step's terms reported of the last step, by term and name ("self-contact",
  // "detection"), shown with the timings whatever the term: a line for each term, then its
  // figures.
  struct TermFigure {
    std::string term, name;
    std::string unit;  // "ms", or empty for a count
    float value = 0.0f;
  };
  std::vector<TermFigure> term_figures;
};

// What the environment section offers for the scene these stats describe.
inline EnvironmentOffer environment_offer(const PanelStats& stats) {
  EnvironmentOffer offer;
  offer.colliders = stats.has_colliders;
  offer.course_scene = stats.course_scene;
  return offer;
}

// Where the panel lies, in ImGui's display units (the window's, from its top-left corner), so
// that the viewer can frame the shape beside it.
struct PanelPlace {
  bool shown = false;  // drawn and not collapsed to its title bar
  float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;
};

// The panel's parts, in the order the panel shows them, each drawn by what owns its settings
// (panel_sections.h): rows at the top, then sections under headers that open and close. A part
// left empty is not shown, nor its header.
struct PanelParts {
  std::function<void()> scene_rows, save_rows, play_rows;
  std::function<void()> simulation, environment, view, instruments, compare;
};

// The "Wobble" panel: its window beside the view, as tall as its contents and never taller than
// the display, the parts in a list that scrolls where the display is shorter, then the timings
// and the scene's notes (from `stats`), and the stats pinned under the list. `paused` is read
// after the parts drew, so that a Play pressed this frame shows in the stats. Returns where the
// panel lies. Call between ImGui::NewFrame and ImGui::Render. `ui_scale` is the high-DPI factor.
PanelPlace draw_control_panel(const PanelParts& parts, const PanelStats& stats, const bool& paused,
                              float ui_scale);

// What the whole panel edits, every section's settings in one struct, for drawing the panel
// whole from it (its tests do).
struct PanelSettings : SceneRowSettings,
                       PlaySettings,
                       SimulationSettings,
                       EnvironmentSettings,
                       ViewSettings,
                       InstrumentSettings,
                       SplitSettings {
  bool recording = false;            // every new state drawn written as a PNG or a video frame (F9)
  int record_format = 0;             // what the recording writes: a RecordFormat (panel_sections.h)
  bool record_whole_window = false;  // a recorded frame shows the window, not the scene alone
};

// Buttons pressed this frame, and where the panel was drawn.
struct PanelRequests : SceneRowRequests, SaveRowRequests, PlayRequests {
  bool restore_defaults = false;  // the scene as it opened, every setting included
  PanelPlace place;
};

// The whole panel drawn from `settings`: each part by its function in panel_sections.h, the
// recording's status and the warning from `stats`, which also say what the environment and
// compare sections offer.
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
