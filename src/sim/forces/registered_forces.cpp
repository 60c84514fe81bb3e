// Wobble's forces, in the order they add to f_ext after gravity. Adding one: its own files (a
// ForceTerm and a ForceFactory), one line here.
#include "sim/forces/force_registry.h"
#include "sim/forces/wind.h"

namespace wobble {

const std::vector<ForceEntry>& built_in_forces() {
  static const std::vector<ForceEntry> forces = {
      {"wind", make_wind_force},
  };
  return forces;
}

}  // namespace wobble
