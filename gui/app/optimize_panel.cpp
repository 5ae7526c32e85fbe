#include "app/optimize_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace saltus::gui {

OptimizePanel::OptimizePanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  formulation_ = new QComboBox(this);
  formulation_->addItem(tr("relaxed (paper)"));
  formulation_->addItem(tr("strict: |F_i| ≤ ε"));
  formulation_->setToolTip(
      tr("Relaxed: the paper's model, keyframes within tolerance, root force minimised.\n"
         "Strict: classic spacetime constraints, every root force/moment component bounded."));
  epsilon_ = new QDoubleSpinBox(this);
  epsilon_->setRange(0.001, 1e6);
  epsilon_->setDecimals(3);
  epsilon_->setSuffix(tr(" N / N·m"));
  epsilon_->setToolTip(tr("Strict model: bound on each |F_i| at every sample"));
  timing_ = new QCheckBox(tr("optimise keyframe times"), this);
  knots_ = new QSpinBox(this);
  knots_->setRange(0, kMaxKnotsPerInterval);
  knots_->setSpecialValueText(tr("auto"));
  knots_->setToolTip(
      tr("Spline knot spans per keyframe interval: auto (chosen from how far the body turns, "
         "then refined where the residual is; the default) or a number (1 = the paper's)"));
  samples_ = new QSpinBox(this);
  samples_->setRange(kMinSamples, 5000);
  samples_->setToolTip(tr("Time samples of the objective on [0, T] (fewer = faster)"));
  iterations_ = new QSpinBox(this);
  iterations_->setRange(0, kMaxIterations);
  iterations_->setToolTip(tr("Ipopt iteration limit"));
  joint_turn_ = new QDoubleSpinBox(this);
  joint_turn_->setRange(0.0, 360.0);
  joint_turn_->setDecimals(0);
  joint_turn_->setSuffix(tr("°"));
  joint_turn_->setSpecialValueText(tr("none"));
  joint_turn_->setToolTip(
      tr("Soft limit on how far a joint turns relative to its parent between two spline control\n"
         "points (or the interpolation's own turn where larger). Without it, light limbs can\n"
         "spin between keyframes at little cost in root force."));
  // Named for tests and style sheets.
  formulation_->setObjectName("formulation");
  epsilon_->setObjectName("epsilon");
  timing_->setObjectName("timing");
  knots_->setObjectName("knots_per_interval");
  samples_->setObjectName("samples");
  iterations_->setObjectName("max_iterations");
  joint_turn_->setObjectName("max_joint_turn");
  // A typed value counts when it is complete (Enter or leaving the box): one undo step each.
  for (QAbstractSpinBox* box : std::initializer_list<QAbstractSpinBox*>{epsilon_, knots_, samples_,
                                                                        iterations_, joint_turn_})
    box->setKeyboardTracking(false);
  form->addRow(tr("Model"), formulation_);
  form->addRow(tr("ε (strict)"), epsilon_);
  form->addRow(QString(), timing_);
  form->addRow(tr("Knots per interval"), knots_);
  form->addRow(tr("Samples"), samples_);
  form->addRow(tr("Max iterations"), iterations_);
  form->addRow(tr("Max joint turn"), joint_turn_);
  layout->addLayout(form);

  auto* buttons = new QHBoxLayout;
  run_ = new QPushButton(tr("Run optimisation"), this);
  run_->setToolTip(tr("Optimise the open motion (Ctrl+R)"));
  cancel_ = new QPushButton(tr("Cancel"), this);
  cancel_->setToolTip(tr("Stop after the current iteration and show that point"));
  buttons->addWidget(run_);
  buttons->addWidget(cancel_);
  layout->addLayout(buttons);
  bar_ = new QProgressBar(this);
  bar_->setTextVisible(true);
  bar_->setRange(0, 1);
  bar_->setValue(0);
  bar_->setFormat(QString());
  status_ = new QLabel(tr("Open a motion to optimise it."), this);
  status_->setWordWrap(true);
  layout->addWidget(bar_);
  layout->addWidget(status_);

  layout->addWidget(new QLabel(tr("Runs of this motion (the best solved one is shown):"), this));
  runs_ = new QListWidget(this);
  runs_->setMaximumHeight(110);
  runs_->setWordWrap(true);
  runs_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  runs_->setToolTip(
      tr("Every run is kept. Choose one to show it; a cancelled or failed run "
         "never replaces a solved one by itself."));
  layout->addWidget(runs_);
  connect(runs_, &QListWidget::currentRowChanged, this, [this](int row) {
    // Row 0 is "interpolation only".
    if (!setting_ && row >= 0) emit run_chosen(row - 1);
  });

  table_ = new QTableWidget(0, 3, this);
  table_->setHorizontalHeaderLabels({tr("Quantity"), tr("Before"), tr("After")});
  table_->verticalHeader()->setVisible(false);
  // Values are short (numbers, one keyframe time per line): they get what they need and the
  // quantity names wrap in the rest.
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setWordWrap(true);
  table_->setToolTip(tr("Before: the interpolated keyframes; after: the optimised motion"));
  layout->addWidget(table_, 1);

  connect(run_, &QPushButton::clicked, this, &OptimizePanel::run_requested);
  connect(cancel_, &QPushButton::clicked, this, &OptimizePanel::cancel_requested);
  connect(formulation_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] {
    update_enabled();
    on_value_changed();
  });
  connect(timing_, &QCheckBox::toggled, this, [this] { on_value_changed(); });
  for (QSpinBox* box : {knots_, samples_, iterations_})
    connect(box, qOverload<int>(&QSpinBox::valueChanged), this, [this] { on_value_changed(); });
  for (QDoubleSpinBox* box : {epsilon_, joint_turn_})
    connect(box, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
            [this] { on_value_changed(); });
  set_settings(OptimizeSettings{});
  reset();
  update_enabled();
}

void OptimizePanel::on_value_changed() {
  if (setting_) return;
  const OptimizeSettings before = current_;
  current_ = settings();
  emit settings_edited(before, current_);
}

OptimizeSettings OptimizePanel::settings() const {
  OptimizeSettings s;
  s.strict = formulation_->currentIndex() == 1;
  s.epsilon = epsilon_->value();
  s.optimize_timing = timing_->isChecked();
  s.knots_per_interval = knots_->value();
  s.samples = samples_->value();
  s.max_iterations = iterations_->value();
  s.max_joint_turn_deg = joint_turn_->value();
  return s;
}

void OptimizePanel::set_settings(const OptimizeSettings& s) {
  setting_ = true;
  formulation_->setCurrentIndex(s.strict ? 1 : 0);
  epsilon_->setValue(s.epsilon);
  timing_->setChecked(s.optimize_timing);
  knots_->setValue(s.knots_per_interval);
  samples_->setValue(s.samples);
  iterations_->setValue(s.max_iterations);
  joint_turn_->setValue(s.max_joint_turn_deg);
  current_ = settings();
  setting_ = false;
  update_enabled();
}

void OptimizePanel::set_available(bool available) {
  if (available && !available_ && !running_) status_->setText(tr("Ready."));
  if (!available) status_->setText(tr("Open a motion to optimise it."));
  available_ = available;
  update_enabled();
}

void OptimizePanel::set_running(bool running) {
  running_ = running;
  if (running) {
    // How many iterations a run needs is unknown (most solve far below the limit): a busy bar
    // and the iteration count, not a fraction of the limit.
    bar_->setRange(0, 0);
    status_->setText(tr("Building the problem (first derivatives)…"));
  } else {
    bar_->setRange(0, 1);
    bar_->setValue(1);
  }
  update_enabled();
}

void OptimizePanel::show_progress(const ProgressInfo& progress) {
  bar_->setFormat(tr("iteration %1").arg(progress.iteration));
  status_->setText(QString::fromStdString(progress_text(progress)));
}

void OptimizePanel::show_message(const QString& message) {
  status_->setText(message);
  if (!running_) bar_->setFormat(message.section(':', 0, 0));
}

QString OptimizePanel::message() const {
  return status_->text();
}

void OptimizePanel::show_runs(const std::vector<std::string>& labels, int shown) {
  setting_ = true;
  runs_->clear();
  runs_->addItem(tr("Interpolated keyframes only (no run shown)"));
  for (const std::string& label : labels) {
    runs_->addItem(QString::fromStdString(label));
    runs_->item(runs_->count() - 1)->setToolTip(QString::fromStdString(label));
  }
  runs_->setCurrentRow(shown + 1);
  runs_->setEnabled(!labels.empty());
  setting_ = false;
}

void OptimizePanel::reset() {
  clear_result();
  show_runs({}, -1);
  bar_->setRange(0, 1);
  bar_->setValue(0);
  bar_->setFormat(QString());
  status_->setText(available_ ? tr("Ready.") : tr("Open a motion to optimise it."));
}

void OptimizePanel::show_result(const std::vector<ResultRow>& rows) {
  table_->setRowCount(static_cast<int>(rows.size()));
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    const ResultRow& row = rows[r];
    table_->setItem(r, 0, new QTableWidgetItem(QString::fromStdString(row.quantity)));
    table_->setItem(r, 1, new QTableWidgetItem(QString::fromStdString(row.before)));
    table_->setItem(r, 2, new QTableWidgetItem(QString::fromStdString(row.after)));
    for (int c = 0; c < 3; ++c)
      table_->item(r, c)->setToolTip(table_->item(r, c)->text());
  }
  table_->resizeRowsToContents();
}

void OptimizePanel::clear_result() {
  table_->setRowCount(0);
}

void OptimizePanel::update_enabled() {
  const bool idle = !running_;
  for (QWidget* w : std::initializer_list<QWidget*>{formulation_, timing_, knots_, samples_,
                                                    iterations_, joint_turn_})
    w->setEnabled(idle);
  epsilon_->setEnabled(idle && formulation_->currentIndex() == 1);
  run_->setEnabled(idle && available_);
  cancel_->setEnabled(running_);
}

}  // namespace saltus::gui
