#pragma once
/// @file
/// Yeadon's 1990 geometric inertia model of a particular person from 95 anthropometric
/// measurements (yeadon_solids.h): 40 solids (8 in the torso and head, 7 in each arm, 9 in each
/// leg) with the segment densities of Dempster, Chandler or Clauser, composed onto Saltus's 13
/// segments exactly. How they map: docs/method.md, "Yeadon's model".

#include <map>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"

namespace saltus {

enum class YeadonDensities { kDempster, kChandler, kClauser };

/// "dempster", "chandler", "clauser".
std::string yeadon_densities_name(YeadonDensities densities);

/// The 95 measurement names of Yeadon's protocol as the `yeadon` package writes them (Ls torso
/// levels, La/Lb left/right arm, Lj/Lk left/right leg; suffix L length, p perimeter, w width,
/// d depth), in the package's order.
const std::vector<std::string>& yeadon_measurement_names();

struct YeadonInput {
  std::string file;                        ///< named in messages
  std::map<std::string, double> measured;  ///< all 95, in metres, > 0
  YeadonDensities densities = YeadonDensities::kDempster;
  double total_mass = 0.0;  ///< > 0: every density scaled so the body weighs this, kg
  std::string name;         ///< the model's name
};

struct YeadonModel {
  BodyModel model;
  /// Measurements that look wrong but are usable: a left/right pair whose sides differ by more
  /// than half the smaller (both keys named), a perimeter too large for its width (taken as a
  /// circle of that perimeter, as the `yeadon` package does).
  std::vector<std::string> warnings;
  int solids = 0;              ///< 40
  double volume = 0.0;         ///< m³, the solids' sum
  double density_scale = 1.0;  ///< total_mass / the mass the densities give (1 without it)
};

/// The model. Refuses, with InputError naming `file` and the key: levels that do not rise
/// (a solid of zero or negative height), a perimeter too small for its width (no stadium has
/// it), a shoulder depth not smaller than its width.
YeadonModel yeadon_model(const YeadonInput& input);

}  // namespace saltus
