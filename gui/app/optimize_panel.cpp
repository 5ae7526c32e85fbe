#include "app/optimize_panel.h"

#include "app/option_form.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QTableWidget>
#include <QVBoxLayout>

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
  layout->addWidget(bar_);
  layout->addWidget(status_);

  auto* runs_title = new QLabel(tr("Runs of this motion (the best solved one is shown):"), this);
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
  table_->setMinimumHeight(80);
  layout->addWidget(table_, 1);

  auto* options_title = new QLabel(tr("<b>Options</b> (those of <tt>saltus optimize</tt>)"), this);
  options_title->setWordWrap(true);
  layout->addWidget(options_title);
  form_ = new OptionForm;
  auto* options = new QScrollArea(this);
  options->setWidget(form_);
  options->setWidgetResizable(true);
  options->setFrameShape(QFrame::NoFrame);
  options->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  options->setMinimumHeight(100);
  layout->addWidget(options, 2);

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
  form_->set_editable(idle);
  run_->setEnabled(idle && available_);
  cancel_->setEnabled(running_);
}

}  // namespace saltus::gui
