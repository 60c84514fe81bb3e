#include "app/viewer/viewer.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "app/cli/scene_catalog.h"
#include "app/cli/solver_choice.h"
#include "app/student/student_server.h"
#include "app/viewer/side_settings.h"
#include "io/load_scene.h"
#include "io/png_image.h"

namespace wobble {

namespace {

std::optional<float> radians(std::optional<float> degrees) {
  if (!degrees) return std::nullopt;
  return *degrees * (3.14159265358979f / 180.0f);
}

}  // namespace

Viewer open_viewer(const CommandLine& command, const std::optional<PageSettings>& page) {
  // The student's code is built first: a compile error is the user's to fix before any window.
  ViewerSettings settings = viewer_settings(command);
  if (!command.student.empty()) {
    settings.student_server = build_student_step_server(command.student);
  }
  if (page) {
    settings.page = page->actions;
    settings.help = page->help;
    settings.panel_folded = page->panel_folded;
  }
  Scene scene = open_scene(command);  // its refusals name the file already: not inside
  return naming_scene(command.scene,
                      [&] { return Viewer(std::move(scene), settings, scene_catalog()); });
}

ViewerSettings viewer_settings(const CommandLine& command) {
  ViewerSettings settings;
  settings.settings = command.settings;
  settings.layers.wireframe = command.wireframe;
  settings.layers.springs = command.springs;
  settings.layers.points = command.points;
  settings.drags = command.drags;
  settings.color_by = command.color_by;
  settings.compare = command.compare;
  settings.plots = command.plots;
  settings.scene_source = command.scene;
  if (command.camera_yaw) settings.camera_yaw_degrees = static_cast<float>(*command.camera_yaw);
  if (command.camera_pitch) {
    settings.camera_pitch_degrees = static_cast<float>(*command.camera_pitch);
  }
  if (command.camera_zoom) settings.camera_zoom = static_cast<float>(*command.camera_zoom);
  return settings;
}

Viewer::Viewer(Scene scene, const ViewerSettings& settings, std::vector<std::string> scene_sources)
    : session_(std::move(scene_sources), settings.scene_source, settings.student_server),
      panel_state_(settings.layers, settings.color_by, settings.help, settings.page,
                   settings.panel_folded),
      drawing_(radians(settings.camera_yaw_degrees), radians(settings.camera_pitch_degrees),
               settings.camera_zoom),
      files_(ViewerFiles::Hooks{[this](Scene opened, const std::string& source) {
                                  load(std::move(opened));
                                  session_.set_source(source);
                                },
                                [this](const std::string& what) { session_.note(what); }},
             static_cast<bool>(settings.page.pick_files)),
      panel_(panel_state_.settings()),
      host_(session_.host()),
      scene_(session_.scene()),
      ground_(drawing_.ground_grid()),
      collider_mesh_(drawing_.colliders()) {
  scene.params = settings.settings.applied_to(scene.params);
  // What --compare set for the left side ("solver=local-global,solver=lbfgs": the first).
  if (settings.compare) scene.params = settings.compare->left.applied_to(scene.params);
  session_.plots().open_both(settings.plots);
  session_.set_free_vertex_held([this] { return pick_and_drag_.holds_free_vertex(); });
  load(std::move(scene));
  host_.set_drag_script(DragScript(settings.drags, scene_.network.V.rows()));
  if (settings.compare && !session_.right().student()) start_split(*settings.compare);
}

Viewer::~Viewer() = default;

void Viewer::restore_defaults() {
  // The session's scene is the scene as it opened: the panel's changes went to the simulation
  // only.
  if (host_.batch_started()) finish_steps();
  Scene opened = scene_;
  load(std::move(opened));
}

void Viewer::load(Scene scene) {
  // A running batch finishes first and what the user did before is handed over, so that the new
  // scene's settings come after it (loading takes longer than a step anyway).
  if (host_.batch_started()) finish_steps();
  // Everything that can fail comes first, so a scene that does not load leaves the viewer as it
  // was.
  RgbaImage texture = scene.look.texture.empty() ? RgbaImage() : read_png(scene.look.texture);
  RightSide& right = session_.right();
  if (right.wants_student()) {
    scene.params = seed_method(scene.params);
    const std::string note =
        "student mode: Wobble's side (left) takes the seed's step, 50 plain "
        "iterations from the current positions with gravity and the pins only, "
        "so that both sides compute the same step; pins cannot be dragged";
    // Restore defaults reloads a scene that already says so.
    if (std::find(scene.notes.begin(), scene.notes.end(), note) == scene.notes.end()) {
      scene.notes.push_back(note);
    }
  }
  auto simulation =
      std::make_unique<Simulation>(scene.network, scene.pins, scene.params, scene.initial_velocity);
  // A split view stays split, its right side keeping its own settings on the new scene.
  std::optional<CompareSettings> split;
  if (right.simulation() && !right.student()) split = right.settings();
  right.stop();
  pick_and_drag_.forget();
  session_.open(std::move(scene), std::move(simulation));
  // Paused by the step limit, not by the user: the new scene runs to the limit in its turn.
  if (paused_at_limit_) panel_.paused = paused_at_limit_ = false;
  if (scene_.params.wind.on) {
    files_.post("the wind blows in " + scene_.name + ": W turns it off and on");
  }
  panel_.scene = session_.scene_index();
  show_settings(scene_.params, panel_, scene_.network.T.rows() > 0);
  show_environment_in_panel();
  panel_state_.show_shape(scene_.network.F.rows() > 0);

  drawing_.set_shape(scene_, std::move(texture));
  update_vertex_arrays();
  place_ground();
  drawing_.view_camera().open(scene_.look, scene_.network.V, ground_.height);
  if (split) start_split(*split);
  if (right.wants_student()) start_student();
  drawing_.mark_stale();  // the split view's side, if any, is drawn from the next render
  session_.copy_shown_figures();
  if (drawing_.has_renderer()) drawing_.attach_renderer();
}

}  // namespace wobble
