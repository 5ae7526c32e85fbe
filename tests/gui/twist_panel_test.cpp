// The Twist panel: for the motion shown it shows what the library's twist_sources says — the
// sentence, each source's tilt and share, the tilt over time of every flight — and never the
// numbers of a motion no longer shown: another motion clears them at once and brings its own;
// a flight without tilt gets a plain statement; a model without left-right pairs the library's
// message. Pictures of the window with the panel are left in the candidate folder to look at.

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QMenu>
#include <QMenuBar>
#include <QTableWidget>
#include <QTest>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/chart_widget.h"
#include "app/main_window.h"
#include "app/run_controller.h"
#include "app/twist_panel.h"
#include "saltus/body/segment_names.h"
#include "saltus/evaluation/twist_sources.h"
#include "scene/chart_view.h"
#include "support/temp_path.h"

namespace saltus::gui {
namespace {

QString motion(const std::string& name) {
  return QString(SALTUS_EXAMPLES_DIR) + "/motions/" + QString::fromStdString(name);
}
const std::string kM1 = "M1-straight-back-somersault.motion.json";
const std::string kM5 = "M5-front-somersault-one-and-a-half-twists.motion.json";
const std::string kM7 = "M7-double-front-one-and-a-half-twists.motion.json";

/// A cell's number as written ("−1.0°", "71 %").
double number_in(const QString& cell) {
  QString text = cell;
  text.replace(QChar(0x2212), '-').remove(QChar(0x00B0)).remove('%');
  bool ok = false;
  const double value = text.trimmed().toDouble(&ok);
  EXPECT_TRUE(ok) << cell.toStdString();
  return value;
}

class TwistPanelTest : public ::testing::Test {
 protected:
  void SetUp() override { make_window(1280, 800); }
  void TearDown() override {
    window_->close();
    window_.reset();
  }
  void make_window(int width, int height) {
    window_ = std::make_unique<MainWindow>(false);
    window_->resize(width, height);
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
  }
  TwistPanel& panel() { return window_->twist(); }
  /// The sentence shown, its non-breaking spaces ("101 %" on one line) as the library's spaces.
  std::string sentence() { return panel().sentence().replace(QChar(0x00A0), ' ').toStdString(); }
  /// Opens a motion (a fatal failure when it does not open: use ASSERT_NO_FATAL_FAILURE).
  void open(const QString& path) {
    QString error;
    ASSERT_TRUE(window_->open_motion(path, &error)) << error.toStdString();
  }
  /// Keeps the event loop running until the panel shows the result for the motion shown.
  bool wait_for_result(int timeout_ms = 60000) {
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < timeout_ms) {
      QApplication::processEvents(QEventLoop::AllEvents, 20);
      if (!panel().busy()) {
        QApplication::processEvents();
        return true;
      }
    }
    return false;
  }
  /// What the library says of the motion shown, called directly as the panel does.
  TwistSources direct() const {
    const Document& d = window_->document();
    return twist_sources(d.file().motion, d.file().model, d.evaluate_options());
  }
  /// The panel's table and chart carry exactly these numbers.
  void expect_shows(const TwistSources& s) {
    EXPECT_EQ(sentence(), s.sentence);
    QTableWidget* table = panel().table();
    ASSERT_TRUE(table->isVisible());
    ASSERT_EQ(table->rowCount(), static_cast<int>(s.shares.size()) + 1);
    // Tilt is written in the direction of the total (so the total reads 23°, not −23°).
    const double sign = s.total_tilt_deg < 0 ? -1.0 : 1.0;
    for (std::size_t i = 0; i < s.shares.size(); ++i) {
      const int row = static_cast<int>(i);
      EXPECT_EQ(table->item(row, 0)->text().toStdString(), capitalised(s.shares[i].source));
      EXPECT_NEAR(number_in(table->item(row, 1)->text()), sign * s.shares[i].tilt_deg, 0.05 + 1e-9)
          << s.shares[i].source;
      EXPECT_NEAR(number_in(table->item(row, 2)->text()), s.shares[i].percent, 0.5 + 1e-9)
          << s.shares[i].source;
    }
    // The shares add up to the total (they are Shapley values): no row is left for the rest.
    const int total = table->rowCount() - 1;
    double shown_sum = 0.0;
    for (int row = 0; row < total; ++row)
      shown_sum += number_in(table->item(row, 1)->text());
    EXPECT_NEAR(shown_sum, std::abs(s.total_tilt_deg), 0.05 * total + 1e-9);
    EXPECT_EQ(table->item(total, 0)->text(), "Total");
    EXPECT_NEAR(number_in(table->item(total, 1)->text()), std::abs(s.total_tilt_deg), 0.05 + 1e-9);
    EXPECT_EQ(table->item(total, 2)->text(), "100 %");
    // The chart: one curve per flight the library flew, with its tilt over time; the actual
    // flight first, "take-off only" (the library's second) drawn last, on top.
    const ChartSpec& chart = panel().chart()->view().chart();
    const std::size_t n = s.tilt_deg.size();
    ASSERT_EQ(chart.lines.size(), n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t flight = k == 0 ? 0 : k == n - 1 ? 1 : k + 1;
      EXPECT_EQ(chart.lines[k].x, s.times);
      EXPECT_EQ(chart.lines[k].y, s.tilt_deg[flight]) << chart.lines[k].label;
    }
    EXPECT_EQ(chart.lines[n - 1].label, "take-off only");
    ASSERT_FALSE(chart.markers.empty());
    EXPECT_EQ(chart.markers[0].x, s.reference_time_s);
  }
  void save_candidate(const QString& name) {
    const QString dir = SALTUS_GUI_CANDIDATE_DIR;
    QDir().mkpath(dir);
    EXPECT_TRUE(window_->grab_window().save(dir + "/" + name));
  }

  std::unique_ptr<MainWindow> window_;
};

TEST_F(TwistPanelTest, TheViewMenuShowsThePanel) {
  QAction* action = nullptr;
  for (QAction* m : window_->menuBar()->actions())
    if (m->text().remove('&') == "View")
      for (QAction* a : m->menu()->actions())
        if (a->text().remove('&') == "Where does the twist come from?") action = a;
  ASSERT_NE(action, nullptr);
  ASSERT_NO_FATAL_FAILURE(open(motion(kM5)));
  auto* dock = window_->findChild<QDockWidget*>("twist_dock");
  ASSERT_NE(dock, nullptr);
  // A tabbed dock behind another is "visible" to Qt but has nothing on screen.
  EXPECT_TRUE(panel().visibleRegion().isEmpty());  // the Optimise panel is in front
  action->trigger();
  QApplication::processEvents();
  EXPECT_FALSE(panel().visibleRegion().isEmpty());
  ASSERT_TRUE(wait_for_result());
  expect_shows(direct());
}

TEST_F(TwistPanelTest, ShowsTheLibrarysAnswerForM5ThenM1ReplacesIt) {
  ASSERT_NO_FATAL_FAILURE(open(motion(kM5)));
  window_->show_twist_panel();
  ASSERT_TRUE(wait_for_result());
  const TwistSources m5 = direct();
  expect_shows(m5);
  EXPECT_TRUE(panel().subject().contains("interpolated keyframes"));
  EXPECT_GT(panel().last_seconds(), 0.0);

  // Another motion: M5's numbers go at once, before M1's are ready.
  ASSERT_NO_FATAL_FAILURE(open(motion(kM1)));
  EXPECT_NE(sentence(), m5.sentence);
  EXPECT_EQ(panel().table()->rowCount(), 0);
  EXPECT_TRUE(panel().chart()->view().chart().lines.empty());
  ASSERT_TRUE(wait_for_result());
  // No tilt: the library's statement alone, no table of zeros, no chart.
  const TwistSources m1 = direct();
  ASSERT_FALSE(has_tilt_to_share(m1.total_tilt_deg));
  EXPECT_EQ(sentence(), m1.sentence);
  EXPECT_TRUE(panel().sentence().contains("nothing to twist with"));
  EXPECT_EQ(panel().table()->rowCount(), 0);
  EXPECT_FALSE(panel().table()->isVisible());
  EXPECT_FALSE(panel().chart()->isVisible());
}

TEST_F(TwistPanelTest, AMotionOpenedWhileComputingNeverShowsTheOldResult) {
  ASSERT_NO_FATAL_FAILURE(open(motion(kM5)));
  window_->show_twist_panel();
  QApplication::processEvents();
  ASSERT_TRUE(panel().busy());
  // Every result shown from now on must be M7's.
  ASSERT_NO_FATAL_FAILURE(open(motion(kM7)));
  std::vector<std::string> shown;
  QObject::connect(&panel(), &TwistPanel::result_shown, &panel(),
                   [&] { shown.push_back(sentence()); });
  ASSERT_TRUE(wait_for_result());
  const TwistSources m7 = direct();
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_EQ(shown[0], m7.sentence);
  expect_shows(m7);
}

TEST_F(TwistPanelTest, AfterARunItAnalysesTheOptimisedMotionAndSaysSo) {
  ASSERT_NO_FATAL_FAILURE(open(motion(kM5)));
  window_->show_twist_panel();
  ASSERT_TRUE(wait_for_result());
  const std::string interpolated = sentence();
  OptimizeSettings settings;
  settings.set("max_iterations", 3);
  settings.set("samples", 31);
  QString error;
  ASSERT_TRUE(window_->runs().start(settings, &error)) << error.toStdString();
  ASSERT_TRUE(window_->runs().wait(300000));
  // A run that stopped early is listed, not shown by itself: show it as a user would.
  ASSERT_TRUE(window_->runs().show_run(window_->workspace().runs().size() - 1, &error))
      << error.toStdString();
  ASSERT_EQ(window_->stage(), Stage::kAfter);
  EXPECT_TRUE(panel().busy());
  ASSERT_TRUE(wait_for_result());
  EXPECT_TRUE(panel().subject().contains("optimised motion of run 1"))
      << panel().subject().toStdString();
  const Document& d = window_->document();
  expect_shows(
      twist_sources(d.optimization().optimized_motion, d.file().model, d.evaluate_options()));
  // Back to the interpolated keyframes (B): their result again, at once.
  window_->set_stage(Stage::kBefore);
  EXPECT_FALSE(panel().busy());
  EXPECT_TRUE(panel().subject().contains("interpolated keyframes"));
  EXPECT_EQ(sentence(), interpolated);
  expect_shows(direct());
}

TEST_F(TwistPanelTest, HiddenItComputesNothingShownItCatchesUp) {
  ASSERT_NO_FATAL_FAILURE(open(motion(kM5)));
  QApplication::processEvents();
  EXPECT_TRUE(panel().busy());
  QTest::qWait(1500);
  EXPECT_TRUE(panel().busy()) << "computed while out of view";
  window_->show_twist_panel();
  ASSERT_TRUE(wait_for_result());
  expect_shows(direct());
}

TEST_F(TwistPanelTest, AModelWithoutLeftRightPairsGetsTheLibrarysMessage) {
  // The default model with the right shoulder renamed, and M5 keyframed on it.
  const std::string models = std::string(SALTUS_EXAMPLES_DIR) + "/../resources/models/";
  nlohmann::json model;
  std::ifstream(models + "zatsiorsky-66kg.json") >> model;
  for (nlohmann::json& segment : model["segments"])
    if (segment["joint"] == "shoulder_r") segment["joint"] = "right_shoulder";
  model["name"] = "no-pairs";
  const std::filesystem::path model_path = saltus::test::temp_path("no-pairs.json");
  std::ofstream(model_path) << model.dump();
  nlohmann::json m5;
  std::ifstream(motion(kM5).toStdString()) >> m5;
  for (nlohmann::json& key : m5["keyframes"]) {
    key["rotations"]["right_shoulder"] = key["rotations"]["shoulder_r"];
    key["rotations"].erase("shoulder_r");
  }
  m5["model"] = model_path.filename().string();  // beside it
  const std::filesystem::path motion_path = saltus::test::temp_path("no-pairs.motion.json");
  std::ofstream(motion_path) << m5.dump();

  ASSERT_NO_FATAL_FAILURE(open(QString::fromStdString(motion_path.string())));
  window_->show_twist_panel();
  ASSERT_TRUE(wait_for_result());
  std::string message;
  try {
    direct();
  } catch (const std::invalid_argument& e) {
    message = e.what();
  }
  ASSERT_FALSE(message.empty()) << "the library found the pairs after all";
  EXPECT_TRUE(panel().sentence().contains(QString::fromStdString(message)))
      << panel().sentence().toStdString();
  EXPECT_EQ(panel().table()->rowCount(), 0);
}

TEST_F(TwistPanelTest, PicturesOfM5AndM7) {
  window_->resize(1600, 1000);
  for (const auto& [name, stem] : {std::pair{kM5, "M5"}, std::pair{kM7, "M7"}}) {
    ASSERT_NO_FATAL_FAILURE(open(motion(name)));
    window_->show_twist_panel();
    ASSERT_TRUE(wait_for_result());
    std::printf("twist_sources on %s: %.3f s on the worker thread\n", stem, panel().last_seconds());
    // Not at mid-flight: the time cursor beside the mid-flight marker, not over it.
    window_->seek(0.7 * window_->document().duration());
    QApplication::processEvents();
    save_candidate(QString("twist_panel_%1_1600x1000.png").arg(stem));
  }
  window_->resize(1366, 768);
  QApplication::processEvents();
  save_candidate("twist_panel_M7_1366x768.png");
  // The chart whole and tall enough to read at laptop size.
  EXPECT_GE(panel().chart()->height(), 200);
}

}  // namespace
}  // namespace saltus::gui
