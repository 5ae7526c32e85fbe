#include "app/video_exporter.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QMainWindow>
#include <QProcess>
#include <QProgressDialog>
#include <QStandardPaths>
#include <stdexcept>

#include "app/scene_widget.h"
#include "app/view_controller.h"
#include "scene/animation_renderer.h"

namespace saltus::gui {

VideoExporter::VideoExporter(AppContext& context, ViewController& view, QObject* parent)
    : QObject(parent), context_(context), view_(view) {
  action_ = new QAction(tr("Export &animation (MP4 or GIF)…"), this);
  action_->setToolTip(tr("The 3D view as a video, with the time and the residual in the picture"));
  connect(action_, &QAction::triggered, this, &VideoExporter::ask_and_export);
}

QString VideoExporter::ffmpeg_program() {
  return QStandardPaths::findExecutable("ffmpeg");
}

void VideoExporter::ask_and_export() {
  if (!context_.workspace().loaded()) return;
  const QString path =
      QFileDialog::getSaveFileName(context_.window(), tr("Export animation"),
                                   QDir(context_.save_dir()).filePath("animation.mp4"),
                                   tr("MP4 video (*.mp4);;Animated GIF (*.gif)"));
  if (path.isEmpty()) return;
  // Size, speed and frame rate, with what people usually want preset.
  QDialog dialog(context_.window());
  dialog.setWindowTitle(tr("Animation"));
  auto* form = new QFormLayout(&dialog);
  auto* size = new QComboBox(&dialog);
  size->addItem("1280 × 720", QSize(1280, 720));
  size->addItem("1920 × 1080", QSize(1920, 1080));
  size->addItem("854 × 480", QSize(854, 480));
  size->addItem("640 × 640", QSize(640, 640));
  auto* speed = new QDoubleSpinBox(&dialog);
  speed->setRange(0.05, 10.0);
  speed->setDecimals(2);
  speed->setValue(0.5);
  speed->setSuffix(tr(" × real time"));
  speed->setToolTip(tr("0.5: slow motion at half speed"));
  auto* fps = new QDoubleSpinBox(&dialog);
  fps->setRange(1.0, 120.0);
  fps->setDecimals(0);
  const auto format = video_format_for(path.toStdString());
  fps->setValue(default_fps(format.value_or(VideoFormat::kMp4)));
  fps->setSuffix(tr(" frames per second"));
  form->addRow(tr("Size"), size);
  form->addRow(tr("Speed"), speed);
  form->addRow(tr("Frame rate"), fps);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  form->addRow(buttons);
  if (dialog.exec() != QDialog::Accepted) return;
  VideoOptions options;
  options.size = size->currentData().toSize();
  options.speed = speed->value();
  options.fps = fps->value();
  if (export_video(path, options)) context_.status(tr("Wrote %1").arg(path), 8000);
}

bool VideoExporter::export_video(const QString& path, const VideoOptions& options, QString* error,
                                 VideoPlan* plan_out) {
  const Workspace& ws = context_.workspace();
  if (!ws.loaded())
    return context_.fail(tr("Nothing to export"), tr("Open a motion first."), error);
  const std::optional<VideoFormat> format = video_format_for(path.toStdString());
  if (!format)
    return context_.fail(tr("Cannot export animation"),
                         tr("%1: the file name must end in .mp4 or .gif").arg(path), error);
  const QString ffmpeg = ffmpeg_program();
  if (ffmpeg.isEmpty())
    return context_.fail(tr("Cannot export animation"),
                         tr("The ffmpeg program is needed to write videos; install it (Debian: "
                            "apt-get install ffmpeg)."),
                         error);
  VideoPlan plan;
  try {
    plan = plan_video(ws.document().duration(),
                      options.fps > 0 ? options.fps : default_fps(*format), options.speed);
  } catch (const std::invalid_argument& e) {
    return context_.fail(tr("Cannot export animation"), QString::fromStdString(e.what()), error);
  }
  // Video encoders want even sizes.
  const int width = std::max(16, options.size.width() / 2 * 2);
  const int height = std::max(16, options.size.height() / 2 * 2);
  AnimationRenderer renderer(width, height);
  renderer.set_document(&ws.document(), ws.stage(), view_.scene_options(), view_.camera());

  QProcess process;
  QStringList arguments;
  for (const std::string& a :
       ffmpeg_arguments(*format, width, height, plan.fps, path.toStdString()))
    arguments << QString::fromStdString(a);
  process.start(ffmpeg, arguments);
  if (!process.waitForStarted(10000))
    return context_.fail(tr("Cannot export animation"),
                         tr("ffmpeg did not start: %1").arg(process.errorString()), error);
  std::unique_ptr<QProgressDialog> progress;
  if (context_.interactive()) {
    progress = std::make_unique<QProgressDialog>(tr("Writing %1…").arg(path), tr("Cancel"), 0,
                                                 plan.frames(), context_.window());
    progress->setWindowModality(Qt::WindowModal);
    progress->setMinimumDuration(500);
  }
  bool cancelled = false;
  for (int i = 0; i < plan.frames(); ++i) {
    const std::vector<unsigned char>& frame =
        renderer.render(plan.times[static_cast<std::size_t>(i)]);
    process.write(reinterpret_cast<const char*>(frame.data()), static_cast<qint64>(frame.size()));
    while (process.bytesToWrite() > 0 && process.state() == QProcess::Running)
      process.waitForBytesWritten(1000);
    if (process.state() != QProcess::Running) break;
    if (progress) {
      progress->setValue(i + 1);
      if (progress->wasCanceled()) {
        cancelled = true;
        break;
      }
    }
  }
  process.closeWriteChannel();
  if (cancelled) {
    process.kill();
    process.waitForFinished(10000);
    QFile::remove(path);
    if (error) *error = tr("Cancelled.");
    return false;
  }
  if (!process.waitForFinished(300000) || process.exitStatus() != QProcess::NormalExit ||
      process.exitCode() != 0) {
    const QString output = QString::fromLocal8Bit(process.readAllStandardError()).trimmed();
    return context_.fail(tr("Cannot export animation"),
                         tr("ffmpeg failed writing %1: %2").arg(path, output), error);
  }
  if (plan_out) *plan_out = plan;
  context_.note_saved(path);
  return true;
}

}  // namespace saltus::gui
