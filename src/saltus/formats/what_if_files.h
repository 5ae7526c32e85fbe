#pragma once
/// @file
/// `saltus analyse what-if`'s files (docs/formats.md, "What-if analysis"): result.json (the
/// change, the tuck it moved, how the flight lands against the motion as keyframed and as it is,
/// the sentence) and what_if.csv (Yeadon's angles over time of the what-if flight and of the
/// flight as it is). The flight itself goes to trajectory.csv (trajectory_csv.h).

#include <nlohmann/json.hpp>
#include <string>

#include "saltus/evaluation/what_if.h"
#include "saltus/formats/motion_file.h"

namespace saltus {

/// A tuck as result.json's "tuck" and "changed_tuck" write it: found (and the reason when not),
/// the bends and times of its phases, the shifts it allows.
nlohmann::json tuck_json(const TuckPhases& tuck);

nlohmann::json what_if_result_json(const MotionFile& file, const WhatIf& prepared,
                                   const WhatIfResult& result);
/// t, then somersault, tilt and twist (degrees, φ and ψ continuous) of the what-if flight and of
/// the flight as it is: what_if_somersault_deg, ..., as_is_twist_deg.
std::string what_if_csv(const WhatIf& prepared, const WhatIfResult& result);

}  // namespace saltus
