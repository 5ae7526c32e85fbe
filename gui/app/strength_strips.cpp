#include "app/strength_strips.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
#include <algorithm>

#include "app/qt_text.h"

namespace saltus::gui {

namespace {

constexpr int kNameWidth = 120;  ///< the joints' names, px
constexpr int kPeakWidth = 56;   ///< the largest share at a row's end, px
constexpr int kTitleHeight = 22;
constexpr int kAxisHeight = 18;
constexpr int kWordsHeight = 18;  ///< the chosen joint's words under the time axis
constexpr int kMinRow = 9;

QColor colour(const Rgb& c) {
  return QColor::fromRgbF(c.r, c.g, c.b);
}

}  // namespace

StrengthStrips::StrengthStrips(QWidget* parent) : QWidget(parent) {
  setObjectName("strength_strips");
  setMouseTracking(false);
  setToolTip(
      tr("Each joint's share of the athlete's strength over the flight: its moment in each "
         "anatomical direction against what the athlete's muscles can give there, at that angle "
         "and speed. Pale green at rest, amber from 80 %, red above 100 %. Click a strip to go "
         "to that time and joint, a joint's name to see its loads."));
}

void StrengthStrips::set_strips(std::vector<StrengthStrip> strips, const QString& of) {
  strips_ = std::move(strips);
  of_ = of;
  duration_ = 0.0;
  for (const StrengthStrip& s : strips_)
    if (!s.times.empty()) duration_ = std::max(duration_, s.times.back());
  if (!(duration_ > 0.0)) duration_ = 1.0;
  // The words stay with the joint chosen; else they are the largest share's.
  const auto kept = std::find_if(strips_.begin(), strips_.end(),
                                 [this](const StrengthStrip& s) { return s.segment == chosen_; });
  if (kept == strips_.end()) {
    const auto largest = std::max_element(
        strips_.begin(), strips_.end(),
        [](const StrengthStrip& a, const StrengthStrip& b) { return a.peak < b.peak; });
    chosen_ = largest == strips_.end() ? -1 : largest->segment;
  }
  updateGeometry();
  update();
}

void StrengthStrips::set_time(double t) {
  time_ = t;
  update();
}

QSize StrengthStrips::sizeHint() const {
  return {600, kTitleHeight + kAxisHeight + kWordsHeight +
                   14 * static_cast<int>(std::max<std::size_t>(1, strips_.size()))};
}

QSize StrengthStrips::minimumSizeHint() const {
  return {300, kTitleHeight + kAxisHeight + kWordsHeight + kMinRow * 4};
}

QRect StrengthStrips::plot_area() const {
  return QRect(kNameWidth, kTitleHeight, std::max(10, width() - kNameWidth - kPeakWidth),
               std::max(10, height() - kTitleHeight - kAxisHeight - kWordsHeight));
}

double StrengthStrips::x_of(double t) const {
  const QRect area = plot_area();
  return area.left() + area.width() * std::clamp(t / duration_, 0.0, 1.0);
}

QRect StrengthStrips::row_rect(int segment) const {
  const QRect area = plot_area();
  const int rows = static_cast<int>(strips_.size());
  for (int i = 0; i < rows; ++i)
    if (strips_[static_cast<std::size_t>(i)].segment == segment) {
      const int top = area.top() + area.height() * i / rows;
      const int bottom = area.top() + area.height() * (i + 1) / rows;
      return QRect(area.left(), top, area.width(), bottom - top);
    }
  return {};
}

void StrengthStrips::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().base());
  QFont bold = font();
  bold.setBold(true);
  p.setFont(bold);
  p.drawText(QRect(4, 2, width() - 8, kTitleHeight - 2), Qt::AlignLeft | Qt::AlignVCenter,
             tr("Share of the athlete's strength at each joint%1 — red above 100 %")
                 .arg(of_.isEmpty() ? QString() : " (" + of_ + ")"));
  p.setFont(font());
  if (strips_.empty()) {
    p.drawText(plot_area(), Qt::AlignCenter, tr("No joint of this model has a strength curve."));
    return;
  }
  const QRect area = plot_area();
  const QFontMetrics metrics(font());
  // Names and peaks in a smaller font where the rows are lower than a line (a laptop's screen).
  const int row_height = area.height() / static_cast<int>(strips_.size());
  QFont row_font = font();
  if (metrics.height() > row_height + 1) row_font.setPixelSize(std::max(8, row_height));
  p.setFont(row_font);
  const QFontMetrics row_metrics(row_font);
  for (const StrengthStrip& strip : strips_) {
    const QRect row = row_rect(strip.segment).adjusted(0, 1, 0, -1);
    // The name, elided to its column; the strip; the largest share at its end.
    p.setPen(palette().text().color());
    p.drawText(QRect(2, row.top(), kNameWidth - 6, row.height()), Qt::AlignRight | Qt::AlignVCenter,
               row_metrics.elidedText(qstr(strip.joint), Qt::ElideRight, kNameWidth - 6));
    for (std::size_t i = 0; i + 1 < strip.times.size(); ++i) {
      const double x0 = x_of(strip.times[i]), x1 = x_of(strip.times[i + 1]);
      const double share = std::max(strip.shares[i], strip.shares[i + 1]);
      p.fillRect(QRectF(x0, row.top(), std::max(1.0, x1 - x0 + 0.5), row.height()),
                 colour(strength_share_colour(share)));
    }
    p.setPen(colour(strength_light_colour(strength_light(strip.peak))));
    p.drawText(QRect(area.right() + 4, row.top(), kPeakWidth - 4, row.height()),
               Qt::AlignLeft | Qt::AlignVCenter,
               QString("%1 %").arg(100.0 * strip.peak, 0, 'f', 0));
  }
  p.setFont(font());
  // The time axis: a tick a half second, and the time shown.
  p.setPen(palette().mid().color());
  p.drawRect(area.adjusted(0, 0, -1, -1));
  p.setPen(palette().text().color());
  const double step = duration_ > 4.0 ? 1.0 : 0.5;
  for (double t = 0.0; t <= duration_ + 1e-9; t += step) {
    const double x = x_of(t);
    p.drawLine(QPointF(x, area.bottom()), QPointF(x, area.bottom() + 4));
    p.drawText(QRectF(x - 20, area.bottom() + 4, 40, kAxisHeight - 4), Qt::AlignCenter,
               QString::number(t, 'g', 3));
  }
  p.drawText(QRect(area.right() + 4, area.bottom() + 2, kPeakWidth, kAxisHeight),
             Qt::AlignLeft | Qt::AlignVCenter, tr("t (s)"));
  // The chosen joint's largest share in words, red beyond the athlete's strength.
  for (const StrengthStrip& strip : strips_)
    if (strip.segment == chosen_) {
      const QRect words(4, area.bottom() + kAxisHeight, width() - 8, kWordsHeight);
      p.setPen(strip.peak > 1.0 ? colour(strength_light_colour(StrengthLight::kRed))
                                : palette().text().color());
      p.drawText(words, Qt::AlignLeft | Qt::AlignVCenter,
                 metrics.elidedText(chosen_words(), Qt::ElideRight, words.width()));
    }
  QPen cursor(Qt::black);
  cursor.setWidth(2);
  p.setPen(cursor);
  const double x = x_of(time_);
  p.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
}

void StrengthStrips::mousePressEvent(QMouseEvent* event) {
  const QRect area = plot_area();
  for (const StrengthStrip& strip : strips_) {
    const QRect row = row_rect(strip.segment);
    if (event->pos().y() < row.top() || event->pos().y() > row.bottom()) continue;
    if (event->pos().x() < area.left()) {
      // The joint's name: its loads.
      chosen_ = strip.segment;
      update();
      emit joint_opened(strip.segment);
    } else if (event->pos().x() <= area.right()) {
      // The strip: that time, that joint.
      chosen_ = strip.segment;
      update();
      emit seek_requested(duration_ * (event->pos().x() - area.left()) / area.width());
      emit joint_chosen(strip.segment);
    }
    return;
  }
}

QString StrengthStrips::chosen_words() const {
  for (const StrengthStrip& strip : strips_)
    if (strip.segment == chosen_) {
      QString words = qstr(strip.peak_words);
      if (!words.isEmpty()) words[0] = words[0].toUpper();
      return words;
    }
  return {};
}

bool StrengthStrips::event(QEvent* event) {
  if (event->type() == QEvent::ToolTip) {
    // Over a row: that joint's largest share in words.
    const auto* help = static_cast<QHelpEvent*>(event);
    for (const StrengthStrip& strip : strips_) {
      const QRect row = row_rect(strip.segment);
      if (help->pos().y() >= row.top() && help->pos().y() <= row.bottom()) {
        QToolTip::showText(help->globalPos(), qstr(strip.peak_words), this);
        return true;
      }
    }
  }
  return QWidget::event(event);
}

}  // namespace saltus::gui
