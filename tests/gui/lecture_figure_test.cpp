// The lecture figure (the stroboscopic side view) from File > Export lecture figure… and from
// `--lecture-figure`: the PNG is written, 1800×900, and the poses show several distinct colours
// of the spin rate where the bodies are drawn.

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QColor>
#include <QImage>
#include <QMenu>
#include <QMenuBar>
#include <filesystem>
#include <map>
#include <set>

#include "app/file_controller.h"
#include "gui/support/image_checks.h"
#include "gui/support/open_motion_fixture.h"
#include "scene/lecture_figure_picture.h"
#include "support/cli_runner.h"

namespace saltus::gui {
namespace {

const std::string kTucked =
    std::string(SALTUS_EXAMPLES_DIR) + "/motions/M2-tucked-back-somersault.motion.json";

/// Hues (in 20° bins) of the saturated pixels in the bodies' part of the figure (not the title,
/// the caption or the colour bar) that cover at least 0.05 % of it each.
std::set<int> pose_hues(const QImage& image) {
  const QRect bodies(0, 70, image.width() - 230, image.height() - 70 - 160);
  std::map<int, int> counts;
  for (int y = bodies.top(); y <= bodies.bottom(); ++y)
    for (int x = bodies.left(); x <= bodies.right(); ++x) {
      const QColor c = QColor(image.pixel(x, y)).toHsv();
      if (c.hsvSaturationF() > 0.45 && c.valueF() > 0.25 && c.hsvHue() >= 0)
        ++counts[c.hsvHue() / 20];
    }
  std::set<int> hues;
  for (const auto& [bin, count] : counts)
    if (count > bodies.width() * bodies.height() / 2000) hues.insert(bin);
  return hues;
}

void expect_lecture_figure(const std::string& path) {
  const QImage image(QString::fromStdString(path));
  ASSERT_FALSE(image.isNull()) << path << " missing or not a PNG";
  EXPECT_EQ(image.width(), kLectureFigureWidth);
  EXPECT_EQ(image.height(), kLectureFigureHeight);
  const test::BlankCheck check = test::blank_check(image);
  EXPECT_GT(check.distinct_colours, 50) << path;
  // M2 tucks: the poses range from slow (open) to fast (tucked), so at least three hues.
  EXPECT_GE(pose_hues(image).size(), 3u) << path;
}

class LectureFigureMenuTest : public test::EmptyWindowTest {};

TEST_F(LectureFigureMenuTest, TheMenuEntryWritesTheFigureOfTheMotionShown) {
  QString error;
  ASSERT_TRUE(window_->open_motion(QString::fromStdString(kTucked), &error)) << error.toStdString();
  saltus::test::TempDir dir;
  const std::string png = dir / "lecture.png";
  window_->files().set_save_chooser(
      [&](const QString&, const QString&, const QString&) { return QString::fromStdString(png); });
  // The entry as the File menu holds it.
  QAction* action = nullptr;
  for (QAction* menu : window_->menuBar()->actions())
    if (menu->text().remove('&') == "File")
      for (QAction* a : menu->menu()->actions())
        if (a->objectName() == "export_lecture_figure") action = a;
  ASSERT_NE(action, nullptr);
  EXPECT_EQ(action->text().remove('&'), "Export lecture figure (stroboscopic side view)…");
  ASSERT_TRUE(action->isEnabled());
  action->trigger();
  QApplication::processEvents();
  ASSERT_TRUE(std::filesystem::exists(png));
  expect_lecture_figure(png);
  const test::Comparison baseline =
      test::compare_with_baseline(QImage(QString::fromStdString(png)), "lecture_figure_M2_before");
  EXPECT_TRUE(baseline.ok) << baseline.message;
}

TEST(LectureFigureBatch, TheBatchOptionWritesTheSameFigure) {
  saltus::test::TempDir dir;
  const std::string png = dir / "strobe.png";
  const saltus::test::CliRun run = saltus::test::run_command(
      std::string(SALTUS_GUI_PATH) + " '" + kTucked + "' --lecture-figure '" + png + "'");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("wrote " + png), std::string::npos) << run.output;
  expect_lecture_figure(png);
  const saltus::test::CliRun bad =
      saltus::test::run_command(std::string(SALTUS_GUI_PATH) + " '" + kTucked +
                                "' --poses 1 --lecture-figure '" + (dir / "x.png") + "'");
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.png"));
}

}  // namespace
}  // namespace saltus::gui
