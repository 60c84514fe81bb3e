// The checker of one student function, built by scripts/check-assignment.sh: the student's
// object for that function with its course call site (course_call.h), Wobble's six functions
// under reference_* names as the oracle, and Wobble's plain six for every other function the
// student's code calls (so a bug is blamed on the function that has it). It runs every check in
// a child process and prints one verdict line, then any notes:
//
//   PASS  name
//   FAIL  name: what differs, where, by how much, on which input[: a hint]
//         note: what else was found (a pin weight other than the handout's, Unext read)
//
// With --facts FILE it also writes "pin_weight W" there: the weight the function was found to
// use (nan when none), which the script compares between a precomputation and its step.
// Exit status: 0 pass, 1 fail, 2 when the checker cannot run (bad option, unreadable scene).
#include <dirent.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "check_cases.h"
#include "check_scene.h"
#include "child_process.h"
#include "compare.h"
#include "course_problem.h"
#include "pin_weight.h"

const std::vector<CheckedFunction>& checked_functions() {
  static const std::vector<CheckedFunction> functions = {
      {"signed_incidence_matrix_dense", check_signed_incidence_matrix_dense, 0, nullptr, nullptr},
      {"signed_incidence_matrix_sparse", check_signed_incidence_matrix_sparse, kLargeChainVertices,
       nullptr, nullptr},
      {"fast_mass_springs_precomputation_dense", check_fast_mass_springs_precomputation_dense, 0,
       nullptr, nullptr},
      {"fast_mass_springs_precomputation_sparse", check_fast_mass_springs_precomputation_sparse,
       kLargeChainVertices, nullptr, nullptr},
      {"fast_mass_springs_step_dense", check_fast_mass_springs_step_dense, 0,
       probe_step_dense_pin_weight, probe_step_dense_reads_unext},
      {"fast_mass_springs_step_sparse", check_fast_mass_springs_step_sparse, kLargeChainVertices,
       probe_step_sparse_pin_weight, probe_step_sparse_reads_unext},
  };
  return functions;
}

namespace {

struct Options {
  std::string function;
  std::string course_folder;
  std::string facts_file;
  ChildLimits limits;
  int large_vertices = 0;  // 0: the function's own (CheckedFunction::large_vertices)
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
    } else if (option == "--facts") {
      options.facts_file = value;
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
      return outcome.text + on;  // decoded: the difference alone
    case ChildOutcome::kCrashed:
      return "crashed with " + outcome.signal_name + on + printed;
    case ChildOutcome::kTimedOut:
      return "did not finish within " + number(limits.seconds) + " s" + on +
             (scene.large ? ": does its work grow faster than the square of the vertices?"
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

// A CheckResult through the child's pipe: the weight, the difference, the hint, then the notes,
// each ended by a unit separator (no message holds one).
constexpr char kSeparator = '\x1f';

std::string encode(const CheckResult& result) {
  std::string text = number(result.pin_weight, 17) + kSeparator + result.difference + kSeparator +
                     result.hint + kSeparator;
  for (const std::string& note : result.notes)
    text += note + kSeparator;
  return text;
}

CheckResult decode(const std::string& text) {
  CheckResult result;
  std::vector<std::string> fields;
  size_t from = 0;
  for (size_t at; (at = text.find(kSeparator, from)) != std::string::npos; from = at + 1)
    fields.push_back(text.substr(from, at - from));
  if (fields.size() < 3) {
    result.difference = text;  // not from encode(): say what came back
    return result;
  }
  result.pin_weight = std::strtod(fields[0].c_str(), nullptr);
  result.difference = fields[1];
  result.hint = fields[2];
  result.notes.assign(fields.begin() + 3, fields.end());
  return result;
}

bool same_weight(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::abs(b);
}

// The probes of a step (check_cases.h), each in a child: the pin weight its step uses, into
// `context`, and the notes they give.
void probe_step(const CheckedFunction& function, const ChildLimits& limits, CheckContext& context,
                double& found_weight, std::vector<std::string>& notes) {
  const ChildOutcome weighed = run_in_child(
      [&](std::string& payload) {
        payload = number(function.probe_pin_weight(), 17);
        return true;
      },
      limits);
  if (weighed.kind == ChildOutcome::kAgreed)
    found_weight = std::strtod(weighed.text.c_str(), nullptr);
  if (acceptable_pin_weight(found_weight)) {
    // The handout's weight, found to rounding, is the handout's: the reference runs unchanged.
    if (same_weight(found_weight, kHandoutPinWeight)) found_weight = kHandoutPinWeight;
    context.step_pin_weight = found_weight;
    if (found_weight != kHandoutPinWeight)
      notes.push_back("its pins are held with w = " + pin_weight_text(found_weight) +
                      " (the handout's example is " + pin_weight_text(kHandoutPinWeight) +
                      "); checked against the reference with that weight");
  } else if (std::abs(found_weight) < 1.0) {  // zero, to the rounding of a 1e10 factor
    notes.push_back("its y has no pin term w CᵀC V: a pinned vertex is not pulled to its place");
  } else if (found_weight > 0) {
    // (A negative weight is no weight at all: the step does something else with pins.)
    notes.push_back("its pins are held with w = " + pin_weight_text(found_weight) +
                    ", outside the weights accepted (" + pin_weight_text(kLightestPinWeight) +
                    " to " + pin_weight_text(kHeaviestPinWeight) +
                    "); checked with the handout's " + pin_weight_text(kHandoutPinWeight));
  }

  const auto reads_unext = [&](bool empty) {
    return run_in_child(
        [&](std::string& payload) {
          payload = function.probe_reads_unext(empty);
          return true;
        },
        limits);
  };
  const ChildOutcome with_nan = reads_unext(false);
  if (with_nan.kind != ChildOutcome::kAgreed) return;  // the step fails on its own; said below
  if (!with_nan.text.empty()) {
    notes.push_back(with_nan.text);
    return;
  }
  const ChildOutcome with_empty = reads_unext(true);
  if (with_empty.kind == ChildOutcome::kAgreed && !with_empty.text.empty())
    notes.push_back(with_empty.text);
  else if (with_empty.kind == ChildOutcome::kCrashed || with_empty.kind == ChildOutcome::kThrew)
    notes.push_back(kReadsUnextNote);
}

void print_verdict(const char* name, const std::string& failure,
                   const std::vector<std::string>& notes) {
  if (failure.empty())
    std::printf("PASS  %s\n", name);
  else
    std::printf("FAIL  %s: %s\n", name, failure.c_str());
  for (const std::string& note : notes)
    std::printf("      note: %s\n", note.c_str());
}

void write_facts(const std::string& path, double pin_weight) {
  if (path.empty()) return;
  if (std::FILE* facts = std::fopen(path.c_str(), "w")) {
    std::fprintf(facts, "pin_weight %.17g\n", pin_weight);
    std::fclose(facts);
  }
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
  if (found->large_vertices > 0)
    scenes.push_back(
        large_chain(options.large_vertices > 0 ? options.large_vertices : found->large_vertices));

  CheckContext context;
  std::vector<std::string> notes;
  double pin_weight = std::numeric_limits<double>::quiet_NaN();
  if (found->probe_pin_weight) probe_step(*found, options.limits, context, pin_weight, notes);

  bool weight_noted = found->probe_pin_weight != nullptr;
  for (const CheckScene& scene : scenes) {
    const ChildOutcome outcome = run_in_child(
        [&](std::string& payload) {
          const CheckResult result = found->check(scene, context);
          payload = encode(result);
          return result.difference.empty();
        },
        options.limits);
    CheckResult result;
    if (outcome.kind == ChildOutcome::kAgreed || outcome.kind == ChildOutcome::kDiffered) {
      result = decode(outcome.text);
      notes.insert(notes.end(), result.notes.begin(), result.notes.end());
      if (!weight_noted && std::isfinite(result.pin_weight)) {
        // The first pinned scene tells the precomputation's weight.
        weight_noted = true;
        pin_weight = result.pin_weight;
        if (acceptable_pin_weight(pin_weight) && !same_weight(pin_weight, kHandoutPinWeight))
          notes.push_back("its Q holds the pins with w = " + pin_weight_text(pin_weight) +
                          " (the handout's example is " + pin_weight_text(kHandoutPinWeight) +
                          "); checked against the reference with that weight");
      }
    }
    if (outcome.kind != ChildOutcome::kAgreed) {
      ChildOutcome told = outcome;
      if (outcome.kind == ChildOutcome::kDiffered) told.text = result.difference;
      std::string failure = describe(told, scene, options.limits);
      if (!result.hint.empty()) failure += "; hint: " + result.hint;
      print_verdict(found->name, failure, notes);
      write_facts(options.facts_file, pin_weight);
      return 1;
    }
  }
  print_verdict(found->name, "", notes);
  write_facts(options.facts_file, pin_weight);
  return 0;
}
