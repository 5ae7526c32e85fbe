#pragma once
/// @file
/// Yeadon's 95 anthropometric measurements in the text format of the open-source `yeadon`
/// package (docs/formats.md, "Yeadon measurements"): `Key=value` or `Key: value` lines, `#`
/// comments, `measurementconversionfactor` (the unit, in metres), optional `totalmass` (kg;
/// <= 0 means not measured). Read here only; Saltus does not write them.

#include <map>
#include <string>

namespace saltus {

struct YeadonMeasurementsFile {
  std::map<std::string, double> measured;  ///< the 95 keys, in metres
  double conversion_factor = 0.0;          ///< the file's measurementconversionfactor
  double total_mass = 0.0;                 ///< kg, 0 when the file gives none (or <= 0)
};

/// Parses the text. `file` names it in messages. Refused with InputError naming the file and
/// "line N" or the key: a line that is not `key = value`, a value that is not a number (a NUL
/// byte in it included), an unknown key (the nearest known one suggested), a key given twice
/// (totalmass and the factor too), a missing key or conversion factor, a factor that is not
/// positive, a measurement outside [kMinBodyMeasurement, kMaxBodyMeasurement] in metres
/// (plausible_ranges.h), a total mass beyond a person's.
YeadonMeasurementsFile parse_yeadon_measurements(const std::string& text, const std::string& file);

/// Reads a file (a regular file of at most 1 MiB) and parses it.
YeadonMeasurementsFile load_yeadon_measurements(const std::string& path);

}  // namespace saltus
