#pragma once
/// @file
/// A chart's legend as a row of entries above the chart instead of a box inside it: inside, on
/// a laptop's short plots, the box covered half of each plot, the last keyframe line and the
/// capture curve. Each entry draws its line as the chart does (colour, dashes, markers) and
/// the entries wrap onto a second row when the chart is narrow. Included only inside gui/app.

#include <QWidget>
#include <vector>

#include "core/chart_spec.h"

namespace saltus::gui {

class ChartWidget;

class LegendStrip : public QWidget {
  Q_OBJECT

 public:
  explicit LegendStrip(QWidget* parent = nullptr);

  /// Shows the labelled lines and markers of `spec` (an empty legend hides the strip).
  void set_chart(const ChartSpec& spec);
  /// The entries' labels, in order (tests).
  QStringList labels() const;

  bool hasHeightForWidth() const override { return true; }
  int heightForWidth(int width) const override;
  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  struct Entry {
    QString label;
    Rgb colour;
    bool dashed = false;
    bool marker = false;  ///< a vertical line at a time (keyframes), drawn thin and dotted
    LineKind kind = LineKind::kLine;
    double width = 2.0;
  };
  /// Each entry's rectangle for a strip `width` pixels wide (flowing left to right, wrapping).
  std::vector<QRect> layout(int width) const;

  std::vector<Entry> entries_;
};

/// `chart` below a LegendStrip that follows its charts; the chart stops drawing its own legend
/// inside the plot (exported figures keep theirs).
QWidget* with_legend_strip(ChartWidget* chart, QWidget* parent);

}  // namespace saltus::gui
