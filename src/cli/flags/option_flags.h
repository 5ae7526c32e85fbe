#pragma once
/// @file
/// The option table's face on a CLI11 command line: `saltus`'s verbs and saltus-gui's command
/// line add their evaluation and optimiser flags here, so both accept and reject the same
/// values with the same messages (every value is read by the table's parse_option_value).

#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "saltus/optim/option_table.h"

namespace saltus::cli {

/// The names of the table's options of `use`, in table order.
std::vector<std::string> option_names(OptionUse use);
/// Every option's name, in table order.
std::vector<std::string> all_option_names();

/// Flags for options of the table on one CLI11 command. Parsed values land in values() (the
/// defaults until given) and given(); the object must outlive the parse and stay where it is.
class OptionFlags {
 public:
  OptionFlags() = default;
  OptionFlags(const OptionFlags&) = delete;
  OptionFlags& operator=(const OptionFlags&) = delete;

  /// Adds the flags of the options named, in the order named: "--samples INT" with the
  /// option's help, unit, range and default. `runs`: the command's (kEvaluation for evaluate and
  /// simulate: their defaults, and no words that only optimisations take).
  void add(CLI::App* command, const std::vector<std::string>& names,
           OptionUse runs = OptionUse::kOptimization);

  const OptionValues& values() const { return values_; }
  /// The options given on the command line, by name.
  const std::vector<std::pair<std::string, OptionValue>>& given() const { return given_; }

 private:
  OptionValues values_;
  std::vector<std::pair<std::string, OptionValue>> given_;
};

}  // namespace saltus::cli
