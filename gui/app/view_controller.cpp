#include "app/view_controller.h"

#include <QAction>
#include <QActionGroup>
#include <QCheckBox>
#include <QGridLayout>
#include <QMenu>
#include <QSettings>
#include <QToolBar>

#include "app/scene_widget.h"

namespace saltus::gui {

ViewController::ViewController(AppContext& context, SceneWidget* scene, QObject* parent)
    : QObject(parent), context_(context), scene_(scene) {
  auto* stages = new QActionGroup(this);
  before_ = new QAction(tr("Show &interpolated motion (before)"), this);
  after_ = new QAction(tr("Show &optimised motion (after)"), this);
  before_->setIconText(tr("Before"));
  after_->setIconText(tr("After"));
  before_->setToolTip(tr("The keyframes as interpolated, before optimisation (B)"));
  after_->setToolTip(tr("The optimised motion of the run shown (A)"));
  for (QAction* a : {before_, after_}) {
    a->setCheckable(true);
    stages->addAction(a);
  }
  before_->setShortcut(Qt::Key_B);
  after_->setShortcut(Qt::Key_A);
  before_->setChecked(true);
  connect(before_, &QAction::triggered, this, [this] { set_stage(Stage::kBefore); });
  connect(after_, &QAction::triggered, this, [this] { set_stage(Stage::kAfter); });

  auto* cameras = new QActionGroup(this);
  int key = 1;
  for (CameraPreset preset : camera_presets()) {
    auto* a = new QAction(QString::fromStdString(camera_preset_label(preset)), this);
    a->setText(tr("%1 camera").arg(a->text()));
    a->setIconText(QString::fromStdString(camera_preset_label(preset)));
    a->setCheckable(true);
    a->setShortcut(QKeySequence(QString::number(key++)));
    cameras->addAction(a);
    connect(a, &QAction::triggered, this, [this, preset] { set_camera(preset); });
    cameras_.push_back(a);
  }
  cameras_.back()->setToolTip(tr("Follow camera: three-quarter view that moves with the body"));
  reset_ = new QAction(tr("&Reset camera"), this);
  reset_->setIconText(tr("Reset"));
  reset_->setShortcut(Qt::Key_R);
  connect(reset_, &QAction::triggered, this, &ViewController::reset_camera);

  const SceneOptions defaults;
  for (const SceneOptionInfo& info : scene_option_table()) {
    auto* a = new QAction(tr(info.label), this);
    a->setCheckable(true);
    a->setChecked(defaults.*info.field);
    a->setToolTip(tr(info.tip));
    connect(a, &QAction::toggled, this, [this] {
      if (!setting_options_) apply_options();
    });
    options_.push_back(a);
  }

  // The single keys act in the 3D view, the timeline and the plots only.
  for (QAction* a : {before_, after_, reset_})
    context_.scope_shortcut(a);
  for (QAction* a : cameras_)
    context_.scope_shortcut(a);

  connect(scene_, &SceneWidget::segment_clicked, this, &ViewController::segment_clicked);
  scene_->scene().set_camera(CameraPreset::kFollow);
  cameras_.back()->setChecked(true);
  context_.workspace().subscribe([this](WorkspaceChange c) { on_workspace(c); });
  update_actions();
}

void ViewController::fill_menu(QMenu* view) {
  view->addAction(before_);
  view->addAction(after_);
  view->addSeparator();
  for (QAction* a : cameras_)
    view->addAction(a);
  view->addAction(reset_);
  view->addSeparator();
  for (QAction* a : options_)
    view->addAction(a);
}

void ViewController::fill_toolbar(QToolBar* bar) {
  bar->addAction(before_);
  bar->addAction(after_);
  bar->addSeparator();
  for (QAction* a : cameras_)
    bar->addAction(a);
  bar->addAction(reset_);
}

QWidget* ViewController::make_display_panel(QWidget* parent) {
  auto* panel = new QWidget(parent);
  auto* layout = new QGridLayout(panel);
  // One column: the panel is a tab of the narrow panel column, as tall as the window.
  const int columns = 1;
  for (std::size_t i = 0; i < options_.size(); ++i) {
    QAction* action = options_[i];
    auto* box = new QCheckBox(action->text().remove('&'), panel);
    box->setChecked(action->isChecked());
    box->setToolTip(action->toolTip());
    connect(box, &QCheckBox::toggled, action, &QAction::setChecked);
    connect(action, &QAction::toggled, box, &QCheckBox::setChecked);
    layout->addWidget(box, static_cast<int>(i) / columns, static_cast<int>(i) % columns);
  }
  layout->setRowStretch(static_cast<int>(options_.size()), 1);
  return panel;
}

void ViewController::on_workspace(WorkspaceChange change) {
  const Workspace& ws = context_.workspace();
  if (change == WorkspaceChange::kSaved) return;
  scene_->scene().set_document(ws.loaded() ? &ws.document() : nullptr, ws.stage());
  if (change == WorkspaceChange::kOpened) {
    scene_->scene().set_highlight(-1);  // a pick belongs to the motion it was made on
    scene_->scene().reset_camera();
  }
  scene_->request_render();
  update_actions();
}

void ViewController::update_actions() {
  const Workspace& ws = context_.workspace();
  before_->setEnabled(ws.loaded());
  after_->setEnabled(ws.loaded() && ws.shown_run().has_value());
  before_->setChecked(ws.stage() == Stage::kBefore);
  after_->setChecked(ws.stage() == Stage::kAfter);
}

void ViewController::set_stage(Stage stage) {
  context_.workspace().set_stage(stage);
  update_actions();
}

void ViewController::set_camera(CameraPreset preset) {
  scene_->scene().set_camera(preset);
  const std::vector<CameraPreset> presets = camera_presets();
  for (std::size_t i = 0; i < presets.size(); ++i)
    if (presets[i] == preset) cameras_[i]->setChecked(true);
  scene_->render_now();
}

CameraPreset ViewController::camera() const {
  return scene_->scene().camera();
}

void ViewController::reset_camera() {
  scene_->scene().reset_camera();
  scene_->render_now();
}

void ViewController::apply_options() {
  scene_->scene().set_options(scene_options());
  scene_->render_now();
}

void ViewController::set_scene_options(const SceneOptions& options) {
  // The actions' signals stay on, so that the Display panel's boxes follow them (a settings
  // load ticks both or neither); the scene is redrawn once, after the last.
  const std::vector<SceneOptionInfo>& table = scene_option_table();
  setting_options_ = true;
  for (std::size_t i = 0; i < table.size(); ++i)
    options_[i]->setChecked(options.*table[i].field);
  setting_options_ = false;
  apply_options();
}

SceneOptions ViewController::scene_options() const {
  SceneOptions options;
  const std::vector<SceneOptionInfo>& table = scene_option_table();
  for (std::size_t i = 0; i < table.size(); ++i)
    options.*table[i].field = options_[i]->isChecked();
  return options;
}

void ViewController::set_time(double t, bool playing) {
  scene_->scene().set_time(t, playing);
  // Rendered with the next repaint: time changes that arrive before it cost one render.
  scene_->request_render();
}

void ViewController::set_what_if(const SimulationResult* flight, const QString& label) {
  scene_->scene().set_what_if(flight ? flight->samples : std::vector<SampleRecord>{},
                              label.toStdString());
  scene_->request_render();
}

void ViewController::highlight(int segment) {
  scene_->scene().set_highlight(segment);
  scene_->request_render();
}

int ViewController::highlighted_segment() const {
  return scene_->scene().highlight();
}

void ViewController::load_settings(const QSettings& s) {
  SceneOptions options = scene_options();
  for (const SceneOptionInfo& info : scene_option_table())
    options.*info.field = s.value(QString("view/") + info.key, options.*info.field).toBool();
  set_scene_options(options);
  if (const auto preset =
          camera_preset_from_name(s.value("view/camera", "follow").toString().toStdString()))
    set_camera(*preset);
}

void ViewController::save_settings(QSettings& s) const {
  const SceneOptions options = scene_options();
  for (const SceneOptionInfo& info : scene_option_table())
    s.setValue(QString("view/") + info.key, options.*info.field);
  s.setValue("view/camera", QString::fromStdString(camera_preset_name(camera())));
}

}  // namespace saltus::gui
