// The checker of one student function, built by scripts/check-assignment.sh: the student's
// object for that function, Wobble's six functions under reference_* names as the oracle, and
// Wobble's plain six for every other function the student's code calls (so a bug is blamed on
// the function that has it). It runs every check in a child process and prints one line:
//
//   PASS  name
//   FAIL  name: what differs, where, by how much, on which input
//
// Exit status: 0 pass, 1 fail, 2 when the checker cannot run (bad option, unreadable scene).
#include <dirent.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "check_cases.h"
#include "check_scene.h"
#include "child_process.h"
#include "compare.h"
#include "course_problem.h"

const std::vector<CheckedFunction>& checked_functions() {
  static const std::vector<CheckedFunction> functions = {
      {"signed_incidence_matrix_dense", check_signed_incidence_matrix_dense, false},
      {"signed_incidence_matrix_sparse", check_signed_incidence_matrix_sparse, true},
      {"fast_mass_springs_precomputation_dense", check_fast_mass_springs_precomputation_dense,
       false},
      {"fast_mass_springs_precomputation_sparse", check_fast_mass_springs_precomputation_sparse,
       true},
      {"fast_mass_springs_step_dense", check_fast_mass_springs_step_dense, false},
      {"fast_mass_springs_step_sparse", check_fast_mass_springs_step_sparse, true},
  };
  return functions;
}

namespace {

struct Options {
  std::string function;
  std::string course_folder;
  ChildLimits limits;
  int large_vertices = 100000;
};

[[noreturn]] void bad_usage(const std::string& message) {
  std::fprintf(stderr, "check: %s\n", message.c_str());
  std::exit(2);
}

Options parse_options(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (i + 1 >= argc) bad_usage(option + " needs a value");
    const std::string value = argv[++i];
    char* end = nullptr;
    if (option == "--function") {
      options.function = value;
    } else if (option == "--course-dir") {
      options.course_folder = value;
    } else if (option == "--time-limit") {
      options.limits.seconds = std::strtod(value.c_str(), &end);
      if (*end || !(options.limits.seconds > 0)) bad_usage("--time-limit: expected seconds > 0");
    } else if (option == "--memory-limit") {
      options.limits.memory_bytes = std::strtoll(value.c_str(), &end, 10) << 20;
      if (*end || options.limits.memory_bytes < (64LL << 20))
        bad_usage("--memory-limit: expected MiB >= 64");
    } else if (option == "--large-vertices") {
      options.large_vertices = static_cast<int>(std::strtol(value.c_str(), &end, 10));
      if (*end || options.large_vertices < 2) bad_usage("--large-vertices: expected a count >= 2");
    } else {
      bad_usage("unknown option " + option);
    }
  }
  if (options.function.empty()) bad_usage("--function NAME is required");
  return options;
}

// Every *.json of the course folder, in name order.
std::vector<CheckScene> course_scenes(const std::string& folder) {
  std::vector<std::string> names;
  if (DIR* listing = opendir(folder.c_str())) {
    while (const dirent* entry = readdir(listing)) {
      const std::string name = entry->d_name;
      if (name.size() > 5 && name.compare(name.size() - 5, 5, ".json") == 0) names.push_back(name);
    }
    closedir(listing);
  } else {
    throw std::runtime_error(folder + ": cannot open the folder of course scenes");
  }
  std::sort(names.begin(), names.end());
  std::vector<CheckScene> scenes;
  for (const std::string& name : names)
    scenes.push_back(load_course_problem(folder + "/" + name, 6));
  return scenes;
}

std::string memory_words(long long bytes) {
  if (bytes % (1LL << 30) == 0) return std::to_string(bytes >> 30) + " GiB";
  return std::to_string(bytes >> 20) + " MiB";
}

// What a FAIL line says after "name: ".
std::string describe(const ChildOutcome& outcome, const CheckScene& scene,
                     const ChildLimits& limits) {
  const std::string on = " on " + scene.description;
  const std::string printed =
      outcome.output_tail.empty() ? "" : " (its last output: \"" + outcome.output_tail + "\")";
  switch (outcome.kind) {
    case ChildOutcome::kDiffered:
      return outcome.text + on;
    case ChildOutcome::kCrashed:
      return "crashed with " + outcome.signal_name + on + printed;
    case ChildOutcome::kTimedOut:
      return "did not finish within " + number(limits.seconds) + " s" + on +
             (scene.large ? ": is a dense matrix built, or a loop over all pairs of vertices?"
                          : printed);
    case ChildOutcome::kOutOfMemory:
      if (scene.large)
        return "uses more than " + memory_words(limits.memory_bytes) + on +
               ": is a dense matrix built and converted (.sparseView())?";
      return "ran out of memory (more than " + memory_words(limits.memory_bytes) + ")" + on;
    case ChildOutcome::kThrew:
      return "threw an exception (" + outcome.text + ")" + on;
    case ChildOutcome::kExited:
      return "ended the whole program (exit code " + std::to_string(outcome.exit_code) + ")" + on +
             printed;
    case ChildOutcome::kAgreed:
      break;
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse_options(argc, argv);
  const auto& functions = checked_functions();
  const auto found = std::find_if(functions.begin(), functions.end(),
                                  [&](const auto& f) { return options.function == f.name; });
  if (found == functions.end()) bad_usage("unknown function " + options.function);

  std::vector<CheckScene> scenes = generated_scenes();
  try {
    if (!options.course_folder.empty()) {
      const std::vector<CheckScene> course = course_scenes(options.course_folder);
      scenes.insert(scenes.end(), course.begin(), course.end());
    }
  } catch (const std::exception& error) {
    bad_usage(error.what());
  }
  // Smallest first, so the first failure is the smallest input that shows the bug.
  std::stable_sort(scenes.begin(), scenes.end(), [](const CheckScene& a, const CheckScene& b) {
    return a.V.rows() != b.V.rows() ? a.V.rows() < b.V.rows() : a.E.rows() < b.E.rows();
  });
  if (found->sparse) scenes.push_back(large_chain(options.large_vertices));

  for (const CheckScene& scene : scenes) {
    const ChildOutcome outcome = run_in_child([&] { return found->check(scene); }, options.limits);
    if (outcome.kind != ChildOutcome::kAgreed) {
      std::printf("FAIL  %s: %s\n", found->name, describe(outcome, scene, options.limits).c_str());
      return 1;
    }
  }
  std::printf("PASS  %s\n", found->name);
  return 0;
}
