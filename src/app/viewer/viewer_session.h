#ifndef WOBBLE_APP_VIEWER_VIEWER_SESSION_H
#define WOBBLE_APP_VIEWER_VIEWER_SESSION_H

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/outputs/video_file.h"
#include "app/viewer/instruments.h"
#include "app/viewer/moving_median.h"
#include "app/viewer/right_side.h"
#include "app/viewer/simulation_host.h"
#include "sim/shapes/builtin_scenes.h"
#include "sim/simulation.h"
#include "ui/control_panel.h"
#include "ui/panel_sections.h"

namespace wobble {

// The viewer's session, a component of it: the scene as it opened and the catalogue the picker
// offers, the simulation's side (SimulationHost: the simulation, its scripted drags, the batches
// of steps), the split view's right side and the plots its batches feed, and what the UI shows of
// them between batches (the step times, the last failed step's warning, the figures). The
// viewer's panel, mouse and drawing reach the simulation through it; it knows none of them.
class ViewerSession {
 public:
  // `sources` are what the scene picker offers (built-in names and scene files, as load_scene
  // takes them); `source` is what the first scene came from; `student_server` is the student's
  // step server for the split view, or empty.
  ViewerSession(std::vector<std::string> sources, std::string source, std::string student_server);

  // The scene as it opened (with the command line's settings): what "Restore defaults" reloads.
  const Scene& scene() const { return scene_; }
  const Simulation& simulation() const { return host_.simulation(); }
  // What the current scene was opened from: a built-in scene's name, or the file's path (as the
  // picker's sources name them, or a file opened or dropped); empty when not known.
  const std::string& scene_source() const { return source_; }
  // What the scene picker lists, in its order; what each loads; the picker's labels,
  // descriptions and groups.
  const std::vector<std::string>& scene_labels() const { return labels_; }
  const std::vector<std::string>& scene_sources() const { return sources_; }
  const std::vector<SceneChoice>& scene_choices() const { return choices_; }
  // The picker's index of the scene on show.
  int scene_index() const;

  // Panel figures that do not come from the wall clock, as of the state drawn.
  PanelStats stats() const;
  // The steps taken as of the state drawn.
  long shown_steps() const { return stats().steps; }
  // The simulated time of the state shown and the dt it was taken with, for a video's frames.
  FrameTime shown_time() const;
  // Why the last step was rolled back (shown in the view until the next good step), or empty.
  const std::string& step_warning() const { return step_warning_; }
  // The median step times (ms) and the last good step's timing, for the panel.
  PanelStats step_times() const;

  // Whether a batch of steps runs on the stepping thread now.
  bool stepping() const { return host_.stepping(); }
  // Run batches on a thread of their own from now on (the window); `wake` runs on that thread
  // after each batch. Before any batch started.
  void step_on_thread(std::function<void()> wake) { host_.step_on_thread(std::move(wake)); }
  // Wait for a running batch and drop its results and any error it met (a run that failed
  // elsewhere, before it writes what it has).
  void stop_stepping() noexcept { host_.stop(); }
  // Step at most `steps` steps in all; once there (Viewer::exchange), paused, and Play goes on.
  void set_step_limit(long steps) { host_.set_step_limit(steps); }
  // Called after each good step, on the thread that took it, with the simulation (the CSV rows
  // and OBJ sequences of the window).
  void set_step_observer(std::function<void(const Simulation&)> observer) {
    host_.set_step_observer(std::move(observer));
  }
  // Keep the simulation recording its convergence whether or not the plot shows it (for
  // --convergence-csv), through scene changes too.
  void set_convergence_required(bool required);

  // The convergence and energy plots, and what they show.
  const Instruments& instruments() const { return instruments_; }
  bool plots_open() const { return instruments_.column_open(); }
  // The split view's right side, or null when the view is not split.
  const Simulation* right_side() const { return right_.simulation(); }
  // Why the right side stopped (a student's step that crashed or hung, a failed step), or empty.
  const std::string& right_side_warning() const { return shown_twin_warning_; }
  // With a student's step on the right: its largest distance from Wobble's positions after the
  // last step (m), and each vertex's colour by it.
  double student_distance() const { return shown_student_distance_; }
  const std::vector<float>& student_colors() const { return shown_student_colors_; }
  // The split view's corner labels for the state drawn.
  const std::string& left_label() const { return shown_left_label_; }
  const std::string& right_label() const { return shown_right_label_; }
  // Whether ImGui draws anything over the scene besides the panel: the plots, the labels.
  bool has_overlays() const { return right_.simulation() || instruments_.column_open(); }

  // What the viewer's wiring uses.
  SimulationHost& host() { return host_; }
  const SimulationHost& host() const { return host_; }
  RightSide& right() { return right_; }
  const RightSide& right() const { return right_; }
  Instruments& plots() { return instruments_; }
  // A new scene, its simulation built: the old one's batch must be finished. `source`, when
  // given, is what it was opened from.
  void open(Scene scene, std::unique_ptr<Simulation> simulation);
  void set_source(std::string source) { source_ = std::move(source); }
  // A note among the panel's notes (of the scene on show; Restore defaults keeps it).
  void note(const std::string& what) { scene_.notes.push_back(what); }
  // A scene file saved: the picker offers it from now on, under its own name.
  void offer(const std::string& path);
  // Whether the mouse holds a free vertex, asked as the figures are: such a vertex is pinned
  // only for the drag, and is not one of the pins.
  void set_free_vertex_held(std::function<bool()> held) { free_vertex_held_ = std::move(held); }
  // Step (the button, the key): one step at the next batch.
  void ask_one_step() { step_requested_ = true; }
  bool one_step_asked() const { return step_requested_; }
  // How many steps the next batch takes (SimulationHost::steps_to_start), the step asked for
  // taken; headless (no `now`) one, unless paused.
  int steps_to_start(bool paused, bool real_time, std::optional<double> now, double frame_seconds);
  // Start a batch of `steps`, the right side stepping in it and both recording for the plots.
  void start_batch(int steps);
  // The finished batch's times, plots and warning. Returns whether a step failed (the viewer
  // pauses). `dragging`: the mouse holds a vertex.
  bool finish_batch(bool dragging);
  // The simulation's recording of its convergence, as the plots and the CSV need it.
  void update_recording();
  // A scene's reset: the plots cleared, the warning gone, the scripted drags afresh.
  void after_reset();
  // Copy what the UI shows out of the simulation's side: the figures, the right side's warning,
  // the student's distance and colours, the corner labels.
  void copy_shown_figures();

 private:
  PanelStats simulation_stats() const;
  void describe_sides();

  Scene scene_;
  std::vector<std::string> sources_, labels_;  // the picker: what to load, as shown
  std::vector<SceneChoice> choices_;
  std::string source_;
  std::function<bool()> free_vertex_held_;
  bool step_requested_ = false;
  MovingMedian step_ms_, local_ms_, global_ms_;  // the panel's step times
  StepTiming last_timing_;                       // the last good step's
  std::string step_warning_;
  Instruments instruments_;  // the convergence and energy plots
  RightSide right_;          // the split view's right side, or a student's step there
  // What the UI shows of the simulation's side, as of the last copy_shown_figures.
  PanelStats shown_stats_;
  double shown_dt_ = 0.0;
  std::string shown_twin_warning_;
  std::string shown_left_label_, shown_right_label_;
  double shown_student_distance_ = 0.0;
  std::vector<float> shown_student_colors_;
  // Last, so that a batch still running finishes before the members it reads go.
  SimulationHost host_;
};

}  // namespace wobble

#endif
