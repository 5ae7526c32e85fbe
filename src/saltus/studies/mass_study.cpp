#include "saltus/studies/mass_study.h"

#include <stdexcept>

#include "saltus/base/text_format.h"

namespace saltus {

MassStudyResult run_mass_study(const MotionFile& file, const MassStudyOptions& options) {
  if (!(options.factor > 0)) throw std::invalid_argument("mass factor must be positive");
  MassStudyResult study;
  for (const std::string& s : options.load_segments)
    if (file.model.segment_index(s) < 0)
      throw std::invalid_argument("no segment named '" + s + "' in model " + file.model.name);
  study.load_segments = options.load_segments;

  BodyModel scaled = file.model;
  std::string label;
  for (const std::string& s : options.scaled_segments) {
    if (file.model.segment_index(s) < 0)
      throw std::invalid_argument("no segment named '" + s + "' in model " + file.model.name);
    scaled = scale_segment_mass(scaled, s, options.factor);
    label += (label.empty() ? "" : "+") + s;
  }
  label += format_number(" x%g", options.factor);
  study.runs.push_back({file.model.name, file.model, {}});
  study.runs.push_back({label, scaled, {}});
  OptimizeOptions optimize = options.optimize;
  if (options.paper_protocol) use_paper_protocol(optimize);
  for (MassStudyRun& run : study.runs)
    run.result = optimize_motion(file.motion, run.model, optimize);
  return study;
}

}  // namespace saltus
