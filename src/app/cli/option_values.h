#ifndef WOBBLE_APP_CLI_OPTION_VALUES_H
#define WOBBLE_APP_CLI_OPTION_VALUES_H

#include <string>

#include "app/outputs/image_compare.h"
#include "sim/value_limits.h"

// The command line's values, read strictly from the text typed: each refusal is an InputError
// of one line that names `option` and quotes the text ("--k: expected a positive finite number,
// got 'abc'").
namespace wobble::cli {

// A positive finite number within `range` (sim/value_limits.h: the same limits as scene files).
double number_in(const char* option, const std::string& text, const ValueRange& range);
// A number within `range` that may be 0 (damping, friction).
double number_from_zero(const char* option, const std::string& text, const ValueRange& range);
// A whole number from 1 to `limit`.
long whole_number(const char* option, const std::string& text, long limit);
// A number from `low` to `high`.
double number_between(const char* option, const std::string& text, double low, double high);
// A path, `what` naming what it is for ("file path"); refused only when empty.
std::string path_value(const char* option, const std::string& text, const char* what);
// --expect-tolerance's "LEVELS[,PERCENT]": whole levels of 255, and a percentage of the pixels.
ImageTolerance parse_expect_tolerance(const std::string& text);

}  // namespace wobble::cli

#endif
