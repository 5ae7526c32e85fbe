#pragma once
/// @file
/// What the What if panel shows of the library's `what_if`: its sliders' steps and words, the
/// tuck the library found, how the flight lands against the motion as keyframed, and the what-if
/// flight at any time for the figure drawn beside the athlete. Which motion it flies is the one
/// the 3D view shows (core/shown_motion.h). The numbers are the library's; this file only steps
/// and words them.

#include <string>
#include <vector>

#include "saltus/evaluation/what_if.h"

namespace saltus::gui {

/// The sliders move the tuck and the opening in steps of this, s, and the tightness in steps of
/// 1 %.
inline constexpr double kWhatIfShiftStepS = 0.01;

/// A slider's whole steps within [min_s, max_s] (a shift's range): [ceil(min/step),
/// floor(max/step)], so that every position is a shift the library allows.
struct SliderSteps {
  int min = 0;
  int max = 0;
};
SliderSteps shift_slider_steps(double min_s, double max_s);
/// The tightness slider's range, percent (kMinTuckScale..kMaxTuckScale).
SliderSteps tightness_slider_steps();

/// The change at these slider positions (shifts in steps of kWhatIfShiftStepS, tightness in %).
WhatIfChange change_at(int tuck_steps, int open_steps, int tightness_percent);

/// "0.05 s later", "0.03 s earlier", "as keyframed".
std::string shift_text(double seconds);
/// "110 % (tighter)", "90 % (looser)", "100 % (as keyframed)".
std::string tightness_text(int percent);

/// "Tucked 0.02–0.28 s, opens 0.84–1.02 s; hips and knees bend up to 145°." or, without a tuck,
/// the library's reason.
std::string tuck_text(const TuckPhases& tuck);

/// "Keyframed to land after 2.00 somersaults and 1.50 twists; flown as it is, 2.01 and 1.49."
std::string reference_text(const WhatIf& prepared);

/// The flight's sample at time t: the two samples around it blended (segment positions and CoM
/// linearly, rotations by slerp), clamped to the flight. For the figure drawn beside the athlete.
/// Requires at least one sample, in time order.
SampleRecord flight_sample_at(const std::vector<SampleRecord>& samples, double t);

/// The median of some latencies (ms), 0 for none: what the panel reports.
double median_ms(std::vector<double> values);

}  // namespace saltus::gui
