#pragma once
/// @file
/// What the plots show, extracted from the library's results: the root wrench F1..F6 before and
/// after optimisation, the loads at one joint and the rotation quantities for teaching, each as a
/// ChartSpec with axis titles and units.

#include <array>
#include <string>
#include <vector>

#include "core/chart_spec.h"
#include "saltus/body/body_model.h"
#include "saltus/evaluation/rotation_metrics.h"
#include "saltus/evaluation/sampling.h"

namespace saltus::gui {

/// The paper's F1..F6 over time: root force (N) then moment (N·m), root frame, root origin.
struct WrenchSeries {
  std::vector<double> time;                      ///< s
  std::array<std::vector<double>, 6> component;  ///< F1..F6, one value per time
};

/// From evaluated samples, or a trajectory CSV read by the library (read_trajectory_csv).
WrenchSeries root_wrench_series(const std::vector<SampleRecord>& samples);

/// "F1 force x" ... "F6 moment z".
std::string wrench_component_name(int component);

/// Which of F1..F6 to draw.
using ComponentMask = std::array<bool, 6>;
inline ComponentMask all_components() {
  return {true, true, true, true, true, true};
}

/// Colour of a component (x red, y green, z blue, for force and moment alike).
Rgb component_colour(int component);
/// Colours of the keyframe markers: given times, optimised times.
Rgb given_keyframe_colour();
Rgb optimised_keyframe_colour();

/// An empty root force (`moment` false) or root moment chart: title and axis titles, the frame
/// both root_wrench_chart and the compare view's chart fill.
ChartSpec root_wrench_chart_frame(bool moment);

/// Root force (F1..F3, `moment` false) or root moment (F4..F6) against time; keyframe times as
/// vertical markers. With `after` (may be null) `before` is dashed and paler and `after` solid,
/// labels end in ", before" / ", after"; alone, `before` is drawn plain.
ChartSpec root_wrench_chart(bool moment, const WrenchSeries& before, const WrenchSeries* after,
                            const ComponentMask& shown, const std::vector<double>& keyframes_before,
                            const std::vector<double>& keyframes_after);

/// Size of the force (N, left axis) and moment (N·m, right axis) transmitted across the joint
/// that attaches `segment` to its parent (segment 0: the root, i.e. the residual the world must
/// supply), before and (if `after` is not null) after optimisation.
ChartSpec joint_load_chart(const BodyModel& model, int segment,
                           const std::vector<SampleRecord>& before,
                           const std::vector<SampleRecord>* after);

enum class RotationQuantity {
  kInertiaAndRate,   ///< I_xx (left) and |somersault rate| (right): the tuck's teaching plot
  kAngularMomentum,  ///< L_x, L_y, L_z about the CoM: constant in a valid flight
  kRates,            ///< somersault and twist rates
  kCounts,           ///< somersaults and twists counted so far
};
/// Menu names in enum order.
std::vector<std::string> rotation_quantity_names();

ChartSpec rotation_chart(RotationQuantity quantity, const std::vector<RotationSample>& before,
                         const std::vector<RotationSample>* after);

}  // namespace saltus::gui
