#pragma once
/// @file
/// The keyframe editor: the motion's keyframes (time), the selected keyframe's time and, for a
/// chosen joint, its rotation as X-Y-Z Euler angles in degrees (sliders and spin boxes); add a
/// keyframe at the current time, delete one, save the motion. It only asks for edits; the main
/// window makes them through the library and shows the result (or the library's message here).

#include <QWidget>
#include <array>

#include "saltus/motion/motion.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSlider;

namespace saltus::gui {

class KeyframePanel : public QWidget {
  Q_OBJECT

 public:
  explicit KeyframePanel(QWidget* parent = nullptr);

  /// Shows a motion (null: none open), keeping the selected keyframe and joint where possible;
  /// with `first_keyframe` (another motion opened, shown from t = 0) the first keyframe is
  /// selected instead.
  void set_motion(const Motion* motion, const BodyModel* model, bool first_keyframe = false);
  int selected_keyframe() const;
  int selected_segment() const;
  void select(int keyframe, int segment);
  /// A problem with the last edit (the library's message), or "" to clear it.
  void show_problem(const QString& message);
  QString problem() const;

 signals:
  void keyframe_selected(int keyframe);
  void angles_edited(int keyframe, int segment, double x_deg, double y_deg, double z_deg);
  void time_edited(int keyframe, double time);
  void add_requested();
  void delete_requested(int keyframe);
  void save_requested();

 private:
  void show_selection();
  void angles_changed_by(int axis, double value);

  const Motion* motion_ = nullptr;
  const BodyModel* model_ = nullptr;
  QListWidget* list_ = nullptr;
  QDoubleSpinBox* time_ = nullptr;
  QComboBox* joint_ = nullptr;
  std::array<QSlider*, 3> sliders_{};
  std::array<QDoubleSpinBox*, 3> angles_{};
  QPushButton* add_ = nullptr;
  QPushButton* delete_ = nullptr;
  QPushButton* save_ = nullptr;
  QLabel* problem_ = nullptr;
};

}  // namespace saltus::gui
