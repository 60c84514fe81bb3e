// wobble: the command-line entry point. Every error is caught here, once, and becomes one line
// on stderr and an exit code: 2 for bad input or usage, and for a machine that cannot draw (no
// display, no EGL, no OpenGL 3.3, a shader the driver refuses: what the user must set up); 1 for
// a failure at run time.
#include <exception>
#include <iostream>

#include "app/cli/command_line.h"
#include "app/cli/thread_setting.h"
#include "app/headless/run_headless.h"
#include "app/window/run_window.h"
#include "io/atomic_file.h"
#include "platform/context_error.h"
#include "render/shader_program.h"
#include "sim/input_error.h"

int main(int argc, char** argv) {
  // A run ended by SIGTERM or Ctrl+C leaves no half-written *.tmp-XXXXXX file behind.
  wobble::remove_temporary_file_on_termination();
  try {
    const std::optional<wobble::CommandLine> command =
        wobble::parse_command_line(argc, argv, std::cout);
    if (!command) return 0;
    wobble::obey_thread_setting(*command, std::cerr);
    if (command->headless) return wobble::run_headless(*command, std::cout, std::cerr);
    return wobble::run_window(*command, std::cout, std::cerr);
  } catch (const wobble::InputError& error) {
    std::cerr << "wobble: " << wobble::one_line(error.what()) << "\n";
    return 2;
  } catch (const wobble::ContextError& error) {
    std::cerr << "wobble: error: " << wobble::one_line(error.what()) << "\n";
    return 2;
  } catch (const wobble::ShaderError& error) {
    std::cerr << "wobble: error: " << wobble::one_line(error.what()) << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "wobble: error: " << wobble::one_line(error.what()) << "\n";
    return 1;
  }
}
