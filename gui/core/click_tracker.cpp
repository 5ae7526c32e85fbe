#include "core/click_tracker.h"

#include <algorithm>
#include <cstdlib>

namespace saltus::gui {

ClickTracker::ClickTracker(int tolerance_pixels) : tolerance_(std::max(1, tolerance_pixels)) {}

void ClickTracker::press(int x, int y) {
  pressed_ = true;
  dragged_ = false;
  x0_ = x;
  y0_ = y;
}

void ClickTracker::move(int x, int y) {
  if (pressed_ && beyond_tolerance(x, y)) dragged_ = true;
}

bool ClickTracker::release(int x, int y) {
  if (!pressed_) return false;
  move(x, y);
  pressed_ = false;
  return !dragged_;
}

void ClickTracker::cancel() {
  pressed_ = false;
  dragged_ = false;
}

bool ClickTracker::beyond_tolerance(int x, int y) const {
  // Manhattan length, as Qt measures the start of a drag.
  return std::abs(x - x0_) + std::abs(y - y0_) >= tolerance_;
}

}  // namespace saltus::gui
