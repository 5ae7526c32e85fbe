// Animation export through ffmpeg, read back with ffprobe: the frame count and the duration the
// plan promises, the size asked for, and frames that show the motion (the first and the last
// differ). MP4 and GIF.

#include <gtest/gtest.h>

#include <QDir>
#include <QImage>
#include <QProcess>
#include <QStandardPaths>
#include <cmath>
#include <filesystem>

#include "app/batch.h"
#include "app/main_window.h"
#include "app/video_exporter.h"
#include "gui/support/image_checks.h"
#include "gui/support/open_motion_fixture.h"
#include "support/cli_runner.h"

namespace saltus::gui {
namespace {

struct Probe {
  int width = 0, height = 0, frames = 0;
  double duration = 0.0;
};

/// ffprobe's count of decoded frames, the size and the container's duration.
Probe probe(const std::string& path) {
  QProcess p;
  p.start("ffprobe", {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                      "stream=width,height,nb_read_frames:format=duration", "-of",
                      "default=noprint_wrappers=1", QString::fromStdString(path)});
  p.waitForFinished(60000);
  Probe out;
  for (const QString& line : QString::fromLocal8Bit(p.readAllStandardOutput()).split('\n')) {
    const QString value = line.section('=', 1);
    if (line.startsWith("width=")) out.width = value.toInt();
    if (line.startsWith("height=")) out.height = value.toInt();
    if (line.startsWith("nb_read_frames=")) out.frames = value.toInt();
    if (line.startsWith("duration=")) out.duration = value.toDouble();
  }
  return out;
}

/// Frame `index` of a video as an image (ffmpeg's decoder, not ours).
QImage frame(const std::string& path, int index, const std::string& png) {
  QProcess p;
  p.start("ffmpeg",
          {"-v", "error", "-y", "-i", QString::fromStdString(path), "-vf",
           QString("select=eq(n\\,%1)").arg(index), "-frames:v", "1", QString::fromStdString(png)});
  p.waitForFinished(60000);
  return QImage(QString::fromStdString(png));
}

class VideoExportTest : public test::OpenMotionTest {
 protected:
  void SetUp() override {
    if (VideoExporter::ffmpeg_program().isEmpty() ||
        QStandardPaths::findExecutable("ffprobe").isEmpty())
      GTEST_SKIP() << "ffmpeg is not installed (tools/bootstrap.sh installs it)";
    test::OpenMotionTest::SetUp();
  }
  saltus::test::TempDir dir_;
};

TEST_F(VideoExportTest, Mp4HasThePlannedFramesAndDuration) {
  VideoOptions options;
  options.fps = 25;
  options.speed = 2.0;  // twice real time: a short file
  options.size = QSize(640, 360);
  VideoPlan plan;
  QString error;
  const std::string path = dir_ / "m1.mp4";
  ASSERT_TRUE(window_->video().export_video(QString::fromStdString(path), options, &error, &plan))
      << error.toStdString();
  // 2.04 s at twice real time, 25 frames per second: 26 intervals, the landing included.
  EXPECT_EQ(plan.frames(), 27);
  const Probe p = probe(path);
  EXPECT_EQ(p.width, 640);
  EXPECT_EQ(p.height, 360);
  EXPECT_EQ(p.frames, plan.frames());
  EXPECT_NEAR(p.duration, plan.frames() / 25.0, 1.0 / 25.0 + 1e-3);

  const QImage first = frame(path, 0, dir_ / "first.png");
  const QImage last = frame(path, plan.frames() - 1, dir_ / "last.png");
  ASSERT_FALSE(first.isNull());
  ASSERT_FALSE(last.isNull());
  EXPECT_GT(test::blank_check(first).distinct_colours, 20);
  EXPECT_FALSE(test::compare_images(first, last, 0.03)) << "the body did not move";
  // Left for a person to look at: a frame from the middle, with the time and residual written.
  QDir().mkpath(SALTUS_GUI_CANDIDATE_DIR);
  frame(path, plan.frames() / 2, std::string(SALTUS_GUI_CANDIDATE_DIR) + "/video_frame.png");
}

TEST_F(VideoExportTest, GifLoopsWithItsOwnFrameRate) {
  VideoOptions options;  // the GIF default of 20 frames per second
  options.speed = 2.0;
  options.size = QSize(240, 240);
  VideoPlan plan;
  QString error;
  const std::string path = dir_ / "m1.gif";
  ASSERT_TRUE(window_->video().export_video(QString::fromStdString(path), options, &error, &plan))
      << error.toStdString();
  EXPECT_DOUBLE_EQ(plan.fps, 20.0);
  const Probe p = probe(path);
  EXPECT_EQ(p.width, 240);
  EXPECT_EQ(p.frames, plan.frames());
  EXPECT_NEAR(p.duration, plan.frames() / 20.0, 0.06);
}

TEST_F(VideoExportTest, BatchWritesTheVideoAndSaysHowLong) {
  VideoOptions options;
  options.speed = 4.0;
  options.size = QSize(160, 120);
  const std::string path = dir_ / "batch.mp4";
  EXPECT_EQ(write_video(*window_, QString::fromStdString(path), options), 0);
  EXPECT_EQ(probe(path).frames, plan_video(window_->document().duration(), 30.0, 4.0).frames());
  EXPECT_EQ(write_video(*window_, QString::fromStdString(dir_ / "batch.webm"), options), 2);
}

TEST_F(VideoExportTest, UnknownFormatsSaySo) {
  QString error;
  EXPECT_FALSE(window_->video().export_video(QString::fromStdString(dir_ / "m1.avi"),
                                             VideoOptions{}, &error));
  EXPECT_NE(error.indexOf(".mp4 or .gif"), -1) << error.toStdString();
  EXPECT_FALSE(std::filesystem::exists(dir_.path() / "m1.avi"));
}

}  // namespace
}  // namespace saltus::gui
