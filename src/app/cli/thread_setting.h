#ifndef WOBBLE_APP_CLI_THREAD_SETTING_H
#define WOBBLE_APP_CLI_THREAD_SETTING_H

#include <ostream>

#include "app/cli/command_line.h"

namespace wobble {

// Obey the user's thread setting, before any simulation is made, in every parallel part of the
// process:
// - the solver's shared pool gets --threads, else OMP_NUM_THREADS, capped by OMP_THREAD_LIMIT
//   (sim/parallel/worker_pool.h, decide_thread_setting); a variable that cannot be obeyed is
//   reported on `err` as one warning line;
// - when the user set the threads (not the default from the processors) and LP_NUM_THREADS is
//   unset, Mesa's llvmpipe renderer gets as many rasterizer threads as the pool has helpers
//   (threads − 1; 0 renders on the calling thread).
// The window's step thread, which runs the steps beside the render loop, is not a parallel
// region: with --threads 1 a step runs on one thread.
void obey_thread_setting(const CommandLine& command, std::ostream& err);

}  // namespace wobble

#endif
