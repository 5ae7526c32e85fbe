#include "app/keyframe_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>
#include <cmath>

#include "core/motion_edit.h"
#include "saltus/body/segment_names.h"

namespace saltus::gui {

namespace {

/// Sliders move in tenths of a degree.
constexpr int kSliderSteps = 10;

}  // namespace

KeyframePanel::KeyframePanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  list_ = new QListWidget(this);
  list_->setMaximumHeight(130);
  list_->setToolTip(tr("Keyframes; selecting one moves the time there"));
  layout->addWidget(list_);

  auto* grid = new QGridLayout;
  grid->addWidget(new QLabel(tr("Time (s):"), this), 0, 0);
  time_ = new QDoubleSpinBox(this);
  time_->setDecimals(3);
  time_->setSingleStep(0.01);
  time_->setKeyboardTracking(false);
  time_->setToolTip(tr("The first keyframe stays at 0 and the last at the end of the flight"));
  grid->addWidget(time_, 0, 1, 1, 2);
  grid->addWidget(new QLabel(tr("Joint:"), this), 1, 0);
  joint_ = new QComboBox(this);
  // The longest joint's name ("Right shoulder (right upper arm)") would widen the panel past
  // its column; the list that drops down shows the names whole.
  joint_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  joint_->setMinimumContentsLength(16);
  grid->addWidget(joint_, 1, 1, 1, 2);
  const char* axes[3] = {"X (°):", "Y (°):", "Z (°):"};
  for (int a = 0; a < 3; ++a) {
    // Intrinsic X-Y-Z angles of the joint's rotation relative to its parent segment.
    const double limit = a == 1 ? 90.0 : 180.0;
    grid->addWidget(new QLabel(tr(axes[a]), this), 2 + a, 0);
    sliders_[a] = new QSlider(Qt::Horizontal, this);
    sliders_[a]->setRange(static_cast<int>(-limit * kSliderSteps),
                          static_cast<int>(limit * kSliderSteps));
    angles_[a] = new QDoubleSpinBox(this);
    angles_[a]->setRange(-limit, limit);
    angles_[a]->setDecimals(1);
    angles_[a]->setKeyboardTracking(false);
    grid->addWidget(sliders_[a], 2 + a, 1);
    grid->addWidget(angles_[a], 2 + a, 2);
    connect(sliders_[a], &QSlider::valueChanged, this,
            [this, a](int v) { angles_changed_by(a, static_cast<double>(v) / kSliderSteps); });
    connect(angles_[a], qOverload<double>(&QDoubleSpinBox::valueChanged), this,
            [this, a](double v) { angles_changed_by(a, v); });
  }
  layout->addLayout(grid);

  // Two rows, as in the Model panel: three buttons in one row were wider than the panel column
  // on a 1366×768 laptop, which cut "Save motion…" and the angle boxes.
  auto* buttons = new QGridLayout;
  add_ = new QPushButton(tr("Add at current time"), this);
  add_->setToolTip(tr("A new keyframe with the pose the motion has now"));
  delete_ = new QPushButton(tr("Delete"), this);
  save_ = new QPushButton(tr("Save motion…"), this);
  buttons->addWidget(add_, 0, 0);
  buttons->addWidget(delete_, 0, 1);
  buttons->addWidget(save_, 1, 0, 1, 2);
  layout->addLayout(buttons);
  problem_ = new QLabel(this);
  problem_->setWordWrap(true);
  problem_->setStyleSheet("color: #b00020;");
  layout->addWidget(problem_);
  layout->addStretch(1);

  connect(list_, &QListWidget::currentRowChanged, this, [this](int row) {
    show_selection();
    if (row >= 0) emit keyframe_selected(row);
  });
  connect(joint_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this] { show_selection(); });
  connect(time_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double t) {
    if (selected_keyframe() >= 0) emit time_edited(selected_keyframe(), t);
  });
  connect(add_, &QPushButton::clicked, this, &KeyframePanel::add_requested);
  connect(delete_, &QPushButton::clicked, this, [this] {
    if (selected_keyframe() >= 0) emit delete_requested(selected_keyframe());
  });
  connect(save_, &QPushButton::clicked, this, &KeyframePanel::save_requested);
  set_motion(nullptr, nullptr);
}

void KeyframePanel::set_motion(const Motion* motion, const BodyModel* model, bool first_keyframe) {
  const int keyframe = first_keyframe ? 0 : selected_keyframe();
  const int segment = selected_segment();
  motion_ = motion;
  model_ = model;
  {
    const QSignalBlocker block_list(list_);
    const QSignalBlocker block_joint(joint_);
    list_->clear();
    joint_->clear();
    if (motion_ && model_) {
      for (std::size_t i = 0; i < motion_->keyframes.size(); ++i)
        list_->addItem(tr("K%1   %2 s").arg(i + 1).arg(motion_->keyframes[i].time, 0, 'f', 3));
      for (const Segment& s : model_->segments)
        joint_->addItem(QString::fromStdString(capitalised(joint_label(s.joint)) + " (" +
                                               segment_label(s.name) + ")"));
      const int count = static_cast<int>(motion_->keyframes.size());
      list_->setCurrentRow(std::clamp(keyframe, 0, count - 1));
      const int knee = model_->joint_index("knee_l");
      joint_->setCurrentIndex(segment >= 0 && segment < joint_->count() ? segment
                                                                        : std::max(0, knee));
    }
  }
  setEnabled(motion_ != nullptr);
  show_selection();
}

int KeyframePanel::selected_keyframe() const {
  return motion_ ? list_->currentRow() : -1;
}

int KeyframePanel::selected_segment() const {
  return model_ ? joint_->currentIndex() : -1;
}

void KeyframePanel::select(int keyframe, int segment) {
  if (segment >= 0) joint_->setCurrentIndex(segment);
  if (keyframe >= 0) list_->setCurrentRow(keyframe);
}

void KeyframePanel::show_problem(const QString& message) {
  problem_->setText(message);
}

QString KeyframePanel::problem() const {
  return problem_->text();
}

void KeyframePanel::show_selection() {
  const int k = selected_keyframe();
  const int s = selected_segment();
  const bool valid = motion_ && model_ && k >= 0 && s >= 0;
  std::array<double, 3> values{0.0, 0.0, 0.0};
  double t = 0.0;
  if (valid) {
    const Keyframe& kf = motion_->keyframes[static_cast<std::size_t>(k)];
    const Eigen::Vector3d e = euler_xyz_deg(kf.rotations[static_cast<std::size_t>(s)]);
    values = {e.x(), e.y(), e.z()};
    t = kf.time;
  }
  for (int a = 0; a < 3; ++a) {
    const QSignalBlocker block_slider(sliders_[a]);
    const QSignalBlocker block_box(angles_[a]);
    angles_[a]->setValue(values[a]);
    sliders_[a]->setValue(static_cast<int>(std::lround(values[a] * kSliderSteps)));
    sliders_[a]->setEnabled(valid);
    angles_[a]->setEnabled(valid);
  }
  const int last = motion_ ? static_cast<int>(motion_->keyframes.size()) - 1 : -1;
  {
    const QSignalBlocker block(time_);
    time_->setRange(0.0, motion_ ? std::max(motion_->flight_time() * 2.0, 10.0) : 0.0);
    time_->setValue(t);
  }
  // The first keyframe stays at 0; the last sets the flight time (it may move).
  time_->setEnabled(valid && k > 0);
  delete_->setEnabled(valid && k > 0 && k < last);
}

void KeyframePanel::angles_changed_by(int axis, double value) {
  const int k = selected_keyframe();
  const int s = selected_segment();
  if (k < 0 || s < 0) return;
  // Keep the slider and the box in step, then ask for the edit.
  {
    const QSignalBlocker block_slider(sliders_[axis]);
    const QSignalBlocker block_box(angles_[axis]);
    sliders_[axis]->setValue(static_cast<int>(std::lround(value * kSliderSteps)));
    angles_[axis]->setValue(value);
  }
  emit angles_edited(k, s, angles_[0]->value(), angles_[1]->value(), angles_[2]->value());
}

}  // namespace saltus::gui
