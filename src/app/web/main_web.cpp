// wobble in the browser: the page's address becomes a command line (page_arguments.h), and the
// viewer runs in the browser's loop (run_browser.h). What the address got wrong is said on the
// page, one line a key, and costs only that key; a scene that does not open opens the default
// scene instead, with the reason.
#include <emscripten.h>
#include <sys/stat.h>

#include <exception>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli/command_line.h"
#include "app/cli/scene_catalog.h"
#include "app/cli/thread_setting.h"
#include "app/web/page_arguments.h"
#include "app/web/run_browser.h"

namespace {

std::optional<wobble::CommandLine> parse(const std::vector<std::string>& arguments) {
  std::vector<const char*> argv;
  for (const std::string& argument : arguments)
    argv.push_back(argument.c_str());
  return wobble::parse_command_line(static_cast<int>(argv.size()), argv.data(), std::cout);
}

}  // namespace

int main() {
  // As a desktop session starts: emscripten's starts with a umask of 0777, which left every file
  // the page writes (a saved PNG, OBJ or scene) unreadable, even to its download.
  umask(022);
  const char* search = emscripten_run_script_string("location.search");
  const wobble::PageRequest request =
      wobble::read_page_address(search != nullptr ? search : "", wobble::scene_catalog());
  std::vector<std::string> arguments = request.arguments;
  std::vector<std::string> messages = request.refusals;
  // A page has one thread: the solver's pool runs everything on the caller.
  arguments.insert(arguments.begin() + 1, {"--threads", "1"});
  std::optional<wobble::CommandLine> command;
  try {
    command = parse(arguments);
    if (command) {
      wobble::obey_thread_setting(*command, std::cerr);
      const bool bench = wobble::page_wants_bench(search != nullptr ? search : "");
      if (bench) {
        messages.push_back("bench: measuring the step (" +
                           std::to_string(command->frames.value_or(60)) +
                           " steps, one thread); the page pauses for a few seconds");
      }
      wobble::run_browser(*command, messages, bench);
      return 0;
    }
  } catch (const std::exception& error) {
    messages.push_back("address: " + wobble::one_line(error.what()) +
                       "; opening the default scene");
  }
  try {
    command = parse({"wobble", "--threads", "1"});
    try {
      wobble::obey_thread_setting(*command, std::cerr);
    } catch (const std::logic_error&) {
      // The pool already has its one thread (the refused scene got that far).
    }
    wobble::run_browser(*command, messages);
  } catch (const std::exception& error) {
    std::cerr << "wobble: error: " << wobble::one_line(error.what()) << "\n";
    return 1;
  }
  return 0;
}
