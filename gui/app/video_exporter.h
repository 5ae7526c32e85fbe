#pragma once
/// @file
/// Animation export (File > Export animation…, and batch mode): the 3D view as the user set it
/// up (stage, camera, display options) rendered frame by frame offscreen with the time and the
/// residual written in the picture, piped as raw frames into the `ffmpeg` program, which writes
/// an MP4 (H.264) or an animated GIF. Frame times come from core/video_plan.h.

#include <QObject>
#include <QSize>
#include <QString>

#include "app/app_context.h"
#include "core/video_plan.h"

class QAction;

namespace saltus::gui {

class ViewController;

struct VideoOptions {
  double fps = 0.0;    ///< 0: the format's default (default_fps)
  double speed = 1.0;  ///< motion seconds per video second
  QSize size{1280, 720};
};

class VideoExporter : public QObject {
  Q_OBJECT

 public:
  VideoExporter(AppContext& context, ViewController& view, QObject* parent = nullptr);

  /// File > Export animation…
  QAction* action() const { return action_; }

  /// Writes the animation of the stage shown to `path` (.mp4 or .gif). False on failure (no
  /// motion, unknown extension, ffmpeg missing or failing), with the reason as for other
  /// operations (`error`, else a dialog or stderr). `plan` (may be null) receives the frames.
  bool export_video(const QString& path, const VideoOptions& options, QString* error = nullptr,
                    VideoPlan* plan = nullptr);

  /// The ffmpeg program found on the PATH ("" if none).
  static QString ffmpeg_program();

 private:
  void ask_and_export();

  AppContext& context_;
  ViewController& view_;
  QAction* action_ = nullptr;
};

}  // namespace saltus::gui
