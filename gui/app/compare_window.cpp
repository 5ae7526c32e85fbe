#include "app/compare_window.h"

#include <QAction>
#include <QActionGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QKeySequence>
#include <QLabel>
#include <QScreen>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTabWidget>
#include <QToolBar>
#include <QVBoxLayout>
#include <cmath>

#include "app/chart_widget.h"
#include "app/legend_strip.h"
#include "app/scene_widget.h"
#include "app/timeline_widget.h"
#include "app/verdict_text.h"
#include "core/compare.h"
#include "core/plot_series.h"
#include "core/screen_fit.h"
#include "saltus/body/mass_properties.h"
#include "saltus/body/segment_names.h"

namespace saltus::gui {

namespace {

/// The run's colours in the plots: blue first, orange second (compare_colour).
const char* const kTitleColours[2] = {"#1f4fa8", "#c25a00"};

}  // namespace

CompareWindow::CompareWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle(tr("Saltus — compare"));

  // Titles in one row and views in the next: a title that wraps onto a second line moves
  // neither view, so both stay level.
  auto* views = new QWidget(this);
  auto* views_layout = new QGridLayout(views);
  views_layout->setContentsMargins(2, 2, 2, 2);
  views_layout->setSpacing(2);
  for (int i = 0; i < 2; ++i) {
    titles_[static_cast<std::size_t>(i)] = new QLabel(views);
    titles_[static_cast<std::size_t>(i)]->setTextFormat(Qt::RichText);
    // Long labels wrap instead of widening the window past the screen.
    titles_[static_cast<std::size_t>(i)]->setWordWrap(true);
    titles_[static_cast<std::size_t>(i)]->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    scenes_[static_cast<std::size_t>(i)] = new SceneWidget(views);
    scenes_[static_cast<std::size_t>(i)]->scene().set_camera(CameraPreset::kFollow);
    views_layout->addWidget(titles_[static_cast<std::size_t>(i)], 0, i);
    views_layout->addWidget(scenes_[static_cast<std::size_t>(i)], 1, i);
    views_layout->setColumnStretch(i, 1);
  }
  views_layout->setRowStretch(1, 1);
  timeline_ = new TimelineWidget(this);
  connect(timeline_, &TimelineWidget::time_changed, this, &CompareWindow::on_time_changed);
  note_ = new QLabel(this);
  note_->setVisible(false);

  auto* top = new QWidget(this);
  auto* top_layout = new QVBoxLayout(top);
  top_layout->setContentsMargins(0, 0, 0, 0);
  top_layout->setSpacing(0);
  top_layout->addWidget(views, 1);
  top_layout->addWidget(note_);
  top_layout->addWidget(timeline_);

  tabs_ = new QTabWidget(this);
  auto* root = new QWidget(tabs_);
  auto* root_layout = new QHBoxLayout(root);
  root_layout->setContentsMargins(2, 2, 2, 2);
  force_chart_ = new ChartWidget(root);
  moment_chart_ = new ChartWidget(root);
  root_layout->addWidget(with_legend_strip(force_chart_, root));
  root_layout->addWidget(with_legend_strip(moment_chart_, root));
  tabs_->addTab(root, tr("Root force && moment"));
  auto* joints = new QWidget(tabs_);
  auto* joints_layout = new QVBoxLayout(joints);
  joints_layout->setContentsMargins(2, 2, 2, 2);
  auto* joint_row = new QHBoxLayout;
  joint_row->addWidget(new QLabel(tr("Joint:"), joints));
  joint_ = new QComboBox(joints);
  joint_->setMinimumContentsLength(22);
  joint_row->addWidget(joint_);
  joint_row->addStretch(1);
  joints_layout->addLayout(joint_row);
  auto* joint_charts = new QHBoxLayout;
  joint_force_chart_ = new ChartWidget(joints);
  joint_moment_chart_ = new ChartWidget(joints);
  joint_charts->addWidget(with_legend_strip(joint_force_chart_, joints));
  joint_charts->addWidget(with_legend_strip(joint_moment_chart_, joints));
  joints_layout->addLayout(joint_charts, 1);
  tabs_->addTab(joints, tr("Joint loads"));
  connect(joint_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this] { refresh_joint_charts(); });
  for (ChartWidget* chart : {force_chart_, moment_chart_, joint_force_chart_, joint_moment_chart_})
    connect(chart, &ChartWidget::seek_requested, this, &CompareWindow::seek);

  auto* splitter = new QSplitter(Qt::Vertical, this);
  splitter->addWidget(top);
  splitter->addWidget(tabs_);
  splitter->setStretchFactor(0, 3);
  splitter->setStretchFactor(1, 2);
  splitter->setChildrenCollapsible(false);
  setCentralWidget(splitter);

  // Single keys act in the views, the timeline and the plots, never in the combo boxes.
  std::vector<QWidget*> scopes = {scenes_[0], scenes_[1], timeline_, tabs_};
  auto scoped = [&scopes](QAction* action) {
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    for (QWidget* w : scopes)
      w->addAction(action);
  };
  QToolBar* bar = addToolBar(tr("Compare"));
  bar->setObjectName("compare_toolbar");
  auto* cameras = new QActionGroup(this);
  int key = 1;
  for (CameraPreset preset : camera_presets()) {
    QAction* a = bar->addAction(QString::fromStdString(camera_preset_label(preset)), this,
                                [this, preset] { set_camera(preset); });
    a->setCheckable(true);
    a->setChecked(preset == CameraPreset::kFollow);
    a->setShortcut(QKeySequence(QString::number(key++)));
    scoped(a);
    cameras->addAction(a);
  }
  bar->addSeparator();
  QAction* play = bar->addAction(tr("Play / pause"), timeline_, &TimelineWidget::toggle_play);
  play->setShortcut(Qt::Key_Space);
  scoped(play);
  bar->addSeparator();
  bar->addWidget(new QLabel(tr(" Plots: "), bar));
  components_ = new QComboBox(bar);
  components_->addItems(
      {tr("|F| and |M|"), tr("x, y, z"), tr("x only"), tr("y only"), tr("z only")});
  components_->setToolTip(tr("Resultants, or which root force and moment components to overlay"));
  connect(components_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this] { refresh_charts(); });
  bar->addWidget(components_);
  log_scale_ = new QCheckBox(tr("Log scale"), bar);
  log_scale_->setToolTip(tr("A logarithmic axis for |F| and |M|"));
  connect(log_scale_, &QCheckBox::toggled, this, [this] { refresh_charts(); });
  bar->addWidget(log_scale_);
  bar->addSeparator();
  QAction* close_action = bar->addAction(tr("Close compare"), this, &QWidget::close);
  close_action->setShortcuts({QKeySequence::Close, QKeySequence(Qt::Key_Escape)});

  // The first size from the screen it opens on (core/screen_fit.h).
  const QScreen* screen =
      parent && parent->screen() ? parent->screen() : QGuiApplication::primaryScreen();
  const QRect available = screen ? screen->availableGeometry() : QRect();
  const WindowFit fit = first_window_size(available.width(), available.height(), 1500, 950);
  resize(fit.width, fit.height);
}

CompareWindow::~CompareWindow() {
  // The views (deleted after the members, with the child widgets) must not keep pointing at
  // the runs' documents, which go first.
  for (SceneWidget* s : scenes_)
    s->scene().set_document(nullptr, Stage::kBefore);
}

void CompareWindow::set_runs(Run first, Run second, bool keep_time) {
  const double t = time();
  runs_ = {std::move(first), std::move(second)};
  double duration = 0.0;
  int frames = 2;
  typicals_ = GlyphTypicals{};
  double tallest = 0.0;
  for (Run& r : runs_) {
    r.stage = r.document->available(r.stage);
    typicals_ = typicals_.max(r.document->glyph_typicals(r.stage));
    tallest = std::max(tallest, standing_body(r.document->file().model).height());
  }
  for (std::size_t i = 0; i < 2; ++i) {
    const Run& r = runs_[i];
    // Both views on one arrow scale, so that equal arrows mean equal forces, and framed for the
    // taller athlete, so that a shorter one looks shorter.
    scenes_[i]->scene().set_glyph_typicals(typicals_);
    scenes_[i]->scene().set_framing_height(tallest);
    scenes_[i]->scene().set_document(r.document.get(), r.stage);
    scenes_[i]->scene().reset_camera();
    const MotionEvaluation& e = r.document->evaluation(r.stage);
    const QString description =
        r.description.isEmpty()
            ? (r.stage == Stage::kAfter ? tr("optimised") : tr("interpolated keyframes"))
            : r.description;
    // The model only when the label does not already name it ("model thighs x1.5").
    const QString model = QString::fromStdString(r.document->file().model.name);
    const QString model_part =
        r.label.contains(model) ? QString() : tr(" · model %1").arg(model.toHtmlEscaped());
    // The run's name on a line of its own, larger: which side is which must read at a glance.
    QString tooltip;
    QString title =
        tr("<span style='color:%1; font-size:large'><b>%2</b></span><br>%3%4 · %5 · average root "
           "force <b>%6&nbsp;N</b>")
            .arg(kTitleColours[i], r.label.toHtmlEscaped(),
                 QString::fromStdString(r.document->file().motion.name).toHtmlEscaped(), model_part,
                 description.toHtmlEscaped())
            .arg(e.metrics.avg_root_force, 0, 'g', 3);
    if (r.landing) {
      // Can this athlete land it? The verdict before anything that could read as success.
      const AthleteVerdict& v = r.landing->verdict;
      // The verdict and its first reason; the others in the title's tooltip, so that the views
      // keep their room.
      title += "<br>" + verdict_html(v, true, 1);
      tooltip = verdict_html(v);
      scenes_[i]->scene().set_what_if(
          v.flight.samples, verdict_figure_label(v),
          "this body's free flight from the same take-off (the same spin)");
    } else {
      scenes_[i]->scene().set_what_if({}, "");
    }
    titles_[i]->setText(title);
    titles_[i]->setToolTip(tooltip);
    duration = compare_duration(duration, r.document->duration());
    frames = std::max(frames, r.document->frame_count(r.stage));
  }
  const Run& a = runs_[0];
  const Run& b = runs_[1];
  timeline_->set_motion(duration, frames, a.document->evaluation(a.stage).keyframe_times,
                        b.document->evaluation(b.stage).keyframe_times);
  setWindowTitle(tr("Saltus — compare %1 with %2").arg(a.label, b.label));
  {
    const int previous = joint_->currentIndex();
    const QSignalBlocker block(joint_);
    joint_->clear();
    const BodyModel& model = a.document->file().model;
    for (const Segment& s : model.segments)
      joint_->addItem(QString::fromStdString(capitalised(joint_label(s.joint)) + " (" +
                                             segment_label(s.name) + ")"));
    const int hip = model.joint_index("hip_r");
    joint_->setCurrentIndex(previous >= 0 && previous < joint_->count() ? previous
                                                                        : std::max(0, hip));
  }
  refresh_charts();
  refresh_joint_charts();
  timeline_->seek(keep_time ? t : 0.0);
  on_time_changed(timeline_->timeline().time());
}

QString CompareWindow::title(int index) const {
  return titles_.at(static_cast<std::size_t>(index))->text();
}

void CompareWindow::set_note(const QString& note) {
  note_->setText(note);
  note_->setVisible(!note.isEmpty());
}

void CompareWindow::set_scene_options(const SceneOptions& options) {
  // Half-width views: keyframe ghosts and the numbers would cover the body; the titles above
  // the views give each run's numbers instead.
  SceneOptions shown = options;
  shown.ghosts = false;
  shown.physics_text = false;
  for (SceneWidget* s : scenes_) {
    s->scene().set_options(shown);
    s->render_now();
  }
}

void CompareWindow::set_camera(CameraPreset preset) {
  for (SceneWidget* s : scenes_) {
    s->scene().set_camera(preset);
    s->render_now();
  }
}

void CompareWindow::refresh_charts() {
  if (!runs_[0].document || !runs_[1].document) return;
  const WrenchSeries a = root_wrench_series(runs_[0].document->plot_samples(runs_[0].stage));
  const WrenchSeries b = root_wrench_series(runs_[1].document->plot_samples(runs_[1].stage));
  const std::array<std::string, 2> labels{runs_[0].label.toStdString(),
                                          runs_[1].label.toStdString()};
  RootChartStyle style;
  const int choice = components_->currentIndex();
  style.components = choice >= 1;
  if (choice >= 2) style.axes = {choice == 2, choice == 3, choice == 4};
  style.log_scale = log_scale_->isChecked();
  log_scale_->setEnabled(!style.components);
  force_chart_->set_chart(compare_root_chart(style, {&a, &b}, labels));
  style.moment = true;
  moment_chart_->set_chart(compare_root_chart(style, {&a, &b}, labels));
  for (ChartWidget* chart : {force_chart_, moment_chart_})
    chart->set_cursor(timeline_->timeline().time());
}

void CompareWindow::refresh_joint_charts() {
  if (!runs_[0].document || !runs_[1].document || joint_->currentIndex() < 0) return;
  const int segment = joint_->currentIndex();
  const std::array<std::string, 2> labels{runs_[0].label.toStdString(),
                                          runs_[1].label.toStdString()};
  const BodyModel& model = runs_[0].document->file().model;
  const std::array<const std::vector<SampleRecord>*, 2> samples{
      &runs_[0].document->plot_samples(runs_[0].stage),
      &runs_[1].document->plot_samples(runs_[1].stage)};
  if (runs_[1].document->file().model.size() != model.size()) return;
  joint_force_chart_->set_chart(compare_joint_chart(model, segment, false, samples, labels));
  joint_moment_chart_->set_chart(compare_joint_chart(model, segment, true, samples, labels));
  for (ChartWidget* chart : {joint_force_chart_, joint_moment_chart_})
    chart->set_cursor(timeline_->timeline().time());
}

void CompareWindow::show_joint(int segment) {
  if (segment < 0 || segment >= joint_->count()) return;
  joint_->setCurrentIndex(segment);
  tabs_->setCurrentIndex(1);
}

GlyphTypicals CompareWindow::shared_glyph_typicals() const {
  return typicals_;
}

void CompareWindow::on_time_changed(double t) {
  const bool playing = timeline_->playing();
  for (std::size_t i = 0; i < 2; ++i) {
    const Run& r = runs_[i];
    if (!r.document) continue;
    scenes_[i]->scene().set_time(run_time(t, r.document->duration()), playing);
    scenes_[i]->request_render();
  }
  for (ChartWidget* chart : {force_chart_, moment_chart_, joint_force_chart_, joint_moment_chart_})
    chart->set_cursor(t);
}

void CompareWindow::seek(double t) {
  timeline_->pause();
  timeline_->seek(t);
}

double CompareWindow::time() const {
  return timeline_->timeline().time();
}

QImage CompareWindow::grab_view(int index) {
  SceneWidget* s = scenes_.at(static_cast<std::size_t>(index));
  s->render_refined();
  return s->picture();
}

QImage CompareWindow::grab_window() {
  for (SceneWidget* s : scenes_)
    s->render_refined();
  return grab().toImage();
}

const ChartSpec& CompareWindow::force_chart() const {
  return force_chart_->view().chart();
}

const ChartSpec& CompareWindow::moment_chart() const {
  return moment_chart_->view().chart();
}

const ChartSpec& CompareWindow::joint_force_chart() const {
  return joint_force_chart_->view().chart();
}

const ChartSpec& CompareWindow::joint_moment_chart() const {
  return joint_moment_chart_->view().chart();
}

}  // namespace saltus::gui
