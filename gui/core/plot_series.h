#pragma once
/// @file
/// What the plots show, extracted from the library's results: the root wrench before and after
/// optimisation (as the paper's Figs. 4 and 5, the resultant |F| and |M| by default, components
/// on demand), the loads at one joint and the rotation quantities for teaching, each as a
/// ChartSpec with axis titles and units.
///
/// One style everywhere (main window, compare window, exported figures): of two curves of the
/// same quantity the first ("before", or the first run) is dashed and paler, the second
/// ("after", or the second run) solid; keyframe times are vertical lines, dotted grey for the
/// given times and solid orange for the optimised ones, each kind named once in the legend.

#include <array>
#include <string>
#include <vector>

#include "core/chart_spec.h"
#include "saltus/body/body_model.h"
#include "saltus/evaluation/rotation_metrics.h"
#include "saltus/evaluation/sampling.h"

namespace saltus::gui {

/// Samples of the dense grid that plots, exported figures and the teaching view draw from, at
/// least (the written trajectory's grid, 101 samples by default, makes jagged curves).
inline constexpr int kPlotSamples = 601;
/// The plot grid's size for a flight of `duration` seconds: kPlotSamples, or more so that it is
/// never coarser than the library's dense residual check (kCheckMaxSpacing) and a plot shows what
/// the reported figures integrate.
int plot_samples_for(double duration);

/// The paper's F1..F6 over time: root force (N) then moment (N·m), root frame, root origin, and
/// their resultants.
struct WrenchSeries {
  std::vector<double> time;                      ///< s
  std::array<std::vector<double>, 6> component;  ///< F1..F6, one value per time
  std::vector<double> force_magnitude;           ///< |F1..F3|, N
  std::vector<double> moment_magnitude;          ///< |F4..F6|, N·m
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
/// Colour of the resultant |F| (force) or |M| (moment) curves.
Rgb magnitude_curve_colour(bool moment);
/// Colours of the keyframe markers: given times, optimised times.
Rgb given_keyframe_colour();
Rgb optimised_keyframe_colour();

/// The shared style of compared curves (see the file comment): `second` false for the first
/// (before) curve, true for the second (after); `comparing` false draws a lone curve plainly.
void style_compared_line(LineSpec& line, bool second, bool comparing);

/// Keyframe times as vertical markers: the given ones, and (if not empty) the optimised ones;
/// the first marker of each kind carries the legend entry.
void add_keyframe_markers(ChartSpec& chart, const std::vector<double>& given,
                          const std::vector<double>& optimised);

/// How a root-wrench chart shows it.
struct RootChartStyle {
  bool moment = false;      ///< the moment F4..F6 (N·m) instead of the force F1..F3 (N)
  bool components = false;  ///< x, y, z components instead of the resultant
  std::array<bool, 3> axes{true, true, true};  ///< components shown (with `components`)
  /// The resultant on a logarithmic axis, so that an "after" curve 100 times smaller than
  /// "before" still shows its shape (only with an "after"; ignored with `components`, which
  /// change sign).
  bool log_scale = false;
  /// > 0: a right-hand axis in % of this body weight (N), for force charts.
  double body_weight_N = 0.0;
};

/// An empty root force or moment chart (title, axis titles) for this style.
ChartSpec root_chart_frame(const RootChartStyle& style);

/// Colour of a motion capture's own curves (thin, grey-green: neither before nor after).
Rgb capture_curve_colour();

/// The root force or moment against time, before and (`after` may be null) after optimisation,
/// keyframe times as markers; `capture` (may be null) adds the motion capture's own residual
/// (the motion was imported from it), labelled "capture".
ChartSpec root_chart(const RootChartStyle& style, const WrenchSeries& before,
                     const WrenchSeries* after, const std::vector<double>& keyframes_before,
                     const std::vector<double>& keyframes_after,
                     const WrenchSeries* capture = nullptr);

/// Components chart of root force (`moment` false) or moment, with the components in `shown`
/// (the form the exported figures of result folders use).
ChartSpec root_wrench_chart(bool moment, const WrenchSeries& before, const WrenchSeries* after,
                            const ComponentMask& shown, const std::vector<double>& keyframes_before,
                            const std::vector<double>& keyframes_after);

enum class RotationQuantity {
  kInertiaAndRate,   ///< I_xx (left) and |somersault rate| (right): the tuck's teaching plot
  kAngularMomentum,  ///< L_x, L_y, L_z about the CoM: constant in a valid flight
  kRates,            ///< somersault and twist rates
  kCounts,           ///< somersaults and twists counted so far (Yeadon's angles)
  kYeadonAngles,     ///< somersault, tilt and twist of the trunk, degrees
};
/// Menu names in enum order.
std::vector<std::string> rotation_quantity_names();

ChartSpec rotation_chart(RotationQuantity quantity, const std::vector<RotationSample>& before,
                         const std::vector<RotationSample>* after);

}  // namespace saltus::gui
