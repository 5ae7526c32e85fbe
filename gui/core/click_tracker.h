#pragma once
/// @file
/// Tells a click from a drag with the same mouse button: in the 3D view a left drag rotates the
/// camera, and only a press and release without moving in between picks a body segment.

namespace saltus::gui {

class ClickTracker {
 public:
  /// @param tolerance_pixels  the pointer may move less than this (Manhattan distance from the
  ///                          press, pixels) and still click; the platform's drag distance
  ///                          (QApplication::startDragDistance) in the app.
  explicit ClickTracker(int tolerance_pixels);

  /// The button went down at (x, y); any earlier press is forgotten.
  void press(int x, int y);
  /// The pointer moved to (x, y). Once it has moved as far as the tolerance the gesture is a
  /// drag, even if it comes back.
  void move(int x, int y);
  /// The button went up at (x, y): true if that ends a click.
  bool release(int x, int y);
  /// The gesture was interrupted (e.g. the window lost the mouse): the next release is no click.
  void cancel();

  bool pressed() const { return pressed_; }
  int tolerance() const { return tolerance_; }

 private:
  bool beyond_tolerance(int x, int y) const;

  int tolerance_;
  bool pressed_ = false;
  bool dragged_ = false;
  int x0_ = 0;
  int y0_ = 0;
};

}  // namespace saltus::gui
