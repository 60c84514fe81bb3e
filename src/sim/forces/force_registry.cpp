#include "sim/forces/force_registry.h"

namespace wobble {

namespace {

std::vector<ForceEntry>& registered_forces() {
  static std::vector<ForceEntry> forces;
  return forces;
}

}  // namespace

ForceRegistration::ForceRegistration(const char* name, ForceFactory make) {
  registered_forces().push_back(ForceEntry{name, make});
}

std::vector<std::unique_ptr<ForceTerm>> make_forces(const ForceSetup& setup) {
  std::vector<std::unique_ptr<ForceTerm>> forces;
  const std::vector<ForceEntry>& built_in = built_in_forces();
  const std::vector<ForceEntry>& registered = registered_forces();
  for (const std::vector<ForceEntry>* list : {&built_in, &registered}) {
    for (const ForceEntry& entry : *list) {
      if (std::unique_ptr<ForceTerm> force = entry.make(setup)) forces.push_back(std::move(force));
    }
  }
  return forces;
}

}  // namespace wobble
