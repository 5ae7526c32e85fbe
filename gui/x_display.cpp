#include "x_display.h"

#include <X11/Xlib.h>

namespace saltus::gui {

bool x_display_reachable() {
  Display* display = XOpenDisplay(nullptr);
  if (!display) return false;
  XCloseDisplay(display);
  return true;
}

}  // namespace saltus::gui
