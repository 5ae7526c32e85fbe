#include "app/what_if_panel.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QMetaObject>
#include <QPushButton>
#include <QSlider>
#include <QVBoxLayout>
#include <chrono>
#include <exception>

#include "app/qt_text.h"

namespace saltus::gui {

namespace {

/// The sentence's size relative to the panel's text: read from a step back.
constexpr double kWhatIfSentenceScale = 1.3;

bool same_what_if_change(const WhatIfChange& a, const WhatIfChange& b) {
  return a.tuck_later_s == b.tuck_later_s && a.open_later_s == b.open_later_s &&
         a.tuck_scale == b.tuck_scale;
}

QSlider* make_what_if_slider(QWidget* parent, const char* name, const QString& tip) {
  auto* slider = new QSlider(Qt::Horizontal, parent);
  slider->setObjectName(name);
  slider->setSingleStep(1);
  slider->setPageStep(5);
  slider->setTickPosition(QSlider::TicksBelow);
  slider->setTickInterval(5);
  slider->setToolTip(tip);
  return slider;
}

void set_what_if_grey(QLabel* label, bool grey) {
  QPalette p = label->palette();
  p.setColor(QPalette::WindowText, grey ? QColor(120, 120, 120) : QColor(0, 0, 0));
  label->setPalette(p);
}

}  // namespace

WhatIfPanel::WhatIfPanel(AppContext& context, QWidget* parent)
    : QWidget(parent), context_(context) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(8, 6, 8, 6);

  layout->addWidget(new QLabel(tr("<b>What if…</b> the same take-off, another tuck"), this));
  subject_ = new QLabel(this);
  subject_->setObjectName("what_if_subject");
  subject_->setWordWrap(true);
  set_what_if_grey(subject_, true);
  layout->addWidget(subject_);
  tuck_text_ = new QLabel(this);
  tuck_text_->setObjectName("what_if_tuck");
  tuck_text_->setWordWrap(true);
  tuck_text_->setToolTip(
      tr("The tuck (or pike) is read off the legs' bend, the mean angle of the hips and knees from "
         "straight: the tuck-in from 10 % to 90 % of its rise above take-off, the opening from "
         "90 % to 10 % of its fall. Straight and layout motions have none."));
  layout->addWidget(tuck_text_);

  const auto row = [&](const QString& title, QSlider* slider, QLabel*& value) {
    auto* line = new QHBoxLayout;
    auto* name = new QLabel(title, this);
    line->addWidget(name);
    line->addStretch(1);
    value = new QLabel(this);
    line->addWidget(value);
    layout->addLayout(line);
    layout->addWidget(slider);
  };
  tuck_ =
      make_what_if_slider(this, "what_if_tuck_slider",
                          tr("Moves the tuck-in earlier or later, in steps of 0.01 s: the movement "
                             "keeps its speed, the phases before it and the hold in the tuck are "
                             "stretched or compressed."));
  open_ =
      make_what_if_slider(this, "what_if_open_slider",
                          tr("Moves the opening earlier or later, in steps of 0.01 s: the movement "
                             "keeps its speed, the hold in the tuck and the phase after it are "
                             "stretched or compressed."));
  tightness_ =
      make_what_if_slider(this, "what_if_tightness_slider",
                          tr("How far the hips and knees turn from their take-off pose, in % of "
                             "the motion's, at every instant: more is a tighter tuck."));
  row(tr("Tuck"), tuck_, tuck_value_);
  row(tr("Opening"), open_, open_value_);
  row(tr("Tuck tightness"), tightness_, tightness_value_);
  const SliderSteps tightness = tightness_slider_steps();
  tightness_->setRange(tightness.min, tightness.max);
  tightness_->setValue(100);
  for (QSlider* slider : {tuck_, open_, tightness_})
    connect(slider, &QSlider::valueChanged, this, &WhatIfPanel::on_slider);

  reset_ = new QPushButton(tr("Reset"), this);
  reset_->setObjectName("what_if_reset");
  reset_->setToolTip(tr("Back to the motion as keyframed"));
  connect(reset_, &QPushButton::clicked, this, &WhatIfPanel::reset);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(reset_);
  buttons->addStretch(1);
  layout->addLayout(buttons);

  sentence_ = new QLabel(this);
  sentence_->setObjectName("what_if_sentence");
  sentence_->setWordWrap(true);
  sentence_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  QFont big = sentence_->font();
  big.setPointSizeF(big.pointSizeF() * kWhatIfSentenceScale);
  sentence_->setFont(big);
  layout->addWidget(sentence_);
  reference_ = new QLabel(this);
  reference_->setObjectName("what_if_reference");
  reference_->setWordWrap(true);
  layout->addWidget(reference_);
  timing_ = new QLabel(this);
  timing_->setObjectName("what_if_timing");
  timing_->setWordWrap(true);
  set_what_if_grey(timing_, true);
  layout->addWidget(timing_);
  auto* method = new QLabel(
      tr("Same take-off: the same velocity, angular momentum, orientation and pose at take-off; "
         "the joints move as changed and the body turns as Newton's laws say (a free flight). "
         "The gold figure beside the athlete flies it."),
      this);
  method->setWordWrap(true);
  QFont small = method->font();
  small.setPointSizeF(small.pointSizeF() * 0.9);
  method->setFont(small);
  set_what_if_grey(method, true);
  layout->addWidget(method);
  layout->addStretch(1);

  set_sliders(nullptr);
  context_.workspace().subscribe([this](WorkspaceChange change) {
    if (change != WorkspaceChange::kSaved) refresh();
  });
  refresh();
}

WhatIfPanel::~WhatIfPanel() {
  if (thread_.joinable()) thread_.join();
}

void WhatIfPanel::set_active(bool active) {
  if (active_ == active) return;
  active_ = active;
  if (active && busy()) {
    if (!shown_) show_message(tr("Flying the motion as it is…"));
    // Asked for now: the change may have been made while out of view.
    since_change_.restart();
    start();
  }
  emit flight_changed();
}

WhatIfChange WhatIfPanel::change() const {
  return change_at(tuck_->value(), open_->value(), tightness_->value());
}

bool WhatIfPanel::wanted_now(const Request& request) const {
  return subject_now_ && request.key == subject_now_->key &&
         same_what_if_change(request.change, change());
}

bool WhatIfPanel::busy() const {
  if (!subject_now_) return false;
  if (!prepare_error_.isEmpty()) return false;  // the library's message is the answer
  return !(answered_ && wanted_now(*answered_));
}

QString WhatIfPanel::sentence() const {
  return sentence_->text();
}

QString WhatIfPanel::subject() const {
  return subject_->text();
}

QString WhatIfPanel::tuck() const {
  return tuck_text_->text();
}

const SimulationResult* WhatIfPanel::flight() const {
  return active_ && shown_ ? &shown_->flight : nullptr;
}

QString WhatIfPanel::flight_label() const {
  if (!shown_) return QString();
  if (shown_->change.unchanged()) return tr("flown as it is");
  return tr("what if: %1").arg(qstr(shown_->change_words));
}

void WhatIfPanel::refresh() {
  std::optional<ShownMotion> subject =
      shown_motion_subject(context_.workspace(), SavedTrajectory::kFlown);
  if (subject && subject_now_ && subject->key == subject_now_->key) return;
  // Another motion (or none): nothing of the previous one stays on screen.
  subject_now_ = std::move(subject);
  prepared_.reset();
  prepare_error_.clear();
  shown_.reset();
  answered_.reset();
  latencies_ms_.clear();
  last_latency_ms_ = 0.0;
  set_sliders(nullptr);
  reference_->clear();
  timing_->clear();
  if (!subject_now_) {
    subject_->clear();
    tuck_text_->clear();
    show_message(tr("Open a motion to ask what if."));
    emit flight_changed();
    return;
  }
  subject_->setText(tr("For %1.").arg(qstr(subject_now_->description)));
  tuck_text_->setText(tr("Finding the tuck…"));
  show_message(active_ ? tr("Flying the motion as it is…")
                       : tr("Shown when this panel is in view."));
  emit flight_changed();
  request();
}

void WhatIfPanel::set_sliders(const TuckPhases* tuck) {
  setting_sliders_ = true;
  const SliderSteps none{0, 0};
  const SliderSteps tuck_steps =
      tuck && tuck->found ? shift_slider_steps(tuck->tuck_later_min_s, tuck->tuck_later_max_s)
                          : none;
  const SliderSteps open_steps =
      tuck && tuck->found && tuck->opens
          ? shift_slider_steps(tuck->open_later_min_s, tuck->open_later_max_s)
          : none;
  tuck_->setRange(tuck_steps.min, tuck_steps.max);
  open_->setRange(open_steps.min, open_steps.max);
  tuck_->setValue(0);
  open_->setValue(0);
  tightness_->setValue(100);
  tuck_->setEnabled(tuck_steps.min < tuck_steps.max);
  open_->setEnabled(open_steps.min < open_steps.max);
  tightness_->setEnabled(tuck && tuck->found);
  reset_->setEnabled(tuck && tuck->found);
  setting_sliders_ = false;
  update_slider_texts();
}

void WhatIfPanel::update_slider_texts() {
  const WhatIfChange c = change();
  tuck_value_->setText(qstr(shift_text(c.tuck_later_s)));
  open_value_->setText(qstr(shift_text(c.open_later_s)));
  tightness_value_->setText(qstr(tightness_text(tightness_->value())));
}

void WhatIfPanel::on_slider() {
  if (setting_sliders_) return;
  update_slider_texts();
  request();
}

void WhatIfPanel::reset() {
  setting_sliders_ = true;
  tuck_->setValue(0);
  open_->setValue(0);
  tightness_->setValue(100);
  setting_sliders_ = false;
  update_slider_texts();
  request();
}

void WhatIfPanel::request() {
  if (!subject_now_) return;
  since_change_.restart();
  if (!busy()) {
    // Already on screen (a slider moved and back): the answer shown is this one's again.
    set_what_if_grey(sentence_, false);
    timing_->clear();
    return;
  }
  if (shown_) {
    set_what_if_grey(sentence_, true);
    timing_->setText(tr("Working out %1…").arg(qstr(what_if_change_words(change()))));
  }
  start();
}

void WhatIfPanel::start() {
  if (running_ || !active_ || !subject_now_ || !busy()) return;
  if (thread_.joinable()) thread_.join();
  running_ = true;
  const Request asked{subject_now_->key, change()};
  // The motion is prepared once (its tuck, take-off and unchanged flight), then each change is
  // one flight; the prepared object is only read, so it can be shared with the worker.
  std::shared_ptr<const WhatIf> prepared = prepared_;
  std::optional<ShownMotion> subject;
  if (!prepared) subject = *subject_now_;
  thread_ = std::thread([this, asked, prepared, subject] {
    auto done = std::make_shared<Done>();
    done->request = asked;
    try {
      done->prepared = prepared ? prepared
                                : std::make_shared<const WhatIf>(subject->motion, subject->model,
                                                                 subject->options);
      const auto begin = std::chrono::steady_clock::now();
      done->result = done->prepared->fly(asked.change);
      done->flight_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
              .count();
    } catch (const std::exception& e) {
      done->error = qstr(e.what());
    }
    // Runs on the GUI thread; dropped if the panel is gone (its destructor joins this thread).
    QMetaObject::invokeMethod(
        this, [this, done] { on_finished(std::move(*done)); }, Qt::QueuedConnection);
  });
}

void WhatIfPanel::on_finished(Done done) {
  if (thread_.joinable()) thread_.join();
  running_ = false;
  if (!subject_now_ || done.request.key != subject_now_->key) {
    // A flight of a motion no longer shown: never on screen.
    start();
    return;
  }
  if (!prepared_ && done.prepared) {
    prepared_ = done.prepared;
    set_sliders(&prepared_->tuck());
    tuck_text_->setText(qstr(tuck_text(prepared_->tuck())));
    reference_->setText(qstr(reference_text(*prepared_)));
  }
  if (!done.prepared) {
    prepare_error_ = done.error;
    tuck_text_->clear();
    show_message(tr("Cannot fly this motion: %1").arg(done.error));
    emit flight_changed();
    emit result_shown();
    return;
  }
  last_flight_ms_ = done.flight_ms;
  answered_ = done.request;
  if (done.result) {
    shown_ = std::move(done.result);
    show_result(*shown_);
  } else {
    // The sliders only offer changes the library allows: say what it said all the same.
    show_message(done.error);
  }
  if (wanted_now(done.request)) {
    last_latency_ms_ = static_cast<double>(since_change_.nsecsElapsed()) / 1e6;
    latencies_ms_.push_back(last_latency_ms_);
    set_what_if_grey(sentence_, false);
    timing_->setText(tr("Flown in %1 ms; on screen %2 ms after the change.")
                         .arg(last_flight_ms_, 0, 'f', 0)
                         .arg(last_latency_ms_, 0, 'f', 0));
  } else {
    // The sliders moved meanwhile: this answer was for an earlier setting (its sentence says
    // which); the newest one is flown next.
    set_what_if_grey(sentence_, true);
    timing_->setText(tr("Working out %1…").arg(qstr(what_if_change_words(change()))));
    start();
  }
  emit flight_changed();
  emit result_shown();
}

void WhatIfPanel::show_message(const QString& text) {
  sentence_->setText(text);
  set_what_if_grey(sentence_, false);
}

void WhatIfPanel::show_result(const WhatIfResult& result) {
  sentence_->setText(qstr(result.sentence));
  sentence_->setToolTip(
      tr("Landing against the motion as keyframed: somersault %1°, twist %2° (over > 0, short "
         "< 0); against the motion flown as it is: %3°, %4°.")
          .arg(result.somersault_over_deg, 0, 'f', 1)
          .arg(result.twist_over_deg, 0, 'f', 1)
          .arg(result.somersault_vs_unchanged_deg, 0, 'f', 1)
          .arg(result.twist_vs_unchanged_deg, 0, 'f', 1));
}

}  // namespace saltus::gui
