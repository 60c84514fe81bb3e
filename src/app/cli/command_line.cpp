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
#include "sim/parse_number.h"
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
  std::optional<std::string> frames, export_obj, width, height, screenshot, record, yaw, pitch,
      zoom, obj_sequence, color_by, threads, expect, expect_tolerance;
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
  std::string compared;  // the settings each side has its own of
  for (const std::string& name : overridable_setting_names())
    compared += (compared.empty() ? "" : ", ") + name;
  app.add_option("--compare", compare,
                 "Split view: the right side with these settings, e.g. \"iterations=5\" (" +
                     compared +
                     "; a switch =on|off; comma-separated; a setting named twice sets the left "
                     "side, then the right)");
  app.add_option(
      "--convergence-csv", convergence_csv,
      "Write frame,iteration,energy,gradient_norm,solver of every iterate of every step");
  app.add_option("--energy-csv", energy_csv,
                 "Write frame,time,kinetic,spring,gravity,potential,total of every frame (J)");
  // Every setting the command line gives (sim/settings/setting_registry.h), as --NAME VALUE, a
  // switch as --NAME; an added one's help says its range and default.
  std::vector<const SettingSpec*> given_settings;
  for (const SettingSpec& spec : all_settings()) {
    if (spec.places & on_command_line) given_settings.push_back(&spec);
  }
  std::vector<std::optional<std::string>> setting_texts(given_settings.size());
  std::unique_ptr<bool[]> setting_switches(new bool[given_settings.size()]());
  for (std::size_t i = 0; i < given_settings.size(); ++i) {
    const SettingSpec& spec = *given_settings[i];
    if (spec.type == SettingType::toggle) {
      app.add_flag("--" + spec.name, setting_switches[i], spec.help);
      continue;
    }
    std::string help = spec.help;
    if (find_added_setting(spec.name)) {
      const std::string unit = *spec.range.unit ? std::string(" ") + spec.range.unit : "";
      help += " (" + limit_text(spec.range.low) + " to " + limit_text(spec.range.high) + unit +
              ", default " + limit_text(spec.default_value) + ")";
    }
    app.add_option("--" + spec.name, setting_texts[i], help);
  }
  app.add_flag("--stats", command.stats, "Print timing statistics as JSON on the last line");
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
  for (std::size_t i = 0; i < given_settings.size(); ++i) {
    const SettingSpec& spec = *given_settings[i];
    if (setting_switches[i]) command.settings.values[spec.name] = true;
    if (setting_texts[i]) {
      command.settings.values[spec.name] = read_setting(spec, *setting_texts[i], "--" + spec.name);
    }
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
  // One rule for every scene format: a setting the scene cannot honour is refused, never
  // accepted and ignored or reported as on. A course scene runs the reference program's method
  // exactly (its k, dt, iterations and wind are the reference's own settings): a setting declared
  // not for one is refused, a number given at all, a switch or a choice unless it is the scene's
  // own (--solver local-global).
  if (params.gravity_model == GravityModel::force_per_vertex) {
    const SettingsOverrides* left = command.compare ? &command.compare->left : nullptr;
    for (const SettingSpec& spec : all_settings()) {
      if (spec.course_scene) continue;
      const auto changes_method = [&](const SettingsOverrides& given) {
        const auto value = given.values.find(spec.name);
        return value != given.values.end() &&
               (spec.type == SettingType::number || value->second != spec.get(params));
      };
      const std::string option = changes_method(command.settings) ? "--" + spec.name
                                 : left && changes_method(*left)  ? "--compare (its left side)"
                                                                  : "";
      if (!option.empty()) {
        throw InputError(option +
                         ": not for a course scene, which keeps the reference's behaviour "
                         "(its k, dt, iterations and wind may be set)");
      }
    }
  }
  // The environment's settings (each side's own are applied where the simulation starts), a
  // switch turned on as a user turns it on (--wind over a calm scene: the default breeze), and
  // what a setting implies turned on with it (--self-collision-thickness: --self-collision).
  for (const auto& [name, value] : command.settings.values) {
    const SettingSpec& spec = *find_setting(name);
    if (spec.per_side) continue;
    if (spec.type == SettingType::toggle && std::get<bool>(value)) {
      turn_on(spec, params);
    } else {
      spec.set(params, value);
    }
    if (*spec.implies != '\0') turn_on(*find_setting(spec.implies), params);
  }
}

}  // namespace wobble
