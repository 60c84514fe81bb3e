#include "app/cli/command_line.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <optional>
#include <ostream>
#include <sstream>
#include <tuple>

#include "app/cli/option_values.h"
#include "app/cli/scene_catalog.h"
#include "app/cli/solver_choice.h"
#include "io/output_target.h"
#include "io/parse_number.h"
#include "sim/input_error.h"
#include "sim/input_limits.h"
#include "sim/parallel/worker_pool.h"
#include "sim/settings/setting_registry.h"
#include "sim/shapes/builtin_scenes.h"
#include "sim/simulation.h"
#include "sim/value_limits.h"

#ifndef WOBBLE_VERSION
#define WOBBLE_VERSION "unknown"
#endif

namespace wobble {

namespace {

using cli::number_between;
using cli::number_from_zero;
using cli::number_in;
using cli::parse_expect_tolerance;
using cli::path_value;
using cli::whole_number;

// Two outputs that would write one file, links followed: the later would silently replace the
// earlier. A device, a terminal or a pipe takes both, one after the other.
void check_distinct_outputs(const CommandLine& command) {
  const std::pair<const char*, const std::string*> outputs[] = {
      {"--screenshot", &command.screenshot},
      {"--export-obj", &command.export_obj},
      {"--convergence-csv", &command.convergence_csv},
      {"--energy-csv", &command.energy_csv}};
  std::vector<std::pair<std::string, std::string>> seen;  // option and identity
  for (const auto& [option, path] : outputs) {
    OutputTarget target;
    // A path that cannot be written is refused later, by the output's own check.
    if (path->empty() || !resolve_output(*path, target).empty() || target.identity.empty()) {
      continue;
    }
    for (const auto& [earlier, identity] : seen) {
      if (identity == target.identity) {
        throw InputError(earlier + ", " + option + ": both would write " +
                         shown_output(*path, target) + ", expected a file for each");
      }
    }
    seen.emplace_back(option, target.identity);
  }
}

// --compare's settings for the left side ("solver=local-global,solver=lbfgs") against the
// options that set the same: given both ways, which was meant?
void check_left_side(const CommandLine& command) {
  const SettingsOverrides& left = command.compare->left;
  for (const std::string& name : overridable_setting_names()) {
    if (left.has(name) && command.settings.has(name)) {
      throw InputError("--" + name + ", --compare: both set the left side's " + name +
                       ", expected one of them");
    }
  }
}

}  // namespace

std::optional<CommandLine> parse_command_line(int argc, const char* const* argv,
                                              std::ostream& out) {
  CommandLine command;
  CLI::App app("Wobble: cloth and jelly as fast mass-spring systems (Liu et al. 2013).", "wobble");
  app.get_formatter()->column_width(28);
  bool version = false, list_scenes = false;
  app.add_option("scene", command.scene,
                 "Built-in scene (see --list-scenes), scene file (.json) or mesh (.obj, .mesh, "
                 ".node/.ele)")
      ->capture_default_str();
  app.add_flag("--fill", command.fill, "Fill a closed OBJ surface with tetrahedra: a jelly");
  app.add_flag("--headless", command.headless,
               "No window: simulate, and render through EGL if an image is asked for");
  // Numbers are taken as text and parsed strictly below, so that every refusal quotes exactly
  // what was typed.
  std::optional<std::string> frames, export_obj, k, dt, iterations, width, height, screenshot,
      record, yaw, pitch, zoom, obj_sequence, damping, friction, color_by, self_collision_thickness,
      threads, solver, expect, expect_tolerance;
  app.add_option("--frames", frames,
                 "Run this many frames (one step each) and exit (headless default: " +
                     std::to_string(CommandLine::default_headless_frames) + ")");
  app.add_option("--export-obj", export_obj, "Write the final positions as OBJ");
  app.add_option("--export-obj-sequence", obj_sequence,
                 "Write every frame as DIR/frame_00001.obj, ...");
  std::optional<std::string> convergence_csv, energy_csv, compare, student;
  app.add_option("--student", student,
                 "Run the student's fast_mass_springs_step_sparse from DIR beside Wobble's, "
                 "coloured by its distance from Wobble's (split view)");
  app.add_option("--compare", compare,
                 "Split view: the right side with these settings, e.g. \"iterations=5\" "
                 "(iterations, solver, chebyshev=on|off, dt, k; comma-separated; a setting "
                 "named twice sets the left side, then the right)");
  app.add_option(
      "--convergence-csv", convergence_csv,
      "Write frame,iteration,energy,gradient_norm,solver of every iterate of every step");
  app.add_option("--energy-csv", energy_csv,
                 "Write frame,time,kinetic,spring,gravity,potential,total of every frame (J)");
  app.add_option("--k", k, "Spring stiffness in N/m (scene default otherwise)");
  app.add_option("--dt", dt, "Time step in seconds (scene default otherwise)");
  app.add_option("--iterations", iterations, "Local-global iterations per step");
  app.add_flag("--stats", command.stats, "Print timing statistics as JSON on the last line");
  app.add_option("--solver", solver,
                 "Step solver: local-global (the course's method, default) or lbfgs (L-BFGS, "
                 "Liu et al. 2017); the scene's otherwise");
  bool chebyshev = false;
  app.add_flag("--chebyshev", chebyshev,
               "Chebyshev acceleration of the local-global iterations (Wang 2015)");
  app.add_option("--damping", damping,
                 "Damping in 1/s: velocities decay as (1 + C dt)^-steps (scene default otherwise, "
                 "0)");
  app.add_option("--friction", friction,
                 "Coulomb friction coefficient against the colliders (scene default otherwise, 0)");
  app.add_flag("--wind", command.wind,
               "Turn the wind on: the scene's, or a default breeze (course scenes: the course "
               "wind)");
  app.add_flag("--self-collision", command.self_collision,
               "Keep the surface from passing through itself (thickness: the scene's, else "
               "0.01 m; not for course scenes)");
  app.add_option("--self-collision-thickness", self_collision_thickness,
                 "Self-collision thickness in m, 1e-5 to 1; implies --self-collision");
  app.add_option("--threads", threads,
                 "Threads the solver may use, 1 to " + std::to_string(max_setting_threads) +
                     " (default: OMP_NUM_THREADS if set, else the processors, at most " +
                     std::to_string(WorkerPool::max_shared_threads) + ")");
  std::vector<std::string> drags;
  app.add_option("--drag", drags,
                 "Drag a vertex: VERTEX:DX,DY,DZ@FRAME (over 30 frames) or @FRAME-LAST; "
                 "repeatable")
      ->take_all()
      ->allow_extra_args(false);
  app.add_option("--width", width, "Window or image width in pixels (default 1280)");
  app.add_option("--height", height, "Window or image height in pixels (default 720)");
  app.add_option("--screenshot", screenshot, "Write the last frame as a PNG");
  app.add_option("--record", record,
                 "Write every frame as DIR/frame_00001.png, ..., or as one video FILE.webm "
                 "(VP9) or FILE.mp4 (H.264)");
  app.add_flag("--ui", command.ui, "Headless images show the control panel too");
  app.add_option("--expect", expect,
                 "Headless: compare the last frame with this PNG; exit 1 and write "
                 "FILE.diff.png beside it when they differ beyond anti-aliasing");
  app.add_option("--expect-tolerance", expect_tolerance,
                 "LEVELS[,PERCENT]: a channel may be off by LEVELS of 255 without counting, and "
                 "PERCENT of the pixels may differ (default 8,0.03)");
  app.add_flag("--plots", command.plots,
               "Open the convergence and energy plots (key G), in images too");
  app.add_flag("--wireframe", command.wireframe, "Start with the wireframe shown");
  app.add_flag("--springs", command.springs, "Start with the springs shown as lines");
  app.add_flag("--points", command.points, "Start with every vertex shown as a point");
  app.add_option("--color-by", color_by,
                 "Colour the shape by spring strain, vertex speed, contacts or a solid's volume "
                 "change, with a legend: material, strain, speed, contacts or volume (default "
                 "material; the V key cycles)");
  // Each added setting (sim/settings/setting_registry.h) as --NAME VALUE.
  std::vector<std::pair<std::string, std::optional<std::string>>> added;
  for (const SettingSpec& spec : added_settings())
    added.emplace_back(spec.name, std::nullopt);
  for (std::size_t i = 0; i < added.size(); ++i) {
    const SettingSpec& spec = added_settings()[i];
    const std::string unit = *spec.range.unit ? std::string(" ") + spec.range.unit : "";
    app.add_option("--" + spec.name, added[i].second,
                   spec.help + " (" + limit_text(spec.range.low) + " to " +
                       limit_text(spec.range.high) + unit + ", default " +
                       limit_text(spec.default_value) + ")");
  }
  app.add_option("--camera-yaw", yaw, "Camera angle about the vertical, degrees (default 30)");
  app.add_option("--camera-pitch", pitch, "Camera elevation, degrees (default 20)");
  app.add_option("--camera-zoom", zoom,
                 "The camera this many times nearer than its framing of the scene (default 1)");
  app.add_flag("--list-scenes", list_scenes, "List the built-in scenes and exit");
  app.add_flag("--version", version, "Print the version and exit");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return std::nullopt;
  } catch (const CLI::ParseError& error) {
    throw InputError(one_line(error.what()) + " (see wobble --help)");
  }

  if (version) {
    out << "wobble " << WOBBLE_VERSION << "\n";
    if (!command.headless) return std::nullopt;
    // With --headless: what would draw (run_headless makes the context and says).
    command.version_with_driver = true;
    return command;
  }
  if (list_scenes) {
    for (const std::string& name : builtin_scene_names()) {
      out << name << "  " << make_builtin_scene(name).description << "\n";
    }
    // The shipped scene files, by path (loading them all just for a description would be slow).
    for (const std::string& source : scene_catalog()) {
      if (source.find('/') != std::string::npos) out << source << "\n";
    }
    return std::nullopt;
  }

  if (frames) command.frames = whole_number("--frames", *frames, CommandLine::max_frames);
  if (iterations) {
    command.settings.iterations =
        static_cast<int>(whole_number("--iterations", *iterations, Simulation::max_iterations));
  }
  if (k) command.settings.k = number_in("--k", *k, limits::stiffness);
  if (dt) command.settings.dt = number_in("--dt", *dt, limits::time_step);
  if (chebyshev) command.settings.chebyshev = true;
  for (const auto& [name, text] : added) {
    if (!text) continue;
    const SettingSpec& spec = *find_added_setting(name);
    command.settings.added[name] = number_from_zero(("--" + name).c_str(), *text, spec.range);
  }
  if (damping) command.damping = number_from_zero("--damping", *damping, limits::damping);
  if (friction) command.friction = number_from_zero("--friction", *friction, limits::friction);
  if (self_collision_thickness) {
    command.self_collision_thickness = number_in(
        "--self-collision-thickness", *self_collision_thickness, limits::self_collision_thickness);
    command.self_collision = true;
  }
  if (threads) {
    command.threads = static_cast<int>(whole_number("--threads", *threads, max_setting_threads));
  }
  if (export_obj) command.export_obj = path_value("--export-obj", *export_obj, "file path");
  if (width)
    command.width = static_cast<int>(whole_number("--width", *width, CommandLine::max_image_side));
  if (height) {
    command.height =
        static_cast<int>(whole_number("--height", *height, CommandLine::max_image_side));
  }
  if (static_cast<long>(command.width) * command.height > CommandLine::max_image_pixels) {
    throw InputError("--width, --height: " + std::to_string(command.width) + "x" +
                     std::to_string(command.height) + " is " +
                     with_thousands_separators(static_cast<long>(command.width) * command.height) +
                     " pixels, expected at most " +
                     with_thousands_separators(CommandLine::max_image_pixels) +
                     " (4096x2160 or the same area)");
  }
  if (obj_sequence) {
    command.export_obj_sequence = path_value("--export-obj-sequence", *obj_sequence, "folder path");
  }
  if (convergence_csv) {
    command.convergence_csv = path_value("--convergence-csv", *convergence_csv, "file path");
  }
  if (solver) command.settings.solver = parse_solver("--solver", *solver);
  if (compare) {
    command.compare = parse_compare_settings(*compare);
    check_left_side(command);
  }
  if (student) command.student = path_value("--student", *student, "folder path");
  if (!command.student.empty() && command.compare) {
    throw InputError("--student, --compare: both take the split view's right side; choose one");
  }
  if (energy_csv) command.energy_csv = path_value("--energy-csv", *energy_csv, "file path");
  if (!command.headless && !command.frames &&
      (!command.convergence_csv.empty() || !command.energy_csv.empty())) {
    throw InputError(
        std::string(command.convergence_csv.empty() ? "--energy-csv" : "--convergence-csv") +
        ": in a window, needs --frames (how long to record)");
  }
  if (screenshot) command.screenshot = path_value("--screenshot", *screenshot, "file path");
  if (record) command.record = path_value("--record", *record, "folder path");
  if (command.compare && command.headless && !command.writes_images()) {
    throw InputError(
        "--compare: shows the two sides in the split view, so it needs the window or, "
        "headless, --screenshot or --record");
  }
  if (!command.student.empty() && command.headless && !command.writes_images()) {
    throw InputError(
        "--student: shows the student's step beside Wobble's, so it needs the window "
        "or, headless, --screenshot or --record (scripts/check-assignment.sh checks "
        "without images)");
  }
  for (const std::string& drag : drags)
    command.drags.push_back(parse_drag(drag, CommandLine::max_frames));
  if (yaw) command.camera_yaw = number_between("--camera-yaw", *yaw, -360.0, 360.0);
  if (zoom) {
    command.camera_zoom = number_between("--camera-zoom", *zoom, CommandLine::min_camera_zoom,
                                         1.0 / CommandLine::min_camera_zoom);
  }
  if (pitch) {
    command.camera_pitch = number_between("--camera-pitch", *pitch, -CommandLine::max_camera_pitch,
                                          CommandLine::max_camera_pitch);
  }
  if (color_by) {
    const std::optional<ColorQuantity> quantity = color_quantity_named(*color_by);
    if (!quantity) {
      throw InputError("--color-by: expected material, strain, speed, contacts or volume, got '" +
                       *color_by + "'");
    }
    command.color_by = *quantity;
  }
  if (expect) command.expect = path_value("--expect", *expect, "PNG file path");
  if (expect_tolerance) {
    if (!expect) throw InputError("--expect-tolerance: needs --expect FILE.png");
    command.expect_tolerance = parse_expect_tolerance(*expect_tolerance);
  }
  if (!command.expect.empty() && !command.headless) {
    throw InputError("--expect: compares a headless run's last frame, so it needs --headless");
  }
  check_distinct_outputs(command);
  return command;
}

void apply_scene_overrides(const CommandLine& command, SimulationParams& params) {
  // One rule for every scene format: a flag the scene cannot honour is refused, never accepted
  // and ignored or reported as on. A course scene runs the reference program's method exactly
  // (its k, dt, iterations and wind are the reference's own settings).
  if (params.gravity_model == GravityModel::force_per_vertex) {
    const std::string course_solver = solver_names().front();  // the course's local-global
    const SettingsOverrides* left = command.compare ? &command.compare->left : nullptr;
    const std::pair<bool, const char*> changes_method[] = {
        {command.settings.chebyshev.value_or(false), "--chebyshev"},
        {command.settings.solver.value_or(course_solver) != course_solver, "--solver"},
        {left && (left->chebyshev.value_or(false) ||
                  left->solver.value_or(course_solver) != course_solver),
         "--compare (its left side)"},
        {command.damping.has_value(), "--damping"},
        {command.friction.has_value(), "--friction"},
        {command.self_collision_thickness.has_value(), "--self-collision-thickness"},
        {command.self_collision, "--self-collision"}};
    for (const auto& [given, option] : changes_method) {
      if (given) {
        throw InputError(std::string(option) +
                         ": not for a course scene, which keeps the reference's behaviour "
                         "(its k, dt, iterations and wind may be set)");
      }
    }
  }
  if (command.damping) params.damping = *command.damping;
  if (command.friction) params.contact.friction = *command.friction;
  if (command.wind) {
    const bool calm =
        params.wind.model == WindModel::aerodynamic && params.wind.velocity.isZero(0.0);
    if (calm) params.wind = WindParams::default_breeze();
    params.wind.on = true;
  }
  if (command.self_collision) {
    params.self_collision.on = true;
    if (command.self_collision_thickness) {
      params.self_collision.thickness = *command.self_collision_thickness;
    }
  }
}

}  // namespace wobble
