#pragma once
/// @file
/// "Can this athlete land it?" for the app: the library's one verdict (use_cases/athlete_verdict.h:
/// the motion's free flight and its joints against the athlete's strength, green, amber or red,
/// with a run the warnings of `saltus optimize`), computed there and not here, so that the app
/// and `saltus evaluate` / `optimize` say the same; with the athlete's label and the colour each
/// light is written in.

#include <string>

#include "saltus/evaluation/evaluate.h"
#include "saltus/motion/motion.h"
#include "saltus/optim/optimize.h"
#include "saltus/use_cases/athlete_verdict.h"

namespace saltus::gui {

struct AthleteLanding {
  std::string athlete;     ///< athlete_label: "junior 1.45 m 38 kg, same take-off spin"
  AthleteVerdict verdict;  ///< the library's, as computed
};

/// The check for `on_athlete` (the motion already carried over to the athlete:
/// load_motion_for_athlete or motion_on_athlete; or the motion on its own model): the motion as
/// keyframed, or with `run` (a result of optimising that motion on that body) its optimised
/// motion and the run's warnings. Throws like the library for bad options.
AthleteLanding athlete_landing(const MotionFile& on_athlete, const EvaluateOptions& options,
                               const OptimizationResult* run = nullptr);

/// The colour a verdict's words are written in, as HTML ("#1e7a34" green, "#9a5b00" amber, dark
/// enough to read on white, "#b00020" red).
std::string verdict_html_colour(VerdictLight light);

/// What a coach reads at a glance above the drawn free flight (the gold figure, which the view's
/// legend names): "lands it", "lands it; see joints" (amber), "does not land it".
std::string verdict_figure_label(const AthleteVerdict& verdict);

}  // namespace saltus::gui
