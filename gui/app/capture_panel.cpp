#include "app/capture_panel.h"

#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHelpEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPushButton>
#include <QToolTip>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "app/qt_text.h"
#include "core/capture_fixes.h"
#include "core/capture_keyframes.h"
#include "core/document.h"
#include "saltus/evaluation/force_metrics.h"
#include "saltus/evaluation/residual_measures.h"

namespace saltus::gui {

namespace {

constexpr int kStripHeight = 46;
constexpr int kMaxCellWidth = 28;
constexpr int kMargin = 6;

}  // namespace

CaptureFrameStrip::CaptureFrameStrip(QWidget* parent) : QWidget(parent) {
  setMouseTracking(true);
  setToolTip(tr("The capture's flight frames: click one to make it a keyframe or to remove it"));
}

void CaptureFrameStrip::set_frames(const std::vector<double>& times,
                                   const std::vector<int>& picked) {
  times_ = times;
  picked_.assign(times.size(), false);
  for (int f : picked)
    if (f >= 0 && f < frame_count()) picked_[static_cast<std::size_t>(f)] = true;
  update();
}

void CaptureFrameStrip::set_time(double t) {
  time_ = t;
  update();
}

QSize CaptureFrameStrip::sizeHint() const {
  return {std::max(120, frame_count() * 14 + 2 * kMargin), kStripHeight};
}

QSize CaptureFrameStrip::minimumSizeHint() const {
  return {120, kStripHeight};
}

QRectF CaptureFrameStrip::cell(int frame) const {
  const double usable = width() - 2.0 * kMargin;
  const double w = frame_count() > 0 ? std::min<double>(kMaxCellWidth, usable / frame_count()) : 0;
  const double left = kMargin + 0.5 * (usable - w * frame_count());
  return {left + frame * w, 6.0, w, height() - 18.0};
}

QPoint CaptureFrameStrip::cell_centre(int frame) const {
  return cell(frame).center().toPoint();
}

int CaptureFrameStrip::frame_at(const QPoint& point) const {
  for (int f = 0; f < frame_count(); ++f)
    if (cell(f).contains(point)) return f;
  return -1;
}

void CaptureFrameStrip::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QColor keyframe(70, 120, 200);
  const QColor locked(110, 110, 110);
  for (int f = 0; f < frame_count(); ++f) {
    const QRectF r = cell(f).adjusted(1.5, 1.5, -1.5, -1.5);
    const bool end = f == 0 || f == frame_count() - 1;
    const bool on = picked_[static_cast<std::size_t>(f)];
    p.setPen(QPen(end ? locked : keyframe, 1.5));
    p.setBrush(on ? (end ? locked : keyframe) : QColor(0, 0, 0, 0));
    p.drawRoundedRect(r, 3, 3);
  }
  // The time shown, between the frames it falls between.
  if (frame_count() >= 2) {
    const double first = times_.front(), last = times_.back();
    const double u = last > first ? std::clamp((time_ - first) / (last - first), 0.0, 1.0) : 0.0;
    const double x0 = cell(0).center().x(), x1 = cell(frame_count() - 1).center().x();
    const double x = x0 + u * (x1 - x0);
    p.setPen(QPen(QColor(230, 120, 20), 2));
    p.drawLine(QPointF(x, 2), QPointF(x, height() - 10));
  }
  p.setPen(palette().color(QPalette::WindowText));
  QFont small = font();
  small.setPointSizeF(std::max(6.0, small.pointSizeF() * 0.8));
  p.setFont(small);
  if (frame_count() > 0) {
    p.drawText(QRectF(0, height() - 12, width() / 2.0, 12), Qt::AlignLeft | Qt::AlignVCenter,
               QString("  %1 s").arg(times_.front(), 0, 'f', 2));
    p.drawText(QRectF(width() / 2.0, height() - 12, width() / 2.0, 12),
               Qt::AlignRight | Qt::AlignVCenter, QString("%1 s  ").arg(times_.back(), 0, 'f', 2));
  }
}

void CaptureFrameStrip::mousePressEvent(QMouseEvent* event) {
  const int f = frame_at(event->pos());
  if (f >= 0 && event->button() == Qt::LeftButton) emit frame_clicked(f);
}

bool CaptureFrameStrip::event(QEvent* e) {
  if (e->type() == QEvent::ToolTip) {
    auto* help = static_cast<QHelpEvent*>(e);
    const int f = frame_at(help->pos());
    if (f < 0) {
      QToolTip::hideText();
      return true;
    }
    const bool end = f == 0 || f == frame_count() - 1;
    const bool on = picked_[static_cast<std::size_t>(f)];
    QToolTip::showText(help->globalPos(),
                       tr("Flight frame %1 of %2, t = %3 s: %4")
                           .arg(f + 1)
                           .arg(frame_count())
                           .arg(times_[static_cast<std::size_t>(f)], 0, 'f', 3)
                           .arg(end  ? tr("a keyframe for good (the flight's start or end)")
                                : on ? tr("a keyframe (click to remove it)")
                                     : tr("not a keyframe (click to add it)")),
                       this);
    return true;
  }
  return QWidget::event(e);
}

CapturePanel::CapturePanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(summary_);
  warnings_ = new QLabel(this);
  warnings_->setWordWrap(true);
  warnings_->setStyleSheet("color: #b35c00;");
  layout->addWidget(warnings_);
  // The advice's fixes as buttons, the value the library suggests one click away, and every
  // flag of `saltus import` the advice may name in the settings dialog.
  fixes_ = new QVBoxLayout;
  layout->addLayout(fixes_);
  settings_ = new QPushButton(tr("Import settings…"), this);
  settings_->setObjectName("capture_import_settings");
  settings_->setToolTip(
      tr("Import the capture again with other settings of `saltus import`: its frame time, "
         "flight, keyframes and mapping file"));
  connect(settings_, &QPushButton::clicked, this, &CapturePanel::import_settings_requested);
  layout->addWidget(settings_);
  auto* strip_title = new QLabel(
      tr("<b>Keyframes on the capture's flight</b> (click a frame to add or remove it):"), this);
  strip_title->setWordWrap(true);
  layout->addWidget(strip_title);
  strip_ = new CaptureFrameStrip(this);
  layout->addWidget(strip_);
  pick_ = new QLabel(this);
  pick_->setWordWrap(true);
  layout->addWidget(pick_);
  auto* buttons = new QHBoxLayout;
  automatic_ = new QPushButton(tr("Pick automatically"), this);
  automatic_->setToolTip(
      tr("The fewest frames whose interpolation stays within the keyframe tolerance of every "
         "captured frame (as `saltus import` picks them)"));
  every_ = new QPushButton(tr("Every frame"), this);
  every_->setToolTip(tr("Every captured frame of the flight a keyframe"));
  buttons->addWidget(automatic_);
  buttons->addWidget(every_);
  buttons->addStretch(1);
  layout->addLayout(buttons);
  problem_ = new QLabel(this);
  problem_->setWordWrap(true);
  problem_->setStyleSheet("color: #c0392b;");
  layout->addWidget(problem_);
  layout->addStretch(1);

  connect(strip_, &CaptureFrameStrip::frame_clicked, this, [this](int f) {
    // Show the frame, then add or remove it.
    if (f >= 0 && f < static_cast<int>(frame_times_.size()))
      emit seek_requested(frame_times_[static_cast<std::size_t>(f)]);
    emit frame_toggled(f);
  });
  connect(automatic_, &QPushButton::clicked, this, [this] { emit automatic_requested(false); });
  connect(every_, &QPushButton::clicked, this, [this] { emit automatic_requested(true); });
  set_document(nullptr);
}

void CapturePanel::set_document(const Document* d) {
  const CaptureFile* capture = d && d->loaded() ? d->capture() : nullptr;
  for (QWidget* w : std::initializer_list<QWidget*>{strip_, automatic_, every_, settings_})
    w->setEnabled(capture != nullptr);
  // Later: a fix's button may be the one whose click brought the new document.
  while (QLayoutItem* item = fixes_->takeAt(0)) {
    if (QWidget* w = item->widget()) {
      w->hide();
      w->deleteLater();
    }
    delete item;
  }
  if (capture) {
    for (const CaptureFix& fix : capture_fixes(*capture, d->capture_options())) {
      auto* button = new QPushButton(qstr(fix.label), this);
      // A long label must not widen the panel's column.
      button->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
      button->setObjectName("capture_fix");
      button->setToolTip(qstr(fix.reason) + "\n(" + qstr(fix.flag) + ")");
      const CaptureFileOptions options = fix.options;
      connect(button, &QPushButton::clicked, this,
              [this, options] { emit reimport_requested(options); });
      fixes_->addWidget(button);
    }
  }
  if (!capture) {
    summary_->setText(
        tr("No motion capture: this motion was opened from a motion file. File > Import motion "
           "capture… (or open or drop a .bvh file) imports one onto the body model; its "
           "keyframes are then picked here."));
    warnings_->clear();
    pick_->clear();
    frame_times_.clear();
    strip_->set_frames({}, {});
    return;
  }
  const CaptureImport& im = capture->import;
  const FlightPhase& f = im.flight;
  const ForceMetrics residual = force_metrics(d->capture_plot_samples());
  const BodyModel& model = d->file().model;
  const double l_mean = im.angular_momentum.mean.norm();
  QString text =
      tr("<b>%1</b>: %2 frames at %3 s (%4 frames a second), %5 joints mapped by %6 onto %7.")
          .arg(QFileInfo(qstr(capture->path)).fileName())
          .arg(im.source_frames)
          .arg(im.frame_time, 0, 'g', 4)
          .arg(1.0 / im.frame_time, 0, 'f', 1)
          .arg(im.source_joints)
          .arg(qstr(im.retargeting.mapping.convention.empty() ? std::string("names")
                                                              : im.retargeting.mapping.convention))
          .arg(qstr(model.name));
  text += "<br>" + tr("Flight: clip frames %1–%2, lift-off %3 s, touch-down %4 s (%5); "
                      "%6 of somersault %7.")
                       .arg(f.first_frame)
                       .arg(f.last_frame)
                       .arg(f.liftoff_time, 0, 'f', 3)
                       .arg(f.touchdown_time, 0, 'f', 3)
                       .arg(qstr(f.method))
                       .arg(QString::number(std::abs(im.somersault_flight_deg), 'f', 0) + "°")
                       .arg(im.somersault_flight_deg < 0 ? tr("backward") : tr("forward"));
  text += "<br>" + tr("Take-off: CoM on a parabola within %1 cm RMS; the CoM's flight implies "
                      "gravity %2 m/s²; angular momentum %3 kg·m²/s on average, varying by up to "
                      "%4 kg·m²/s.")
                       .arg(100 * im.takeoff_fit.rms_residual_m, 0, 'f', 1)
                       .arg(im.implied_gravity, 0, 'f', 2)
                       .arg(l_mean, 0, 'f', 1)
                       .arg(im.angular_momentum.max_deviation, 0, 'f', 1);
  text += "<br>" + tr("The capture's own residual (grey figure, grey-green curves): average root "
                      "force %1 N (%2 % of body weight).")
                       .arg(residual.avg_root_force, 0, 'g', 3)
                       .arg(percent_of_body_weight(residual.avg_root_force, model), 0, 'f', 1);
  summary_->setText(text);
  QStringList warnings;
  for (const std::string& w : im.warnings)
    warnings << "⚠ " + qstr(w);
  warnings_->setText(warnings.join("<br>"));

  const Motion& motion = d->file().motion;
  const std::vector<int> picked = capture_frames_in(motion, *capture);
  frame_times_.clear();
  for (const Keyframe& k : im.captured.keyframes)
    frame_times_.push_back(k.time);
  strip_->set_frames(frame_times_, picked);
  QString pick = tr("%1 of %2 flight frames are keyframes")
                     .arg(picked.size())
                     .arg(im.captured.keyframes.size());
  const std::size_t others = motion.keyframes.size() - picked.size();
  if (others > 0) pick += tr(", and %1 keyframes at other times").arg(others);
  if (!picked.empty() && picked.front() == 0) {
    const KeyframePick errors = capture_pick_errors(*capture, picked);
    pick += tr(". Interpolated through these captured frames, the motion misses the capture by "
               "at most %1°")
                .arg(errors.max_rotation_error_deg, 0, 'f', 1);
    pick += errors.max_rotation_error_deg >= 0.05
                ? tr(" (at flight frame %1).").arg(errors.worst_frame + 1)
                : QString(".");
  } else {
    pick += ".";
  }
  pick_->setText(pick);
}

void CapturePanel::set_time(double t) {
  strip_->set_time(t);
}

void CapturePanel::show_problem(const QString& message) {
  problem_->setText(message);
}

QString CapturePanel::problem() const {
  return problem_->text();
}

std::vector<QPushButton*> CapturePanel::fix_buttons() const {
  std::vector<QPushButton*> out;
  for (int i = 0; i < fixes_->count(); ++i)
    if (auto* button = qobject_cast<QPushButton*>(fixes_->itemAt(i)->widget()))
      out.push_back(button);
  return out;
}

QString CapturePanel::summary() const {
  return summary_->text();
}

QString CapturePanel::pick_text() const {
  return pick_->text();
}

}  // namespace saltus::gui
