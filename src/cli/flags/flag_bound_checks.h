#pragma once
/// @file
/// The library's table of number flags' bounds (saltus/use_cases/flag_bounds.h) on a CLI11
/// command line: `saltus` and saltus-gui check every number flag they parse against its row, so
/// a value out of bounds is refused at parsing, exit status 2, with the library's message
/// ("--jobs: 0 is outside [1, 4096]").

#include <CLI/CLI.hpp>
#include <string>

namespace saltus::cli {

/// A validator of `flag`'s row for `verb` ("study athletes", "saltus-gui"): the text read as a
/// number (nan and inf included) and checked with the row's bound; std::logic_error when the
/// table has no such row.
CLI::Validator flag_bound_check(const std::string& flag, const std::string& verb);

/// Adds flag_bound_check to every number option (type FLOAT, INT, UINT) of `app`'s subcommands,
/// and of `app` itself as verb `program`, and the row's bound to the option's help. The option
/// table's flags keep their own reader (the same bounds). A number option the table lacks is a
/// programming error: std::logic_error before any parsing.
void add_flag_bound_checks(CLI::App& app, const std::string& program);

}  // namespace saltus::cli
