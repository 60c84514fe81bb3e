#include "app/viewer/viewer.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <optional>
#include <utility>

#include "app/cli/scene_catalog.h"
#include "app/cli/solver_choice.h"
#include "app/student/student_server.h"
#include "app/viewer/side_settings.h"
#include "app/viewer/step_advice.h"
#include "io/load_scene.h"
#include "sim/contact/collider_contact_term.h"
#include "sim/parallel/worker_pool.h"

namespace wobble {

namespace {

std::optional<float> radians(std::optional<float> degrees) {
  if (!degrees) return std::nullopt;
  return *degrees * (3.14159265358979f / 180.0f);
}

}  // namespace

Viewer open_viewer(const CommandLine& command) {
  // The student's code is built first: a compile error is the user's to fix before any window.
  ViewerSettings settings = viewer_settings(command);
  if (!command.student.empty()) {
    settings.student_server = build_student_step_server(command.student);
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
    : scene_sources_(std::move(scene_sources)),
      scene_source_(settings.scene_source),
      view_camera_(radians(settings.camera_yaw_degrees), radians(settings.camera_pitch_degrees),
                   settings.camera_zoom),
      right_(settings.student_server) {
  for (const std::string& source : scene_sources_) {
    scene_labels_.push_back(scene_label(source));
    scene_choices_.push_back(SceneChoice{scene_labels_.back(), scene_description(source),
                                         is_course_scene_source(source)});
  }
  scene.params = settings.settings.applied_to(scene.params);
  // What --compare set for the left side ("solver=local-global,solver=lbfgs": the first).
  if (settings.compare) scene.params = settings.compare->left.applied_to(scene.params);
  panel_.surface = settings.layers.surface;
  panel_.wireframe = settings.layers.wireframe;
  panel_.springs = settings.layers.springs;
  panel_.points = settings.layers.points;
  panel_.ground = settings.layers.ground;
  panel_.color_by = static_cast<int>(settings.color_by);
  instruments_.open_both(settings.plots);
  // After each step, on the thread that took it, the split view's right side catches up.
  host_.set_after_step([this](const Simulation& left) { right_.advance(left, left.params().dt); });
  load(std::move(scene));
  host_.set_drag_script(DragScript(settings.drags, scene_.network.V.rows()));
  if (settings.compare && !right_.student()) start_split(*settings.compare);
}

Viewer::~Viewer() = default;

bool Viewer::open_file(const std::string& path, const std::string& hidden_folder) {
  // What is said of a dropped file names it without the folder the page put the dropped files
  // in: the user dropped "banner.json", not "/opened/2/a/b/c/banner.json".
  const auto as_dropped = [&hidden_folder](std::string text) {
    const std::string folder = hidden_folder + "/";
    for (std::size_t at = hidden_folder.empty() ? std::string::npos : text.find(folder);
         at != std::string::npos; at = text.find(folder, at))
      text.erase(at, folder.size());
    return text;
  };
  try {
    Scene scene = load_scene(path, false, missing_texture_);
    for (std::string& note : scene.notes)
      note = as_dropped(note);
    const std::vector<std::string> notes = scene.notes;
    load(std::move(scene));
    scene_source_ = path;
    // A file's notes (a texture that did not come with it, drawn untextured) on screen too, as
    // the command line prints them: the panel's notes are out of sight below its sections.
    for (const std::string& note : notes)
      notices_.post(note, notice_clock());
    return true;
  } catch (const std::exception& error) {
    // In the notes, and on screen (a dropped file's reason would otherwise go unseen).
    tell(as_dropped(error.what()));
    return false;
  }
}

bool Viewer::open_files(const std::vector<std::string>& paths) {
  if (paths.empty()) return false;
  std::string chosen = paths.back();
  for (const std::string& path : paths) {
    const std::string name = std::filesystem::path(path).extension().string();
    if (name == ".json" || name == ".JSON") chosen = path;
  }
  // The page's dropped files lie in a folder of its own making; a window's have real paths.
  return open_file(chosen, panel_.page ? std::filesystem::path(chosen).parent_path().string() : "");
}

void Viewer::set_page_actions(PageActions actions) {
  page_actions_ = std::move(actions);
  panel_.page = static_cast<bool>(page_actions_.pick_files);
  if (panel_.page) save_and_record_.hide_record();
  missing_texture_ = panel_.page ? MissingTexture::note : MissingTexture::refuse;
}

void Viewer::restore_defaults() {
  // scene_ is the scene as it opened: the panel's changes went to the simulation only.
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
  if (right_.wants_student()) {
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
  if (right_.simulation() && !right_.student()) split = right_.settings();
  right_.stop();
  pick_and_drag_.forget();
  step_warning_.clear();
  scene_ = std::move(scene);
  host_.replace(std::move(simulation));  // its scripted drags forgotten, its clock afresh
  // Paused by the step limit, not by the user: the new scene runs to the limit in its turn.
  if (paused_at_limit_) panel_.paused = paused_at_limit_ = false;
  instruments_.clear();
  update_recording();
  if (scene_.params.wind.on) {
    notices_.post("the wind blows in " + scene_.name + ": W turns it off and on", notice_clock());
  }
  // The picker shows the scene as current; a scene from elsewhere joins the list.
  const auto found = std::find(scene_labels_.begin(), scene_labels_.end(), scene_.name);
  if (found == scene_labels_.end()) {
    scene_labels_.push_back(scene_.name);
    scene_sources_.push_back(scene_.name);
  }
  panel_.scene = static_cast<int>(
      std::find(scene_labels_.begin(), scene_labels_.end(), scene_.name) - scene_labels_.begin());
  show_settings(scene_.params, panel_, scene_.network.T.rows() > 0);
  panel_.gravity = static_cast<float>(scene_.params.gravity.norm());
  show_environment_in_panel();

  const SpringNetwork& network = scene_.network;
  // Springs without faces (a chain, a net) draw no surface, so without their springs and
  // vertices the view would show only the pins: they are shown as the course's viewer shows
  // them, and the user can still turn them off. What was chosen for meshes with faces is kept
  // for the next one.
  if (!faceless_) {
    chosen_springs_ = panel_.springs;
    chosen_points_ = panel_.points;
  }
  faceless_ = network.F.rows() == 0;
  panel_.springs = faceless_ || chosen_springs_;
  panel_.points = faceless_ || chosen_points_;
  triangles_.resize(3 * network.F.rows());
  for (Eigen::Index f = 0; f < network.F.rows(); ++f) {
    for (int k = 0; k < 3; ++k)
      triangles_[3 * f + k] = static_cast<unsigned>(network.F(f, k));
  }
  springs_.resize(2 * network.E.rows());
  for (Eigen::Index e = 0; e < network.E.rows(); ++e) {
    for (int k = 0; k < 2; ++k)
      springs_[2 * e + k] = static_cast<unsigned>(network.E(e, k));
  }
  const int n = static_cast<int>(network.V.rows());
  positions_.resize(3 * n);
  normals_.resize(3 * n);
  marks_.resize(n);
  pinned_flags_.resize(n);
  update_vertex_arrays();
  place_ground();
  view_camera_.open(scene_.look, scene_.network.V, ground_.height);
  const SceneLook& look = scene_.look;
  uv_.clear();
  if (look.uv.rows() == n && look.uv.cols() == 2) {
    uv_.resize(2 * n);
    for (int i = 0; i < n; ++i) {
      uv_[2 * i] = static_cast<float>(look.uv(i, 0));
      uv_[2 * i + 1] = static_cast<float>(look.uv(i, 1));
    }
  }
  texture_ = std::move(texture);
  if (split) start_split(*split);
  if (right_.wants_student()) start_student();
  arrays_stale_ = true;  // the split view's side, if any, is drawn from the next render
  copy_shown_figures();
  if (renderer_) attach_renderer();
}

PanelStats Viewer::stats() const {
  if (host_.batch_started()) return shown_stats_;
  return simulation_stats();
}

PanelStats Viewer::simulation_stats() const {
  PanelStats stats;
  stats.vertices = static_cast<int>(scene_.network.V.rows());
  stats.springs = static_cast<int>(scene_.network.E.rows());
  // A free vertex held by the mouse is pinned only for the drag: it is not one of the pins.
  stats.pins = host_.simulation().pin_count() - (pick_and_drag_.holds_free_vertex() ? 1 : 0);
  stats.threads = shared_thread_setting().threads;
  stats.steps = host_.simulation().steps_taken();
  // The accepted steps' dt summed: a new dt changes the rate from now on, not the past.
  stats.simulated_seconds = host_.simulation().time();
  stats.notes = scene_.notes;
  stats.has_colliders = !colliders_in(host_.simulation().terms()).empty();
  stats.contacts = static_cast<int>(
      host_.simulation().last_step_timing().figure("collider contact", "contacts"));
  stats.self_collision = host_.simulation().params().self_collision.on;
  stats.self_contacts =
      static_cast<int>(host_.simulation().last_step_timing().figure("self-contact", "contacts"));
  stats.student_side = right_.student();
  stats.course_scene = scene_.params.gravity_model == GravityModel::force_per_vertex;
  stats.solver = solver_label(host_.simulation().params().solver);
  stats.warning = step_warning_;
  return stats;
}

}  // namespace wobble
