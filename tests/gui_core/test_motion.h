#pragma once
// The motion the GUI tests open. To switch (e.g. to M7 once it exists) change kGuiTestMotion, or
// set SALTUS_GUI_TEST_MOTION to a file name under examples/motions/; the screenshot baseline is
// named after the motion, so a new motion asks for a new baseline.

#include <cstdlib>
#include <string>

namespace saltus::gui::test {

inline constexpr const char* kGuiTestMotion = "M1-straight-back-somersault.motion.json";

inline std::string gui_test_motion_name() {
  const char* env = std::getenv("SALTUS_GUI_TEST_MOTION");
  return env && *env ? std::string(env) : std::string(kGuiTestMotion);
}

inline std::string gui_test_motion_path() {
  return std::string(SALTUS_EXAMPLES_DIR) + "/motions/" + gui_test_motion_name();
}

/// "M1-straight-back-somersault" for baseline file names.
inline std::string gui_test_motion_stem() {
  std::string name = gui_test_motion_name();
  const std::string suffix = ".motion.json";
  if (name.size() > suffix.size() &&
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
    name.erase(name.size() - suffix.size());
  return name;
}

}  // namespace saltus::gui::test
