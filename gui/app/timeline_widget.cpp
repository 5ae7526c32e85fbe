#include "app/timeline_widget.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QProxyStyle>
#include <QRegularExpression>
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

/// A flag's colour, on the strip and in its legend.
QColor flag_colour(FlagKind kind) {
  switch (kind) {
    case FlagKind::kClearance:
      return QColor(44, 160, 44);
    case FlagKind::kCollision:
      return QColor(214, 39, 40);
    case FlagKind::kEntry:
      return QColor(31, 119, 180);
    case FlagKind::kEntryOffLine:
      return QColor(148, 103, 189);
  }
  return QColor(Qt::black);
}

/// A flag's name in the legend beside the strip: a few words; the figures stay in the tooltip.
QString flag_name(FlagKind kind) {
  switch (kind) {
    case FlagKind::kClearance:
      return QCoreApplication::translate("TimelineWidget", "closest pass, clear");
    case FlagKind::kCollision:
      return QCoreApplication::translate("TimelineWidget", "closest pass, inside");
    case FlagKind::kEntry:
      return QCoreApplication::translate("TimelineWidget", "entry, vertical");
    case FlagKind::kEntryOffLine:
      return QCoreApplication::translate("TimelineWidget", "entry, not vertical");
  }
  return {};
}

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
    const QColor colour = flag_colour(flag.kind);
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
  // What the flags are, in a smaller font under the time and speed, so that a coach sees it
  // without pointing at them; it never widens the window (the tooltip has it all).
  flag_legend_ = new QLabel(this);
  flag_legend_->setObjectName("timeline_flag_legend");
  flag_legend_->setTextFormat(Qt::RichText);
  QFont small = flag_legend_->font();
  small.setPointSizeF(small.pointSizeF() * 0.85);
  flag_legend_->setFont(small);
  flag_legend_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
  flag_legend_->setVisible(false);

  layout->addWidget(back_button_, 0, 0);
  layout->addWidget(play_button_, 0, 1);
  layout->addWidget(forward_button_, 0, 2);
  layout->addWidget(slider_, 0, 3);
  layout->addWidget(ticks_, 1, 3);
  layout->addWidget(time_label_, 0, 4);
  layout->addWidget(new QLabel(tr("Speed"), this), 0, 5);
  layout->addWidget(speed_, 0, 6);
  layout->addWidget(loop_, 0, 7);
  layout->addWidget(flag_legend_, 1, 4, 1, 4, Qt::AlignLeft | Qt::AlignVCenter);
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
  // One entry per kind shown, in the flags' order: a coloured triangle and its name.
  QStringList entries;
  for (const TimelineFlag& f : flags) {
    const QString entry = QString("<span style='color:%1'>&#9650;</span>&nbsp;%2")
                              .arg(flag_colour(f.kind).name(), flag_name(f.kind).toHtmlEscaped());
    if (!entries.contains(entry)) entries << entry;
  }
  flag_legend_->setText(entries.join("&nbsp;&nbsp; "));
  flag_legend_->setVisible(!entries.isEmpty());
  ticks_->set_flags(std::move(flags));
  flag_legend_->setToolTip(ticks_->toolTip());
}

QString TimelineWidget::flag_legend() const {
  if (flag_legend_->isHidden()) return {};
  QString text = flag_legend_->text();
  text.remove(QRegularExpression("<[^>]*>"));
  return text.replace("&#9650;", QString(QChar(0x25B2))).replace("&nbsp;", " ");
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
