#include "app/main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCheckBox>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/chart_widget.h"
#include "app/compare_window.h"
#include "app/keyframe_panel.h"
#include "app/model_panel.h"
#include "app/optimization_runner.h"
#include "app/optimize_panel.h"
#include "app/scene_widget.h"
#include "app/timeline_widget.h"
#include "core/compare.h"
#include "core/model_edit.h"
#include "core/motion_edit.h"
#include "saltus/base/input_error.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/readable_formats.h"
#include "scene/chart_view.h"

namespace saltus::gui {

namespace {

constexpr int kMaxRecent = 8;
constexpr int kPlotExportWidth = 1400;
constexpr int kPlotExportHeight = 700;

/// Settings keys. The ghosts' key changed when they became off by default: every earlier
/// session stored the old default (on), which must not override the new one.
const char* const kOptionNames[8] = {"trampoline",      "floor_grid",      "parabola",
                                     "com_trace",       "residual_arrows", "joint_arrows",
                                     "keyframe_ghosts", "physics_text"};
const char* const kOptionLabels[8] = {"Trampoline bed",
                                      "Floor grid",
                                      "CoM parabola (ballistic)",
                                      "CoM trace (this motion)",
                                      "Residual force/moment arrows",
                                      "Joint force arrows",
                                      "Keyframe poses (ghosts)",
                                      "Physics numbers"};

bool* option_field(SceneOptions& o, int i) {
  bool* fields[8] = {&o.trampoline,      &o.floor_grid,   &o.parabola, &o.com_trace,
                     &o.residual_arrows, &o.joint_arrows, &o.ghosts,   &o.physics_text};
  return fields[i];
}

QString qstr(const std::string& s) {
  return QString::fromStdString(s);
}

/// A checkbox that mirrors a checkable action both ways.
QCheckBox* checkbox_for(QAction* action, QWidget* parent) {
  auto* box = new QCheckBox(action->text().remove('&'), parent);
  box->setChecked(action->isChecked());
  box->setToolTip(action->toolTip());
  QObject::connect(box, &QCheckBox::toggled, action, &QAction::setChecked);
  QObject::connect(action, &QAction::toggled, box, &QCheckBox::setChecked);
  return box;
}

}  // namespace

MainWindow::MainWindow(bool interactive, QWidget* parent)
    : QMainWindow(parent), interactive_(interactive) {
  setWindowTitle(tr("Saltus"));
  setAcceptDrops(true);
  runner_ = new OptimizationRunner(this);
  connect(runner_, &OptimizationRunner::progress, this, &MainWindow::on_optimization_progress);
  connect(runner_, &OptimizationRunner::finished, this, &MainWindow::on_optimization_finished);
  build_ui();
  build_menus();
  scene_->scene().set_camera(CameraPreset::kFollow);
  if (interactive_) load_settings();
  refresh_all(true);
}

MainWindow::~MainWindow() = default;

void MainWindow::build_ui() {
  scene_ = new SceneWidget(this);
  // A frame counts when the window shows a new 3D picture (chart-only redraws do not).
  connect(scene_, &SceneWidget::frame_shown, this, [this] { ++frames_drawn_; });
  connect(scene_, &SceneWidget::segment_clicked, this, &MainWindow::pick_segment);
  timeline_ = new TimelineWidget(this);
  connect(timeline_, &TimelineWidget::time_changed, this, &MainWindow::on_time_changed);

  auto* top = new QWidget(this);
  auto* top_layout = new QVBoxLayout(top);
  top_layout->setContentsMargins(0, 0, 0, 0);
  top_layout->setSpacing(0);
  top_layout->addWidget(scene_, 1);
  top_layout->addWidget(timeline_);

  plots_ = new QTabWidget(this);
  // Root force and moment, side by side, with the component switches.
  auto* root_tab = new QWidget(plots_);
  auto* root_layout = new QVBoxLayout(root_tab);
  root_layout->setContentsMargins(2, 2, 2, 2);
  auto* switches = new QHBoxLayout;
  switches->addWidget(new QLabel(tr("Components:"), root_tab));
  for (int i = 0; i < 6; ++i) {
    // Short labels keep the row narrow; the legends and tooltips name them in full.
    component_boxes_[i] = new QCheckBox(QString("F%1").arg(i + 1), root_tab);
    component_boxes_[i]->setToolTip(qstr(wrench_component_name(i)) +
                                    (i < 3 ? tr(" (N, root frame)") : tr(" (N·m, root frame)")));
    component_boxes_[i]->setChecked(true);
    connect(component_boxes_[i], &QCheckBox::toggled, this, [this] { refresh_root_charts(); });
    switches->addWidget(component_boxes_[i]);
  }
  switches->addStretch(1);
  switches->addWidget(new QLabel(tr("dashed: before, solid: after"), root_tab));
  root_layout->addLayout(switches);
  auto* root_charts = new QHBoxLayout;
  force_chart_ = new ChartWidget(root_tab);
  moment_chart_ = new ChartWidget(root_tab);
  root_charts->addWidget(force_chart_);
  root_charts->addWidget(moment_chart_);
  root_layout->addLayout(root_charts, 1);
  plots_->addTab(root_tab, tr("Root force && moment"));

  auto* joint_tab = new QWidget(plots_);
  joint_tab_ = joint_tab;
  auto* joint_layout = new QVBoxLayout(joint_tab);
  joint_layout->setContentsMargins(2, 2, 2, 2);
  auto* joint_row = new QHBoxLayout;
  joint_row->addWidget(new QLabel(tr("Joint:"), joint_tab));
  joint_combo_ = new QComboBox(joint_tab);
  joint_combo_->setMinimumContentsLength(18);
  joint_row->addWidget(joint_combo_);
  joint_row->addStretch(1);
  joint_layout->addLayout(joint_row);
  joint_chart_ = new ChartWidget(joint_tab);
  joint_layout->addWidget(joint_chart_, 1);
  connect(joint_combo_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int joint) {
    refresh_joint_chart();
    // The highlighted segment follows the list, so the 3D view never marks another joint than
    // the plot shows.
    if (scene_->scene().highlight() >= 0 && joint >= 0) {
      scene_->scene().set_highlight(joint);
      scene_->request_render();
    }
  });
  plots_->addTab(joint_tab, tr("Joint loads"));

  auto* rotation_tab = new QWidget(plots_);
  auto* rotation_layout = new QVBoxLayout(rotation_tab);
  rotation_layout->setContentsMargins(2, 2, 2, 2);
  auto* rotation_row = new QHBoxLayout;
  rotation_row->addWidget(new QLabel(tr("Show:"), rotation_tab));
  rotation_combo_ = new QComboBox(rotation_tab);
  for (const std::string& name : rotation_quantity_names())
    rotation_combo_->addItem(qstr(name));
  rotation_row->addWidget(rotation_combo_);
  rotation_row->addStretch(1);
  rotation_layout->addLayout(rotation_row);
  rotation_chart_ = new ChartWidget(rotation_tab);
  rotation_layout->addWidget(rotation_chart_, 1);
  connect(rotation_combo_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this] { refresh_rotation_chart(); });
  plots_->addTab(rotation_tab, tr("Rotation (teaching)"));
  connect(plots_, &QTabWidget::currentChanged, this, [this] { update_cursors(); });

  for (ChartWidget* chart : {force_chart_, moment_chart_, joint_chart_, rotation_chart_})
    connect(chart, &ChartWidget::seek_requested, this, &MainWindow::seek);

  auto* splitter = new QSplitter(Qt::Vertical, this);
  splitter->addWidget(top);
  splitter->addWidget(plots_);
  splitter->setStretchFactor(0, 3);
  splitter->setStretchFactor(1, 2);
  splitter->setChildrenCollapsible(false);
  setCentralWidget(splitter);

  optimize_panel_ = new OptimizePanel(this);
  connect(optimize_panel_, &OptimizePanel::run_requested, this,
          [this] { start_optimization(optimize_panel_->settings()); });
  connect(optimize_panel_, &OptimizePanel::cancel_requested, this,
          &MainWindow::cancel_optimization);

  keyframe_panel_ = new KeyframePanel(this);
  connect(keyframe_panel_, &KeyframePanel::keyframe_selected, this, [this](int k) {
    if (document_.loaded() && k < static_cast<int>(document_.file().motion.keyframes.size()))
      seek(document_.file().motion.keyframes[static_cast<std::size_t>(k)].time);
  });
  connect(keyframe_panel_, &KeyframePanel::angles_edited, this,
          [this](int k, int s, double x, double y, double z) {
            set_keyframe_angles(k, s, x, y, z, nullptr);
          });
  connect(keyframe_panel_, &KeyframePanel::time_edited, this,
          [this](int k, double t) { set_keyframe_time(k, t, nullptr); });
  connect(keyframe_panel_, &KeyframePanel::add_requested, this,
          [this] { add_keyframe(time(), nullptr); });
  connect(keyframe_panel_, &KeyframePanel::delete_requested, this,
          [this](int k) { delete_keyframe(k, nullptr); });
  connect(keyframe_panel_, &KeyframePanel::save_requested, this, [this] {
    const QFileInfo motion(qstr(document_.file().path));
    const QString suggestion = QDir(last_dir_).filePath(
        motion.completeBaseName().remove(".motion") + "-edited.motion.json");
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save motion"), suggestion, qstr(save_dialog_filter(ReadableKind::kMotion)));
    if (!path.isEmpty()) save_motion(path);
  });

  model_panel_ = new ModelPanel(this);
  connect(model_panel_, &ModelPanel::factors_edited, this,
          [this](const std::vector<double>& f) { set_mass_factors(f, nullptr); });
  connect(model_panel_, &ModelPanel::save_requested, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save body model"),
                                                      QDir(last_dir_).filePath("edited-model.json"),
                                                      qstr(dialog_filter(ReadableKind::kModel)));
    if (!path.isEmpty()) save_model(path);
  });

  status_label_ = new QLabel(this);
  statusBar()->addWidget(status_label_, 1);
  resize(1600, 1000);
}

void MainWindow::build_menus() {
  // File.
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* open = file->addAction(
      style()->standardIcon(QStyle::SP_DialogOpenButton), tr("&Open motion…"), this, [this] {
        const QString path =
            ask_open_file(tr("Open motion"), qstr(dialog_filter(ReadableKind::kMotion)));
        if (!path.isEmpty()) open_motion(path);
      });
  open->setShortcut(QKeySequence::Open);
  file->addAction(tr("Open &model…"), this, [this] {
    const QString path =
        ask_open_file(tr("Open body model"), qstr(dialog_filter(ReadableKind::kModel)));
    if (!path.isEmpty()) open_model(path);
  });
  recent_menu_ = file->addMenu(tr("Open &recent"));
  rebuild_recent_menu();
  file->addSeparator();
  save_action_ = file->addAction(
      style()->standardIcon(QStyle::SP_DialogSaveButton), tr("&Save result folder…"), this, [this] {
        const QFileInfo motion(qstr(document_.file().path));
        const QString suggestion =
            QDir(last_dir_).filePath(motion.completeBaseName().remove(".motion") + "-result");
        const QString dir = QFileDialog::getSaveFileName(
            this, tr("Save result folder (created or replaced)"), suggestion, QString(), nullptr,
            QFileDialog::DontConfirmOverwrite);
        if (!dir.isEmpty()) save_result(dir);
      });
  save_action_->setShortcut(QKeySequence::Save);
  export_view_action_ = file->addAction(tr("Export 3D view as PNG…"), this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export 3D view"), QDir(last_dir_).filePath("view.png"), tr("PNG (*.png)"));
    if (!path.isEmpty()) export_view_png(path);
  });
  export_plots_action_ = file->addAction(tr("Export plots as PNG…"), this, [this] {
    const QString dir =
        QFileDialog::getExistingDirectory(this, tr("Export plots into folder"), last_dir_);
    if (dir.isEmpty()) return;
    QStringList written;
    if (export_plots(dir, &written))
      statusBar()->showMessage(tr("Wrote %1 into %2").arg(written.join(", "), dir), 8000);
  });
  export_window_action_ = file->addAction(tr("Export window screenshot…"), this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export window"), QDir(last_dir_).filePath("saltus.png"), tr("PNG (*.png)"));
    if (!path.isEmpty()) export_window_png(path);
  });
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);

  // View: stage, camera, what is drawn.
  QMenu* view = menuBar()->addMenu(tr("&View"));
  auto* stages = new QActionGroup(this);
  before_action_ = view->addAction(tr("Show &interpolated motion (before)"));
  after_action_ = view->addAction(tr("Show &optimised motion (after)"));
  for (QAction* a : {before_action_, after_action_}) {
    a->setCheckable(true);
    stages->addAction(a);
  }
  before_action_->setShortcut(Qt::Key_B);
  after_action_->setShortcut(Qt::Key_A);
  before_action_->setChecked(true);
  connect(before_action_, &QAction::triggered, this, [this] { set_stage(Stage::kBefore); });
  connect(after_action_, &QAction::triggered, this, [this] { set_stage(Stage::kAfter); });
  view->addSeparator();
  auto* cameras = new QActionGroup(this);
  const char* camera_labels[4] = {"&Side view", "&Front view", "&Top view", "F&ollow the CoM"};
  const char* camera_keys[4] = {"1", "2", "3", "4"};
  for (int i = 0; i < 4; ++i) {
    camera_actions_[i] = view->addAction(tr(camera_labels[i]));
    camera_actions_[i]->setCheckable(true);
    camera_actions_[i]->setShortcut(QKeySequence(camera_keys[i]));
    cameras->addAction(camera_actions_[i]);
    connect(camera_actions_[i], &QAction::triggered, this,
            [this, i] { set_camera(static_cast<CameraPreset>(i)); });
  }
  // Follow by default: the body fills the view; Side shows the whole flight.
  camera_actions_[static_cast<int>(CameraPreset::kFollow)]->setChecked(true);
  QAction* reset = view->addAction(tr("&Reset camera"), this, [this] {
    scene_->scene().reset_camera();
    scene_->render_now();
  });
  reset->setShortcut(Qt::Key_R);
  view->addSeparator();
  SceneOptions defaults;
  for (int i = 0; i < 8; ++i) {
    option_actions_[i] = view->addAction(tr(kOptionLabels[i]));
    option_actions_[i]->setCheckable(true);
    option_actions_[i]->setChecked(*option_field(defaults, i));
    connect(option_actions_[i], &QAction::toggled, this, [this] {
      SceneOptions o;
      for (int k = 0; k < 8; ++k)
        *option_field(o, k) = option_actions_[k]->isChecked();
      scene_->scene().set_options(o);
      scene_->render_now();
    });
  }

  // Playback.
  QMenu* playback = menuBar()->addMenu(tr("&Playback"));
  play_action_ = playback->addAction(tr("&Play / pause"), timeline_, &TimelineWidget::toggle_play);
  play_action_->setShortcut(Qt::Key_Space);
  QAction* back = playback->addAction(tr("Step &back"), timeline_, &TimelineWidget::step_back);
  back->setShortcut(Qt::Key_Left);
  QAction* forward =
      playback->addAction(tr("Step &forward"), timeline_, &TimelineWidget::step_forward);
  forward->setShortcut(Qt::Key_Right);
  QAction* start = playback->addAction(tr("Go to &start"), timeline_, &TimelineWidget::go_to_start);
  start->setShortcut(Qt::Key_Home);
  QAction* end = playback->addAction(tr("Go to &end"), timeline_, &TimelineWidget::go_to_end);
  end->setShortcut(Qt::Key_End);
  QAction* slower = playback->addAction(tr("S&lower"), this, [this] {
    const std::vector<double> c = speed_choices();
    const double now = timeline_->timeline().speed();
    double next = c.front();
    for (double s : c)
      if (s < now - 1e-9) next = s;
    timeline_->set_speed(next);
  });
  slower->setShortcut(Qt::Key_Down);
  QAction* faster = playback->addAction(tr("F&aster"), this, [this] {
    const std::vector<double> c = speed_choices();
    const double now = timeline_->timeline().speed();
    double next = c.back();
    for (auto it = c.rbegin(); it != c.rend(); ++it)
      if (*it > now + 1e-9) next = *it;
    timeline_->set_speed(next);
  });
  faster->setShortcut(Qt::Key_Up);
  QAction* loop = playback->addAction(tr("&Loop"));
  loop->setCheckable(true);
  loop->setChecked(timeline_->timeline().loop());
  connect(loop, &QAction::toggled, timeline_, &TimelineWidget::set_loop);
  connect(timeline_, &TimelineWidget::loop_changed, loop, &QAction::setChecked);
  connect(timeline_, &TimelineWidget::playing_changed, this, [this](bool playing) {
    play_action_->setText(playing ? tr("&Pause") : tr("&Play"));
    if (!playing) update_cursors();
  });

  // Optimise.
  QMenu* optimise = menuBar()->addMenu(tr("&Optimise"));
  run_action_ = optimise->addAction(tr("&Run optimisation"), this,
                                    [this] { start_optimization(optimize_panel_->settings()); });
  run_action_->setShortcut(Qt::CTRL | Qt::Key_R);
  cancel_action_ = optimise->addAction(tr("&Cancel"), this, &MainWindow::cancel_optimization);
  cancel_action_->setShortcut(Qt::Key_Escape);

  // Compare: a second window with two runs side by side.
  QMenu* compare = menuBar()->addMenu(tr("&Compare"));
  compare_before_after_action_ = compare->addAction(tr("&Before vs after optimisation"), this,
                                                    [this] { compare_before_after(); });
  compare_motion_action_ = compare->addAction(tr("With another &motion…"), this, [this] {
    const QString path =
        ask_open_file(tr("Compare with motion"), qstr(dialog_filter(ReadableKind::kMotion)));
    if (!path.isEmpty()) compare_with_motion(path);
  });
  compare_model_action_ = compare->addAction(tr("With another body m&odel…"), this, [this] {
    const QString path =
        ask_open_file(tr("Compare with body model"), qstr(dialog_filter(ReadableKind::kModel)));
    if (!path.isEmpty()) compare_with_model(path);
  });
  compare_folder_action_ = compare->addAction(tr("With a saved &result folder…"), this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(
        this, tr("Compare with a `saltus optimize` result folder"), last_dir_);
    if (!dir.isEmpty()) compare_with_folder(dir);
  });
  compare->addSeparator();
  close_compare_action_ =
      compare->addAction(tr("&Close compare"), this, &MainWindow::close_compare);

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&Keyboard and mouse"), this, [this] {
    QMessageBox::information(
        this, tr("Keyboard and mouse"),
        tr("Space  play / pause\nLeft / Right  one frame back / forward\nHome / End  start / end\n"
           "Up / Down  faster / slower\nB / A  show before / after optimisation\n"
           "1 2 3 4  side, front, top, follow camera;  R  reset camera\n"
           "Ctrl+O open, Ctrl+S save result, Ctrl+R run optimisation, Esc cancel\n\n"
           "3D view: left-drag rotates, middle-drag pans, wheel zooms; a click on a body\n"
           "segment plots the loads at its joint (a click beside the body unmarks it).\n"
           "Plots: click or drag to move the time cursor.\n"
           "Drop a *.motion.json (or a body model) on the window to open it."));
  });
  help->addAction(tr("&About Saltus"), this, [this] {
    QMessageBox::about(
        this, tr("About Saltus"),
        tr("<b>Saltus</b> — physics-based simulation of human aerial motion.<br>"
           "Keyframes are interpolated with quaternion B-splines, inverse dynamics gives the "
           "force and moment the motion would need at the root (zero in a valid flight), and "
           "the optimiser makes the motion obey Newton's laws (Wei, Xia &amp; Wang 2008)."));
  });

  // Toolbar: the everyday actions.
  QToolBar* bar = addToolBar(tr("Main"));
  bar->setObjectName("main_toolbar");
  bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  bar->addAction(open);
  bar->addAction(save_action_);
  bar->addSeparator();
  bar->addAction(before_action_);
  bar->addAction(after_action_);
  before_action_->setIconText(tr("Before"));
  after_action_->setIconText(tr("After"));
  bar->addSeparator();
  const char* short_names[4] = {"Side", "Front", "Top", "Follow"};
  for (int i = 0; i < 4; ++i) {
    camera_actions_[i]->setIconText(tr(short_names[i]));
    bar->addAction(camera_actions_[i]);
  }
  reset->setIconText(tr("Reset"));
  bar->addAction(reset);
  bar->addSeparator();
  // "Compare…" drops down the Compare menu's choices.
  auto* compare_button = new QToolButton(bar);
  compare_button->setText(tr("Compare…"));
  compare_button->setToolTip(tr("Show this motion side by side with another run"));
  compare_button->setMenu(compare);
  compare_button->setPopupMode(QToolButton::InstantPopup);
  bar->addWidget(compare_button);

  // Docks: display options and the optimisation panel.
  auto* display_dock = new QDockWidget(tr("Display"), this);
  display_dock->setObjectName("display_dock");
  auto* display = new QWidget(display_dock);
  auto* display_layout = new QGridLayout(display);
  for (int i = 0; i < 8; ++i)
    display_layout->addWidget(checkbox_for(option_actions_[i], display), i / 2, i % 2);
  display_dock->setWidget(display);
  addDockWidget(Qt::RightDockWidgetArea, display_dock);

  auto* optimise_dock = new QDockWidget(tr("Optimise"), this);
  optimise_dock->setObjectName("optimise_dock");
  optimise_dock->setWidget(optimize_panel_);
  addDockWidget(Qt::RightDockWidgetArea, optimise_dock);
  auto* keyframe_dock = new QDockWidget(tr("Keyframes"), this);
  keyframe_dock->setObjectName("keyframe_dock");
  keyframe_dock->setWidget(keyframe_panel_);
  addDockWidget(Qt::RightDockWidgetArea, keyframe_dock);
  tabifyDockWidget(optimise_dock, keyframe_dock);
  auto* model_dock = new QDockWidget(tr("Model"), this);
  model_dock->setObjectName("model_dock");
  model_dock->setWidget(model_panel_);
  addDockWidget(Qt::RightDockWidgetArea, model_dock);
  tabifyDockWidget(keyframe_dock, model_dock);
  optimise_dock->raise();
  view->addSeparator();
  view->addAction(display_dock->toggleViewAction());
  view->addAction(optimise_dock->toggleViewAction());
  view->addAction(keyframe_dock->toggleViewAction());
  view->addAction(model_dock->toggleViewAction());
  resizeDocks({display_dock, optimise_dock}, {400, 400}, Qt::Horizontal);
}

void MainWindow::load_settings() {
  QSettings s;
  restoreGeometry(s.value("window/geometry").toByteArray());
  restoreState(s.value("window/state").toByteArray());
  last_dir_ = s.value("files/last_dir", QDir::homePath()).toString();
  recent_ = s.value("files/recent").toStringList();
  rebuild_recent_menu();
  optimize_panel_->set_settings(
      settings_from_entries([&s](const std::string& key) -> std::optional<std::string> {
        if (!s.contains(qstr(key))) return std::nullopt;
        return s.value(qstr(key)).toString().toStdString();
      }));
  for (int i = 0; i < 8; ++i)
    option_actions_[i]->setChecked(
        s.value(QString("view/") + kOptionNames[i], option_actions_[i]->isChecked()).toBool());
  const auto preset =
      camera_preset_from_name(s.value("view/camera", "follow").toString().toStdString());
  if (preset) set_camera(*preset);
  timeline_->set_speed(s.value("playback/speed", 1.0).toDouble());
  timeline_->set_loop(s.value("playback/loop", true).toBool());
  rotation_combo_->setCurrentIndex(s.value("plots/rotation_quantity", 0).toInt());
  for (int i = 0; i < 6; ++i)
    component_boxes_[i]->setChecked(
        s.value(QString("plots/component_%1").arg(i + 1), true).toBool());
  plots_->setCurrentIndex(s.value("plots/tab", 0).toInt());
}

void MainWindow::save_settings() const {
  QSettings s;
  s.setValue("window/geometry", saveGeometry());
  s.setValue("window/state", saveState());
  s.setValue("files/last_dir", last_dir_);
  s.setValue("files/recent", recent_);
  for (const auto& [key, text] : settings_entries(optimize_panel_->settings()))
    s.setValue(qstr(key), qstr(text));
  for (int i = 0; i < 8; ++i)
    s.setValue(QString("view/") + kOptionNames[i], option_actions_[i]->isChecked());
  s.setValue("view/camera", qstr(camera_preset_name(scene_->scene().camera())));
  s.setValue("playback/speed", timeline_->timeline().speed());
  s.setValue("playback/loop", timeline_->timeline().loop());
  s.setValue("plots/rotation_quantity", rotation_combo_->currentIndex());
  for (int i = 0; i < 6; ++i)
    s.setValue(QString("plots/component_%1").arg(i + 1), component_boxes_[i]->isChecked());
  s.setValue("plots/tab", plots_->currentIndex());
}

bool MainWindow::fail(const QString& title, const QString& message, QString* error) {
  if (error) {
    *error = message;
  } else {
    QMessageBox::critical(this, title, message);
  }
  return false;
}

QString MainWindow::ask_open_file(const QString& title, const QString& filter) {
  return QFileDialog::getOpenFileName(this, title, last_dir_, filter);
}

bool MainWindow::open_motion(const QString& path, QString* error) {
  if (optimization_running()) cancel_optimization();
  try {
    // A model chosen with "Open model" applies to every motion opened after it.
    document_.load(path.toStdString(), model_override_);
  } catch (const InputError& e) {
    return fail(tr("Cannot open motion"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return fail(tr("Cannot open motion"), path + ": " + qstr(e.what()), error);
  }
  ++generation_;
  stage_ = Stage::kBefore;
  last_dir_ = QFileInfo(path).absolutePath();
  add_recent(QFileInfo(path).absoluteFilePath());
  optimize_panel_->clear_result();
  optimize_panel_->set_available(true);
  refresh_all(true);
  scene_->scene().set_highlight(-1);  // a pick belongs to the motion it was made on
  timeline_->seek(0.0);
  const MotionFile& f = document_.file();
  status_label_->setText(
      tr("%1 — model %2 (%3 kg), %4 keyframes, flight %5 s, average root force %6 N")
          .arg(qstr(f.motion.name), qstr(f.model.name))
          .arg(f.model.total_mass(), 0, 'f', 1)
          .arg(f.motion.keyframes.size())
          .arg(f.motion.flight_time(), 0, 'f', 2)
          .arg(document_.evaluation(Stage::kBefore).metrics.avg_root_force, 0, 'g', 3));
  emit motion_opened();
  return true;
}

bool MainWindow::open_model(const QString& path, QString* error) {
  const std::string absolute = QFileInfo(path).absoluteFilePath().toStdString();
  try {
    // Validate the model on its own first, so that its own errors are reported as such.
    load_body_model(absolute);
    if (document_.loaded()) {
      if (optimization_running()) cancel_optimization();
      const double t = time();
      document_.load(document_.file().path, absolute, document_.evaluate_options().samples);
      ++generation_;
      stage_ = Stage::kBefore;
      optimize_panel_->clear_result();
      refresh_all(false);
      timeline_->seek(t);
    }
  } catch (const InputError& e) {
    return fail(tr("Cannot use model"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return fail(tr("Cannot use model"), path + ": " + qstr(e.what()), error);
  }
  // Used for the motions opened from now on, too.
  model_override_ = absolute;
  last_dir_ = QFileInfo(path).absolutePath();
  statusBar()->showMessage(tr("Model %1 in use").arg(path), 6000);
  return true;
}

bool MainWindow::save_result(const QString& dir, QString* error) {
  if (!document_.loaded()) return fail(tr("Nothing to save"), tr("Open a motion first."), error);
  try {
    document_.save_result(dir.toStdString());
  } catch (const InputError& e) {
    return fail(tr("Cannot save result"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return fail(tr("Cannot save result"), dir + ": " + qstr(e.what()), error);
  }
  last_dir_ = QFileInfo(dir).absolutePath();
  statusBar()->showMessage(tr("Saved %1").arg(dir), 6000);
  return true;
}

bool MainWindow::export_view_png(const QString& path, QString* error) {
  const QImage image = grab_view();
  if (image.isNull() || !image.save(path, "PNG"))
    return fail(tr("Cannot export"), tr("%1: cannot write the image").arg(path), error);
  last_dir_ = QFileInfo(path).absolutePath();
  return true;
}

bool MainWindow::export_window_png(const QString& path, QString* error) {
  const QImage image = grab_window();
  if (image.isNull() || !image.save(path, "PNG"))
    return fail(tr("Cannot export"), tr("%1: cannot write the image").arg(path), error);
  last_dir_ = QFileInfo(path).absolutePath();
  return true;
}

bool MainWindow::export_plots(const QString& dir, QStringList* written, QString* error) {
  if (!document_.loaded()) return fail(tr("Nothing to export"), tr("Open a motion first."), error);
  const std::string joint =
      document_.file().model.segments[std::max(0, joint_combo_->currentIndex())].joint;
  const std::vector<std::pair<QString, ChartWidget*>> charts = {
      {"root_force.png", force_chart_},
      {"root_moment.png", moment_chart_},
      {qstr("joint_loads_" + joint + ".png"), joint_chart_},
      {QString("rotation_%1.png").arg(rotation_combo_->currentIndex() + 1), rotation_chart_}};
  try {
    std::filesystem::create_directories(dir.toStdString());
    for (const auto& [name, chart] : charts) {
      const QString path = QDir(dir).filePath(name);
      write_chart_png(chart->view().chart(), path.toStdString(), kPlotExportWidth,
                      kPlotExportHeight);
      if (written) written->append(name);
    }
  } catch (const std::exception& e) {
    return fail(tr("Cannot export plots"), qstr(e.what()), error);
  }
  last_dir_ = dir;
  return true;
}

OptimizeSettings MainWindow::optimize_settings() const {
  return optimize_panel_->settings();
}

bool MainWindow::start_optimization(const OptimizeSettings& settings, QString* error) {
  if (!document_.loaded())
    return fail(tr("Nothing to optimise"), tr("Open a motion first."), error);
  if (optimization_running())
    return fail(tr("Already running"), tr("An optimisation is already running."), error);
  try {
    running_options_ = to_optimize_options(settings);
  } catch (const std::invalid_argument& e) {
    return fail(tr("Cannot optimise"), qstr(e.what()), error);
  }
  optimize_panel_->set_settings(settings);
  runner_->start(document_.file(), running_options_, generation_);
  optimize_panel_->set_running(true);
  update_actions();
  statusBar()->showMessage(tr("Optimising…"));
  return true;
}

void MainWindow::cancel_optimization() {
  if (!optimization_running()) return;
  runner_->cancel();
  optimize_panel_->show_message(tr("Cancelling after the current iteration…"));
}

bool MainWindow::optimization_running() const {
  return runner_->running();
}

bool MainWindow::wait_for_optimization(int timeout_ms) {
  if (!optimization_running()) return true;
  // A nested event loop that sleeps between events (no busy polling competing with the worker).
  QEventLoop loop;
  connect(this, &MainWindow::optimization_finished, &loop, &QEventLoop::quit);
  QTimer::singleShot(timeout_ms, &loop, &QEventLoop::quit);
  loop.exec();
  return !optimization_running();
}

void MainWindow::on_optimization_progress(const ProgressInfo& info) {
  optimize_panel_->show_progress(info);
}

void MainWindow::on_optimization_finished(int tag, bool ok, const QString& error) {
  optimize_panel_->set_running(false);
  std::optional<OptimizationResult> result = runner_->take_result();
  update_actions();
  if (tag != generation_) {
    // The motion changed while optimising: the result belongs to a file no longer open.
    optimize_panel_->show_message(tr("Discarded the result of the previous motion."));
    emit optimization_finished(false);
    return;
  }
  if (!ok || !result) {
    optimize_panel_->show_message(tr("Failed: %1").arg(error));
    statusBar()->clearMessage();
    if (interactive_)
      QMessageBox::critical(this, tr("Optimisation failed"), error);
    else
      qWarning("saltus-gui: the optimisation failed: %s", qPrintable(error));
    emit optimization_finished(false);
    return;
  }
  const OptimizationResult& r = *result;
  optimize_panel_->show_result(result_table(r, running_options_));
  optimize_panel_->show_message(tr("%1 after %2 iterations in %3 s: average root force %4 N → %5 N")
                                    .arg(qstr(r.solve.status))
                                    .arg(r.solve.iterations)
                                    .arg(r.solve.seconds, 0, 'f', 1)
                                    .arg(r.before.metrics.avg_root_force, 0, 'g', 3)
                                    .arg(r.after.metrics.avg_root_force, 0, 'g', 3));
  statusBar()->showMessage(tr("Optimised (%1)").arg(qstr(r.solve.status)), 10000);
  const double t = time();
  document_.set_optimization(std::move(*result), running_options_);
  stage_ = Stage::kAfter;
  refresh_all(false);
  timeline_->seek(t);
  emit optimization_finished(true);
}

void MainWindow::refresh_all(bool fit_camera) {
  const bool loaded = document_.loaded();
  stage_ = loaded ? document_.available(stage_) : Stage::kBefore;
  scene_->scene().set_document(loaded ? &document_ : nullptr, stage_);
  if (fit_camera) scene_->scene().reset_camera();
  if (loaded) {
    const MotionEvaluation& given = document_.evaluation(Stage::kBefore);
    std::vector<double> optimised;
    if (document_.has_optimization())
      optimised = document_.evaluation(Stage::kAfter).keyframe_times;
    timeline_->set_motion(document_.duration(), document_.frame_count(stage_), given.keyframe_times,
                          optimised);
    setWindowTitle(tr("Saltus — %1%2")
                       .arg(qstr(document_.file().motion.name),
                            document_.edited() ? tr(" (edited)") : QString()));
    // Joint list: every joint of the model (the root's "joint" is the residual itself).
    const int previous = joint_combo_->currentIndex();
    {
      const QSignalBlocker block(joint_combo_);
      joint_combo_->clear();
      for (const Segment& s : document_.file().model.segments)
        joint_combo_->addItem(qstr(s.joint + "  (" + s.name + ")"));
      const int knee = document_.file().model.joint_index("knee_l");
      joint_combo_->setCurrentIndex(
          previous >= 0 && previous < joint_combo_->count() ? previous : std::max(0, knee));
    }
  }
  keyframe_panel_->set_motion(loaded ? &document_.file().motion : nullptr,
                              loaded ? &document_.file().model : nullptr);
  model_panel_->set_model(loaded ? &document_.loaded_model() : nullptr,
                          loaded ? &document_.file().model : nullptr);
  refresh_root_charts();
  refresh_joint_chart();
  refresh_rotation_chart();
  update_actions();
  timeline_->setEnabled(loaded);
  on_time_changed(timeline_->timeline().time());
}

void MainWindow::refresh_root_charts() {
  if (!document_.loaded()) {
    ChartSpec empty;
    empty.title = "Open a motion to see its root force and moment";
    force_chart_->set_chart(empty);
    moment_chart_->set_chart(empty);
    return;
  }
  ComponentMask mask;
  for (int i = 0; i < 6; ++i)
    mask[i] = component_boxes_[i]->isChecked();
  const bool optimised = document_.has_optimization();
  const WrenchSeries before = root_wrench_series(document_.evaluation(Stage::kBefore).samples);
  WrenchSeries after;
  if (optimised) after = root_wrench_series(document_.evaluation(Stage::kAfter).samples);
  const std::vector<double>& times_before = document_.evaluation(Stage::kBefore).keyframe_times;
  const std::vector<double> times_after =
      optimised ? document_.evaluation(Stage::kAfter).keyframe_times : std::vector<double>{};
  force_chart_->set_chart(root_wrench_chart(false, before, optimised ? &after : nullptr, mask,
                                            times_before, times_after));
  moment_chart_->set_chart(root_wrench_chart(true, before, optimised ? &after : nullptr, mask,
                                             times_before, times_after));
  update_cursors();
}

void MainWindow::refresh_joint_chart() {
  if (!document_.loaded() || joint_combo_->currentIndex() < 0) {
    ChartSpec empty;
    empty.title = "Open a motion to see the loads at its joints";
    joint_chart_->set_chart(empty);
    return;
  }
  const bool optimised = document_.has_optimization();
  joint_chart_->set_chart(
      joint_load_chart(document_.file().model, joint_combo_->currentIndex(),
                       document_.evaluation(Stage::kBefore).samples,
                       optimised ? &document_.evaluation(Stage::kAfter).samples : nullptr));
  update_cursors();
}

void MainWindow::refresh_rotation_chart() {
  if (!document_.loaded()) {
    ChartSpec empty;
    empty.title = "Open a motion to see how it rotates";
    rotation_chart_->set_chart(empty);
    return;
  }
  const bool optimised = document_.has_optimization();
  rotation_chart_->set_chart(
      rotation_chart(static_cast<RotationQuantity>(std::max(0, rotation_combo_->currentIndex())),
                     document_.rotation(Stage::kBefore),
                     optimised ? &document_.rotation(Stage::kAfter) : nullptr));
  update_cursors();
}

void MainWindow::on_time_changed(double t) {
  const bool playing = timeline_->playing();
  scene_->scene().set_time(t, playing);
  // Rendered with the next repaint: time changes that arrive before it cost one render.
  scene_->request_render();
  update_cursors();
}

int MainWindow::selected_joint() const {
  return document_.loaded() ? joint_combo_->currentIndex() : -1;
}

void MainWindow::pick_segment(int segment) {
  if (!document_.loaded() || segment < 0 || segment >= joint_combo_->count()) {
    // A click beside the body drops the highlight; the plot keeps its joint.
    scene_->scene().set_highlight(-1);
    scene_->request_render();
    return;
  }
  // The list holds every segment in model order (its joint, then its name).
  scene_->scene().set_highlight(segment);
  joint_combo_->setCurrentIndex(segment);
  plots_->setCurrentWidget(joint_tab_);
  scene_->request_render();
}

int MainWindow::highlighted_segment() const {
  return scene_->scene().highlight();
}

void MainWindow::update_cursors() {
  // Cheap: the cursors are Qt widgets over the charts, no chart is redrawn.
  const double t = document_.loaded() ? timeline_->timeline().time() : std::nan("");
  for (ChartWidget* chart : {force_chart_, moment_chart_, joint_chart_, rotation_chart_})
    chart->set_cursor(t);
}

void MainWindow::update_actions() {
  const bool loaded = document_.loaded();
  const bool running = optimization_running();
  for (QAction* a : {save_action_, export_view_action_, export_plots_action_})
    a->setEnabled(loaded);
  run_action_->setEnabled(loaded && !running);
  cancel_action_->setEnabled(running);
  before_action_->setEnabled(loaded);
  after_action_->setEnabled(loaded && document_.has_optimization());
  before_action_->setChecked(stage_ == Stage::kBefore);
  after_action_->setChecked(stage_ == Stage::kAfter);
  optimize_panel_->set_available(loaded);
  compare_before_after_action_->setEnabled(loaded && document_.has_optimization());
  for (QAction* a : {compare_motion_action_, compare_model_action_, compare_folder_action_})
    a->setEnabled(loaded);
  close_compare_action_->setEnabled(!compare_.isNull());
}

bool MainWindow::load_second(const std::string& motion, const std::string& model, Document* out,
                             QString* error) {
  try {
    out->load(motion, model, document_.evaluate_options().samples);
  } catch (const InputError& e) {
    return fail(tr("Cannot compare"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return fail(tr("Cannot compare"), qstr(motion) + ": " + qstr(e.what()), error);
  }
  return true;
}

bool MainWindow::show_compare(const QString& first_label, Stage first_stage,
                              std::shared_ptr<const Document> second, const QString& second_label,
                              Stage second_stage, QString* error) {
  if (!document_.loaded()) return fail(tr("Nothing to compare"), tr("Open a motion first."), error);
  // A copy: the compare window keeps showing this run if the main window opens another motion.
  CompareWindow::Run first{first_label, std::make_shared<const Document>(document_), first_stage};
  CompareWindow::Run other{second_label, std::move(second), second_stage};
  if (compare_.isNull()) {
    compare_ = new CompareWindow(this);
    compare_->setAttribute(Qt::WA_DeleteOnClose);
    connect(compare_, &QObject::destroyed, this, [this] { update_actions(); });
  }
  compare_->set_scene_options(scene_->scene().options());
  compare_->set_runs(std::move(first), std::move(other));
  compare_->show();
  compare_->raise();
  update_actions();
  return true;
}

QString MainWindow::stage_label(Stage stage) const {
  const QString name = qstr(document_.file().motion.name);
  return stage == Stage::kAfter ? tr("%1 (optimised)").arg(name) : name;
}

bool MainWindow::compare_before_after(QString* error) {
  if (!document_.loaded() || !document_.has_optimization())
    return fail(tr("Nothing to compare"), tr("Run an optimisation first."), error);
  return show_compare(tr("before"), Stage::kBefore, std::make_shared<const Document>(document_),
                      tr("after (optimised)"), Stage::kAfter, error);
}

bool MainWindow::compare_with_motion(const QString& path, QString* error) {
  if (!document_.loaded()) return fail(tr("Nothing to compare"), tr("Open a motion first."), error);
  auto second = std::make_shared<Document>();
  if (!load_second(path.toStdString(), model_override_, second.get(), error)) return false;
  QString label = qstr(second->file().motion.name);
  if (label == qstr(document_.file().motion.name)) label = QFileInfo(path).fileName();
  return show_compare(stage_label(stage_), stage_, std::move(second), label, Stage::kBefore, error);
}

bool MainWindow::compare_with_model(const QString& path, QString* error) {
  if (!document_.loaded()) return fail(tr("Nothing to compare"), tr("Open a motion first."), error);
  auto second = std::make_shared<Document>();
  const std::string model = QFileInfo(path).absoluteFilePath().toStdString();
  if (!load_second(document_.file().path, model, second.get(), error)) return false;
  const QString first = tr("model %1").arg(qstr(document_.file().model.name));
  QString label = tr("model %1").arg(qstr(second->file().model.name));
  if (label == first) label = tr("model %1").arg(QFileInfo(path).fileName());
  // Same motion, other masses: both as interpolated (the optimisation belongs to one model).
  return show_compare(first, Stage::kBefore, std::move(second), label, Stage::kBefore, error);
}

bool MainWindow::compare_with_folder(const QString& dir, QString* error) {
  if (!document_.loaded()) return fail(tr("Nothing to compare"), tr("Open a motion first."), error);
  FolderRun run;
  try {
    run = folder_run(dir.toStdString());
  } catch (const InputError& e) {
    return fail(tr("Cannot compare"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return fail(tr("Cannot compare"), dir + ": " + qstr(e.what()), error);
  }
  auto second = std::make_shared<Document>();
  if (!load_second(run.motion_path, run.model_path, second.get(), error)) return false;
  last_dir_ = QFileInfo(dir).absolutePath();
  return show_compare(stage_label(stage_), stage_, std::move(second), qstr(run.label),
                      Stage::kBefore, error);
}

CompareWindow* MainWindow::compare_window() const {
  return compare_.data();
}

void MainWindow::close_compare() {
  if (!compare_.isNull()) compare_->close();
  // The window deletes itself on close (deferred): finish that now, so compare_window() is null.
  QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
  update_actions();
}

bool MainWindow::apply_edit(const std::function<Motion()>& make, QString* error) {
  if (!document_.loaded()) return fail(tr("Nothing to edit"), tr("Open a motion first."), error);
  QString problem;
  try {
    const Motion edited = make();
    if (optimization_running()) cancel_optimization();
    document_.set_motion(edited);
  } catch (const InputError& e) {
    problem = qstr(e.what());
  } catch (const std::exception& e) {
    problem = qstr(e.what());
  }
  if (!problem.isEmpty()) {
    // No dialog: edits come from sliders and spin boxes; the panel says what is wrong and shows
    // the motion's values again.
    keyframe_panel_->set_motion(&document_.file().motion, &document_.file().model);
    keyframe_panel_->show_problem(problem);
    if (error) *error = problem;
    return false;
  }
  keyframe_panel_->show_problem(QString());
  show_edited();
  return true;
}

void MainWindow::show_edited() {
  ++generation_;
  stage_ = Stage::kBefore;
  optimize_panel_->clear_result();
  const double t = time();
  refresh_all(false);
  timeline_->seek(std::min(t, document_.duration()));
  status_label_->setText(
      tr("%1 (edited) — model %2 (%3 kg), average root force %4 N")
          .arg(qstr(document_.file().motion.name), qstr(document_.file().model.name))
          .arg(document_.file().model.total_mass(), 0, 'f', 1)
          .arg(document_.evaluation(Stage::kBefore).metrics.avg_root_force, 0, 'g', 3));
}

bool MainWindow::set_mass_factors(const std::vector<double>& factors, QString* error) {
  if (!document_.loaded()) return fail(tr("Nothing to edit"), tr("Open a motion first."), error);
  QString problem;
  try {
    const BodyModel model = model_with_mass_factors(document_.loaded_model(), factors);
    if (optimization_running()) cancel_optimization();
    document_.set_model(model);
  } catch (const InputError& e) {
    problem = qstr(e.what());
  } catch (const std::exception& e) {
    problem = qstr(e.what());
  }
  if (!problem.isEmpty()) {
    model_panel_->set_model(&document_.loaded_model(), &document_.file().model);
    model_panel_->show_problem(problem);
    if (error) *error = problem;
    return false;
  }
  model_panel_->show_problem(QString());
  show_edited();
  return true;
}

bool MainWindow::save_model(const QString& path, QString* error) {
  if (!document_.loaded()) return fail(tr("Nothing to save"), tr("Open a motion first."), error);
  try {
    BodyModel model = document_.file().model;
    if (document_.edited()) model.name = QFileInfo(path).completeBaseName().toStdString();
    {
      std::ofstream out(path.toStdString());
      out << body_model_to_json(model).dump(2) << '\n';
      if (!out) throw std::runtime_error("cannot write the file");
    }
    load_body_model(path.toStdString());  // what was written must load
  } catch (const InputError& e) {
    return fail(tr("Cannot save model"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return fail(tr("Cannot save model"), path + ": " + qstr(e.what()), error);
  }
  last_dir_ = QFileInfo(path).absolutePath();
  statusBar()->showMessage(tr("Saved %1").arg(path), 6000);
  return true;
}

bool MainWindow::set_keyframe_angles(int keyframe, int segment, double x_deg, double y_deg,
                                     double z_deg, QString* error) {
  return apply_edit(
      [&] {
        return with_joint_angles(document_.file().motion, document_.file().model, keyframe, segment,
                                 Eigen::Vector3d(x_deg, y_deg, z_deg));
      },
      error);
}

bool MainWindow::set_keyframe_time(int keyframe, double t, QString* error) {
  return apply_edit(
      [&] {
        return with_keyframe_time(document_.file().motion, document_.file().model, keyframe, t);
      },
      error);
}

bool MainWindow::add_keyframe(double t, QString* error) {
  const bool ok = apply_edit(
      [&] {
        // The pose of the motion as shown (interpolated or optimised) at t.
        return with_keyframe_added(document_.file().motion, document_.file().model, t,
                                   document_.sample_at(stage_, t));
      },
      error);
  if (ok) {
    const std::vector<Keyframe>& k = document_.file().motion.keyframes;
    for (std::size_t i = 0; i < k.size(); ++i)
      if (k[i].time == t) keyframe_panel_->select(static_cast<int>(i), -1);
  }
  return ok;
}

bool MainWindow::delete_keyframe(int keyframe, QString* error) {
  return apply_edit(
      [&] {
        return with_keyframe_deleted(document_.file().motion, document_.file().model, keyframe);
      },
      error);
}

bool MainWindow::save_motion(const QString& path, QString* error) {
  if (!document_.loaded()) return fail(tr("Nothing to save"), tr("Open a motion first."), error);
  try {
    Motion motion = document_.file().motion;
    // A model chosen with "Open model" is named by its full path, so the file loads as shown.
    if (!document_.model_override().empty()) {
      motion.model = document_.model_override();
    } else if (QFileInfo(qstr(motion.model)).isRelative() &&
               qstr(motion.model).endsWith(".json", Qt::CaseInsensitive)) {
      // A model file named relative to the original motion: keep pointing at the same file
      // wherever the edited motion is saved.
      motion.model =
          QFileInfo(QFileInfo(qstr(document_.file().path)).absoluteDir(), qstr(motion.model))
              .absoluteFilePath()
              .toStdString();
    }
    const nlohmann::json json = motion_to_json(motion, document_.file().model);
    {
      std::ofstream out(path.toStdString());
      out << json.dump(2) << '\n';
      if (!out) throw std::runtime_error("cannot write the file");
    }
    // Read back through the library: what was written must load as this motion.
    load_motion_file(path.toStdString());
  } catch (const InputError& e) {
    return fail(tr("Cannot save motion"), qstr(e.what()), error);
  } catch (const std::exception& e) {
    return fail(tr("Cannot save motion"), path + ": " + qstr(e.what()), error);
  }
  last_dir_ = QFileInfo(path).absolutePath();
  statusBar()->showMessage(tr("Saved %1").arg(path), 6000);
  return true;
}

void MainWindow::seek(double t) {
  timeline_->pause();
  timeline_->seek(t);
}

double MainWindow::time() const {
  return timeline_->timeline().time();
}

void MainWindow::set_stage(Stage stage) {
  if (!document_.loaded()) return;
  const double t = time();
  stage_ = document_.available(stage);
  scene_->scene().set_document(&document_, stage_);
  const MotionEvaluation& given = document_.evaluation(Stage::kBefore);
  std::vector<double> optimised;
  if (document_.has_optimization()) optimised = document_.evaluation(Stage::kAfter).keyframe_times;
  timeline_->set_motion(document_.duration(), document_.frame_count(stage_), given.keyframe_times,
                        optimised);
  timeline_->seek(t);
  update_actions();
}

void MainWindow::set_camera(CameraPreset preset) {
  scene_->scene().set_camera(preset);
  camera_actions_[static_cast<int>(preset)]->setChecked(true);
  scene_->render_now();
}

void MainWindow::set_scene_options(const SceneOptions& options) {
  SceneOptions copy = options;
  for (int i = 0; i < 8; ++i) {
    const QSignalBlocker block(option_actions_[i]);
    option_actions_[i]->setChecked(*option_field(copy, i));
  }
  scene_->scene().set_options(options);
  scene_->render_now();
}

QImage MainWindow::grab_view() {
  scene_->render_now();
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
  scene_->render_now();
  return grab().toImage();
}

double MainWindow::benchmark_playback(double seconds) {
  if (!document_.loaded()) return 0.0;
  timeline_->go_to_start();
  QApplication::processEvents();
  frames_drawn_ = 0;
  const int renders_before = scene_->render_count();
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
  return elapsed > 0 ? frames_drawn_ / elapsed : 0.0;
}

void MainWindow::add_recent(const QString& path) {
  recent_.removeAll(path);
  recent_.prepend(path);
  while (recent_.size() > kMaxRecent)
    recent_.removeLast();
  rebuild_recent_menu();
}

void MainWindow::rebuild_recent_menu() {
  recent_menu_->clear();
  for (const QString& path : recent_) {
    recent_menu_->addAction(QFileInfo(path).fileName(), this, [this, path] { open_motion(path); })
        ->setToolTip(path);
  }
  recent_menu_->setEnabled(!recent_.isEmpty());
  if (!recent_.isEmpty()) {
    recent_menu_->addSeparator();
    recent_menu_->addAction(tr("Clear list"), this, [this] {
      recent_.clear();
      rebuild_recent_menu();
    });
  }
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (optimization_running()) {
    runner_->cancel();
    wait_for_optimization(30000);
  }
  if (interactive_) save_settings();
  close_compare();
  QMainWindow::closeEvent(event);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (!event->mimeData()->hasUrls()) return;
  for (const QUrl& url : event->mimeData()->urls()) {
    const auto kind =
        url.isLocalFile() ? identify_readable(url.toLocalFile().toStdString()) : std::nullopt;
    if (kind == ReadableKind::kMotion || kind == ReadableKind::kModel) {
      event->acceptProposedAction();
      return;
    }
  }
}

void MainWindow::dropEvent(QDropEvent* event) {
  // A dropped model applies first, so "model + motion" dropped together opens the motion with it.
  QStringList motions;
  for (const QUrl& url : event->mimeData()->urls()) {
    if (!url.isLocalFile()) continue;
    const QString path = url.toLocalFile();
    const auto kind = identify_readable(path.toStdString());
    if (kind == ReadableKind::kModel)
      open_model(path);
    else if (kind == ReadableKind::kMotion)
      motions.append(path);
  }
  if (!motions.isEmpty()) open_motion(motions.first());
  event->acceptProposedAction();
}

}  // namespace saltus::gui
