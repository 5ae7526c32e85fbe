#include "app/optimize_panel.h"

#include "app/option_form.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QTableWidget>
#include <QVBoxLayout>

namespace saltus::gui {

OptimizePanel::OptimizePanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  // The table's options scroll when the window is short, so they never set its height.
  form_ = new OptionForm;
  auto* options = new QScrollArea(this);
  options->setWidget(form_);
  options->setWidgetResizable(true);
  options->setFrameShape(QFrame::NoFrame);
  options->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  layout->addWidget(options);

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
  status_ = new QLabel(tr("Open a motion to optimise it."), this);
  status_->setWordWrap(true);
  layout->addWidget(bar_);
  layout->addWidget(status_);

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
  set_settings(OptimizeSettings{});
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
    bar_->setRange(0, std::max(1, form_->values().integer("max_iterations")));
    bar_->setValue(0);
    bar_->setFormat(tr("iteration %v of at most %m"));
    status_->setText(tr("Building the problem (first derivatives)…"));
  }
  update_enabled();
}

void OptimizePanel::show_progress(const ProgressInfo& progress) {
  bar_->setValue(std::min(progress.iteration, bar_->maximum()));
  status_->setText(QString::fromStdString(progress_text(progress)));
}

void OptimizePanel::show_message(const QString& message) {
  status_->setText(message);
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
  bar_->setValue(0);
}

void OptimizePanel::update_enabled() {
  const bool idle = !running_;
  form_->set_editable(idle);
  run_->setEnabled(idle && available_);
  cancel_->setEnabled(running_);
}

}  // namespace saltus::gui
