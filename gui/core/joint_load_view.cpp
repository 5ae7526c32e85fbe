#include "core/joint_load_view.h"

#include <algorithm>
#include <stdexcept>

#include "core/plot_series.h"
#include "saltus/base/text_format.h"
#include "saltus/body/segment_names.h"
#include "saltus/evaluation/joint_strength.h"
#include "saltus/evaluation/residual_measures.h"

namespace saltus::gui {

namespace {

/// The joint's rise of `after` over `before` (nullopt for the root or a model of one segment).
std::optional<JointLoadRise> rise_of(const BodyModel& model, int segment, const DenseCheck& before,
                                     const DenseCheck& after) {
  for (const JointLoadRise& r : joint_load_rises(model, before, after))
    if (r.joint == model.segments[static_cast<std::size_t>(segment)].joint) return r;
  return std::nullopt;
}

/// One magnitude of the joint's load over the samples, labelled and styled as before/after.
LineSpec load_line(const std::vector<SampleRecord>& samples, int segment, bool moment, int stage,
                   bool comparing) {
  LineSpec line;
  line.label =
      std::string(moment ? "|M|" : "|F|") + (comparing ? (stage == 0 ? " before" : " after") : "");
  line.colour = magnitude_curve_colour(moment);
  for (const SampleRecord& r : samples) {
    const auto& wrench = r.joint_wrench.at(static_cast<std::size_t>(segment));
    line.x.push_back(r.time);
    line.y.push_back(moment ? moment_magnitude(wrench) : force_magnitude(wrench));
  }
  style_compared_line(line, stage == 1, comparing);
  return line;
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
      return "within its strength";
    case StrengthLight::kAmber:
      return "near its maximum";
    case StrengthLight::kRed:
      return "beyond its maximum";
    case StrengthLight::kUnknown:
      break;
  }
  return "no published maximum";
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
  const PublishedJointMoment* published = root ? nullptr : published_joint_moment(s.joint);
  const double strength = published ? published->max_moment_per_kg * model.total_mass() : 0.0;

  JointLoadView view;
  view.force.title = "Force " + where;
  view.force.x_title = "time (s)";
  view.force.y_title = "|F| (N)";
  view.force.y2_title = "% of body weight";
  view.force.y2_per_y = 100.0 / weight;
  view.moment.title = "Moment " + where;
  view.moment.x_title = "time (s)";
  view.moment.y_title = "|M| (N·m)";
  if (published) {
    view.moment.y2_title = "% of published max";
    view.moment.y2_per_y = 100.0 / strength;
  }
  const bool comparing = after != nullptr;
  for (int stage = 0; stage < 2; ++stage) {
    const std::vector<SampleRecord>* samples = stage == 0 ? &before : after;
    if (!samples) continue;
    view.force.lines.push_back(load_line(*samples, segment, false, stage, comparing));
    view.moment.lines.push_back(load_line(*samples, segment, true, stage, comparing));
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
    if (published) {
      view.share = peak.moment_Nm / strength;
      view.summary += format_number(": %.0f %% of the published maximum for this athlete",
                                    100.0 * *view.share) +
                      format_number(" (%.3g N·m/kg", published->max_moment_per_kg) +
                      format_number(" × %.3g kg", model.total_mass()) +
                      format_number(" = %.3g N·m, ", strength) + published->direction + ")";
    } else if (!root) {
      view.summary += " (no published maximum for this joint)";
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

}  // namespace saltus::gui
