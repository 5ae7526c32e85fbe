#include "app/main_window.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QGuiApplication>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTabBar>
#include <QToolBar>
#include <QToolButton>
#include <QUndoView>
#include <QVBoxLayout>
#include <ctime>

#include "app/athlete_controller.h"
#include "app/capture_panel.h"
#include "app/chart_widget.h"
#include "app/compare_controller.h"
#include "app/edit_controller.h"
#include "app/file_controller.h"
#include "app/keyframe_panel.h"
#include "app/model_panel.h"
#include "app/optimize_panel.h"
#include "app/playback_controller.h"
#include "app/plots_panel.h"
#include "app/run_controller.h"
#include "app/scene_widget.h"
#include "app/study_controller.h"
#include "app/study_panel.h"
#include "app/timeline_widget.h"
#include "app/twist_panel.h"
#include "app/video_exporter.h"
#include "app/view_controller.h"
#include "app/what_if_panel.h"
#include "core/screen_fit.h"

namespace saltus::gui {

namespace {

/// The panels' width, px: a quarter of a 1366-pixel laptop screen, a sixth of a 1920 one; the
/// option form wraps its fields below their labels when narrower.
constexpr int kDockWidth = 340;
/// The saved dock layout's version: a layout saved before the panels became one tabbed column
/// is not restored (it would bring back the crowded one).
constexpr int kLayoutVersion = 2;
/// The window's size where the screen has room (core/screen_fit.h).
constexpr int kPreferredWidth = 1600;
constexpr int kPreferredHeight = 1000;

}  // namespace

MainWindow::MainWindow(bool interactive, QWidget* parent) : QMainWindow(parent) {
  setWindowTitle(tr("Saltus"));
  setAcceptDrops(true);
  context_ = std::make_unique<AppContext>(this, interactive);

  // The widgets where the view's single-key shortcuts act exist before the parts that add
  // those shortcuts.
  scene_ = new SceneWidget(this);
  scene_->setFocusPolicy(Qt::StrongFocus);
  scene_->setToolTip(
      tr("Drag to turn, middle-drag to pan, wheel to zoom; click a segment for "
         "the loads at its joint"));
  timeline_ = new TimelineWidget(this);
  context_->add_shortcut_scope(scene_);
  context_->add_shortcut_scope(timeline_);
  plots_ = new PlotsPanel(*context_, this);
  // The charts, not the whole plots panel: its check boxes and lists keep their own keys.
  for (ChartWidget* chart : plots_->charts())
    context_->add_shortcut_scope(chart);

  view_ = new ViewController(*context_, scene_, this);
  playback_ = new PlaybackController(*context_, timeline_, this);
  runs_ = new RunController(*context_, this);
  edits_ = new EditController(*context_, *runs_, this);
  files_ = new FileController(*context_, *view_, *playback_, *plots_, this);
  compare_ = new CompareController(*context_, *view_, this);
  athletes_ = new AthleteController(*context_, *files_, *compare_, this);
  studies_ = new StudyController(*context_, this);
  video_ = new VideoExporter(*context_, *view_, this);
  twist_ = new TwistPanel(*context_, this);
  context_->add_shortcut_scope(twist_->chart());
  what_if_ = new WhatIfPanel(*context_, this);
  remembered_ = {files_, view_, playback_, runs_, plots_, studies_};

  // A frame counts when the window shows a new 3D picture (chart-only redraws do not).
  connect(scene_, &SceneWidget::frame_shown, this, [this] { ++frames_drawn_; });
  connect(playback_, &PlaybackController::time_changed, this, [this](double t, bool playing) {
    view_->set_time(t, playing);
    plots_->set_time(t, playing);
    edits_->capture_panel()->set_time(t);
    twist_->set_time(t);
  });
  connect(edits_->capture_panel(), &CapturePanel::seek_requested, this, &MainWindow::seek);
  // The import's advice, one click away: the capture imported again with the fix.
  connect(edits_->capture_panel(), &CapturePanel::reimport_requested, this,
          [this](const CaptureFileOptions& options) {
            if (document().loaded())
              files_->import_capture(QString::fromStdString(document().file().path), options);
          });
  connect(edits_->capture_panel(), &CapturePanel::import_settings_requested, files_,
          [this] { files_->ask_import_settings(); });
  connect(plots_, &PlotsPanel::seek_requested, this, &MainWindow::seek);
  connect(twist_, &TwistPanel::seek_requested, this, &MainWindow::seek);
  // The what-if flight is drawn beside the athlete while the What if panel is in view.
  connect(what_if_, &WhatIfPanel::flight_changed, this,
          [this] { view_->set_what_if(what_if_->flight(), what_if_->flight_label()); });
  connect(edits_, &EditController::keyframe_chosen, this, &MainWindow::seek);
  connect(edits_->keyframe_panel(), &KeyframePanel::add_requested, this,
          [this] { edits_->add_keyframe(time()); });
  // The panels' Save buttons do what File > Save motion / body model as… do.
  connect(edits_->keyframe_panel(), &KeyframePanel::save_requested, files_,
          [this] { files_->ask_save_motion(); });
  connect(edits_->model_panel(), &ModelPanel::save_requested, files_,
          [this] { files_->ask_save_model(); });
  connect(edits_->model_panel(), &ModelPanel::new_athlete_requested, athletes_,
          [this] { athletes_->open_dialog(); });
  // A click on a segment shows the loads at its joint and marks it; a click beside the body
  // unmarks it (the plot keeps its joint).
  connect(view_, &ViewController::segment_clicked, this, [this](int segment) {
    view_->highlight(segment);
    if (segment >= 0) plots_->show_joint(segment);
  });
  // The mark follows the joint list, so the view never marks another joint than the plot shows.
  connect(plots_, &PlotsPanel::joint_selected, this, [this](int segment) {
    if (view_->highlighted_segment() >= 0) view_->highlight(segment);
  });

  auto* top = new QWidget(this);
  auto* top_layout = new QVBoxLayout(top);
  top_layout->setContentsMargins(0, 0, 0, 0);
  top_layout->setSpacing(0);
  top_layout->addWidget(scene_, 1);
  top_layout->addWidget(timeline_);
  auto* splitter = new QSplitter(Qt::Vertical, this);
  splitter->addWidget(top);
  splitter->addWidget(plots_);
  splitter->setStretchFactor(0, 3);
  splitter->setStretchFactor(1, 2);
  splitter->setChildrenCollapsible(false);
  setCentralWidget(splitter);

  build_menus();
  // Ctrl+Z in a number field whose value was entered undoes that edit, as the Edit menu says.
  edits_->route_undo_keys(this);
  // The first size from the screen it opens on: a laptop's keeps every panel in view.
  const QScreen* screen = QGuiApplication::primaryScreen();
  const QRect available = screen ? screen->availableGeometry() : QRect();
  const WindowFit fit =
      first_window_size(available.width(), available.height(), kPreferredWidth, kPreferredHeight);
  resize(fit.width, fit.height);
  if (interactive && fit.maximise) setWindowState(windowState() | Qt::WindowMaximized);
  if (interactive) load_settings();
  keep_tab_titles_whole();
  scene_->setFocus();
}

MainWindow::~MainWindow() {
  // A window destroyed while shown hides its docks from ~QWidget, once its controllers and the
  // document are gone: the Twist and What if panels must not hear of it then (the What if
  // panel's figure would be drawn from a document already destroyed).
  for (QDockWidget* d : {twist_dock_, what_if_dock_})
    disconnect(d, &QDockWidget::visibilityChanged, nullptr, nullptr);
}

void MainWindow::build_menus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  files_->fill_menu(file, athletes_->new_action(), {video_->action()});

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  edits_->fill_menu(edit);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  view_->fill_menu(view);

  QMenu* playback = menuBar()->addMenu(tr("&Playback"));
  playback_->fill_menu(playback);

  QMenu* optimise = menuBar()->addMenu(tr("&Optimise"));
  runs_->fill_menu(optimise);
  studies_->fill_menu(optimise);

  QMenu* compare = menuBar()->addMenu(tr("&Compare"));
  compare_->fill_menu(compare, athletes_->compare_action());

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&Keyboard and mouse"), this, [this] {
    QMessageBox::information(
        this, tr("Keyboard and mouse"),
        tr("In the 3D view, the timeline and the plots (not while typing in a field):\n"
           "Space  play / pause;  Left / Right  one frame back / forward\n"
           "Home / End  start / end;  Up / Down  faster / slower\n"
           "B / A  show before / after optimisation\n"
           "1 2 3 4  side, front, top, follow camera;  R  reset camera;  Esc  cancel a run\n\n"
           "Anywhere: Ctrl+O open, Ctrl+I import a motion capture, Ctrl+S save result,\n"
           "Ctrl+R run optimisation, "
           "Ctrl+Z undo, Ctrl+Shift+Z redo\n\n"
           "3D view: left-drag turns, middle-drag pans, the wheel zooms towards the body;\n"
           "a click on a body segment plots the loads at its joint (a click beside the body\n"
           "unmarks it). Plots: click or drag to move the time cursor.\n"
           "Drop a *.motion.json, a .bvh capture or a body model on the window to open it."));
  });
  help->addAction(tr("&About Saltus"), this, [this] {
    QMessageBox::about(
        this, tr("About Saltus"),
        tr("<b>Saltus</b> — physics-based simulation of human aerial motion.<br>"
           "Keyframes are interpolated with quaternion B-splines, inverse dynamics gives the "
           "force and moment the motion would need at the root (zero in a valid flight), and "
           "the optimiser makes the motion obey Newton's laws (Wei, Xia &amp; Wang 2008)."));
  });

  QToolBar* bar = addToolBar(tr("Main"));
  bar->setObjectName("main_toolbar");
  bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  files_->fill_toolbar(bar);
  bar->addSeparator();
  view_->fill_toolbar(bar);
  bar->addSeparator();
  // "Compare…" drops down the Compare menu's choices.
  auto* compare_button = new QToolButton(bar);
  compare_button->setText(tr("Compare…"));
  compare_button->setToolTip(tr("Show this motion side by side with another run"));
  compare_button->setMenu(compare);
  compare_button->setPopupMode(QToolButton::InstantPopup);
  bar->addWidget(compare_button);

  build_docks(view);
}

void MainWindow::build_docks(QMenu* view_menu) {
  auto dock = [this](const QString& title, const char* name, QWidget* widget,
                     bool scrolled = true) {
    auto* d = new QDockWidget(title, this);
    d->setObjectName(name);
    // Scrollable, so that no panel sets a minimum height on the window (1280×720 must fit).
    if (scrolled) {
      auto* scroll = new QScrollArea(d);
      scroll->setWidget(widget);
      scroll->setWidgetResizable(true);
      scroll->setFrameShape(QFrame::NoFrame);
      d->setWidget(scroll);
    } else {
      d->setWidget(widget);
    }
    addDockWidget(Qt::RightDockWidgetArea, d);
    return d;
  };
  // The Optimise panel scrolls its own table and options and asks for little height; in a
  // scroll area of its own it was given its wrapped labels' preferred height (886 px at
  // 1366×768) and the column scrolled around the options' scroll bar, two bars side by side.
  QDockWidget* optimise = dock(tr("Optimise"), "optimise_dock", runs_->panel(), false);
  QDockWidget* keyframes = dock(tr("Keyframes"), "keyframe_dock", edits_->keyframe_panel());
  QDockWidget* capture = dock(tr("Capture"), "capture_dock", edits_->capture_panel());
  QDockWidget* model = dock(tr("Model"), "model_dock", edits_->model_panel());
  model_dock_ = model;
  QDockWidget* display = dock(tr("Display"), "display_dock", view_->make_display_panel(this));
  QDockWidget* history = dock(tr("History"), "history_dock", edits_->make_history_view(this));
  history->toggleViewAction()->setText(tr("Edit history"));
  twist_dock_ = dock(tr("Twist"), "twist_dock", twist_);
  study_dock_ = dock(tr("Study"), "study_dock", studies_->panel());
  study_dock_->toggleViewAction()->setText(tr("Study panel"));
  twist_dock_->toggleViewAction()->setText(tr("Twist panel"));
  // It computes only while in view (a tab raised): a hidden panel costs no CPU per edit.
  connect(twist_dock_, &QDockWidget::visibilityChanged, twist_,
          [this](bool visible) { twist_->set_active(visible); });
  what_if_dock_ = dock(tr("What if"), "what_if_dock", what_if_);
  what_if_dock_->toggleViewAction()->setText(tr("What if panel"));
  // It flies only while in view, and the 3D view shows its figure only then.
  connect(what_if_dock_, &QDockWidget::visibilityChanged, what_if_,
          [this](bool visible) { what_if_->set_active(visible); });
  // One column of panels, tabbed, the tabs standing on the window's right edge: on a
  // 1366×768 laptop six tab titles in a row would not fit a panel narrow enough to leave the
  // 3D view three quarters of the width (they were elided to "Optim… Keyfra…"), while a
  // column holds them whole; and one panel at a time gets the full height, so the Optimise
  // panel's run list and status stay in view.
  setTabPosition(Qt::RightDockWidgetArea, QTabWidget::East);
  const std::vector<QDockWidget*> docks = {optimise,    keyframes,     capture,
                                           model,       display,       history,
                                           twist_dock_, what_if_dock_, study_dock_};
  for (std::size_t i = 1; i < docks.size(); ++i)
    tabifyDockWidget(docks[i - 1], docks[i]);
  optimise->raise();
  // The Study panel is a tab of its own once a study runs (View > Study panel before that): its
  // progress and results never cover the 3D view.
  study_dock_->hide();
  connect(studies_, &StudyController::panel_wanted, this, &MainWindow::show_study_panel);
  // The study's tables are wide: a tab under the 3D view, beside the plots, while there are
  // results to show.
  connect(studies_, &StudyController::tables_changed, this, [this](bool results) {
    QWidget* tables = studies_->panel()->tables();
    const int index = plots_->indexOf(tables);
    if (!results) {
      if (index >= 0) plots_->removeTab(index);
      return;
    }
    if (index < 0) plots_->addTab(tables, tr("Study results"));
    plots_->setCurrentWidget(tables);
  });
  // An imported capture brings its panel to the front (its keyframes are picked there).
  connect(files_, &FileController::motion_opened, this, [this, capture] {
    if (document().capture()) capture->raise();
  });
  view_menu->addSeparator();
  for (QDockWidget* d : docks)
    view_menu->addAction(d->toggleViewAction());
  view_menu->addSeparator();
  view_menu->addAction(tr("Where does the &twist come from?"), this, &MainWindow::show_twist_panel);
  view_menu->addAction(tr("&What if…"), this, &MainWindow::show_what_if_panel);
  resizeDocks({optimise}, {kDockWidth}, Qt::Horizontal);
  keep_tab_titles_whole();
}

void MainWindow::keep_tab_titles_whole() {
  // The panels' tabs stand on the right edge: on a short screen (1024×700) they scroll rather
  // than shorten their titles to "T…" and "Wha…".
  for (QTabBar* bar : findChildren<QTabBar*>(QString(), Qt::FindDirectChildrenOnly)) {
    bar->setElideMode(Qt::ElideNone);
    bar->setUsesScrollButtons(true);
  }
}

void MainWindow::show_study_panel() {
  study_dock_->show();
  study_dock_->raise();
}

void MainWindow::show_model_panel() {
  model_dock_->show();
  model_dock_->raise();
}

void MainWindow::show_twist_panel() {
  twist_dock_->show();
  twist_dock_->raise();
}

void MainWindow::show_what_if_panel() {
  what_if_dock_->show();
  what_if_dock_->raise();
}

void MainWindow::load_settings() {
  QSettings s;
  restoreGeometry(s.value("window/geometry").toByteArray());
  restoreState(s.value("window/state").toByteArray(), kLayoutVersion);
  for (RemembersSettings* part : remembered_)
    part->load_settings(s);
}

void MainWindow::save_settings() const {
  QSettings s;
  s.setValue("window/geometry", saveGeometry());
  s.setValue("window/state", saveState(kLayoutVersion));
  for (const RemembersSettings* part : remembered_)
    part->save_settings(s);
}

bool MainWindow::open_motion(const QString& path, QString* error) {
  return files_->open_motion(path, error);
}

void MainWindow::seek(double t) {
  playback_->seek(t);
}

double MainWindow::time() const {
  return playback_->time();
}

void MainWindow::set_stage(Stage stage) {
  view_->set_stage(stage);
}

void MainWindow::set_camera(CameraPreset preset) {
  view_->set_camera(preset);
}

void MainWindow::set_scene_options(const SceneOptions& options) {
  view_->set_scene_options(options);
}

QImage MainWindow::grab_view() {
  scene_->render_refined();
  return scene_->picture();
}

void MainWindow::fix_view_size(const QSize& size) {
  if (size.isEmpty()) {
    scene_->setMinimumSize(320, 240);
    scene_->setMaximumSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
  } else {
    scene_->setFixedSize(size);
  }
  QApplication::processEvents();
}

QImage MainWindow::grab_window() {
  scene_->render_refined();
  return grab().toImage();
}

double MainWindow::benchmark_playback(double seconds) {
  if (!document().loaded()) return 0.0;
  timeline_->go_to_start();
  QApplication::processEvents();
  frames_drawn_ = 0;
  const int renders_before = scene_->render_count();
  const std::clock_t cpu_before = std::clock();  // the process's CPU time, all threads
  QElapsedTimer clock;
  clock.start();
  timeline_->play();
  while (clock.elapsed() < seconds * 1000.0) {
    QApplication::processEvents(QEventLoop::AllEvents, 5);
    if (!timeline_->playing()) timeline_->play();  // keeps going without loop too
  }
  timeline_->pause();
  const double elapsed = clock.elapsed() / 1000.0;
  benchmark_renders_ = scene_->render_count() - renders_before;
  benchmark_cpu_ms_per_frame_ =
      frames_drawn_ > 0
          ? 1000.0 * static_cast<double>(std::clock() - cpu_before) / CLOCKS_PER_SEC / frames_drawn_
          : 0.0;
  return elapsed > 0 ? frames_drawn_ / elapsed : 0.0;
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!files_->confirm_discard(tr("closing"))) {
    event->ignore();
    return;
  }
  if (runs_->running()) {
    runs_->cancel();
    runs_->wait(30000);
  }
  if (context_->interactive()) save_settings();
  compare_->close();
  QMainWindow::closeEvent(event);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  files_->drag_enter(event);
}

void MainWindow::dropEvent(QDropEvent* event) {
  files_->drop(event);
}

}  // namespace saltus::gui
