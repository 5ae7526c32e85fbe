#include "saltus/base/number_bound.h"

#include <cmath>

#include "saltus/base/input_error.h"
#include "saltus/base/text_format.h"

namespace saltus {

namespace {

std::string with_unit(const std::string& number, const char* unit) {
  return *unit ? number + " " + unit : number;
}

/// A bound's end in full (4294967295 and 100000, not 4.29497e+09 or 1e+05): bounds are short.
std::string end_text(double end) {
  if (std::isinf(end)) return end > 0 ? "∞" : "-∞";
  if (end == std::floor(end) && std::fabs(end) < 1e15) return format_number("%.0f", end);
  return exact_number(end);
}

}  // namespace

bool within(const NumberBound& bound, double value) {
  if (!std::isfinite(value)) return false;
  if (bound.whole && value != std::floor(value)) return false;
  const bool above_lower = bound.lower_open ? value > bound.lower : value >= bound.lower;
  const bool below_upper = bound.upper_open ? value < bound.upper : value <= bound.upper;
  return above_lower && below_upper;
}

std::string bound_text(const NumberBound& bound) {
  // An infinite end is never reached: it is printed open whatever lower_open/upper_open say.
  const bool lower_open = bound.lower_open || std::isinf(bound.lower);
  const bool upper_open = bound.upper_open || std::isinf(bound.upper);
  return with_unit(std::string(lower_open ? "(" : "[") + end_text(bound.lower) + ", " +
                       end_text(bound.upper) + (upper_open ? ")" : "]"),
                   bound.unit);
}

std::string bound_problem(const NumberBound& bound, double value, const std::string& why) {
  if (within(bound, value)) return "";
  const std::string number = std::isfinite(value)
                                 ? message_number_beside(value, bound.lower, bound.upper)
                                 : message_number(value);
  std::string problem;
  if (bound.whole && std::isfinite(value) && value != std::floor(value))
    problem = number + " is not a whole number (allowed: " + bound_text(bound) + ")";
  else
    problem = with_unit(number, bound.unit) + " is outside " + bound_text(bound);
  if (!why.empty()) problem += " (" + why + ")";
  return problem;
}

void check_bound(const std::string& flag, const NumberBound& bound, double value,
                 const std::string& why) {
  const std::string problem = bound_problem(bound, value, why);
  if (!problem.empty()) throw InputError(flag, "", problem);
}

}  // namespace saltus
