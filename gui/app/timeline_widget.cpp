#include "app/timeline_widget.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QProxyStyle>
#include <QSignalBlocker>
#include <QSlider>
#include <QStringList>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QToolButton>

namespace saltus::gui {

namespace {
constexpr int kClockIntervalMs = 15;  ///< playback clock; the frame rate is what rendering allows

/// The application's style, except that a left click on the slider's groove jumps to the time
/// under the mouse (and a drag goes on from there) instead of stepping a page towards it.
class JumpToClickStyle : public QProxyStyle {
 public:
  int styleHint(StyleHint hint, const QStyleOption* option, const QWidget* widget,
                QStyleHintReturn* returned) const override {
    if (hint == QStyle::SH_Slider_AbsoluteSetButtons) return Qt::LeftButton | Qt::MiddleButton;
    return QProxyStyle::styleHint(hint, option, widget, returned);
  }
};

}  // namespace

TickStrip::TickStrip(QSlider* slider, QWidget* parent) : QWidget(parent), slider_(slider) {
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void TickStrip::set_ticks(std::vector<KeyframeTick> ticks) {
  ticks_ = std::move(ticks);
  update();
}

void TickStrip::set_flags(std::vector<TimelineFlag> flags) {
  flags_ = std::move(flags);
  QStringList lines;
  for (const TimelineFlag& f : flags_)
    lines << QString::fromStdString(f.text);
  setToolTip(lines.join('\n'));
  update();
}

QSize TickStrip::sizeHint() const {
  return {200, 14};
}

void TickStrip::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  QStyleOptionSlider option;
  option.initFrom(slider_);
  option.orientation = Qt::Horizontal;
  option.minimum = slider_->minimum();
  option.maximum = slider_->maximum();
  option.sliderPosition = slider_->value();
  const QRect groove = slider_->style()->subControlRect(QStyle::CC_Slider, &option,
                                                        QStyle::SC_SliderGroove, slider_);
  const QRect handle = slider_->style()->subControlRect(QStyle::CC_Slider, &option,
                                                        QStyle::SC_SliderHandle, slider_);
  // The handle's centre travels from groove.left + handle/2 to groove.right - handle/2.
  const int x0 = slider_->x() - x() + groove.left() + handle.width() / 2;
  const int span = groove.width() - handle.width();
  for (const KeyframeTick& tick : ticks_) {
    const int x = x0 + static_cast<int>(tick.fraction * span + 0.5);
    const bool given = tick.kind == TickKind::kGiven;
    painter.setPen(QPen(given ? QColor(110, 110, 110) : QColor(242, 140, 13), given ? 2 : 3));
    if (given)
      painter.drawLine(x, 0, x, height() / 2);
    else
      painter.drawLine(x, height() / 2, x, height());
  }
  // Flags: a triangle pointing up at the moment, over the whole strip's height.
  painter.setRenderHint(QPainter::Antialiasing);
  for (const TimelineFlag& flag : flags_) {
    const int x = x0 + static_cast<int>(flag.fraction * span + 0.5);
    QColor colour;
    switch (flag.kind) {
      case FlagKind::kClearance:
        colour = QColor(44, 160, 44);
        break;
      case FlagKind::kCollision:
        colour = QColor(214, 39, 40);
        break;
      case FlagKind::kEntry:
        colour = QColor(31, 119, 180);
        break;
      case FlagKind::kEntryOffLine:
        colour = QColor(148, 103, 189);
        break;
    }
    const int h = height(), w = h / 2 + 1;
    const QPoint triangle[3] = {{x, 0}, {x - w, h}, {x + w, h}};
    painter.setPen(QPen(colour.darker(130), 1));
    painter.setBrush(colour);
    painter.drawPolygon(triangle, 3);
  }
}

TimelineWidget::TimelineWidget(QWidget* parent) : QWidget(parent) {
  // Focusable, so that the playback keys (scoped to it) work after a click on it.
  setFocusPolicy(Qt::StrongFocus);
  auto* layout = new QGridLayout(this);
  layout->setContentsMargins(6, 2, 6, 2);
  layout->setVerticalSpacing(0);

  auto button = [this](const QString& text, const QString& tip, QStyle::StandardPixmap icon) {
    auto* b = new QToolButton(this);
    b->setIcon(style()->standardIcon(icon));
    b->setText(text);
    b->setToolTip(tip);
    b->setAutoRaise(true);
    return b;
  };
  back_button_ =
      button(tr("Step back"), tr("One frame back (Left arrow)"), QStyle::SP_MediaSeekBackward);
  play_button_ = button(tr("Play"), tr("Play / pause (Space)"), QStyle::SP_MediaPlay);
  forward_button_ = button(tr("Step forward"), tr("One frame forward (Right arrow)"),
                           QStyle::SP_MediaSeekForward);

  slider_ = new QSlider(Qt::Horizontal, this);
  // Without a base style the proxy follows the application's; the slider owns it.
  auto* jump = new JumpToClickStyle;
  jump->setParent(slider_);
  slider_->setStyle(jump);
  slider_->setToolTip(
      tr("Click or drag to go to a time. Ticks: grey = given keyframe times, orange = "
         "optimised. Triangles: the closest pass to the apparatus (green clear, red inside it) "
         "and a dive's entry (blue vertical, purple not); point at them for the figures"));
  ticks_ = new TickStrip(slider_, this);

  speed_ = new QComboBox(this);
  for (double s : speed_choices())
    speed_->addItem(QString::number(s) + QStringLiteral("×"), s);
  speed_->setCurrentIndex(speed_->findData(1.0));
  speed_->setToolTip(tr("Playback speed"));
  loop_ = new QCheckBox(tr("Loop"), this);
  loop_->setChecked(timeline_.loop());
  time_label_ = new QLabel(this);
  time_label_->setMinimumWidth(fontMetrics().horizontalAdvance("00.000 s / 00.000 s") + 8);

  layout->addWidget(back_button_, 0, 0);
  layout->addWidget(play_button_, 0, 1);
  layout->addWidget(forward_button_, 0, 2);
  layout->addWidget(slider_, 0, 3);
  layout->addWidget(ticks_, 1, 3);
  layout->addWidget(time_label_, 0, 4);
  layout->addWidget(new QLabel(tr("Speed"), this), 0, 5);
  layout->addWidget(speed_, 0, 6);
  layout->addWidget(loop_, 0, 7);
  layout->setColumnStretch(3, 1);

  connect(play_button_, &QToolButton::clicked, this, &TimelineWidget::toggle_play);
  connect(back_button_, &QToolButton::clicked, this, &TimelineWidget::step_back);
  connect(forward_button_, &QToolButton::clicked, this, &TimelineWidget::step_forward);
  connect(slider_, &QSlider::valueChanged, this, [this](int frame) {
    timeline_.pause();
    timeline_.seek_frame(frame);
    emit_time();
  });
  connect(speed_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this](int index) { set_speed(speed_->itemData(index).toDouble()); });
  connect(loop_, &QCheckBox::toggled, this, &TimelineWidget::set_loop);

  clock_.setInterval(kClockIntervalMs);
  clock_.setTimerType(Qt::PreciseTimer);
  connect(&clock_, &QTimer::timeout, this, &TimelineWidget::tick);
  sync_controls();
}

void TimelineWidget::set_motion(double duration, int frame_count, const std::vector<double>& given,
                                const std::vector<double>& optimised) {
  timeline_.set_range(duration, frame_count);
  ticks_->set_ticks(keyframe_ticks(given, optimised, duration));
  {
    const QSignalBlocker block(slider_);
    slider_->setRange(0, frame_count - 1);
    slider_->setPageStep(std::max(1, frame_count / 10));
  }
  emit_time();
}

void TimelineWidget::set_flags(std::vector<TimelineFlag> flags) {
  ticks_->set_flags(std::move(flags));
}

const std::vector<TimelineFlag>& TimelineWidget::flags() const {
  return ticks_->flags();
}

void TimelineWidget::seek(double t) {
  timeline_.seek(t);
  emit_time();
}

void TimelineWidget::toggle_play() {
  timeline_.playing() ? pause() : play();
}

void TimelineWidget::play() {
  timeline_.play();
  wall_.start();
  clock_.start();
  emit_time();
}

void TimelineWidget::pause() {
  timeline_.pause();
  clock_.stop();
  emit_time();
}

void TimelineWidget::step_forward() {
  timeline_.step(1);
  clock_.stop();
  emit_time();
}

void TimelineWidget::step_back() {
  timeline_.step(-1);
  clock_.stop();
  emit_time();
}

void TimelineWidget::go_to_start() {
  timeline_.pause();
  clock_.stop();
  timeline_.seek(0.0);
  emit_time();
}

void TimelineWidget::go_to_end() {
  timeline_.pause();
  clock_.stop();
  timeline_.seek(timeline_.duration());
  emit_time();
}

void TimelineWidget::set_speed(double speed) {
  timeline_.set_speed(speed);
  {
    const QSignalBlocker block(speed_);
    int best = 0;
    for (int i = 0; i < speed_->count(); ++i)
      if (std::abs(speed_->itemData(i).toDouble() - timeline_.speed()) <
          std::abs(speed_->itemData(best).toDouble() - timeline_.speed()))
        best = i;
    speed_->setCurrentIndex(best);
  }
  emit speed_changed(timeline_.speed());
}

void TimelineWidget::set_loop(bool loop) {
  timeline_.set_loop(loop);
  {
    const QSignalBlocker block(loop_);
    loop_->setChecked(loop);
  }
  emit loop_changed(loop);
}

void TimelineWidget::tick() {
  // Advance by the wall-clock time since the last tick, so playback runs in real time (times
  // the speed) whatever the frame rate.
  const double seconds = wall_.restart() / 1000.0;
  if (timeline_.advance(seconds) || !timeline_.playing()) emit_time();
  if (!timeline_.playing()) clock_.stop();
}

void TimelineWidget::sync_controls() {
  const bool playing = timeline_.playing();
  play_button_->setIcon(
      style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
  play_button_->setText(playing ? tr("Pause") : tr("Play"));
  {
    const QSignalBlocker block(slider_);
    slider_->setValue(timeline_.frame());
  }
  time_label_->setText(QString::fromStdString(format_time(timeline_.time(), timeline_.duration())));
  if (playing != was_playing_) {
    was_playing_ = playing;
    emit playing_changed(playing);
  }
}

void TimelineWidget::emit_time() {
  sync_controls();
  emit time_changed(timeline_.time());
}

}  // namespace saltus::gui
