#include "saltus/body/segment_names.h"

#include <cstdio>
#include <map>

namespace saltus {

std::pair<std::string, std::string> split_side(const std::string& name) {
  if (name.size() > 2 && name[name.size() - 2] == '_') {
    const char side = name.back();
    if (side == 'l') return {"left", name.substr(0, name.size() - 2)};
    if (side == 'r') return {"right", name.substr(0, name.size() - 2)};
  }
  return {"", name};
}

namespace {

std::string spaced(std::string text) {
  for (char& c : text)
    if (c == '_') c = ' ';
  return text;
}

std::string label(const std::string& name, const std::map<std::string, std::string>& words) {
  const auto [side, base] = split_side(name);
  const auto it = words.find(base);
  const std::string word = it == words.end() ? spaced(base) : it->second;
  return side.empty() ? word : side + " " + word;
}

std::string plural(const std::string& word) {
  if (word.empty() || word.back() == 's') return word;
  if (word == "foot") return "feet";
  return word + "s";
}

std::string format_factor(double factor) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", factor);
  return buffer;
}

}  // namespace

std::string segment_label(const std::string& segment) {
  // The bundled model's thorax carries the head and neck, its forearm the hand
  // (docs/formats.md, "Body model").
  static const std::map<std::string, std::string> kWords = {
      {"thorax", "upper trunk and head"},
      {"shank", "lower leg"},
      {"upper_arm", "upper arm"},
  };
  return label(segment, kWords);
}

std::string joint_label(const std::string& joint) {
  static const std::map<std::string, std::string> kWords = {
      {"root", "root (the body in space)"},
      {"lumbar", "lower back"},
      {"thoracic", "mid back"},
  };
  return label(joint, kWords);
}

std::string capitalised(const std::string& text) {
  std::string out = text;
  if (!out.empty() && out[0] >= 'a' && out[0] <= 'z') out[0] = static_cast<char>(out[0] - 32);
  return out;
}

std::string mass_scaling_label(const std::vector<std::string>& segments, double factor) {
  const std::string times = " × " + format_factor(factor);
  if (segments.empty()) return "every segment" + times;
  // "thigh_l" + "thigh_r": one base on both sides reads "left and right thighs".
  if (segments.size() == 2) {
    const auto a = split_side(segments[0]);
    const auto b = split_side(segments[1]);
    if (a.second == b.second && !a.first.empty() && !b.first.empty() && a.first != b.first) {
      const std::string base = segment_label(a.second + "_l").substr(5);  // without "left "
      return "left and right " + plural(base) + times;
    }
  }
  std::string out;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (i > 0) out += i + 1 == segments.size() ? " and " : ", ";
    out += segment_label(segments[i]);
  }
  return out + times;
}

}  // namespace saltus
