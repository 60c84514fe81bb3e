#include "app/headless/run_headless.h"

#include <memory>

#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "app/cli/scene_catalog.h"
#include "app/headless/render_offscreen.h"
#include "app/interaction/drag_script.h"
#include "app/outputs/image_compare.h"
#include "app/outputs/image_outputs.h"
#include "app/outputs/instrument_csv.h"
#include "app/outputs/obj_sequence.h"
#include "app/outputs/run_statistics.h"
#include "app/outputs/step_outputs.h"
#include "app/viewer/viewer.h"
#include "io/atomic_file.h"
#include "io/write_obj.h"
#include "platform/egl_context.h"
#include "sim/input_error.h"
#include "sim/shapes/builtin_scenes.h"
#include "sim/simulation.h"

namespace wobble {

namespace {

// --expect: the last frame against the expected picture. One line either way, on `progress`;
// a mismatch writes the difference image beside the expected one and gives exit code 1.
int check_expected(const CommandLine& command, const RgbaImage& expected, const RgbaImage& last,
                   std::ostream& progress) {
  const ImageComparison comparison = compare_images(expected, last, command.expect_tolerance);
  const std::string summary = comparison.summary(command.expect_tolerance);
  if (comparison.matches(command.expect_tolerance)) {
    progress << "wobble: " << command.expect << ": matches (" << summary << ")\n";
    return 0;
  }
  std::string written;
  if (comparison.same_size) {
    std::string diff_path = command.expect;
    const std::size_t dot = diff_path.rfind('.');
    const std::size_t slash = diff_path.find_last_of('/');
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash))
      diff_path.resize(dot);
    diff_path += ".diff.png";
    try {
      write_png(diff_path, difference_image(expected, last, command.expect_tolerance));
      written = "; differing pixels in red: " + diff_path;
    } catch (const std::exception& error) {
      written = "; no difference image (" + one_line(error.what()) + ")";
    }
  }
  progress << "wobble: " << command.expect << ": does not match: " << summary << written << "\n";
  return 1;
}

// --version --headless: the version (already printed), then what would draw.
int print_driver(std::ostream& out) {
  const EglContext context;
  const GlDriver& driver = context.driver();
  out << "EGL platform: " << driver.platform << "\nGL vendor: " << driver.vendor
      << "\nGL renderer: " << driver.renderer << "\nGL version: " << driver.version << "\n";
  return 0;
}

// --headless with --screenshot or --record: the viewer's frame loop in an EGL context.
int render_headless(const CommandLine& command, std::ostream& out, std::ostream& progress) {
  // The expected picture is read before any work: a file that is not a PNG is bad input.
  RgbaImage expected;
  if (!command.expect.empty()) {
    try {
      expected = read_png(command.expect, CommandLine::max_image_side);
    } catch (const InputError& error) {
      throw InputError(std::string("--expect: ") + error.what());
    }
  }
  const long frames = command.frames.value_or(CommandLine::default_headless_frames);
  ImageOutputs outputs(command.screenshot, command.record, frames, progress);
  if (!command.export_obj.empty()) check_output_path("--export-obj", command.export_obj);
  const ObjSequence obj_sequence(command.export_obj_sequence);
  Viewer viewer = open_viewer(command);
  InstrumentCsv instruments(command.convergence_csv, command.energy_csv, frames,
                            viewer.session().simulation().params().iterations);
  viewer.session().set_convergence_required(instruments.wants_convergence());
  instruments.start(viewer.session().simulation());
  print_notes(viewer.session().scene(),
              progress);  // the scene, its texture and the simulation loaded
  // Each step's files and rows, as the window writes them.
  StepOutputs step_outputs(obj_sequence, instruments, command.stats);
  step_outputs.reserve(frames);
  viewer.session().set_step_observer(
      [&](const Simulation& simulation) { step_outputs.after_step(simulation); });

  OffscreenOptions options;
  options.width = command.width;
  options.height = command.height;
  options.frames = frames;
  options.ui = command.ui;
  OffscreenReport report;
  RgbaImage last;
  try {
    last = render_offscreen(viewer, options, &outputs, &report);
    outputs.finish();  // the video's index; a failure above completes it in its destructor
  } catch (...) {
    instruments.write();  // the frames before a failure are kept, as the images are
    throw;
  }
  instruments.write();

  const Simulation& simulation = viewer.session().simulation();
  if (!command.export_obj.empty()) {
    write_obj(command.export_obj, simulation.positions(), viewer.session().scene().network.F,
              viewer.session().scene().network.E);
  }
  if (command.stats) {
    nlohmann::ordered_json stats =
        run_statistics(simulation, viewer.session().scene(), frames, step_outputs.times());
    stats["render_ms_median"] = median(report.render_ms);
    stats["width"] = command.width;
    stats["height"] = command.height;
    stats["context"] = report.context;
    stats["egl_platform"] = report.driver.platform;
    stats["gl_vendor"] = report.driver.vendor;
    stats["gl_renderer"] = report.driver.renderer;
    stats["gl_version"] = report.driver.version;
    out << stats.dump() << "\n";
  }
  if (!command.expect.empty()) return check_expected(command, expected, last, progress);
  return 0;
}

}  // namespace

int run_headless(const CommandLine& command, std::ostream& out, std::ostream& progress) {
  if (command.version_with_driver) return print_driver(out);
  if (command.writes_images()) return render_headless(command, out, progress);
  if (!command.export_obj.empty()) check_output_path("--export-obj", command.export_obj);
  const ObjSequence obj_sequence(command.export_obj_sequence);

  Scene scene = open_scene(command);
  const SimulationParams params = command.settings.applied_to(scene.params);
  const auto simulation_pointer = naming_scene(command.scene, [&] {
    return std::make_unique<Simulation>(scene.network, scene.pins, params, scene.initial_velocity);
  });
  Simulation& simulation = *simulation_pointer;
  DragScript drags(command.drags, scene.network.V.rows());
  const long frames = command.frames.value_or(CommandLine::default_headless_frames);
  InstrumentCsv instruments(command.convergence_csv, command.energy_csv, frames, params.iterations);
  simulation.set_convergence_recording(instruments.wants_convergence());
  instruments.start(simulation);
  print_notes(scene, progress);  // everything was accepted: the notes cannot precede a refusal

  StepOutputs step_outputs(obj_sequence, instruments, command.stats);
  step_outputs.reserve(frames);
  for (long frame = 0; frame < frames; ++frame) {
    drags.before_step(simulation, frame + 1);
    const StepStatus status = simulation.step();
    if (status != StepStatus::ok) {
      // The positions are still those of the last good frame, but the run did not finish:
      // report it, and write no final export. The instruments' rows so far are kept: they show
      // how the run failed.
      instruments.write();
      throw std::runtime_error("frame " + std::to_string(frame + 1) + ": " +
                               Simulation::describe(status));
    }
    step_outputs.after_step(simulation);
  }

  instruments.write();
  if (!command.export_obj.empty()) {
    write_obj(command.export_obj, simulation.positions(), scene.network.F, scene.network.E);
  }
  if (command.stats) {
    out << run_statistics(simulation, scene, frames, step_outputs.times()).dump() << "\n";
  }
  return 0;
}

}  // namespace wobble
