// Wobble's made terms, in step order after the pins. Adding one: its own files (a StepTerm and a
// TermFactory), one line here.
#include "sim/forces/wind.h"
#include "sim/terms/term_registry.h"
#include "sim/volume/volume_term.h"

namespace wobble {

const std::vector<TermEntry>& built_in_terms() {
  static const std::vector<TermEntry> terms = {
      {"wind", make_wind_force},
      {"volume", make_volume_term},
  };
  return terms;
}

}  // namespace wobble
