#pragma once
/// @file
/// Names of segments and joints as a coach or a teacher says them: "right thigh", "left knee",
/// "lower back", instead of the model's identifiers (thigh_r, knee_l, lumbar). Identifiers that
/// end in "_l" / "_r" become "left ..." / "right ..."; a few anatomical names are translated;
/// anything else keeps its words with underscores read as spaces, so other models read too.

#include <string>
#include <utility>
#include <vector>

namespace saltus {

/// "thigh_r" -> "right thigh", "shank_l" -> "left lower leg", "thorax" -> "upper trunk and head".
std::string segment_label(const std::string& segment);
/// Side and base of an identifier: "thigh_r" -> {"right", "thigh"}; no side -> {"", name}.
std::pair<std::string, std::string> split_side(const std::string& name);
/// "knee_r" -> "right knee", "lumbar" -> "lower back", "root" -> "root (the body in space)".
std::string joint_label(const std::string& joint);
/// The same with a capital first letter, for the start of a line or a list entry.
std::string capitalised(const std::string& text);
/// Segments scaled by a factor, as one phrase: {"thigh_l", "thigh_r"}, 1.5 -> "left and right
/// thighs × 1.5"; {"thigh_r"}, 1.5 -> "right thigh × 1.5"; {} -> "every segment × 1.5".
std::string mass_scaling_label(const std::vector<std::string>& segments, double factor);

}  // namespace saltus
