// wobble_step_positions SCENE [--frames N] [--k K] [--dt DT] [--iterations N]: the positions
// after N steps as JSON (step_positions.h), built natively and for node. Exit codes as wobble's.
#include <exception>
#include <iostream>

#include "app/cli/command_line.h"
#include "app/cli/thread_setting.h"
#include "app/web/step_positions.h"
#include "sim/input_error.h"

int main(int argc, char** argv) {
  try {
    const std::optional<wobble::CommandLine> command =
        wobble::parse_command_line(argc, argv, std::cout);
    if (!command) return 0;
    wobble::obey_thread_setting(*command, std::cerr);
    wobble::step_positions(*command, std::cout);
  } catch (const wobble::InputError& error) {
    std::cerr << "wobble_step_positions: " << wobble::one_line(error.what()) << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "wobble_step_positions: error: " << wobble::one_line(error.what()) << "\n";
    return 1;
  }
  return 0;
}
