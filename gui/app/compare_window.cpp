#include "app/compare_window.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QHBoxLayout>
#include <QKeySequence>
#include <QLabel>
#include <QSplitter>
#include <QToolBar>
#include <QVBoxLayout>
#include <cmath>

#include "app/chart_widget.h"
#include "app/scene_widget.h"
#include "app/timeline_widget.h"
#include "core/compare.h"
#include "core/plot_series.h"

namespace saltus::gui {

namespace {

/// Components shown in the overlay: all three axes, or one (six lines are hard to follow).
ComponentMask mask_for(int choice) {
  if (choice <= 0) return all_components();
  ComponentMask mask{};
  const int axis = choice - 1;
  mask[static_cast<std::size_t>(axis)] = mask[static_cast<std::size_t>(axis + 3)] = true;
  return mask;
}

}  // namespace

CompareWindow::CompareWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle(tr("Saltus — compare"));

  auto* views = new QWidget(this);
  auto* views_layout = new QHBoxLayout(views);
  views_layout->setContentsMargins(0, 0, 0, 0);
  for (int i = 0; i < 2; ++i) {
    auto* column = new QWidget(views);
    auto* column_layout = new QVBoxLayout(column);
    column_layout->setContentsMargins(2, 2, 2, 2);
    column_layout->setSpacing(2);
    titles_[i] = new QLabel(column);
    // The runs' colours in the plots: blue first, orange second.
    titles_[i]->setStyleSheet(i == 0 ? "color: #1f4fa8;" : "color: #c25a00;");
    titles_[i]->setTextFormat(Qt::RichText);
    // Long labels wrap instead of widening the window past the screen.
    titles_[i]->setWordWrap(true);
    scenes_[i] = new SceneWidget(column);
    scenes_[i]->scene().set_camera(CameraPreset::kFollow);
    column_layout->addWidget(titles_[i]);
    column_layout->addWidget(scenes_[i], 1);
    views_layout->addWidget(column, 1);
  }
  timeline_ = new TimelineWidget(this);
  connect(timeline_, &TimelineWidget::time_changed, this, &CompareWindow::on_time_changed);

  auto* top = new QWidget(this);
  auto* top_layout = new QVBoxLayout(top);
  top_layout->setContentsMargins(0, 0, 0, 0);
  top_layout->setSpacing(0);
  top_layout->addWidget(views, 1);
  top_layout->addWidget(timeline_);

  auto* charts = new QWidget(this);
  auto* charts_layout = new QHBoxLayout(charts);
  charts_layout->setContentsMargins(2, 2, 2, 2);
  force_chart_ = new ChartWidget(charts);
  moment_chart_ = new ChartWidget(charts);
  charts_layout->addWidget(force_chart_);
  charts_layout->addWidget(moment_chart_);
  for (ChartWidget* chart : {force_chart_, moment_chart_})
    connect(chart, &ChartWidget::seek_requested, this, &CompareWindow::seek);

  auto* splitter = new QSplitter(Qt::Vertical, this);
  splitter->addWidget(top);
  splitter->addWidget(charts);
  splitter->setStretchFactor(0, 3);
  splitter->setStretchFactor(1, 2);
  splitter->setChildrenCollapsible(false);
  setCentralWidget(splitter);

  QToolBar* bar = addToolBar(tr("Compare"));
  bar->setObjectName("compare_toolbar");
  auto* cameras = new QActionGroup(this);
  const char* names[4] = {"Side", "Front", "Top", "Follow"};
  for (int i = 0; i < 4; ++i) {
    QAction* a =
        bar->addAction(tr(names[i]), this, [this, i] { set_camera(static_cast<CameraPreset>(i)); });
    a->setCheckable(true);
    a->setChecked(static_cast<CameraPreset>(i) == CameraPreset::kFollow);
    a->setShortcut(QKeySequence(QString::number(i + 1)));
    cameras->addAction(a);
  }
  bar->addSeparator();
  QAction* play = bar->addAction(tr("Play / pause"), timeline_, &TimelineWidget::toggle_play);
  play->setShortcut(Qt::Key_Space);
  bar->addSeparator();
  bar->addWidget(new QLabel(tr(" Plot components: "), bar));
  components_ = new QComboBox(bar);
  components_->addItems({tr("x, y, z"), tr("x only"), tr("y only"), tr("z only")});
  components_->setToolTip(tr("Which root force and moment components the plots overlay"));
  connect(components_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this] { refresh_charts(); });
  bar->addWidget(components_);
  bar->addSeparator();
  QAction* close_action = bar->addAction(tr("Close compare"), this, &QWidget::close);
  close_action->setShortcuts({QKeySequence::Close, QKeySequence(Qt::Key_Escape)});

  resize(1500, 950);
}

CompareWindow::~CompareWindow() {
  // The views (deleted after the members, with the child widgets) must not keep pointing at
  // the runs' documents, which go first.
  for (SceneWidget* s : scenes_)
    s->scene().set_document(nullptr, Stage::kBefore);
}

void CompareWindow::set_runs(Run first, Run second) {
  runs_ = {std::move(first), std::move(second)};
  double duration = 0.0;
  int frames = 2;
  for (int i = 0; i < 2; ++i) {
    const Run& r = runs_[static_cast<std::size_t>(i)];
    const Stage stage = r.document->available(r.stage);
    runs_[static_cast<std::size_t>(i)].stage = stage;
    scenes_[i]->scene().set_document(r.document.get(), stage);
    scenes_[i]->scene().reset_camera();
    const MotionEvaluation& e = r.document->evaluation(stage);
    titles_[i]->setText(
        tr("<b>%1</b> — %2 · model %3 · %4 · average root force <b>%5 N</b>")
            .arg(r.label.toHtmlEscaped(),
                 QString::fromStdString(r.document->file().motion.name).toHtmlEscaped(),
                 QString::fromStdString(r.document->file().model.name).toHtmlEscaped(),
                 stage == Stage::kAfter ? tr("optimised") : tr("interpolated keyframes"))
            .arg(e.metrics.avg_root_force, 0, 'g', 3));
    duration = compare_duration(duration, r.document->duration());
    frames = std::max(frames, r.document->frame_count(stage));
  }
  const Run& a = runs_[0];
  const Run& b = runs_[1];
  timeline_->set_motion(duration, frames, a.document->evaluation(a.stage).keyframe_times,
                        b.document->evaluation(b.stage).keyframe_times);
  setWindowTitle(tr("Saltus — compare %1 with %2").arg(a.label, b.label));
  refresh_charts();
  timeline_->seek(0.0);
  on_time_changed(timeline_->timeline().time());
}

void CompareWindow::set_scene_options(const SceneOptions& options) {
  // Half-width views: keyframe ghosts and the physics text would cover the body; the titles
  // above the views give each run's numbers instead.
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
  const WrenchSeries a = root_wrench_series(runs_[0].document->evaluation(runs_[0].stage).samples);
  const WrenchSeries b = root_wrench_series(runs_[1].document->evaluation(runs_[1].stage).samples);
  const std::array<std::string, 2> labels{runs_[0].label.toStdString(),
                                          runs_[1].label.toStdString()};
  const ComponentMask mask = mask_for(components_->currentIndex());
  force_chart_->set_chart(compare_root_chart(false, {&a, &b}, labels, mask));
  moment_chart_->set_chart(compare_root_chart(true, {&a, &b}, labels, mask));
  for (ChartWidget* chart : {force_chart_, moment_chart_})
    chart->set_cursor(timeline_->timeline().time());
}

void CompareWindow::on_time_changed(double t) {
  const bool playing = timeline_->playing();
  for (int i = 0; i < 2; ++i) {
    const Run& r = runs_[static_cast<std::size_t>(i)];
    if (!r.document) continue;
    scenes_[i]->scene().set_time(run_time(t, r.document->duration()), playing);
    scenes_[i]->request_render();
  }
  for (ChartWidget* chart : {force_chart_, moment_chart_})
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
  s->render_now();
  return s->picture();
}

const ChartSpec& CompareWindow::force_chart() const {
  return force_chart_->view().chart();
}

const ChartSpec& CompareWindow::moment_chart() const {
  return moment_chart_->view().chart();
}

}  // namespace saltus::gui
