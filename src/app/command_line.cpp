#include "command_line.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <ostream>
#include <sstream>

#include "sim/builtin_scenes.h"
#include "sim/input_error.h"
#include "sim/simulation.h"

#ifndef WOBBLE_VERSION
#define WOBBLE_VERSION "unknown"
#endif

namespace wobble {

namespace {

std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!text.empty() && text.back() == ' ')
    text.pop_back();
  return text;
}

std::string number_text(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

void check_positive(const char* option, double value, double limit) {
  if (!std::isfinite(value) || !(value > 0.0)) {
    throw InputError(std::string(option) + ": expected a positive finite number, got " +
                     number_text(value));
  }
  if (value > limit) {
    throw InputError(std::string(option) + ": " + number_text(value) + " is above the limit of " +
                     number_text(limit));
  }
}

void check_count(const char* option, long value, long limit) {
  if (value < 1 || value > limit) {
    throw InputError(std::string(option) + ": expected a whole number from 1 to " +
                     std::to_string(limit) + ", got " + std::to_string(value));
  }
}

}  // namespace

std::optional<CommandLine> parse_command_line(int argc, const char* const* argv,
                                              std::ostream& out) {
  CommandLine command;
  CLI::App app("Wobble: cloth and jelly as fast mass-spring systems (Liu et al. 2013).", "wobble");
  app.get_formatter()->column_width(28);
  bool version = false, list_scenes = false;
  app.add_option("scene", command.scene, "Built-in scene to load (see --list-scenes)")
      ->capture_default_str();
  app.add_flag("--headless", command.headless, "Run without a window");
  app.add_option("--frames", command.frames,
                 "Run this many steps and exit (headless default: " +
                     std::to_string(CommandLine::default_headless_frames) + ")");
  app.add_option("--export-obj", command.export_obj, "Write the final positions as OBJ");
  app.add_option("--k", command.k, "Spring stiffness in N/m (scene default otherwise)");
  app.add_option("--dt", command.dt, "Time step in seconds (scene default otherwise)");
  app.add_option("--iterations", command.iterations, "Local-global iterations per step");
  app.add_flag("--stats", command.stats, "Print timing statistics as JSON on the last line");
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
    return std::nullopt;
  }
  if (list_scenes) {
    for (const std::string& name : builtin_scene_names()) {
      out << name << "  " << make_builtin_scene(name).description << "\n";
    }
    return std::nullopt;
  }

  if (command.frames) check_count("--frames", *command.frames, CommandLine::max_frames);
  if (command.iterations) {
    check_count("--iterations", *command.iterations, Simulation::max_iterations);
  }
  if (command.k) check_positive("--k", *command.k, CommandLine::max_k);
  if (command.dt) check_positive("--dt", *command.dt, CommandLine::max_dt);
  return command;
}

}  // namespace wobble
