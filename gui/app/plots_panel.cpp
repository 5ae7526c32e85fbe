#include "app/plots_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QHBoxLayout>
#include <QLabel>
#include <QSettings>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <cmath>
#include <filesystem>

#include "app/chart_widget.h"
#include "app/legend_strip.h"
#include "app/qt_text.h"
#include "app/strength_strips.h"
#include "app/teaching_panel.h"
#include "core/figures.h"
#include "core/joint_load_view.h"
#include "core/plot_series.h"
#include "saltus/body/segment_names.h"
#include "saltus/evaluation/residual_measures.h"
#include "scene/chart_view.h"

namespace saltus::gui {

namespace {

constexpr int kFigureWidth = 1400;
constexpr int kFigureHeight = 700;

}  // namespace

PlotsPanel::PlotsPanel(AppContext& context, QWidget* parent)
    : QTabWidget(parent), context_(context) {
  // Root force and moment, side by side.
  auto* root_tab = new QWidget(this);
  auto* root_layout = new QVBoxLayout(root_tab);
  root_layout->setContentsMargins(2, 2, 2, 2);
  // The root charts' switches sit beside the tabs, not in a row of their own: on a laptop
  // screen that row's height goes to the charts.
  auto* corner = new QWidget(this);
  auto* switches = new QHBoxLayout(corner);
  switches->setContentsMargins(0, 0, 4, 0);
  components_ = new QCheckBox(tr("Components"), corner);
  components_->setToolTip(
      tr("x, y and z in the root segment's frame instead of the resultant |F| and |M|"));
  switches->addWidget(components_);
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    axes_[static_cast<std::size_t>(a)] = new QCheckBox(axes[a], corner);
    axes_[static_cast<std::size_t>(a)]->setChecked(true);
    switches->addWidget(axes_[static_cast<std::size_t>(a)]);
  }
  log_scale_ = new QCheckBox(tr("Log scale"), corner);
  log_scale_->setChecked(true);
  log_scale_->setToolTip(
      tr("A logarithmic axis for |F| and |M|, so that the small residual "
         "after optimisation shows next to the large one before"));
  switches->addWidget(log_scale_);
  setCornerWidget(corner, Qt::TopRightCorner);
  connect(this, &QTabWidget::currentChanged, corner,
          [this, corner, root_tab] { corner->setVisible(currentWidget() == root_tab); });
  auto* root_charts = new QHBoxLayout;
  force_chart_ = new ChartWidget(root_tab);
  moment_chart_ = new ChartWidget(root_tab);
  root_charts->addWidget(with_legend_strip(force_chart_, root_tab));
  root_charts->addWidget(with_legend_strip(moment_chart_, root_tab));
  root_layout->addLayout(root_charts, 1);
  addTab(root_tab, tr("Root force && moment"));
  for (QCheckBox* box : {components_, log_scale_, axes_[0], axes_[1], axes_[2]})
    connect(box, &QCheckBox::toggled, this, [this] { refresh_root_charts(); });

  joint_tab_ = new QWidget(this);
  auto* joint_layout = new QVBoxLayout(joint_tab_);
  joint_layout->setContentsMargins(2, 2, 2, 2);
  joint_layout->setSpacing(2);
  auto* joint_row = new QHBoxLayout;
  joint_row->addWidget(new QLabel(tr("Joint:"), joint_tab_));
  joint_combo_ = new QComboBox(joint_tab_);
  joint_combo_->setMinimumContentsLength(22);
  joint_combo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  joint_combo_->setToolTip(tr("Or click a body segment in the 3D view"));
  joint_row->addWidget(joint_combo_);
  // The peaks as a coach reads them, with a traffic light for the share of the athlete's
  // strength.
  joint_light_ = new QLabel(joint_tab_);
  joint_light_->setFixedSize(14, 14);
  joint_row->addWidget(joint_light_);
  joint_summary_ = new QLabel(joint_tab_);
  joint_summary_->setWordWrap(true);
  joint_summary_->setObjectName("joint_summary");
  joint_summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  joint_row->addWidget(joint_summary_, 1);
  joint_layout->addLayout(joint_row);
  joint_raised_ = new QLabel(joint_tab_);
  joint_raised_->setWordWrap(true);
  joint_raised_->setObjectName("joint_raised");
  joint_layout->addWidget(joint_raised_);
  auto* joint_charts = new QHBoxLayout;
  joint_force_chart_ = new ChartWidget(joint_tab_);
  joint_moment_chart_ = new ChartWidget(joint_tab_);
  // Lower than the root force's charts may be: under the peaks' two lines and the optimiser's
  // rise, a 1366x768 screen leaves them about 130 px, and a taller minimum cut their time axis
  // off at the tab's bottom.
  for (ChartWidget* chart : {joint_force_chart_, joint_moment_chart_})
    chart->setMinimumHeight(110);
  joint_charts->addWidget(with_legend_strip(joint_force_chart_, joint_tab_));
  joint_charts->addWidget(with_legend_strip(joint_moment_chart_, joint_tab_));
  joint_layout->addLayout(joint_charts, 1);
  connect(joint_combo_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int joint) {
    refresh_joint_chart();
    if (joint >= 0) emit joint_selected(joint);
  });
  addTab(joint_tab_, tr("Joint loads"));

  // Every joint's share of the athlete's strength over the flight, a strip each.
  strength_ = new StrengthStrips(this);
  addTab(strength_, tr("Strength"));
  connect(strength_, &StrengthStrips::seek_requested, this, &PlotsPanel::seek_requested);
  connect(strength_, &StrengthStrips::joint_chosen, this, [this](int segment) {
    const QSignalBlocker block(joint_combo_);
    joint_combo_->setCurrentIndex(segment);
    refresh_joint_chart();
    emit joint_selected(segment);
  });
  connect(strength_, &StrengthStrips::joint_opened, this, &PlotsPanel::show_joint);

  teaching_ = new TeachingPanel(context_, this);
  addTab(teaching_, tr("Why it spins"));
  connect(teaching_, &TeachingPanel::seek_requested, this, &PlotsPanel::seek_requested);

  for (ChartWidget* chart : {force_chart_, moment_chart_, joint_force_chart_, joint_moment_chart_})
    connect(chart, &ChartWidget::seek_requested, this, &PlotsPanel::seek_requested);
  context_.workspace().subscribe([this](WorkspaceChange c) { on_workspace(c); });
  on_workspace(WorkspaceChange::kOpened);
}

std::vector<ChartWidget*> PlotsPanel::charts() const {
  return {force_chart_, moment_chart_, joint_force_chart_, joint_moment_chart_, teaching_->chart()};
}

void PlotsPanel::on_workspace(WorkspaceChange change) {
  const Workspace& ws = context_.workspace();
  if (change == WorkspaceChange::kSaved) return;
  if (change != WorkspaceChange::kStage) {
    // Joint list: every joint of the model, named as people name them.
    const int previous = joint_combo_->currentIndex();
    const QSignalBlocker block(joint_combo_);
    joint_combo_->clear();
    if (ws.loaded()) {
      // A joint the run shown made pay is named so in the list.
      const Document& d = ws.document();
      const BodyModel& model = d.file().model;
      std::vector<JointLoadRise> rises;
      if (d.has_optimization())
        rises =
            joint_load_rises(model, d.optimization().before.check, d.optimization().after.check);
      for (int k = 0; k < model.size(); ++k) {
        const JointLoadRise* rise = k >= 1 && k - 1 < static_cast<int>(rises.size())
                                        ? &rises[static_cast<std::size_t>(k - 1)]
                                        : nullptr;
        joint_combo_->addItem(qstr(joint_choice_label(model, k, rise)));
      }
      const int knee = model.joint_index("knee_l");
      joint_combo_->setCurrentIndex(
          previous >= 0 && previous < joint_combo_->count() ? previous : std::max(0, knee));
    }
    refresh_root_charts();
    refresh_joint_chart();
  }
  refresh_strength();
  teaching_->refresh();
}

void PlotsPanel::refresh_root_charts() {
  const Workspace& ws = context_.workspace();
  const bool components = components_->isChecked();
  for (QCheckBox* box : axes_)
    box->setVisible(components);
  log_scale_->setEnabled(!components);
  if (!ws.loaded()) {
    ChartSpec empty;
    empty.title = "Open a motion to see its root force and moment";
    force_chart_->set_chart(empty);
    moment_chart_->set_chart(empty);
    return;
  }
  const Document& d = ws.document();
  const bool optimised = d.has_optimization();
  const WrenchSeries before = root_wrench_series(d.plot_samples(Stage::kBefore));
  WrenchSeries after;
  if (optimised) after = root_wrench_series(d.plot_samples(Stage::kAfter));
  const std::vector<double>& times_before = d.evaluation(Stage::kBefore).keyframe_times;
  const std::vector<double> times_after =
      optimised ? d.evaluation(Stage::kAfter).keyframe_times : std::vector<double>{};
  RootChartStyle style;
  style.components = components;
  for (std::size_t a = 0; a < 3; ++a)
    style.axes[a] = axes_[a]->isChecked();
  style.log_scale = log_scale_->isChecked();
  style.body_weight_N = body_weight(d.file().model);
  // A motion imported from a capture: the capture's own residual beside it.
  WrenchSeries capture;
  if (d.capture()) capture = root_wrench_series(d.capture_plot_samples());
  const WrenchSeries* captured = d.capture() ? &capture : nullptr;
  force_chart_->set_chart(
      root_chart(style, before, optimised ? &after : nullptr, times_before, times_after, captured));
  style.moment = true;
  moment_chart_->set_chart(
      root_chart(style, before, optimised ? &after : nullptr, times_before, times_after, captured));
  update_cursors();
}

void PlotsPanel::refresh_joint_chart() {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded() || joint_combo_->currentIndex() < 0) {
    ChartSpec empty;
    empty.title = "Open a motion to see the loads at its joints";
    joint_force_chart_->set_chart(empty);
    joint_moment_chart_->set_chart(empty);
    joint_summary_->clear();
    joint_raised_->clear();
    joint_raised_->hide();
    joint_light_->hide();
    return;
  }
  const Document& d = ws.document();
  const bool optimised = d.has_optimization();
  const JointLoadView view = joint_load_view(
      d.file().model, joint_combo_->currentIndex(), d.plot_samples(Stage::kBefore),
      d.evaluation(Stage::kBefore).check, optimised ? &d.plot_samples(Stage::kAfter) : nullptr,
      optimised ? &d.evaluation(Stage::kAfter).check : nullptr);
  joint_force_chart_->set_chart(view.force);
  joint_moment_chart_->set_chart(view.moment);
  const Rgb light = strength_light_colour(view.light);
  joint_light_->setStyleSheet(QString("background: rgb(%1, %2, %3); border-radius: 7px;")
                                  .arg(static_cast<int>(255 * light.r))
                                  .arg(static_cast<int>(255 * light.g))
                                  .arg(static_cast<int>(255 * light.b)));
  joint_light_->setToolTip(qstr(strength_light_words(view.light)));
  joint_light_->setVisible(joint_combo_->currentIndex() > 0);
  joint_summary_->setText(qstr(view.summary));
  joint_raised_->setText(qstr(view.raised));
  joint_raised_->setStyleSheet(view.raised_past_limit ? "color: #b00020; font-weight: bold;"
                                                      : "color: #8a5a00;");
  joint_raised_->setVisible(!view.raised.empty());
  update_cursors();
}

void PlotsPanel::refresh_strength() {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded()) {
    strength_->set_strips({}, QString());
    return;
  }
  // The stage the 3D view shows.
  const Document& d = ws.document();
  const Stage stage = d.available(ws.stage());
  strength_->set_strips(
      strength_strips(d.file().model, d.plot_samples(stage), d.evaluation(stage).check),
      stage == Stage::kAfter ? tr("the optimised motion") : tr("the interpolated keyframes"));
  strength_->set_time(time_);
}

QString PlotsPanel::joint_summary() const {
  return joint_summary_->text();
}

QString PlotsPanel::joint_raised() const {
  return joint_raised_->text();
}

void PlotsPanel::set_time(double t, bool playing) {
  time_ = t;
  update_cursors();
  // The words change with the numbers: while playing, only on the tab shown.
  if (!playing || currentWidget() == teaching_) teaching_->set_time(t);
}

void PlotsPanel::update_cursors() {
  // Cheap: the cursors are Qt widgets over the charts, no chart is redrawn.
  const double t = context_.workspace().loaded() ? time_ : std::nan("");
  for (ChartWidget* chart : {force_chart_, moment_chart_, joint_force_chart_, joint_moment_chart_})
    chart->set_cursor(t);
  strength_->set_time(t);
}

void PlotsPanel::show_joint(int segment) {
  if (segment < 0 || segment >= joint_combo_->count()) return;
  joint_combo_->setCurrentIndex(segment);
  setCurrentWidget(joint_tab_);
}

int PlotsPanel::selected_joint() const {
  return context_.workspace().loaded() ? joint_combo_->currentIndex() : -1;
}

void PlotsPanel::set_show_components(bool components) {
  components_->setChecked(components);
}

void PlotsPanel::set_log_scale(bool log) {
  log_scale_->setChecked(log);
}

bool PlotsPanel::export_figures(const QString& dir, QStringList* written, QString* error) {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded())
    return context_.fail(tr("Nothing to export"), tr("Open a motion first."), error);
  const Document& d = ws.document();
  const std::string joint =
      d.file().model.segments[static_cast<std::size_t>(std::max(0, selected_joint()))].joint;
  const std::string stem = figure_stem(d.file().motion.name);
  std::string settings;
  if (ws.shown_run()) {
    const RunRecord& run = ws.runs().at(*ws.shown_run());
    settings = settings_summary(run.settings) + " · " + status_text(run.result->solve.status);
  }
  const std::vector<std::pair<std::string, ChartWidget*>> charts = {
      {stem + "_root_force.png", force_chart_},
      {stem + "_root_moment.png", moment_chart_},
      {stem + "_joint_force_" + joint + ".png", joint_force_chart_},
      {stem + "_joint_moment_" + joint + ".png", joint_moment_chart_},
      {stem + "_rotation_" + std::to_string(teaching_->quantity()->currentIndex() + 1) + ".png",
       teaching_->chart()}};
  try {
    std::filesystem::create_directories(dir.toStdString());
    for (const auto& [name, chart] : charts) {
      const QString path = QDir(dir).filePath(qstr(name));
      const ChartSpec spec = titled_figure(chart->view().chart(), d.file().motion.name, settings);
      write_chart_png(spec, path.toStdString(), kFigureWidth, kFigureHeight);
      if (written) written->append(qstr(name));
    }
  } catch (const std::exception& e) {
    return context_.fail(tr("Cannot export plots"), qstr(e.what()), error);
  }
  context_.set_last_dir(dir);
  return true;
}

void PlotsPanel::load_settings(const QSettings& s) {
  components_->setChecked(s.value("plots/components", false).toBool());
  log_scale_->setChecked(s.value("plots/log_scale", true).toBool());
  for (int a = 0; a < 3; ++a)
    axes_[static_cast<std::size_t>(a)]->setChecked(
        s.value(QString("plots/axis_%1").arg(a), true).toBool());
  teaching_->quantity()->setCurrentIndex(s.value("plots/rotation_quantity", 0).toInt());
  setCurrentIndex(s.value("plots/tab", 0).toInt());
}

void PlotsPanel::save_settings(QSettings& s) const {
  s.setValue("plots/components", components_->isChecked());
  s.setValue("plots/log_scale", log_scale_->isChecked());
  for (int a = 0; a < 3; ++a)
    s.setValue(QString("plots/axis_%1").arg(a), axes_[static_cast<std::size_t>(a)]->isChecked());
  s.setValue("plots/rotation_quantity", teaching_->quantity()->currentIndex());
  s.setValue("plots/tab", currentIndex());
}

}  // namespace saltus::gui
