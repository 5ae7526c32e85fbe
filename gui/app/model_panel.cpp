#include "app/model_panel.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>
#include <limits>

#include "app/verdict_text.h"
#include "core/model_edit.h"
#include "saltus/body/segment_names.h"

namespace saltus::gui {

namespace {

constexpr int kMassColumn = 1;
constexpr int kFactorColumn = 2;

}  // namespace

ModelPanel::ModelPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  table_ = new QTableWidget(0, 3, this);
  table_->setHorizontalHeaderLabels({tr("segment"), tr("mass (kg)"), tr("× loaded")});
  // The numbers' columns as wide as they need, the segment's names the rest: with equal
  // columns the names were cut ("Upper trun…", "Right …") in the panel column of a laptop.
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
  table_->verticalHeader()->setVisible(false);
  table_->setToolTip(tr("Edit a mass or a factor: the segment's mass and inertia scale together"));
  layout->addWidget(table_, 1);
  total_ = new QLabel(this);
  layout->addWidget(total_);
  auto* buttons = new QHBoxLayout;
  reset_ = new QPushButton(tr("Reset masses"), this);
  save_ = new QPushButton(tr("Save model…"), this);
  buttons->addWidget(reset_);
  buttons->addWidget(save_);
  layout->addLayout(buttons);
  new_athlete_ = new QPushButton(tr("New athlete…"), this);
  new_athlete_->setToolTip(
      tr("A body model of one athlete from height, mass and sex, or from Yeadon's "
         "measurements, for this motion"));
  layout->addWidget(new_athlete_);
  problem_ = new QLabel(this);
  problem_->setWordWrap(true);
  problem_->setStyleSheet("color: #b00020;");
  layout->addWidget(problem_);
  landing_ = new QLabel(this);
  landing_->setWordWrap(true);
  landing_->setObjectName("model_landing");
  landing_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  landing_->setToolTip(
      tr("The open motion's take-off (its angular momentum on this body: the same spin as on "
         "the model it was made for) flown freely by this body, as `saltus simulate --model` "
         "flies it"));
  layout->addWidget(landing_);

  connect(table_, &QTableWidget::itemChanged, this, &ModelPanel::on_item_changed);
  connect(reset_, &QPushButton::clicked, this, [this] {
    if (loaded_)
      emit factors_edited(std::vector<double>(static_cast<std::size_t>(loaded_->size()), 1.0));
  });
  connect(save_, &QPushButton::clicked, this, &ModelPanel::save_requested);
  connect(new_athlete_, &QPushButton::clicked, this, &ModelPanel::new_athlete_requested);
  set_model(nullptr, nullptr);
}

void ModelPanel::set_model(const BodyModel* loaded, const BodyModel* current) {
  loaded_ = loaded;
  current_ = current;
  const QSignalBlocker block(table_);
  const int rows = current_ && loaded_ ? current_->size() : 0;
  table_->setRowCount(rows);
  for (int i = 0; i < rows; ++i) {
    const Segment& s = current_->segments[static_cast<std::size_t>(i)];
    const double factor = s.mass / loaded_->segments[static_cast<std::size_t>(i)].mass;
    auto* name = new QTableWidgetItem(QString::fromStdString(capitalised(segment_label(s.name))));
    name->setFlags(name->flags() & ~Qt::ItemIsEditable);
    table_->setItem(i, 0, name);
    table_->setItem(i, kMassColumn, new QTableWidgetItem(QString::number(s.mass, 'f', 3)));
    table_->setItem(i, kFactorColumn, new QTableWidgetItem(QString::number(factor, 'g', 4)));
  }
  total_->setText(current_ ? tr("Model %1, total mass %2 kg")
                                 .arg(QString::fromStdString(current_->name))
                                 .arg(current_->total_mass(), 0, 'f', 2)
                           : QString());
  setEnabled(rows > 0);
}

void ModelPanel::landing_changed() {
  landing_stale_ = true;
  if (isVisible()) refresh_landing();
}

void ModelPanel::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  if (landing_stale_) refresh_landing();
}

void ModelPanel::refresh_landing() {
  landing_stale_ = false;
  const std::optional<AthleteLanding> l = landing_source_ ? landing_source_() : std::nullopt;
  if (!l) {
    landing_->clear();
    return;
  }
  // The library's one verdict: green only when it lands within the athlete's strength.
  const QString text = tr("<b>Can this athlete land it?</b><br>") + verdict_html(l->verdict);
  landing_->setText(text);
}

QString ModelPanel::landing_text() const {
  return landing_->text();
}

std::vector<double> ModelPanel::factors() const {
  std::vector<double> out;
  for (int i = 0; i < table_->rowCount(); ++i)
    out.push_back(table_->item(i, kFactorColumn)->text().toDouble());
  return out;
}

void ModelPanel::show_problem(const QString& message) {
  problem_->setText(message);
}

QString ModelPanel::problem() const {
  return problem_->text();
}

void ModelPanel::on_item_changed(QTableWidgetItem* item) {
  if (!loaded_ || !current_) return;
  const int row = item->row();
  const bool mass = item->column() == kMassColumn;
  bool ok = false;
  const double value = item->text().toDouble(&ok);
  const QString segment =
      QString::fromStdString(segment_label(current_->segments[static_cast<std::size_t>(row)].name));
  if (!ok || !std::isfinite(value) || value <= 0.0) {
    // Said here in the user's words; the table shows the values in force again.
    const QString entered = item->text();
    QTimer::singleShot(0, this, [this, mass, segment, entered] {
      set_model(loaded_, current_);
      show_problem(mass ? tr("The mass of the %1 must be a positive number of kilograms "
                             "(\"%2\" is not).")
                              .arg(segment, entered)
                        : tr("The factor for the %1 must be a positive number (\"%2\" is not).")
                              .arg(segment, entered));
    });
    return;
  }
  std::vector<double> f;
  for (int i = 0; i < current_->size(); ++i)
    f.push_back(current_->segments[static_cast<std::size_t>(i)].mass /
                loaded_->segments[static_cast<std::size_t>(i)].mass);
  f[static_cast<std::size_t>(row)] = mass ? mass_factor_for(*loaded_, row, value) : value;
  // After the table has finished with the edited item: the edit rebuilds the table.
  QTimer::singleShot(0, this, [this, f] { emit factors_edited(f); });
}

}  // namespace saltus::gui
