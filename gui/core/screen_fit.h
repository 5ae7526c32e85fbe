#pragma once
/// @file
/// The size a window first opens at, from the screen it opens on: its preferred size where the
/// screen has room, else the screen's available area less the window's frame (title bar and
/// borders), so that no panel or plot starts off-screen on a laptop (the main window used to
/// open at 1600×1000 whatever the screen, the compare window at 1500×950).

namespace saltus::gui {

/// Room a window manager's frame takes around a window's client area, pixels.
inline constexpr int kFrameWidth = 8;
inline constexpr int kFrameHeight = 38;

struct WindowFit {
  int width = 0;
  int height = 0;
  /// The screen is smaller than the preferred size: open maximised where a window manager can.
  bool maximise = false;
};

/// The first size of a window preferring `preferred_width` × `preferred_height` on a screen
/// whose available area (without panels and docks) is `available_width` × `available_height`.
WindowFit first_window_size(int available_width, int available_height, int preferred_width,
                            int preferred_height);

}  // namespace saltus::gui
