#include "core/screen_fit.h"

#include <algorithm>

namespace saltus::gui {

WindowFit first_window_size(int available_width, int available_height, int preferred_width,
                            int preferred_height) {
  if (available_width <= 0 || available_height <= 0)
    return {preferred_width, preferred_height, false};
  WindowFit fit;
  const int room_width = std::max(1, available_width - kFrameWidth);
  const int room_height = std::max(1, available_height - kFrameHeight);
  fit.width = std::min(preferred_width, room_width);
  fit.height = std::min(preferred_height, room_height);
  fit.maximise = preferred_width > room_width || preferred_height > room_height;
  return fit;
}

}  // namespace saltus::gui
