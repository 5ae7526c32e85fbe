#include "app/legend_strip.h"

#include <QPainter>
#include <QVBoxLayout>
#include <algorithm>

#include "app/chart_widget.h"

namespace saltus::gui {

namespace {

constexpr int kSample = 24;   ///< length of an entry's line sample, px
constexpr int kGap = 4;       ///< between the sample and its label
constexpr int kSpacing = 14;  ///< between entries
constexpr int kMargin = 4;    ///< left and right of the strip

QColor colour_of(const Rgb& c) {
  return QColor::fromRgbF(std::clamp(c.r, 0.0, 1.0), std::clamp(c.g, 0.0, 1.0),
                          std::clamp(c.b, 0.0, 1.0));
}

}  // namespace

LegendStrip::LegendStrip(QWidget* parent) : QWidget(parent) {
  QSizePolicy policy(QSizePolicy::Preferred, QSizePolicy::Fixed);
  policy.setHeightForWidth(true);
  setSizePolicy(policy);
  QFont small = font();
  small.setPointSizeF(small.pointSizeF() * 0.9);
  setFont(small);
  hide();
}

void LegendStrip::set_chart(const ChartSpec& spec) {
  entries_.clear();
  if (spec.legend) {
    for (const LineSpec& line : spec.lines)
      if (!line.label.empty())
        entries_.push_back({QString::fromStdString(line.label), line.colour, line.dashed, false,
                            line.kind, line.width});
    for (const MarkerSpec& marker : spec.markers)
      if (!marker.label.empty())
        entries_.push_back({QString::fromStdString(marker.label), marker.colour, marker.dashed,
                            true, LineKind::kLine, 1.0});
  }
  setVisible(!entries_.empty());
  updateGeometry();
  update();
}

QStringList LegendStrip::labels() const {
  QStringList out;
  for (const Entry& e : entries_)
    out << e.label;
  return out;
}

std::vector<QRect> LegendStrip::layout(int width) const {
  const QFontMetrics metrics(font());
  const int row_height = metrics.height() + 2;
  std::vector<QRect> rects;
  int x = kMargin, y = 1;
  for (const Entry& e : entries_) {
    const int w = kSample + kGap + metrics.horizontalAdvance(e.label);
    if (x > kMargin && x + w > width - kMargin) {
      x = kMargin;
      y += row_height;
    }
    rects.emplace_back(x, y, w, row_height);
    x += w + kSpacing;
  }
  return rects;
}

int LegendStrip::heightForWidth(int width) const {
  if (entries_.empty()) return 0;
  const std::vector<QRect> rects = layout(width);
  return rects.back().bottom() + 2;
}

QSize LegendStrip::sizeHint() const {
  const int width = parentWidget() ? parentWidget()->width() : 400;
  return {width, heightForWidth(width)};
}

QSize LegendStrip::minimumSizeHint() const {
  return {0, heightForWidth(width() > 0 ? width() : 400)};
}

void LegendStrip::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  const std::vector<QRect> rects = layout(width());
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    const QRect& r = rects[i];
    const int mid = r.center().y();
    QPen pen(colour_of(e.colour));
    pen.setWidthF(e.marker ? 1.2 : std::max(1.5, e.width));
    if (e.dashed) pen.setStyle(e.marker ? Qt::DotLine : Qt::DashLine);
    painter.setPen(pen);
    if (e.kind == LineKind::kBars) {
      painter.fillRect(QRect(r.left() + 4, mid - 5, kSample - 8, 10), colour_of(e.colour));
    } else {
      painter.drawLine(r.left(), mid, r.left() + kSample, mid);
      if (e.kind == LineKind::kPoints) {
        painter.setBrush(colour_of(e.colour));
        painter.drawEllipse(QPoint(r.left() + kSample / 2, mid), 3, 3);
        painter.setBrush(Qt::NoBrush);
      }
    }
    painter.setPen(palette().color(QPalette::WindowText));
    painter.drawText(
        QRect(r.left() + kSample + kGap, r.top(), r.width() - kSample - kGap, r.height()),
        Qt::AlignVCenter | Qt::AlignLeft, e.label);
  }
}

QWidget* with_legend_strip(ChartWidget* chart, QWidget* parent) {
  auto* box = new QWidget(parent);
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  auto* strip = new LegendStrip(box);
  strip->setObjectName("legend_strip");
  layout->addWidget(strip);
  layout->addWidget(chart, 1);
  chart->view().set_legend_drawn(false);
  strip->set_chart(chart->view().chart());
  QObject::connect(chart, &ChartWidget::chart_changed, strip,
                   [strip, chart] { strip->set_chart(chart->view().chart()); });
  return box;
}

}  // namespace saltus::gui
