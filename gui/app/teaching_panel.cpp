#include "app/teaching_panel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "app/chart_widget.h"
#include "app/legend_strip.h"
#include "core/plot_series.h"
#include "saltus/evaluation/flight_checks.h"

namespace saltus::gui {

namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

QString num(double value, int decimals) {
  // No "-0.00" for tiny negatives.
  const double scale = std::pow(10.0, decimals);
  const double rounded = std::round(value * scale) / scale;
  return QString::number(rounded == 0.0 ? 0.0 : rounded, 'f', decimals);
}

}  // namespace

TeachingPanel::TeachingPanel(AppContext& context, QWidget* parent)
    : QWidget(parent), context_(context) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);

  auto* text = new QWidget(this);
  auto* text_layout = new QVBoxLayout(text);
  text_layout->setContentsMargins(6, 2, 6, 2);
  explanation_ = new QLabel(text);
  explanation_->setWordWrap(true);
  explanation_->setTextFormat(Qt::RichText);
  explanation_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  checks_ = new QLabel(text);
  checks_->setWordWrap(true);
  checks_->setTextFormat(Qt::RichText);
  checks_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  text_layout->addWidget(explanation_);
  text_layout->addWidget(checks_);
  text_layout->addStretch(1);
  auto* scroll = new QScrollArea(this);
  scroll->setWidget(text);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setMinimumWidth(300);

  auto* right = new QWidget(this);
  auto* right_layout = new QVBoxLayout(right);
  right_layout->setContentsMargins(0, 0, 0, 0);
  auto* row = new QHBoxLayout;
  row->addWidget(new QLabel(tr("Plot:"), right));
  quantity_ = new QComboBox(right);
  for (const std::string& name : rotation_quantity_names())
    quantity_->addItem(QString::fromStdString(name));
  row->addWidget(quantity_);
  row->addStretch(1);
  right_layout->addLayout(row);
  chart_ = new ChartWidget(right);
  right_layout->addWidget(with_legend_strip(chart_, right), 1);
  connect(quantity_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this] { refresh_chart(); });
  connect(chart_, &ChartWidget::seek_requested, this, &TeachingPanel::seek_requested);

  layout->addWidget(scroll, 1);
  layout->addWidget(right, 1);
  refresh();
}

QString TeachingPanel::text() const {
  return explanation_->text() + "\n" + checks_->text();
}

void TeachingPanel::refresh() {
  refresh_chart();
  const Workspace& ws = context_.workspace();
  if (!ws.loaded()) {
    explanation_->setText(
        tr("<b>Why it spins</b><p>Open a motion to see why the body turns as it "
           "does in the air.</p>"));
    checks_->clear();
    return;
  }
  const Document& d = ws.document();
  const Stage stage = ws.stage();
  const FlightChecks& c = d.flight_checks(stage);
  const Takeoff& takeoff = d.file().motion.takeoff;
  const double drop = -c.height_change_m;
  const QString ending = std::abs(drop) < 0.05
                             ? tr("lands at its take-off height")
                             : (drop > 0 ? tr("ends %1 m lower").arg(num(drop, 2))
                                         : tr("ends %1 m higher").arg(num(-drop, 2)));
  const FlightCheckVerdict verdict = judge_flight(c);
  const auto mark = [](bool pass) {
    return pass ? QStringLiteral("<span style='color:#2e7d32'>✓</span>")
                : QStringLiteral("<span style='color:#c62828'>✗</span>");
  };
  // The closing sentence says what holds for the motion shown, never more.
  const QString failing =
      verdict.failed() == 1 ? tr("one check fails") : tr("%1 checks fail").arg(verdict.failed());
  QString closing;
  if (verdict.failed() == 0)
    closing = tr("All three hold: gravity alone could fly this motion.");
  else if (stage == Stage::kBefore)
    closing = tr("Here %1: no free flight moves like this. Optimising lowers the root force that "
                 "makes up the difference; View &gt; After shows what holds then.")
                  .arg(failing);
  else
    closing =
        tr("Even after optimisation %1: the root force left still moves the body.").arg(failing);
  checks_->setText(
      tr("<b>Is it a real flight?</b> Only gravity acts in the air, so:"
         "<br>%1 the centre of mass stays on its take-off parabola: at most %2 mm off "
         "(a real flight: within %3 mm);"
         "<br>%4 L stays as at take-off: it changes by up to %5 % (within %6 %);"
         "<br>%7 the time in the air follows from the take-off (%8 m/s up; it %9): %10 s, "
         "this motion %11 s (within %12 s)."
         "<br>%13")
          .arg(mark(verdict.on_parabola))
          .arg(num(1000.0 * c.max_com_off_parabola_m, 1))
          .arg(num(1000.0 * kFreeFlightComToleranceM, 0))
          .arg(mark(verdict.angular_momentum_kept))
          .arg(num(c.max_angular_momentum_drift_percent, 1))
          .arg(num(kFreeFlightAngularMomentumTolerancePercent, 0))
          .arg(mark(verdict.flight_time_matches))
          .arg(num(takeoff.com_velocity.y(), 2), ending)
          .arg(std::isfinite(c.ballistic_flight_time) ? num(c.ballistic_flight_time, 2)
                                                      : QString("—"))
          .arg(num(c.flight_time, 2))
          .arg(num(kFreeFlightTimeToleranceS, 2))
          .arg(closing));
  set_time(time_);
}

void TeachingPanel::set_time(double t) {
  time_ = t;
  const Workspace& ws = context_.workspace();
  if (!ws.loaded()) return;
  const Document& d = ws.document();
  const Stage stage = ws.stage();
  const RotationSample r = d.rotation_at(stage, t);
  const std::vector<RotationSample>& series = d.rotation(stage);
  double i_min = r.somersault_inertia, i_max = r.somersault_inertia;
  for (const RotationSample& s : series) {
    i_min = std::min(i_min, s.somersault_inertia);
    i_max = std::max(i_max, s.somersault_inertia);
  }
  const std::vector<SampleRecord>& samples = d.plot_samples(stage);
  const double forward = samples.empty() ? 1.0 : forward_somersault_sign(samples.front());
  const double somersaults = forward * r.somersaults;
  const double flight = series.empty() ? 0.0 : forward * series.back().somersaults;
  const QString direction =
      somersault_direction(somersaults, flight) == "backward" ? tr("backward") : tr("forward");
  // Where along the flight the drift is now (the checks are per sample of the dense grid).
  double drift_now = 0.0;
  const FlightChecks& checks = d.flight_checks(stage);
  if (!checks.samples.empty()) {
    const auto at =
        std::lower_bound(checks.samples.begin(), checks.samples.end(), t,
                         [](const FlightCheckSample& s, double time) { return s.time < time; });
    drift_now =
        (at == checks.samples.end() ? checks.samples.back() : *at).angular_momentum_drift_percent;
  }
  const Eigen::Vector3d& l = r.angular_momentum;
  explanation_->setText(
      tr("<b>Why it spins</b> &nbsp; t = %1 s"
         "<br>• <b>L</b>, the angular momentum about the centre of mass, cannot change in the "
         "air: (%2, %3, %4) kg·m²/s, %5 % off its take-off value."
         "<br>• <b>I</b>, the moment of inertia about the somersault axis, changes with the "
         "shape: %6 kg·m² now, %7 to %8 in this flight."
         "<br>• So the body turns at <b>ω = I⁻¹·L</b>: %9 rad/s, %10 turns a second. Half the "
         "inertia (a tuck), twice the spin."
         "<br>• So far: <b>%11 somersaults %12</b>, %13 twists.")
          .arg(num(t, 3))
          .arg(num(l.x(), 1), num(l.y(), 1), num(l.z(), 1))
          .arg(num(drift_now, 1))
          .arg(num(r.somersault_inertia, 2), num(i_min, 2), num(i_max, 2))
          .arg(num(std::abs(r.somersault_rate), 2))
          .arg(num(std::abs(r.somersault_rate) / kTwoPi, 2))
          .arg(num(std::abs(somersaults), 2), direction)
          .arg(num(std::abs(r.twists), 2)));
  chart_->set_cursor(t);
}

void TeachingPanel::refresh_chart() {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded()) {
    ChartSpec empty;
    empty.title = "Open a motion to see how it rotates";
    chart_->set_chart(empty);
    return;
  }
  const Document& d = ws.document();
  const bool optimised = d.has_optimization();
  chart_->set_chart(
      rotation_chart(static_cast<RotationQuantity>(std::max(0, quantity_->currentIndex())),
                     d.rotation(Stage::kBefore), optimised ? &d.rotation(Stage::kAfter) : nullptr));
  chart_->set_cursor(time_);
}

}  // namespace saltus::gui
