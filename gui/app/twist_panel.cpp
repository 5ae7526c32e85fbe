#include "app/twist_panel.h"

#include <QHeaderView>
#include <QLabel>
#include <QMetaObject>
#include <QTableWidget>
#include <QVBoxLayout>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>

#include "app/chart_widget.h"
#include "app/legend_strip.h"
#include "app/qt_text.h"

namespace saltus::gui {

namespace {

/// Results kept: the interpolated motion and a few runs of it.
constexpr std::size_t kCachedResults = 6;
/// The sentence's size relative to the panel's text: read from a step back.
constexpr double kSentenceScale = 1.35;

}  // namespace

TwistPanel::TwistPanel(AppContext& context, QWidget* parent) : QWidget(parent), context_(context) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(8, 6, 8, 6);

  auto* title = new QLabel(tr("<b>Where does the twist come from?</b>"), this);
  layout->addWidget(title);
  subject_ = new QLabel(this);
  subject_->setObjectName("twist_subject");
  subject_->setWordWrap(true);
  QPalette grey = subject_->palette();
  grey.setColor(QPalette::WindowText, QColor(90, 90, 90));
  subject_->setPalette(grey);
  subject_->setToolTip(
      tr("The library flies the keyframes' interpolation of this motion: for a run, its keyframes "
         "at their optimised times with its own take-off state, as saltus analyse twist does "
         "with the run's optimized.motion.json"));
  layout->addWidget(subject_);

  sentence_ = new QLabel(this);
  sentence_->setObjectName("twist_sentence");
  sentence_->setWordWrap(true);
  sentence_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  QFont big = sentence_->font();
  big.setPointSizeF(big.pointSizeF() * kSentenceScale);
  sentence_->setFont(big);
  layout->addWidget(sentence_);
  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  layout->addWidget(summary_);

  table_ = new QTableWidget(0, 3, this);
  table_->setObjectName("twist_table");
  table_->setHorizontalHeaderLabels({tr("Source"), tr("Tilt"), tr("Share")});
  table_->horizontalHeaderItem(1)->setToolTip(
      tr("Its share of the tilt at mid-flight, degrees, counted in the direction of the total "
         "tilt: below 0 it works against it"));
  table_->horizontalHeaderItem(2)->setToolTip(
      tr("Of the total tilt at mid-flight; below 0 it works against it"));
  table_->verticalHeader()->hide();
  // One line a row, all rows in view: the table never scrolls.
  table_->setWordWrap(false);
  table_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
  table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 5);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionMode(QAbstractItemView::NoSelection);
  table_->setFocusPolicy(Qt::NoFocus);
  table_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  table_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
  layout->addWidget(table_);

  method_ = new QLabel(
      tr("A share is the tilt a movement adds: lost when it is made symmetric, averaged over the "
         "orders of making them symmetric (same take-off). The shares add up to the total."),
      this);
  method_->setWordWrap(true);
  method_->setToolTip(
      tr("A movement made symmetric: an arm replaced by the mean of itself and the other arm's "
         "mirror image, legs and trunk likewise. The take-off's share is the tilt left with "
         "every movement symmetric. Each movement's share is its Shapley value, so that an "
         "asymmetry between the two arms is shared between them. (Yeadon's counterfactual free "
         "flights.)"));
  QFont small = method_->font();
  small.setPointSizeF(small.pointSizeF() * 0.9);
  method_->setFont(small);
  layout->addWidget(method_);

  chart_ = new ChartWidget(this);
  chart_->setMinimumHeight(220);
  chart_box_ = with_legend_strip(chart_, this);
  layout->addWidget(chart_box_, 1);
  // With no chart to show (nothing to twist with) the lines stay together at the top, not
  // spread down the column.
  layout->addStretch(0);
  connect(chart_, &ChartWidget::seek_requested, this, &TwistPanel::seek_requested);

  context_.workspace().subscribe([this](WorkspaceChange change) {
    if (change != WorkspaceChange::kSaved) refresh();
  });
  refresh();
}

TwistPanel::~TwistPanel() {
  if (thread_.joinable()) thread_.join();
}

void TwistPanel::set_active(bool active) {
  active_ = active;
  if (active) refresh();
}

void TwistPanel::set_time(double t) {
  chart_->set_cursor(t);
}

bool TwistPanel::busy() const {
  return wanted_ && !cached(*wanted_);
}

QString TwistPanel::sentence() const {
  return sentence_->text();
}

QString TwistPanel::subject() const {
  return subject_->text();
}

const TwistPanel::Result* TwistPanel::cached(const ShownMotion::Key& key) const {
  for (const Result& r : cache_)
    if (r.key == key) return &r;
  return nullptr;
}

void TwistPanel::refresh() {
  const std::optional<ShownMotion> subject =
      shown_motion_subject(context_.workspace(), SavedTrajectory::kReinterpolated);
  if (!subject) {
    wanted_.reset();
    subject_->clear();
    show_message(tr("Open a motion to see where its twist comes from."));
    return;
  }
  wanted_ = subject->key;
  subject_->setText(tr("For %1").arg(qstr(subject->description)));
  if (const Result* r = cached(subject->key)) {
    show_result(*r);
    return;
  }
  // Never the numbers of another motion: cleared until this one's are ready.
  show_message(active_ || running_ ? tr("Working out where the twist comes from…")
                                   : tr("Shown when this panel is in view."));
  if (active_ && !running_) start(*subject);
}

void TwistPanel::start(const ShownMotion& subject) {
  if (thread_.joinable()) thread_.join();
  running_ = subject.key;
  thread_ = std::thread([this, subject] {
    const auto begin = std::chrono::steady_clock::now();
    auto result = std::make_shared<Result>();
    result->key = subject.key;
    try {
      result->sources = twist_sources(subject.motion, subject.model, subject.options);
    } catch (const std::exception& e) {
      result->error = qstr(e.what());
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    // Runs on the GUI thread; dropped if the panel is gone (its destructor joins this thread).
    QMetaObject::invokeMethod(
        this, [this, result, seconds] { on_finished(std::move(*result), seconds); },
        Qt::QueuedConnection);
  });
}

void TwistPanel::on_finished(Result result, double seconds) {
  if (thread_.joinable()) thread_.join();
  running_.reset();
  last_seconds_ = seconds;
  cache_.push_back(std::move(result));
  if (cache_.size() > kCachedResults) cache_.erase(cache_.begin());
  const Result& done = cache_.back();
  if (wanted_ && done.key == *wanted_) {
    show_result(done);
    return;
  }
  // The motion changed meanwhile: that result waits in the cache; work out the one shown now.
  refresh();
}

void TwistPanel::show_message(const QString& text) {
  sentence_->setText(text);
  summary_->clear();
  summary_->hide();
  table_->setRowCount(0);
  table_->hide();
  method_->hide();
  chart_box_->hide();
  chart_->set_chart(ChartSpec{});
}

void TwistPanel::show_result(const Result& result) {
  if (!result.sources) {
    show_message(tr("Cannot work out where the twist comes from: %1").arg(result.error));
    emit result_shown();
    return;
  }
  const TwistReport report = twist_report(*result.sources);
  // "101 %" kept on one line.
  sentence_->setText(qstr(report.sentence).replace(" %", QString(QChar(0x00A0)) + "%"));
  summary_->setText(qstr(report.summary));
  summary_->show();
  if (!report.tilted) {
    // Nothing to share out: the sentence says so, without a table of zeros.
    table_->setRowCount(0);
    table_->hide();
    method_->hide();
    chart_box_->hide();
    chart_->set_chart(ChartSpec{});
    emit result_shown();
    return;
  }
  table_->setRowCount(static_cast<int>(report.rows.size()));
  for (std::size_t i = 0; i < report.rows.size(); ++i) {
    const TwistRow& row = report.rows[i];
    const int r = static_cast<int>(i);
    const QStringList cells = {qstr(row.label), qstr(row.tilt_text), qstr(row.percent_text)};
    for (int c = 0; c < 3; ++c) {
      auto* item = new QTableWidgetItem(cells[c]);
      if (c > 0) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      QFont font = item->font();
      font.setBold(row.kind == TwistRow::Kind::kTotal);
      item->setFont(font);
      table_->setItem(r, c, item);
    }
  }
  int height = table_->horizontalHeader()->height() + 2 * table_->frameWidth();
  for (int r = 0; r < table_->rowCount(); ++r)
    height += table_->rowHeight(r);
  table_->setFixedHeight(height);
  table_->show();
  method_->show();
  chart_box_->show();
  chart_->set_chart(report.chart);
  emit result_shown();
}

}  // namespace saltus::gui
