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

void make_terms(const TermSetup& setup, const SimulationParams* before,
                std::vector<std::unique_ptr<StepTerm>>& terms) {
  std::vector<const TermEntry*> entries;
  for (const TermEntry& entry : built_in_terms()) {
    if (!entry.after_registered) entries.push_back(&entry);
  }
  for (const TermEntry& entry : registered_terms())
    entries.push_back(&entry);
  for (const TermEntry& entry : built_in_terms()) {
    if (entry.after_registered) entries.push_back(&entry);
  }
  const bool slots_kept = before && terms.size() == entries.size();
  if (!slots_kept) terms.clear();
  terms.resize(entries.size());
  for (std::size_t e = 0; e < entries.size(); ++e) {
    const TermEntry& entry = *entries[e];
    if (slots_kept && entry.still_serves && entry.still_serves(*before, setup.params)) continue;
    terms[e] = entry.make(setup);
  }
}

}  // namespace wobble
