#include "saltus/formats/yeadon_measurements_file.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/base/input_file.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/text_format.h"
#include "saltus/body/yeadon_model.h"
#include "saltus/formats/plausible_ranges.h"

namespace saltus {

namespace {

constexpr std::size_t kMaxMeasurementFileBytes = 1u << 20;

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

}  // namespace

YeadonMeasurementsFile parse_yeadon_measurements(const std::string& text, const std::string& file) {
  const std::vector<std::string>& names = yeadon_measurement_names();
  std::vector<std::string> known = names;
  known.push_back("measurementconversionfactor");
  known.push_back("totalmass");
  YeadonMeasurementsFile out;
  std::map<std::string, double> raw;
  bool has_factor = false;
  bool has_total_mass = false;
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    const std::string where = "line " + std::to_string(number);
    const std::string content = trimmed(line.substr(0, line.find('#')));
    if (content.empty()) continue;
    const auto split = content.find_first_of("=:");
    if (split == std::string::npos)
      throw InputError(file, where,
                       "expected \"key = value\" or \"key: value\", found \"" +
                           printable(content.substr(0, 60)) + "\"");
    const std::string key = trimmed(content.substr(0, split));
    const std::string value_text = trimmed(content.substr(split + 1));
    char* end = nullptr;
    const double value = std::strtod(value_text.c_str(), &end);
    // A NUL byte would end the number for strtod and hide the rest of the value.
    if (value_text.empty() || end != value_text.c_str() + value_text.size() ||
        !std::isfinite(value))
      throw InputError(file, where + ": " + printable(key),
                       "expected a number, found \"" + printable(value_text.substr(0, 60)) + "\"");
    if (key == "measurementconversionfactor") {
      if (has_factor) throw InputError(file, where + ": " + key, "given twice");
      if (!(value > 0.0))
        throw InputError(file, where + ": " + key,
                         "must be positive (the measurements' unit in metres: 1, 0.01, 0.001, "
                         "0.0254), found " +
                             message_number(value));
      has_factor = true;
      out.conversion_factor = value;
      continue;
    }
    if (key == "totalmass") {
      if (has_total_mass) throw InputError(file, where + ": totalmass", "given twice");
      has_total_mass = true;
      if (value > 0.0 && !(value >= plausible::kMinBodyMass && value <= plausible::kMaxBodyMass))
        throw InputError(
            file, where + ": totalmass",
            "a mass of " +
                message_number_beside(value, plausible::kMinBodyMass, plausible::kMaxBodyMass) +
                " kg is outside the human range [" + message_number(plausible::kMinBodyMass) +
                ", " + message_number(plausible::kMaxBodyMass) +
                "] kg (0 or less: not "
                "measured)");
      out.total_mass = value > 0.0 ? value : 0.0;
      continue;
    }
    bool is_known = false;
    for (const std::string& name : names)
      is_known = is_known || name == key;
    if (!is_known) {
      const std::string nearest = nearest_name(key, known);
      throw InputError(file, where + ": " + printable(key),
                       "unknown measurement" +
                           (nearest.empty() ? std::string(" (Yeadon's 95 keys: Ls1L ... Lk6d)")
                                            : " (did you mean " + nearest + "?)"));
    }
    if (raw.count(key)) throw InputError(file, where + ": " + key, "given twice");
    if (!(value > 0.0))
      throw InputError(
          file, where + ": " + key,
          "must be positive (a length, perimeter, width or depth), found " + message_number(value));
    raw[key] = value;
  }
  if (!has_factor)
    throw InputError(file, "measurementconversionfactor",
                     "missing: the measurements' unit in metres (1 for m, 0.01 for cm, 0.001 for "
                     "mm)");
  for (const std::string& name : names)
    if (!raw.count(name))
      throw InputError(file, name,
                       "missing measurement (" + std::to_string(names.size() - raw.size()) +
                           " of Yeadon's 95 are missing)");
  for (const auto& [key, value] : raw) {
    const double metres = value * out.conversion_factor;
    if (!(metres >= plausible::kMinBodyMeasurement && metres <= plausible::kMaxBodyMeasurement))
      throw InputError(file, key,
                       message_number_beside(metres, plausible::kMinBodyMeasurement,
                                             plausible::kMaxBodyMeasurement) +
                           " m is outside [" + message_number(plausible::kMinBodyMeasurement) +
                           ", " + message_number(plausible::kMaxBodyMeasurement) + "] m, " +
                           (metres > plausible::kMaxBodyMeasurement ? "longer" : "shorter") +
                           " than any body part's length, perimeter, width or depth: is "
                           "measurementconversionfactor (" +
                           message_number(out.conversion_factor) + ") the unit of the values?");
    out.measured[key] = metres;
  }
  return out;
}

YeadonMeasurementsFile load_yeadon_measurements(const std::string& path) {
  return parse_yeadon_measurements(
      read_input_file(path, kMaxMeasurementFileBytes, "measurement files"), path);
}

}  // namespace saltus
