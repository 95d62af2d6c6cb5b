// Validators for the numeric command-line options: CLI11's own (PositiveNumber, Range) let NaN pass
// (every comparison with NaN is false) and print their bounds with std::to_string, 309 digits for
// DBL_MAX. These refuse what is not a finite number and name the bounds as a person writes them.
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

namespace signalsim::app {

namespace cli_detail {

inline std::string readable(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// "" when `text` is a finite number within the bounds, else why not.
inline std::string check_number(const std::string& text, double min, bool min_inclusive, double max) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return "'" + text + "' is not a number";
  if (!std::isfinite(v) || errno == ERANGE) return "'" + text + "' is not a finite number";
  const bool above_min = min_inclusive ? v >= min : v > min;
  if (above_min && v <= max) return {};
  if (max == HUGE_VAL) return text + " is out of range: it must be " + (min_inclusive ? "at least " : "more than ") + readable(min);
  return text + " is out of range: it must be between " + readable(min) + " and " + readable(max);
}

}  // namespace cli_detail

/// A finite number > 0.
inline CLI::Validator positive_number() {
  return CLI::Validator([](std::string& text) { return cli_detail::check_number(text, 0.0, false, HUGE_VAL); },
                        "POSITIVE");
}

/// A finite number >= 0.
inline CLI::Validator non_negative_number() {
  return CLI::Validator([](std::string& text) { return cli_detail::check_number(text, 0.0, true, HUGE_VAL); },
                        "NONNEGATIVE");
}

/// A finite number in [min, max].
inline CLI::Validator number_between(double min, double max) {
  return CLI::Validator([min, max](std::string& text) { return cli_detail::check_number(text, min, true, max); },
                        "NUMBER in [" + cli_detail::readable(min) + ", " + cli_detail::readable(max) + "]");
}

}  // namespace signalsim::app
