#pragma once
/// @file
/// `saltus analyse twist`'s files (docs/formats.md, "Twist analysis"): result.json (the shares
/// of the tilt at mid-flight and the sentence), twist.csv (the tilt over time of the actual free
/// flight and of each counterfactual) and twist.md (the table).

#include <nlohmann/json.hpp>
#include <string>

#include "saltus/evaluation/twist_sources.h"
#include "saltus/formats/motion_file.h"

namespace saltus {

inline constexpr const char* kAnalysisFormat = "saltus-analysis/1";

nlohmann::json twist_result_json(const MotionFile& file, const TwistSources& sources);
/// t, then one tilt column (degrees) per flight: actual, take_off_only, without_left_arm, ...
std::string twist_csv(const TwistSources& sources);
std::string twist_markdown(const MotionFile& file, const TwistSources& sources);

/// A `saltus analyse twist` folder read back (for its figure, `saltus-gui --export-figures`).
struct TwistFolder {
  std::string path;
  std::string name;    ///< the folder's own name
  std::string motion;  ///< the motion's name
  /// As written: the shares, the sentence, and the tilt over time of the flights twist.csv
  /// holds, named as twist_sources names them ("take-off only", "without left arm").
  TwistSources sources;
};

/// Whether DIR/result.json parses and says "analysis": "twist". Anything else is false, so that
/// another reader can say what is wrong.
bool is_twist_analysis_folder(const std::string& dir);
/// Throws InputError naming the file (and field, or line) that is missing or malformed.
TwistFolder read_twist_analysis_folder(const std::string& dir);

}  // namespace saltus
