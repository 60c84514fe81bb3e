#include "app/cli/option_values.h"

#include <cmath>
#include <optional>
#include <sstream>

#include "sim/parse_number.h"
#include "sim/input_error.h"

namespace wobble::cli {

namespace {

std::string number_text(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

// A value of `range` (sim/value_limits.h: the same limits as in scene files).
double number_in(const char* option, const std::string& text, const ValueRange& range) {
  const std::optional<double> value = parse_number<double>(text);
  if (!value || !std::isfinite(*value) || !(*value > 0.0)) {
    throw InputError(std::string(option) + ": expected a positive finite number, got '" + text +
                     "'");
  }
  if (!range.contains(*value)) {
    throw InputError(std::string(option) + ": expected " + expected_in(range) + ", got '" + text +
                     "'");
  }
  return *value;
}

// A value of `range` that may be 0 (damping, friction): "expected a number within ...".
double number_from_zero(const char* option, const std::string& text, const ValueRange& range) {
  const std::optional<double> value = parse_number<double>(text);
  if (!value || !range.contains(*value)) {
    throw InputError(std::string(option) + ": expected " + expected_in(range) + ", got '" + text +
                     "'");
  }
  return *value;
}

long whole_number(const char* option, const std::string& text, long limit) {
  const std::optional<long> value = parse_number<long>(text);
  if (!value || *value < 1 || *value > limit) {
    throw InputError(std::string(option) + ": expected a whole number from 1 to " +
                     std::to_string(limit) + ", got '" + text + "'");
  }
  return *value;
}

double number_between(const char* option, const std::string& text, double low, double high) {
  const std::optional<double> value = parse_number<double>(text);
  if (!value || !(*value >= low && *value <= high)) {
    throw InputError(std::string(option) + ": expected a number from " + number_text(low) + " to " +
                     number_text(high) + ", got '" + text + "'");
  }
  return *value;
}

std::string path_value(const char* option, const std::string& text, const char* what) {
  if (text.empty()) throw InputError(std::string(option) + ": expected a " + what + ", got ''");
  return text;
}

// --expect-tolerance's "LEVELS[,PERCENT]": whole levels of 255, and a percentage of the pixels.
ImageTolerance parse_expect_tolerance(const std::string& text) {
  const std::size_t comma = text.find(',');
  const std::optional<long> levels = parse_number<long>(text.substr(0, comma));
  const std::optional<double> percent = comma == std::string::npos
                                            ? std::optional<double>(100.0 * ImageTolerance{}.share)
                                            : parse_number<double>(text.substr(comma + 1));
  if (!levels || *levels < 0 || *levels > 255 || !percent || !(*percent >= 0.0) ||
      !(*percent <= 100.0)) {
    throw InputError(
        "--expect-tolerance: expected LEVELS[,PERCENT] (a whole number from 0 to "
        "255, then a number from 0 to 100), got '" +
        text + "'");
  }
  ImageTolerance tolerance;
  tolerance.channel = static_cast<int>(*levels);
  tolerance.share = 0.01 * *percent;
  return tolerance;
}

}  // namespace wobble::cli
