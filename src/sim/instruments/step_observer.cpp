#include "step_observer.h"

namespace wobble {

void StepObservers::set(std::vector<StepObserver*> observers) {
  observers_ = std::move(observers);
  wants_measures_ = false;
  for (StepObserver* observer : observers_)
    wants_measures_ = wants_measures_ || observer->wants_measures();
}

}  // namespace wobble
