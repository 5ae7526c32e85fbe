#include "saltus/formats/finite_check.h"

#include <cmath>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/text_format.h"

namespace saltus {

namespace {

/// JSON pointer of the first non-finite number under `value`, or "" if there is none.
bool find_non_finite(const nlohmann::json& value, const std::string& pointer, std::string& where) {
  if (value.is_number_float()) {
    if (std::isfinite(value.get<double>())) return false;
    where = pointer.empty() ? "/" : pointer;
    return true;
  }
  if (value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it)
      if (find_non_finite(it.value(), pointer + "/" + json_pointer_escape(it.key()), where))
        return true;
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      if (find_non_finite(value[i], pointer + "/" + std::to_string(i), where)) return true;
  }
  return false;
}

[[noreturn]] void fail(const std::string& input, const std::string& what) {
  throw InputError(input, "",
                   "the computed result is not finite (" + what +
                       "): this motion's numbers are beyond what Saltus can compute reliably; "
                       "nothing was written");
}

template <typename Vector>
bool finite(const Vector& v) {
  return v.allFinite();
}

}  // namespace

void require_finite(const nlohmann::json& result, const std::string& input,
                    const std::string& document) {
  std::string where;
  if (find_non_finite(result, "", where)) fail(input, document + " " + where);
}

void require_finite(const std::vector<SampleRecord>& samples, const std::string& input,
                    const std::string& csv_name) {
  for (const SampleRecord& s : samples) {
    const auto at = [&](const std::string& column) {
      fail(input, csv_name + " " + column + " at t = " + message_number(s.time) + " s");
    };
    if (!std::isfinite(s.time)) at("t");
    for (std::size_t i = 0; i < s.segment_position.size(); ++i) {
      if (!finite(s.segment_position[i])) at("segment " + std::to_string(i) + " position");
      if (!finite(s.segment_rotation[i].coeffs())) at("segment " + std::to_string(i) + " rotation");
    }
    if (!finite(s.com) || !finite(s.com_velocity)) at("com");
    if (!finite(s.angular_momentum)) at("angular momentum");
    if (!finite(s.root_wrench)) at("root wrench");
    if (!finite(s.residual)) at("residual");
  }
}

void require_finite(const std::vector<BodyState<double>>& states, const std::vector<double>& times,
                    const std::string& input, const std::string& what) {
  for (std::size_t k = 0; k < states.size(); ++k) {
    const BodyState<double>& s = states[k];
    const auto at = [&](const std::string& quantity) {
      fail(input, what + " " + quantity +
                      " at t = " + message_number(k < times.size() ? times[k] : 0.0) + " s");
    };
    if (!finite(s.root_position) || !finite(s.root_velocity) || !finite(s.root_acceleration))
      at("root translation");
    for (std::size_t j = 0; j < s.joints.size(); ++j)
      if (!finite(s.joints[j].q.coeffs()) || !finite(s.joints[j].omega) ||
          !finite(s.joints[j].alpha))
        at("joint " + std::to_string(j));
  }
}

}  // namespace saltus
