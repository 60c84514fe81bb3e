#ifndef WOBBLE_PLATFORM_CONTEXT_ERROR_H
#define WOBBLE_PLATFORM_CONTEXT_ERROR_H

#include <stdexcept>

namespace wobble {

// No GL context could be made, windowed or headless. The message is one line saying what failed
// and what to do about it; the command line exits with code 2 (the machine's
// set-up, not the run, is what has to change).
class ContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace wobble

#endif
