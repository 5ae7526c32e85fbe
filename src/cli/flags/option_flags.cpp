#include "flags/option_flags.h"

namespace saltus::cli {

namespace {

std::string type_name(const OptionSpec& spec, OptionUse runs) {
  switch (spec.kind) {
    case OptionKind::kChoice:
      return option_range_text(spec, runs);
    case OptionKind::kInteger:
      return spec.takes_word(runs) ? "INT|" + spec.word : "INT";
    case OptionKind::kReal:
      return spec.takes_word(runs) ? "FLOAT|" + spec.word : "FLOAT";
    case OptionKind::kSwitch:
      break;
  }
  return "";
}

}  // namespace

std::vector<std::string> option_names(OptionUse use) {
  std::vector<std::string> out;
  for (const OptionSpec& spec : option_table())
    if (spec.use == use) out.push_back(spec.name);
  return out;
}

std::vector<std::string> all_option_names() {
  std::vector<std::string> out;
  for (const OptionSpec& spec : option_table())
    out.push_back(spec.name);
  return out;
}

void OptionFlags::add(CLI::App* command, const std::vector<std::string>& names, OptionUse runs) {
  if (runs != values_.runs()) values_ = OptionValues(runs);
  for (const std::string& name : names) {
    const OptionSpec& spec = option_spec(name);
    if (spec.kind == OptionKind::kSwitch) {
      // The flag turns the option away from its default (--no-timing).
      const bool flagged = !std::get<bool>(values_.get(name));
      command->add_flag_function(
          spec.flag,
          [this, name, flagged](std::int64_t) {
            values_.set(name, flagged);
            given_.emplace_back(name, flagged);
          },
          option_description(spec, runs));
      continue;
    }
    CLI::Validator check(
        [&spec, runs](std::string& text) -> std::string {
          try {
            parse_option_value(spec, text, runs);
          } catch (const OptionValueError& e) {
            return e.problem();
          }
          return "";
        },
        "", spec.name);
    command
        ->add_option(
            spec.flag,
            [this, &spec, runs](const CLI::results_t& results) {
              const OptionValue value = parse_option_value(spec, results.front(), runs);
              values_.set(spec.name, value);
              given_.emplace_back(spec.name, value);
              return true;
            },
            option_description(spec, runs))
        ->type_name(type_name(spec, runs))
        ->default_str(option_value_text(values_.get(name)))
        ->check(check);
  }
}

}  // namespace saltus::cli
