#ifndef WOBBLE_SIM_INPUT_ERROR_H
#define WOBBLE_SIM_INPUT_ERROR_H

#include <stdexcept>

namespace wobble {

// Bad input: a scene, mesh, parameter or option that Wobble refuses. The message names what was
// wrong and what was expected; the command line prints it on one line and exits with code 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace wobble

#endif
