#pragma once
/// @file
/// The last guard before a result is written: no number in it may be NaN or infinite. The
/// readers refuse implausible input (plausible_ranges.h), so this should never fire; if it
/// does, the result is not written as a success (nlohmann writes NaN as null, a CSV as "nan").

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "saltus/dynamics/body_state.h"
#include "saltus/evaluation/sampling.h"

namespace saltus {

/// Throws InputError naming `input` (the motion file the result came from) and the JSON pointer
/// of the first non-finite number in `result`, a document written as `document`.
void require_finite(const nlohmann::json& result, const std::string& input,
                    const std::string& document = "result.json");

/// The same for the samples of a trajectory CSV: names the column and the time.
void require_finite(const std::vector<SampleRecord>& samples, const std::string& input,
                    const std::string& csv_name);

/// The same for sampled states (an export's): names `what`, the quantity and the time.
void require_finite(const std::vector<BodyState<double>>& states, const std::vector<double>& times,
                    const std::string& input, const std::string& what);

}  // namespace saltus
