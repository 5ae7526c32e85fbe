#pragma once
/// @file
/// The Strength tab: every joint's share of the athlete's strength over the flight as a strip, a
/// row per joint on one time axis (core/joint_load_view.h: strength_strips), pale green at rest,
/// amber near the athlete's maximum, red above 100 %; each row's largest share written at its
/// end; the time shown as a line; under them, a joint's largest share in words (the CLI's line
/// beyond the athlete's strength), also each row's tooltip. A click in a strip goes to that time
/// and selects that joint; a click on a joint's name opens its loads.

#include <QWidget>
#include <vector>

#include "core/joint_load_view.h"

namespace saltus::gui {

class StrengthStrips : public QWidget {
  Q_OBJECT

 public:
  explicit StrengthStrips(QWidget* parent = nullptr);

  /// The strips to draw (none: a line saying so) and what they are of ("the optimised motion").
  void set_strips(std::vector<StrengthStrip> strips, const QString& of);
  void set_time(double t);
  const std::vector<StrengthStrip>& strips() const { return strips_; }
  /// The row of a joint's strip (tests click there), -1 when it has none.
  QRect row_rect(int segment) const;

  /// The words under the strips: the chosen joint's (the last clicked, else the largest
  /// share's) largest share, "Left knee flexion would need 708 % of his strength …".
  QString chosen_words() const;

  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

 signals:
  /// A click in the joint's strip (with seek_requested at the clicked time).
  void joint_chosen(int segment);
  /// A click on the joint's name.
  void joint_opened(int segment);
  void seek_requested(double t);

 protected:
  bool event(QEvent* event) override;
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;

 private:
  /// The strips' area (without the joints' names, the peaks and the title).
  QRect plot_area() const;
  double x_of(double t) const;

  std::vector<StrengthStrip> strips_;
  QString of_;
  double time_ = 0.0;
  double duration_ = 1.0;
  int chosen_ = -1;  ///< the segment whose words show under the strips
};

}  // namespace saltus::gui
