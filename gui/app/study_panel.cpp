#include "app/study_panel.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include "app/chart_widget.h"
#include "app/qt_text.h"

namespace saltus::gui {

namespace {

QString clock_qtext(double seconds) {
  return qstr(clock_text(seconds));
}

QTableWidget* make_study_table(QWidget* parent, const char* name) {
  auto* table = new QTableWidget(parent);
  table->setObjectName(name);
  table->verticalHeader()->hide();
  table->setWordWrap(false);
  table->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
  table->verticalHeader()->setDefaultSectionSize(table->fontMetrics().height() + 5);
  table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table->setSelectionBehavior(QAbstractItemView::SelectRows);
  table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table->horizontalHeader()->setStretchLastSection(true);
  return table;
}

/// Fills `table` with `text`; cells from column `first_number` on are numbers, right-aligned.
void fill_study_table(QTableWidget* table, const TextTable& text, int first_number) {
  table->clear();
  table->setColumnCount(static_cast<int>(text.headings.size()));
  table->setRowCount(static_cast<int>(text.rows.size()));
  for (std::size_t c = 0; c < text.headings.size(); ++c) {
    auto* heading = new QTableWidgetItem(qstr(text.headings[c]));
    if (c < text.tooltips.size()) heading->setToolTip(qstr(text.tooltips[c]));
    table->setHorizontalHeaderItem(static_cast<int>(c), heading);
  }
  for (std::size_t r = 0; r < text.rows.size(); ++r)
    for (std::size_t c = 0; c < text.rows[r].size(); ++c) {
      auto* item = new QTableWidgetItem(qstr(text.rows[r][c]));
      if (static_cast<int>(c) >= first_number)
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      table->setItem(static_cast<int>(r), static_cast<int>(c), item);
    }
  table->resizeColumnsToContents();
}

/// The size that shows every row and column of `table` without scrolling.
QSize table_size(const QTableWidget* table) {
  int width = 2 * table->frameWidth();
  for (int c = 0; c < table->columnCount(); ++c)
    width += table->horizontalHeader()->sectionSize(c);
  const int height = 2 * table->frameWidth() + table->horizontalHeader()->sizeHint().height() +
                     table->rowCount() * table->verticalHeader()->defaultSectionSize();
  return {width, height};
}

}  // namespace

StudyPanel::StudyPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(8, 6, 8, 6);

  title_ = new QLabel(tr("<b>No study yet</b>"), this);
  title_->setObjectName("study_title");
  title_->setWordWrap(true);
  layout->addWidget(title_);
  folder_ = new QLabel(
      tr("Optimise > Convergence study of this motion… runs the paper's experiment on the open "
         "motion; its progress and results show here."),
      this);
  folder_->setObjectName("study_folder");
  folder_->setWordWrap(true);
  folder_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  QPalette grey = folder_->palette();
  grey.setColor(QPalette::WindowText, QColor(90, 90, 90));
  folder_->setPalette(grey);
  layout->addWidget(folder_);

  bar_ = new QProgressBar(this);
  bar_->setObjectName("study_progress");
  bar_->setRange(0, 1);
  bar_->setValue(0);
  bar_->hide();
  layout->addWidget(bar_);
  progress_ = new QLabel(this);
  progress_->setObjectName("study_progress_text");
  progress_->setWordWrap(true);
  layout->addWidget(progress_);
  last_ = new QLabel(this);
  last_->setObjectName("study_last_case");
  last_->setWordWrap(true);
  last_->setPalette(grey);
  layout->addWidget(last_);
  stop_ = new QPushButton(tr("Stop (keep finished cases)"), this);
  stop_->setObjectName("study_stop");
  stop_->setToolTip(
      tr("Stops the study as Ctrl+C does: the finished cases stay in FOLDER.partial, and running "
         "the study into the same folder again offers to resume"));
  stop_->hide();
  connect(stop_, &QPushButton::clicked, this, &StudyPanel::stop_requested);
  layout->addWidget(stop_);
  outcome_ = new QLabel(this);
  outcome_->setObjectName("study_outcome");
  outcome_->setWordWrap(true);
  outcome_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(outcome_);

  results_ = new QWidget(this);
  auto* results = new QVBoxLayout(results_);
  results->setContentsMargins(0, 4, 0, 0);
  results_line_ = new QLabel(results_);
  results_line_->setObjectName("study_results_line");
  results_line_->setWordWrap(true);
  results->addWidget(results_line_);
  chart_ = new ChartWidget(results_);
  chart_->setObjectName("study_chart");
  chart_->setMinimumHeight(190);
  results->addWidget(chart_);
  auto* buttons = new QHBoxLayout;
  open_folder_ = new QPushButton(tr("Open folder"), results_);
  open_folder_->setObjectName("study_open_folder");
  open_folder_->setToolTip(tr("Shows the study's folder in the file manager"));
  connect(open_folder_, &QPushButton::clicked, this, &StudyPanel::open_folder_requested);
  open_report_ = new QPushButton(tr("Open report"), results_);
  open_report_->setObjectName("study_open_report");
  open_report_->setToolTip(tr("Opens convergence.md, the study's report"));
  connect(open_report_, &QPushButton::clicked, this, &StudyPanel::open_report_requested);
  buttons->addWidget(open_folder_);
  buttons->addWidget(open_report_);
  buttons->addStretch(1);
  results->addLayout(buttons);
  auto* where = new QLabel(tr("The summary and every case: the Study results tab under the 3D "
                              "view."),
                           results_);
  where->setWordWrap(true);
  where->setPalette(grey);
  results->addWidget(where);

  // The tables, for the tab under the 3D view (the main window puts them there).
  tables_ = new QWidget(this);
  tables_->setObjectName("study_tables");
  auto* tables = new QHBoxLayout(tables_);
  tables->setContentsMargins(2, 2, 2, 2);
  auto* summary_box = new QVBoxLayout;
  summary_box->addWidget(new QLabel(tr("Summary per model (convergence.md)"), tables_));
  summary_ = make_study_table(tables_, "study_summary");
  summary_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  summary_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  summary_->horizontalHeader()->setStretchLastSection(false);
  summary_->setToolTip(
      tr("Per model, the cases solved and the medians over the cases that "
         "finished, as convergence.md has them"));
  summary_box->addWidget(summary_);
  summary_box->addStretch(1);
  tables->addLayout(summary_box);
  auto* cases_box = new QVBoxLayout;
  cases_box->addWidget(new QLabel(tr("Cases (convergence.csv)"), tables_));
  cases_ = make_study_table(tables_, "study_cases");
  cases_box->addWidget(cases_, 1);
  tables->addLayout(cases_box, 1);
  tables_->hide();
  results_->hide();
  layout->addWidget(results_);
  layout->addStretch(1);
}

QString StudyPanel::progress_text(const StudyProgressLine& p) {
  const QString left =
      p.eta_s < 0 ? tr("time left unknown") : tr("about %1 left").arg(clock_qtext(p.eta_s));
  return tr("%1 of %2 cases · %3 failed · %4 not solved · %5 elapsed · %6")
      .arg(p.done)
      .arg(p.total)
      .arg(p.failed)
      .arg(p.unsolved)
      .arg(clock_qtext(p.elapsed_s), left);
}

void StudyPanel::show_started(const QString& title, const QString& folder,
                              const QString& first_words) {
  clear_results();
  title_->setText("<b>" + title.toHtmlEscaped() + "</b>");
  folder_->setText(tr("into %1").arg(folder));
  bar_->setRange(0, 0);  // busy until the first case reports the total
  bar_->setValue(0);
  bar_->show();
  progress_->setText(first_words);
  progress_->show();
  last_->clear();
  last_->show();
  outcome_->clear();
  stop_->setEnabled(true);
  stop_->show();
}

void StudyPanel::show_progress(const StudyProgressLine& p) {
  bar_->setRange(0, p.total);
  bar_->setValue(p.done);
  progress_->setText(progress_text(p));
  last_->setText(tr("last: %1 — %2").arg(qstr(p.last_case), qstr(p.last_result)));
}

void StudyPanel::show_ended(const QString& outcome, bool failure) {
  // The outcome says how many cases; the time left and the last case are over.
  stop_->hide();
  progress_->hide();
  last_->hide();
  outcome_->setText(outcome);
  QPalette palette = outcome_->palette();
  palette.setColor(QPalette::WindowText, failure ? QColor(170, 20, 20) : QColor(0, 0, 0));
  outcome_->setPalette(palette);
}

void StudyPanel::show_results(const ConvergenceStudyFolder& folder) {
  results_line_->setText(qstr(study_folder_line(folder)));
  fill_study_table(summary_, study_summary_table(folder), 1);
  fill_study_table(cases_, study_case_table(folder), 2);
  summary_->setFixedSize(table_size(summary_));
  chart_->set_chart(study_solved_chart(folder));
  open_report_->setEnabled(!folder.markdown_path.empty());
  results_->show();
}

void StudyPanel::clear_results() {
  results_->hide();
  summary_->setRowCount(0);
  cases_->setRowCount(0);
  results_line_->clear();
}

}  // namespace saltus::gui
