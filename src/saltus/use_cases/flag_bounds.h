#pragma once
/// @file
/// The bounds of every number flag of every verb, in one table: the CLI checks each flag it
/// parses against its row (as saltus-gui's command line does), the use cases check the values
/// the Python module and the app pass with the same bounds, and docs/safety.md shows the table
/// as flag_bounds_markdown() writes it (a test compares the two). The optimiser options' rows
/// are read from the option table (optim/option_table.h), the body and capture rows from
/// plausible_ranges.h, the what-if tightness from evaluation/what_if.h: each number is stated
/// once, where it is used.

#include <string>
#include <string_view>
#include <vector>

#include "saltus/base/number_bound.h"

namespace saltus {

struct FlagBound {
  std::string flag;                ///< e.g. "--height"
  std::vector<std::string> verbs;  ///< e.g. {"model new", "model scale"}; "saltus-gui": the app
  NumberBound bound;
  std::string meaning;  ///< what the number is, for docs/safety.md
  std::string why;      ///< added to the refusal in brackets ("" none), e.g. "the human range"
  /// What else bounds it where the input decides (docs/safety.md), "" when nothing does.
  std::string further;
  bool option_table = false;  ///< an option of optim/option_table.h, parsed by its own reader
};

/// Every number flag of every verb, in the order docs/safety.md lists them.
const std::vector<FlagBound>& flag_bounds();

/// The row of `flag` for `verb` ("" for the first row of `flag`); std::logic_error when there is
/// none (a programming error: a flag was added without its row).
const FlagBound& flag_bound(std::string_view flag, std::string_view verb = "");

/// Throws InputError(flag, "", "VALUE UNIT is outside [LO, HI] UNIT (why)") when `value` is not
/// within the row's bound (NaN and ±inf never are); the error names `named` instead of the flag
/// when given (the app's form field, "Height").
void check_flag(std::string_view flag, double value, std::string_view verb = "",
                const std::string& named = "");

/// The table as docs/safety.md holds it: a Markdown table, one row per flag and bound.
std::string flag_bounds_markdown();

}  // namespace saltus
