#include "app/new_athlete_dialog.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QTimer>
#include <QVBoxLayout>
#include <exception>

#include "app/qt_text.h"
#include "app/verdict_text.h"
#include "app/vtk_image_widget.h"
#include "saltus/body/athlete_model.h"
#include "saltus/use_cases/athlete_models.h"
#include "scene/standing_figures.h"

namespace saltus::gui {

namespace {

/// The words above a figure: `prefix` on a line of its own ("in use:"), its name, then its
/// height and mass: short lines, so that neighbours' labels do not run together.
std::string figure_label(const std::string& prefix, const BodyModel& model) {
  return (prefix.empty() ? "" : prefix + "\n") + model.name + "\n" + athlete_size(model);
}

}  // namespace

NewAthleteDialog::NewAthleteDialog(const MotionFile* open, const EvaluateOptions& options,
                                   QWidget* parent)
    : QDialog(parent),
      figures_(std::make_unique<StandingFigures>()),
      options_(options),
      can_compare_(open != nullptr),
      landing_figures_(std::make_unique<StandingFigures>()) {
  setWindowTitle(tr("New athlete"));
  if (open) {
    current_ = open->model;
    open_ = *open;
  }

  auto* intro = new QLabel(
      tr("A body model of one athlete, on the same 13 segments as every motion. It is saved as "
         "a model file, then flies the open motion with the same take-off spin."),
      this);
  intro->setWordWrap(true);

  name_ = new QLineEdit(this);
  name_->setPlaceholderText(tr("e.g. junior (empty: a name from the figures)"));

  from_size_ = new QRadioButton(tr("From &height, mass and sex (de Leva 1996)"), this);
  from_yeadon_ = new QRadioButton(tr("From &Yeadon's 95 measurements (a file)"), this);
  from_size_->setChecked(true);
  auto* source = new QButtonGroup(this);
  source->addButton(from_size_);
  source->addButton(from_yeadon_);

  // The library's defaults (AthleteSize); the widget ranges only bound what can be typed, the
  // library says what a person can be.
  const AthleteSize defaults;
  size_fields_ = new QWidget(this);
  auto* size_form = new QFormLayout(size_fields_);
  size_form->setContentsMargins(24, 0, 0, 0);
  height_ = new QDoubleSpinBox(size_fields_);
  height_->setRange(0.0, 9.99);
  height_->setDecimals(2);
  height_->setSingleStep(0.01);
  height_->setValue(defaults.height_m);
  mass_ = new QDoubleSpinBox(size_fields_);
  mass_->setRange(0.0, 999.9);
  mass_->setDecimals(1);
  mass_->setSingleStep(0.5);
  mass_->setValue(defaults.mass_kg);
  sex_ = new QComboBox(size_fields_);
  sex_->addItems({"female", "male"});
  sex_->setCurrentIndex(defaults.sex == Sex::kFemale ? 0 : 1);
  size_form->addRow(tr("Height (m):"), height_);
  size_form->addRow(tr("Mass (kg):"), mass_);
  size_form->addRow(tr("Sex:"), sex_);

  yeadon_fields_ = new QWidget(this);
  auto* yeadon_form = new QFormLayout(yeadon_fields_);
  yeadon_form->setContentsMargins(24, 0, 0, 0);
  measurements_ = new QLineEdit(yeadon_fields_);
  measurements_->setPlaceholderText(tr("a measurements file (Key: value lines)"));
  auto* browse = new QPushButton(tr("Browse…"), yeadon_fields_);
  auto* file_row = new QHBoxLayout;
  file_row->addWidget(measurements_, 1);
  file_row->addWidget(browse);
  densities_ = new QComboBox(yeadon_fields_);
  for (const std::string& name : yeadon_density_names())
    densities_->addItem(qstr(name));
  yeadon_mass_ = new QDoubleSpinBox(yeadon_fields_);
  yeadon_mass_->setRange(0.0, 999.9);
  yeadon_mass_->setDecimals(1);
  yeadon_mass_->setSpecialValueText(tr("from the file"));
  yeadon_mass_->setToolTip(
      tr("Scales every density so the body weighs this; \"from the file\": its totalmass, else "
         "what the densities give"));
  yeadon_form->addRow(tr("File:"), file_row);
  yeadon_form->addRow(tr("Densities:"), densities_);
  yeadon_form->addRow(tr("Mass (kg):"), yeadon_mass_);

  auto* fields = new QVBoxLayout;
  auto* name_form = new QFormLayout;
  name_form->addRow(tr("&Name:"), name_);
  fields->addLayout(name_form);
  fields->addSpacing(6);
  fields->addWidget(from_size_);
  fields->addWidget(size_fields_);
  fields->addWidget(from_yeadon_);
  fields->addWidget(yeadon_fields_);
  fields->addStretch(1);

  preview_ = new VtkImageWidget(this);
  preview_->setMinimumSize(220, 260);
  preview_->setToolTip(tr("The new athlete standing beside the model in use (grey), on one scale"));
  figures_->attach(preview_->render_window());
  // Both free flights at landing, side by side: a body that lands on its head is drawn so.
  landing_view_ = new VtkImageWidget(this);
  landing_view_->setMinimumSize(220, 260);
  landing_view_->setToolTip(
      tr("The open motion's take-off flown freely by the new athlete and by the model in use "
         "(grey): each drawn as it lands"));
  landing_figures_->attach(landing_view_->render_window());
  landing_view_->setVisible(open_.has_value());

  auto* middle = new QHBoxLayout;
  middle->addLayout(fields, 1);
  middle->addWidget(preview_, 1);
  middle->addWidget(landing_view_, 1);

  // Can this athlete land it? The verdict first, in large letters, then the flight in words and
  // the joints against the athlete's strength.
  landing_title_ = new QLabel(this);
  landing_title_->setWordWrap(true);
  landing_headline_ = new QLabel(this);
  landing_headline_->setWordWrap(true);
  landing_headline_->setObjectName("landing_headline");
  landing_details_ = new QLabel(this);
  landing_details_->setWordWrap(true);
  landing_details_->setObjectName("landing_details");
  landing_details_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  for (QLabel* label : {landing_title_, landing_headline_, landing_details_})
    label->setVisible(open_.has_value());
  landing_timer_ = new QTimer(this);
  landing_timer_->setSingleShot(true);
  landing_timer_->setInterval(150);
  connect(landing_timer_, &QTimer::timeout, this, &NewAthleteDialog::refresh_landing);

  figures_line_ = new QLabel(this);
  figures_line_->setWordWrap(true);
  figures_line_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  // Yeadon's warnings can be many: a few lines, scrolled, one warning a line.
  warnings_ = new QPlainTextEdit(this);
  warnings_->setReadOnly(true);
  warnings_->setMaximumHeight(5 * fontMetrics().lineSpacing());
  warnings_->setStyleSheet("color: #8a5a00;");
  problem_ = new QLabel(this);
  problem_->setWordWrap(true);
  problem_->setStyleSheet("color: #b00020; font-weight: bold;");

  auto* buttons = new QDialogButtonBox(this);
  use_ = buttons->addButton(tr("Save and &use…"), QDialogButtonBox::AcceptRole);
  use_->setToolTip(tr("Save the model file, then fly the open motion (and the next ones) with it"));
  compare_ = buttons->addButton(tr("Save and &compare…"), QDialogButtonBox::ActionRole);
  compare_->setToolTip(
      tr("Save the model file, then show the open motion on the model in use and on this "
         "athlete side by side"));
  buttons->addButton(QDialogButtonBox::Cancel);
  use_->setDefault(true);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(use_, &QPushButton::clicked, this, [this] {
    if (draft_.model) emit save_requested(false);
  });
  connect(compare_, &QPushButton::clicked, this, [this] {
    if (draft_.model) emit save_requested(true);
  });

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(intro);
  layout->addLayout(middle, 1);
  layout->addWidget(landing_title_);
  layout->addWidget(landing_headline_);
  layout->addWidget(landing_details_);
  layout->addWidget(figures_line_);
  layout->addWidget(warnings_);
  layout->addWidget(problem_);
  layout->addWidget(buttons);

  connect(name_, &QLineEdit::textChanged, this, &NewAthleteDialog::refresh);
  connect(from_size_, &QRadioButton::toggled, this, &NewAthleteDialog::refresh);
  for (QDoubleSpinBox* box : {height_, mass_, yeadon_mass_})
    connect(box, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
            &NewAthleteDialog::refresh);
  for (QComboBox* box : {sex_, densities_})
    connect(box, qOverload<int>(&QComboBox::currentIndexChanged), this, &NewAthleteDialog::refresh);
  connect(measurements_, &QLineEdit::textChanged, this, &NewAthleteDialog::refresh);
  connect(browse, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Yeadon's measurements"), QFileInfo(measurements_->text()).absolutePath(),
        tr("Measurements (*.txt);;All files (*)"));
    if (!path.isEmpty()) measurements_->setText(path);
  });
  refresh();
  resize(900, 640);
}

NewAthleteDialog::~NewAthleteDialog() = default;

AthleteRequest NewAthleteDialog::request() const {
  AthleteRequest r;
  r.source =
      from_yeadon_->isChecked() ? AthleteRequest::Source::kYeadon : AthleteRequest::Source::kSize;
  r.name = name_->text().trimmed().toStdString();
  r.height_m = height_->value();
  r.mass_kg = mass_->value();
  r.sex = sex_->currentText().toStdString();
  r.measurements = measurements_->text().trimmed().toStdString();
  r.densities = densities_->currentText().toStdString();
  r.yeadon_mass_kg = yeadon_mass_->value();
  return r;
}

void NewAthleteDialog::refresh() {
  const bool yeadon = from_yeadon_->isChecked();
  size_fields_->setEnabled(!yeadon);
  yeadon_fields_->setEnabled(yeadon);
  draft_ = draft_athlete(request());

  std::vector<StandingFigures::Figure> shown;
  if (draft_.model)
    shown.push_back({*draft_.model, figure_label("", *draft_.model), false, std::nullopt});
  if (current_)
    shown.push_back(
        {*current_, figure_label(tr("in use:").toStdString(), *current_), true, std::nullopt});
  figures_->set_figures(shown);
  preview_->request_render();

  figures_line_->setText(draft_.model ? qstr(athlete_figures(*draft_.model)) : QString());
  QStringList warnings;
  for (const std::string& w : draft_.warnings)
    warnings << tr("Warning: %1").arg(qstr(w));
  warnings_->setPlainText(warnings.join("\n"));
  warnings_->setVisible(!warnings.isEmpty());
  problem_->setText(qstr(draft_.problem));
  problem_->setVisible(!draft_.problem.empty());
  use_->setEnabled(draft_.model.has_value());
  compare_->setEnabled(draft_.model.has_value() && can_compare_);
  landing_stale_ = true;
  if (open_) {
    landing_headline_->setText(draft_.model ? tr("Flying it…") : QString());
    landing_details_->clear();
    landing_timer_->start();
  }
}

const AthleteLanding* NewAthleteDialog::landing() {
  if (landing_stale_) refresh_landing();
  return landing_ ? &*landing_ : nullptr;
}

void NewAthleteDialog::refresh_landing() {
  landing_timer_->stop();
  landing_stale_ = false;
  landing_.reset();
  if (!open_) return;
  const QString motion = qstr(open_->motion.name);
  try {
    if (!current_landing_) current_landing_ = athlete_landing(*open_, options_);
    if (draft_.model)
      landing_ = athlete_landing(motion_on_athlete(*open_, *draft_.model), options_);
  } catch (const std::exception& e) {
    landing_headline_->setText(qstr(e.what()));
    return;
  }
  std::vector<StandingFigures::Figure> shown;
  if (landing_)
    shown.push_back({*draft_.model, figure_label("", *draft_.model), false,
                     landing_->verdict.flight.samples.back()});
  shown.push_back({open_->model, figure_label(tr("in use:").toStdString(), open_->model), true,
                   current_landing_->verdict.flight.samples.back()});
  landing_figures_->set_figures(shown);
  landing_view_->request_render();
  landing_title_->setText(
      tr("<b>Can %1 land %2?</b> The same take-off (the same spin), flown freely by this body:")
          .arg(draft_.model ? qstr(draft_.model->name) : tr("this athlete"), motion));
  if (!landing_) {
    landing_headline_->clear();
    landing_details_->clear();
    return;
  }
  // The library's one verdict on the new body, and the one on the body in use beside it.
  const AthleteVerdict& v = landing_->verdict;
  const AthleteVerdict& in_use = current_landing_->verdict;
  landing_headline_->setText(qstr(v.headline));
  landing_headline_->setStyleSheet(QString("color: %1; font-weight: bold; font-size: 14pt;")
                                       .arg(QString::fromStdString(verdict_html_colour(v.light))));
  QStringList details;
  details << verdict_html(v, false);  // the headline is the label above, larger
  details << tr("In use (%1): <span style=\"color: %2;\">%3</span>.")
                 .arg(qstr(open_->model.name).toHtmlEscaped(),
                      QString::fromStdString(verdict_html_colour(in_use.light)),
                      qstr(in_use.headline).toHtmlEscaped());
  landing_details_->setText(details.join("<br>"));
}

QImage NewAthleteDialog::grab_landing() {
  landing();
  landing_view_->render_now();
  return landing_view_->picture();
}

QString NewAthleteDialog::landing_headline() const {
  return landing_headline_->text();
}

QString NewAthleteDialog::landing_details() const {
  return landing_details_->text();
}

QImage NewAthleteDialog::grab_preview() {
  preview_->render_now();
  return preview_->picture();
}

std::vector<double> NewAthleteDialog::preview_heights() const {
  return figures_->drawn_heights();
}

QString NewAthleteDialog::problem() const {
  return problem_->text();
}

QString NewAthleteDialog::figures() const {
  return figures_line_->text();
}

}  // namespace saltus::gui
