#include "app/optimize_panel.h"

#include "app/option_form.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace saltus::gui {

OptimizePanel::OptimizePanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  // What a run says comes first: Run, its progress, its status and the list of runs stay in
  // view on a 1366×768 screen; the options and the before/after table share the rest, each
  // scrolling when the window is short, so neither sets the window's height.
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
  status_->setObjectName("optimise_status");
  // While a run goes: the time left, and what the objective means (it starts again with each
  // stage, which looks like a failure to anyone who is not told).
  time_left_ = new QLabel(this);
  time_left_->setWordWrap(true);
  time_left_->setObjectName("optimise_time_left");
  objective_ = new QLabel(this);
  objective_->setWordWrap(true);
  objective_->setObjectName("optimise_objective");
  objective_->setStyleSheet("color: #555; font-size: 9pt;");
  layout->addWidget(bar_);
  layout->addWidget(status_);
  layout->addWidget(time_left_);
  layout->addWidget(objective_);
  time_left_->hide();
  objective_->hide();

  auto* runs_title = new QLabel(tr("Runs, best first:"), this);
  runs_title->setToolTip(
      tr("As the optimiser ranks them: solved first, then every joint within its policy (no "
         "joint past 1.5 times its input's peak load), then the least root force"));
  runs_title->setWordWrap(true);
  layout->addWidget(runs_title);
  runs_ = new QListWidget(this);
  runs_->setMinimumHeight(60);
  runs_->setMaximumHeight(110);
  runs_->setWordWrap(true);
  runs_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  runs_->setToolTip(
      tr("Every run is kept. Choose one to show it; a cancelled or failed run "
         "never replaces a solved one by itself."));
  layout->addWidget(runs_);
  connect(runs_, &QListWidget::currentRowChanged, this, [this](int row) {
    // Each row holds its run's index (-1: "interpolation only").
    if (!setting_ && row >= 0) emit run_chosen(runs_->item(row)->data(Qt::UserRole).toInt());
  });

  // The run's before/after table and the options share the rest of the height as two tabs:
  // one under the other, on a 1366×768 laptop the table showed four rows with its quantities
  // cut to "s…". After a run the table is in front, before one the options.
  details_ = new QTabWidget(this);
  table_ = new QTableWidget(0, 3, details_);
  table_->setHorizontalHeaderLabels({tr("Quantity"), tr("Before"), tr("After")});
  table_->verticalHeader()->setVisible(false);
  // Three columns sharing the width, every cell wrapped: a long value (the keyframe times) makes
  // its row taller, never another column narrower.
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  table_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setWordWrap(true);
  table_->setToolTip(tr("Before: the interpolated keyframes; after: the optimised motion"));
  details_->addTab(table_, tr("Before / after"));

  auto* options_page = new QWidget(details_);
  auto* options_layout = new QVBoxLayout(options_page);
  options_layout->setContentsMargins(2, 2, 2, 2);
  auto* options_title = new QLabel(tr("The options of <tt>saltus optimize</tt>:"), options_page);
  options_title->setWordWrap(true);
  options_layout->addWidget(options_title);
  form_ = new OptionForm;
  auto* options = new QScrollArea(options_page);
  options->setWidget(form_);
  options->setWidgetResizable(true);
  options->setFrameShape(QFrame::NoFrame);
  options->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  options_layout->addWidget(options, 1);
  details_->addTab(options_page, tr("Options"));
  details_->setCurrentWidget(options_page);
  details_->setMinimumHeight(140);
  layout->addWidget(details_, 1);

  connect(run_, &QPushButton::clicked, this, &OptimizePanel::run_requested);
  connect(cancel_, &QPushButton::clicked, this, &OptimizePanel::cancel_requested);
  connect(form_, &OptionForm::edited, this, &OptimizePanel::settings_edited);
  set_settings(OptimizeSettings{});
  reset();
  update_enabled();
}

OptimizeSettings OptimizePanel::settings() const {
  return form_->values();
}

void OptimizePanel::set_settings(const OptimizeSettings& s) {
  form_->set_values(s);
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
    // How many iterations a run needs is unknown (most solve far below the limit): a busy bar,
    // the stage and the iteration count, and the time left as a range from the run's own pace,
    // not a fraction of the limit.
    const OptimizeSettings s = settings();
    progress_ = RunProgress(s.real("joint_load_weight") > 0 &&
                            std::get<std::string>(s.get("formulation")) == "relaxed");
    bar_->setRange(0, 0);
    status_->setText(tr("Building the problem (first derivatives)…"));
    time_left_->setText(QString::fromStdString(progress_.time_left_line()));
    time_left_->show();
    objective_->hide();
  } else {
    bar_->setRange(0, 1);
    bar_->setValue(1);
    time_left_->hide();
    objective_->hide();
  }
  update_enabled();
}

void OptimizePanel::show_progress(const ProgressInfo& progress) {
  progress_.add(progress);
  bar_->setFormat(tr("iteration %1").arg(progress.iteration));
  status_->setText(
      QString::fromStdString("<b>" + progress_.stage_line() + "</b><br>" + progress_.count_line()));
  time_left_->setText(QString::fromStdString(progress_.time_left_line()));
  objective_->setText(QString::fromStdString(progress_.objective_line()));
  objective_->show();
}

void OptimizePanel::show_message(const QString& message) {
  status_->setText(message);
  if (!running_) bar_->setFormat(message.section(':', 0, 0));
}

QString OptimizePanel::message() const {
  return status_->text();
}

void OptimizePanel::show_runs(const std::vector<RunRow>& runs, int shown) {
  setting_ = true;
  runs_->clear();
  runs_->addItem(tr("Interpolated keyframes only (no run shown)"));
  runs_->item(0)->setData(Qt::UserRole, -1);
  for (const RunRow& run : runs) {
    auto* item = new QListWidgetItem(QString::fromStdString(run.label), runs_);
    item->setData(Qt::UserRole, run.index);
    item->setToolTip(QString::fromStdString(run.details));
  }
  runs_->setCurrentRow(std::max(0, row_of_run(shown)));
  runs_->setEnabled(!runs.empty());
  setting_ = false;
}

int OptimizePanel::row_of_run(int index) const {
  for (int row = 0; row < runs_->count(); ++row)
    if (runs_->item(row)->data(Qt::UserRole).toInt() == index) return row;
  return -1;
}

void OptimizePanel::reset() {
  clear_result();
  show_runs({}, -1);
  time_left_->hide();
  objective_->hide();
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
  details_->setCurrentWidget(table_);
}

void OptimizePanel::clear_result() {
  table_->setRowCount(0);
  details_->setCurrentIndex(1);
}

void OptimizePanel::update_enabled() {
  const bool idle = !running_;
  form_->set_editable(idle);
  run_->setEnabled(idle && available_);
  cancel_->setEnabled(running_);
}

}  // namespace saltus::gui
