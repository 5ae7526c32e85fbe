#include "core/joint_load_view.h"

#include <algorithm>
#include <stdexcept>

#include "core/plot_series.h"
#include "saltus/base/text_format.h"
#include "saltus/body/segment_names.h"
#include "saltus/evaluation/residual_measures.h"
#include "saltus/evaluation/strength_demand.h"

namespace saltus::gui {

namespace {

/// The joint's rise of `after` over `before` (nullopt for the root or a model of one segment).
std::optional<JointLoadRise> rise_of(const BodyModel& model, int segment, const DenseCheck& before,
                                     const DenseCheck& after) {
  for (const JointLoadRise& r : joint_load_rises(model, before, after))
    if (r.joint == model.segments[static_cast<std::size_t>(segment)].joint) return r;
  return std::nullopt;
}

std::string stage_label(const std::string& what, int stage, bool comparing) {
  return what + (comparing ? (stage == 0 ? " before" : " after") : "");
}

/// One magnitude of the joint's load over the samples, labelled and styled as before/after.
LineSpec load_line(const std::vector<SampleRecord>& samples, int segment, bool moment, int stage,
                   bool comparing) {
  LineSpec line;
  line.label = stage_label(moment ? "|M|" : "|F|", stage, comparing);
  line.colour = magnitude_curve_colour(moment);
  for (const SampleRecord& r : samples) {
    const auto& wrench = r.joint_wrench.at(static_cast<std::size_t>(segment));
    line.x.push_back(r.time);
    line.y.push_back(moment ? moment_magnitude(wrench) : force_magnitude(wrench));
  }
  style_compared_line(line, stage == 1, comparing);
  return line;
}

/// The joint's share of strength over the samples, in %, on the right axis.
LineSpec share_line(const std::vector<SampleRecord>& samples, int segment, int stage,
                    bool comparing) {
  LineSpec line;
  line.label = stage_label("% of strength", stage, comparing);
  line.colour = strength_light_colour(StrengthLight::kAmber);
  line.right_axis = true;
  for (const SampleRecord& r : samples) {
    line.x.push_back(r.time);
    line.y.push_back(static_cast<std::size_t>(segment) < r.strength_share.size()
                         ? 100.0 * r.strength_share[static_cast<std::size_t>(segment)]
                         : 0.0);
  }
  style_compared_line(line, stage == 1, comparing);
  return line;
}

/// The joint's strength peak in a check, none where no direction has a curve.
const JointStrengthPeak* strength_peak(const DenseCheck& check, int segment) {
  if (segment < 1 || segment >= static_cast<int>(check.strength_peaks.size())) return nullptr;
  const JointStrengthPeak& p = check.strength_peaks[static_cast<std::size_t>(segment)];
  return p.coordinate >= 0 ? &p : nullptr;
}

std::string percent_words(double share) {
  return format_number("%.0f %%", 100.0 * share);
}

}  // namespace

StrengthLight strength_light(const std::optional<double>& share) {
  if (!share) return StrengthLight::kUnknown;
  if (*share > 1.0) return StrengthLight::kRed;
  if (*share >= kAmberShare) return StrengthLight::kAmber;
  return StrengthLight::kGreen;
}

std::string strength_light_words(StrengthLight light) {
  switch (light) {
    case StrengthLight::kGreen:
      return "within the athlete's strength";
    case StrengthLight::kAmber:
      return "near the athlete's maximum";
    case StrengthLight::kRed:
      return "beyond the athlete's strength";
    case StrengthLight::kUnknown:
      break;
  }
  return "no strength curve";
}

Rgb strength_light_colour(StrengthLight light) {
  switch (light) {
    case StrengthLight::kGreen:
      return {0.16, 0.60, 0.25};
    case StrengthLight::kAmber:
      return {0.90, 0.60, 0.05};
    case StrengthLight::kRed:
      return {0.80, 0.10, 0.12};
    case StrengthLight::kUnknown:
      break;
  }
  return {0.55, 0.55, 0.55};
}

Rgb strength_share_colour(double share) {
  const Rgb full = strength_light_colour(strength_light(share));
  // Green pales towards white as the share falls to 0, so that effort shows as colour.
  if (share >= kAmberShare) return full;
  const double k = std::clamp(share / kAmberShare, 0.0, 1.0);
  const double white = 0.85 * (1.0 - k);
  return {full.r + white * (1.0 - full.r), full.g + white * (1.0 - full.g),
          full.b + white * (1.0 - full.b)};
}

JointLoadView joint_load_view(const BodyModel& model, int segment,
                              const std::vector<SampleRecord>& before,
                              const DenseCheck& before_check,
                              const std::vector<SampleRecord>* after,
                              const DenseCheck* after_check) {
  if (segment < 0 || segment >= model.size()) throw std::out_of_range("joint load segment");
  const Segment& s = model.segments[static_cast<std::size_t>(segment)];
  const bool root = segment == 0;
  const std::string where =
      root ? "the world must supply at the " + segment_label(s.name)
           : "at the " + joint_label(s.joint) + " (on the " + segment_label(s.name) + ")";
  const double weight = body_weight_N(model);
  const bool covered =
      strength_peak(before_check, segment) || (after_check && strength_peak(*after_check, segment));

  JointLoadView view;
  view.force.title = "Force " + where;
  view.force.x_title = "time (s)";
  view.force.y_title = "|F| (N)";
  view.force.y2_title = "% of body weight";
  view.force.y2_per_y = 100.0 / weight;
  view.moment.title = "Moment " + where;
  view.moment.x_title = "time (s)";
  view.moment.y_title = "|M| (N·m)";
  if (covered) view.moment.y2_title = "% of strength";
  const bool comparing = after != nullptr;
  for (int stage = 0; stage < 2; ++stage) {
    const std::vector<SampleRecord>* samples = stage == 0 ? &before : after;
    if (!samples) continue;
    view.force.lines.push_back(load_line(*samples, segment, false, stage, comparing));
    view.moment.lines.push_back(load_line(*samples, segment, true, stage, comparing));
    if (covered) view.moment.lines.push_back(share_line(*samples, segment, stage, comparing));
  }

  // The peaks of the stage shown, from its dense check.
  const DenseCheck& shown = after_check ? *after_check : before_check;
  if (static_cast<int>(shown.joint_peaks.size()) > segment) {
    const JointLoadPeak& peak = shown.joint_peaks[static_cast<std::size_t>(segment)];
    view.summary = (after_check ? "After optimisation: peak force " : "Peak force ") +
                   format_number("%.3g N", peak.force_N) +
                   format_number(" (%.0f %% of body weight)", 100.0 * peak.force_N / weight) +
                   format_number(" at %.3f s", peak.force_time_s) + " · peak moment " +
                   format_number("%.3g N·m", peak.moment_Nm) +
                   format_number(" at %.3f s", peak.moment_time_s);
    if (const JointStrengthPeak* strength = strength_peak(shown, segment)) {
      view.share = strength->share;
      view.summary += " · largest share of the athlete's strength " +
                      percent_words(strength->share) + " (" +
                      strength_direction_words(model, segment, *strength) +
                      format_number(" at t = %.2f s)", strength->time_s);
    } else if (!root) {
      view.summary += " (no strength curve for this joint)";
    }
    view.light = strength_light(view.share);
  }

  // The optimiser's rise of this joint, marked where the raised peak is.
  if (after_check && !root) {
    if (const std::optional<JointLoadRise> rise =
            rise_of(model, segment, before_check, *after_check);
        rise && rise->ratio() > kMarkedJointRise) {
      view.raised_past_limit = rise->ratio() > kJointLoadRiseLimit;
      view.raised = "Raised by the optimiser: " + joint_load_rise_words(*rise, weight);
      if (view.raised_past_limit) view.raised += "; " + joint_load_verdict_words(*rise);
      const bool moment = rise->moment_ratio >= rise->force_ratio;
      const Rgb colour = view.raised_past_limit ? strength_light_colour(StrengthLight::kRed)
                                                : strength_light_colour(StrengthLight::kAmber);
      (moment ? view.moment : view.force)
          .markers.push_back({moment ? rise->after.moment_time_s : rise->after.force_time_s, colour,
                              false,
                              format_number("raised %.2fx by the optimiser", rise->ratio())});
    }
  }
  return view;
}

std::string joint_choice_label(const BodyModel& model, int segment, const JointLoadRise* rise) {
  const Segment& s = model.segments.at(static_cast<std::size_t>(segment));
  std::string label = capitalised(joint_label(s.joint)) + " (" + segment_label(s.name) + ")";
  if (rise && rise->ratio() > kJointLoadRiseLimit)
    label += format_number(" — %.2fx its peak before", rise->ratio());
  return label;
}

std::vector<StrengthStrip> strength_strips(const BodyModel& model,
                                           const std::vector<SampleRecord>& samples,
                                           const DenseCheck& check) {
  std::vector<StrengthStrip> strips;
  for (int k = 1; k < model.size(); ++k) {
    const JointStrengthPeak* peak = strength_peak(check, k);
    if (!peak) continue;
    StrengthStrip strip;
    strip.segment = k;
    strip.joint = capitalised(joint_label(model.segments[static_cast<std::size_t>(k)].joint));
    for (const SampleRecord& r : samples) {
      strip.times.push_back(r.time);
      strip.shares.push_back(static_cast<std::size_t>(k) < r.strength_share.size()
                                 ? r.strength_share[static_cast<std::size_t>(k)]
                                 : 0.0);
    }
    strip.peak = peak->share;
    strip.peak_time_s = peak->time_s;
    if (peak->share > 1.0) {
      // Beyond the athlete's strength: the line `saltus evaluate` prints for this joint alone.
      std::vector<JointStrengthPeak> alone(check.strength_peaks.size());
      alone[static_cast<std::size_t>(k)] = *peak;
      strip.peak_words = over_strength_lines(model, alone).front();
    } else {
      strip.peak_words = strength_direction_words(model, k, *peak) + " " +
                         percent_words(peak->share) + " of the athlete's strength" +
                         format_number(" at t = %.2f s", peak->time_s);
    }
    strips.push_back(std::move(strip));
  }
  return strips;
}

}  // namespace saltus::gui
