#include "value_limits.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace wobble {

std::string limit_text(double value, int max_digits) {
  // The fewest significant digits that give the value back, then "1e+08" written as "1e8".
  char text[32];
  for (int digits = 1; digits <= max_digits; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  std::string shown(text);
  const std::size_t e = shown.find('e');
  if (e == std::string::npos) return shown;
  // Whole numbers up to 99999 read better written out: 1000, not 1e3.
  const int power = std::atoi(text + e + 1);
  if (power >= 0 && power <= 4) {
    // %g gave an exponent only because the digits ran out, so the rounded value is whole.
    std::snprintf(text, sizeof text, "%.0f", std::strtod(text, nullptr));
    return text;
  }
  std::string exponent = shown.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent.erase(0, exponent[0] == '-' || exponent[0] == '+' ? 1 : 0);
  exponent.erase(0, exponent.find_first_not_of('0') == std::string::npos
                        ? exponent.size() - 1
                        : exponent.find_first_not_of('0'));
  return shown.substr(0, e) + "e" + (negative ? "-" : "") + exponent;
}

std::string within_text(const ValueRange& range) {
  const std::string unit = *range.unit ? std::string(" ") + range.unit : "";
  return "within the limits " + limit_text(range.low) + " to " + limit_text(range.high) + unit;
}

std::string expected_in(const ValueRange& range) {
  return std::string(range.low > 0.0 ? "a positive number " : "a number ") + within_text(range);
}

std::string outside_limits(const Eigen::Ref<const Eigen::ArrayXd>& values, const ValueRange& range,
                           const std::string& what) {
  if (values.size() == 0) return "";
  if (!values.allFinite()) return "non-finite " + what + ", expected each " + within_text(range);
  const double low = values.minCoeff(), high = values.maxCoeff();
  if (range.contains(low) && range.contains(high)) return "";
  const std::string unit = *range.unit ? std::string(" ") + range.unit : "";
  // Three digits, unless rounding would carry a value across a limit (1000001 is not 1e6).
  const auto shown = [&](double value) {
    const std::string text = limit_text(value, 3);
    return range.contains(std::strtod(text.c_str(), nullptr)) == range.contains(value)
               ? text
               : limit_text(value);
  };
  return what + " from " + shown(low) + " to " + shown(high) + unit + ", expected each " +
         within_text(range);
}

}  // namespace wobble
