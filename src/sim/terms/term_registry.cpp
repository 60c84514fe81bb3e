#include "sim/terms/term_registry.h"

namespace wobble {

namespace {

std::vector<TermEntry>& registered_terms() {
  static std::vector<TermEntry> terms;
  return terms;
}

}  // namespace

TermRegistration::TermRegistration(const char* name, TermFactory make) {
  registered_terms().push_back(TermEntry{name, make});
}

std::vector<std::unique_ptr<StepTerm>> make_terms(const TermSetup& setup) {
  std::vector<std::unique_ptr<StepTerm>> terms;
  const std::vector<TermEntry>& built_in = built_in_terms();
  const std::vector<TermEntry>& registered = registered_terms();
  for (const std::vector<TermEntry>* list : {&built_in, &registered}) {
    for (const TermEntry& entry : *list) {
      if (std::unique_ptr<StepTerm> term = entry.make(setup)) terms.push_back(std::move(term));
    }
  }
  return terms;
}

}  // namespace wobble
