#include "core/athlete_landing.h"

#include "core/athletes.h"

namespace saltus::gui {

AthleteLanding athlete_landing(const MotionFile& on_athlete, const EvaluateOptions& options,
                               const OptimizationResult* run) {
  AthleteLanding out;
  out.athlete = athlete_label(on_athlete);
  out.verdict =
      run ? athlete_verdict(on_athlete, options, *run) : athlete_verdict(on_athlete, options);
  return out;
}

std::string verdict_html_colour(VerdictLight light) {
  switch (light) {
    case VerdictLight::kGreen:
      return "#1e7a34";
    case VerdictLight::kAmber:
      return "#9a5b00";
    case VerdictLight::kRed:
      break;
  }
  return "#b00020";
}

std::string verdict_figure_label(const AthleteVerdict& verdict) {
  switch (verdict.light) {
    case VerdictLight::kGreen:
      return "lands it";
    case VerdictLight::kAmber:
      return "lands it; see joints";
    case VerdictLight::kRed:
      break;
  }
  return "does not land it";
}

}  // namespace saltus::gui
