#include "saltus/optim/polish_rules.h"

#include <algorithm>

#include "saltus/evaluation/joint_loads.h"

namespace saltus {

bool polish_try_lands(const PolishTryFigures& figures, const PolishBaseline& baseline) {
  return figures.landing_drift_deg <= baseline.max_landing_drift_deg ||
         figures.landing_drift_deg <= baseline.landing_drift_deg;
}

bool polish_try_holds(const PolishTryFigures& figures, const PolishBaseline& baseline) {
  return figures.solved &&
         root_force_within_limit(figures.avg_root_force, baseline.avg_root_force) &&
         polish_try_lands(figures, baseline);
}

bool polish_bounded_tries_hopeless(const PolishTry& attempt, bool kept,
                                   const PolishTryFigures& figures,
                                   const PolishBaseline& baseline) {
  return attempt.joints_bounded && !kept &&
         figures.landing_drift_deg >
             std::max(kPolishHopelessDriftFactor * baseline.max_landing_drift_deg,
                      baseline.landing_drift_deg);
}

bool polish_tightens(bool kept, double joint_rise) {
  return kept && joint_rise > kJointLoadRiseLimit;
}

bool polish_refines_before_unbounded(const PolishTry& next, bool automatic,
                                     const PolishBaseline& baseline, bool have_over_limit) {
  return automatic && !next.joints_bounded && baseline.joints_pay && have_over_limit;
}

bool polish_over_limit_candidate(const PolishTry& attempt, bool kept,
                                 const PolishTryFigures& figures, const PolishBaseline& baseline,
                                 std::optional<double> current) {
  return attempt.joints_bounded && figures.solved && !kept && polish_try_lands(figures, baseline) &&
         (!current || figures.avg_root_force < *current);
}

bool polish_fallback_candidate(const PolishTry& attempt, bool kept, const PolishTryFigures& figures,
                               const PolishBaseline& baseline, std::optional<double> current) {
  return !kept && attempt.joints_bounded && baseline.joints_pay && figures.solved &&
         polish_try_lands(figures, baseline) &&
         figures.avg_root_force <= kPolishMaxRootForceOverPayingJoints &&
         (!current || figures.avg_root_force < *current);
}

}  // namespace saltus
