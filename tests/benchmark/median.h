#ifndef WOBBLE_TESTS_BENCHMARK_MEDIAN_H
#define WOBBLE_TESTS_BENCHMARK_MEDIAN_H

#include <algorithm>
#include <vector>

namespace wobble::benchmark {

// The middle value of a benchmark's timings (the upper middle of an even count): robust to the
// few slow samples a shared machine adds. `values` must not be empty.
inline double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

}  // namespace wobble::benchmark

#endif
