#include "flags/flag_bound_checks.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include "saltus/base/text_format.h"
#include "saltus/optim/option_table.h"
#include "saltus/use_cases/flag_bounds.h"

namespace saltus::cli {

namespace {

bool is_option_table_flag(const CLI::Option& option) {
  for (const OptionSpec& spec : option_table())
    if (option.check_name(spec.flag)) return true;
  return false;
}

bool is_number(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  return type == "FLOAT" || type == "INT" || type == "UINT" || type == "NUMBER";
}

/// `command`'s number options checked as `verb`'s, its subcommands' as theirs ("analyse" +
/// "what-if": "analyse what-if").
void add_checks(CLI::App& command, const std::string& verb, const std::string& prefix) {
  for (CLI::Option* option : command.get_options()) {
    if (!is_number(*option) || is_option_table_flag(*option)) continue;
    const FlagBound& row = flag_bound(option->get_name(), verb);
    option->check(flag_bound_check(row.flag, verb));
    if (std::isfinite(row.bound.lower) || std::isfinite(row.bound.upper))
      option->description(option->get_description() + " (" + bound_text(row.bound) + ")");
  }
  for (CLI::App* sub : command.get_subcommands([](CLI::App*) { return true; }))
    add_checks(*sub, prefix + sub->get_name(), prefix + sub->get_name() + " ");
}

}  // namespace

CLI::Validator flag_bound_check(const std::string& flag, const std::string& verb) {
  const FlagBound& row = flag_bound(flag, verb);
  return CLI::Validator(
      [&row](std::string& text) -> std::string {
        double value = 0.0;  // from_chars: "nan" and "inf" too, in every locale
        const char* last = text.data() + text.size();
        const auto [end, error] = std::from_chars(text.data(), last, value);
        if (text.empty()) return "";  // the shared not-empty check names it
        if (end != last || (error != std::errc() && error != std::errc::result_out_of_range))
          return "\"" + message_text(text) +
                 "\" is not a number (allowed: " + bound_text(row.bound) + ")";
        if (error == std::errc::result_out_of_range)  // 1e400: ±HUGE_VAL; 1e-400: 0
          value = std::strtod(text.c_str(), nullptr);
        return bound_problem(row.bound, value, row.why);
      },
      "", "");
}

void add_flag_bound_checks(CLI::App& app, const std::string& program) {
  add_checks(app, program, "");
}

}  // namespace saltus::cli
