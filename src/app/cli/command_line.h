#ifndef WOBBLE_APP_CLI_COMMAND_LINE_H
#define WOBBLE_APP_CLI_COMMAND_LINE_H

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/color_quantity.h"
#include "app/cli/compare_settings.h"
#include "app/cli/settings_overrides.h"
#include "app/interaction/drag_script.h"
#include "app/outputs/image_compare.h"
#include "sim/simulation.h"

namespace wobble {

// What the user asked for on the command line, already checked for range and sanity.
struct CommandLine {
  std::string scene = "cloth";  // a built-in scene's name or a scene or mesh file
  bool headless = false;
  std::optional<long> frames;  // steps to run; headless runs default to default_headless_frames
  std::string export_obj;      // empty: no export
  std::string export_obj_sequence;  // folder for one OBJ per frame; empty: none
  std::string convergence_csv;      // every iterate's objective and gradient; empty: none
  std::string energy_csv;           // every frame's kinetic and potential energy; empty: none
  std::optional<CompareSettings> compare;  // --compare: the split view's right side
  std::string student;  // --student DIR: a student's six functions beside Wobble's; empty: none
  bool fill = false;    // fill a closed OBJ surface with tetrahedra
  // Every setting the command line gives (sim/settings/setting_registry.h: --k, --dt,
  // --iterations, --solver, --chebyshev, --damping, --friction, --wind, --self-collision,
  // --self-collision-thickness and each added setting's --NAME), by name: what they change of
  // the scene's settings. A switch given is on.
  SettingsOverrides settings;
  bool stats = false;
  std::vector<ScriptedDrag> drags;  // --drag, in the order given
  // --threads: threads the solver may use, 1 to max_setting_threads (sim/parallel/worker_pool.h);
  // unset: OMP_NUM_THREADS, else the processors (at most 4).
  std::optional<int> threads;
  // Images (both modes) and what they show.
  int width = 1280, height = 720;  // window or offscreen image size, pixels
  std::string screenshot;          // PNG of the frame after the last step; empty: none
  std::string record;              // folder for one PNG per frame, or a .webm/.mp4; empty: none
  bool ui = false;                 // headless: draw the ImGui panel too
  // --expect FILE.png (headless): the last frame compared with FILE by compare_images; a
  // mismatch exits with 1 and writes FILE's stem + ".diff.png" beside it. --expect-tolerance
  // LEVELS[,PERCENT] loosens the comparison.
  std::string expect;
  ImageTolerance expect_tolerance;
  // --version --headless: the version, then which EGL platform and GL driver would draw.
  bool version_with_driver = false;
  bool plots = false;  // open the convergence and energy plots
  bool wireframe = false, springs = false, points = false;
  std::optional<double> camera_yaw, camera_pitch;    // degrees
  std::optional<double> camera_zoom;                 // times nearer than the framing
  ColorQuantity color_by = ColorQuantity::material;  // else coloured, with a legend

  bool writes_images() const { return !screenshot.empty() || !record.empty() || !expect.empty(); }

  static constexpr long default_headless_frames = 120;
  static constexpr long max_frames = 10'000'000;
  // Window and image size: each side up to 4096 and at most 4096×2160 pixels in all (DCI 4K),
  // which render and save in about 1.2 s and 480 MB headless (docs/scenes.md, "Limits").
  static constexpr long max_image_side = 4096;
  static constexpr long max_image_pixels = 4096L * 2160L;
  static constexpr double max_camera_pitch = 89.0;
  static constexpr double min_camera_zoom = 0.001;  // and at most its inverse
};

// Parse argv. Returns nothing when the request was fully answered here (--help, --version,
// --list-scenes), after writing the answer to `out`. Throws InputError with a one-line message
// for an unknown option, a malformed value, or a value out of range.
std::optional<CommandLine> parse_command_line(int argc, const char* const* argv, std::ostream& out);

// Puts the command line's settings of the environment (those the two sides of the split view
// share: --damping, --friction, --wind, --self-collision, ...) into a scene's parameters (each
// side's own, --solver, --k and the rest, are applied where the simulation starts). --wind turns
// on the wind the scene has (the course wind for a course scene); a scene whose aerodynamic wind
// has no velocity gets WindParams::default_breeze(). --self-collision turns self-collision on
// with the scene's thickness (default 0.01 m) unless --self-collision-thickness gives one, which
// implies it. Throws InputError when a setting declared not for a course scene
// (SettingSpec::course_scene: --chebyshev, another solver than the default, or either for the
// left side through --compare, --damping, --friction, either self-collision option) meets one
// (params.gravity_model force_per_vertex): those keep the reference's behaviour.
void apply_scene_overrides(const CommandLine& command, SimulationParams& params);

}  // namespace wobble

#endif
