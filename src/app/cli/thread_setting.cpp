#include "app/cli/thread_setting.h"

#include <cstdlib>
#include <string>

#include "sim/parallel/worker_pool.h"

namespace wobble {

void obey_thread_setting(const CommandLine& command, std::ostream& err) {
  if (command.threads) request_shared_threads(*command.threads);
  const ThreadSetting& setting = shared_thread_setting();
  if (!setting.warning.empty()) err << "wobble: warning: " << setting.warning << "\n";
  if (setting.source != "processors" && std::getenv("LP_NUM_THREADS") == nullptr) {
    setenv("LP_NUM_THREADS", std::to_string(setting.threads - 1).c_str(), 0);
  }
}

}  // namespace wobble
