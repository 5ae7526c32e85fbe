#pragma once
/// @file
/// A number's accepted interval and the one message for a value outside it, shared by every
/// check of a flag, a form field or a keyword argument: "--flag: VALUE UNIT is outside [LO, HI]
/// UNIT" with short numbers (docs/safety.md, "Bounds of every number flag").

#include <limits>
#include <string>

namespace saltus {

/// An interval of accepted numbers: [lower, upper], either end excluded when open, either end
/// infinite when unbounded (the value must still be finite). NaN and ±inf are never inside.
struct NumberBound {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  const char* unit = "";  ///< "" when dimensionless, e.g. "m", "s per frame", "%"
  bool lower_open = false;
  bool upper_open = false;
  bool whole = false;  ///< whole numbers only (a count)
};

/// Whether `value` is finite, inside `bound` and (for whole bounds) a whole number.
bool within(const NumberBound& bound, double value);

/// The interval as the messages and docs/safety.md print it: "[0.5, 2.8] m", "(0, ∞)",
/// "[1, 4096]".
std::string bound_text(const NumberBound& bound);

/// "" when `value` is within `bound`, else "VALUE UNIT is outside [LO, HI] UNIT" (the value with
/// the digits that tell it from a bound, message_number_beside), followed by " (why)" when `why`
/// is given, or "VALUE is not a whole number" for a whole bound.
std::string bound_problem(const NumberBound& bound, double value, const std::string& why = "");

/// Throws InputError(flag, "", bound_problem(...)) when `value` is not within `bound`.
void check_bound(const std::string& flag, const NumberBound& bound, double value,
                 const std::string& why = "");

}  // namespace saltus
