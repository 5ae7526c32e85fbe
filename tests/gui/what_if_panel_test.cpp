// The What if panel: each slider pressed as a user would (its keys) and Reset clicked, the answer
// waited for and checked against the library's what_if for those settings, computed here
// directly; the 3D view draws that flight beside the athlete. Another motion clears the answer at
// once and brings its own; a straight motion says it has no tuck; a drag is answered while it
// goes on and the newest value wins. The latency from a slider's change to its answer on M7 is
// measured and printed (median); pictures are left in the candidate folder to look at.

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSlider>
#include <QTest>
#include <algorithm>
#include <cstdio>
#include <memory>
#include <tuple>

#include "app/main_window.h"
#include "app/scene_widget.h"
#include "app/what_if_panel.h"
#include "core/what_if_report.h"
#include "saltus/evaluation/what_if.h"

namespace saltus::gui {
namespace {

QString motion(const std::string& name) {
  return QString(SALTUS_EXAMPLES_DIR) + "/motions/" + QString::fromStdString(name);
}
const std::string kM1 = "M1-straight-back-somersault.motion.json";
const std::string kM2 = "M2-tucked-back-somersault.motion.json";
const std::string kM7 = "M7-double-front-one-and-a-half-twists.motion.json";

class WhatIfPanelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    window_ = std::make_unique<MainWindow>(false);
    window_->resize(1366, 768);
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
  }
  void TearDown() override {
    window_->close();
    window_.reset();
  }
  WhatIfPanel& panel() { return window_->what_if(); }
  void open(const std::string& name) {
    QString error;
    ASSERT_TRUE(window_->open_motion(motion(name), &error)) << error.toStdString();
  }
  /// Keeps the event loop running until the panel answers for the motion and sliders shown.
  bool wait_for_answer(int timeout_ms = 60000) {
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < timeout_ms) {
      QApplication::processEvents(QEventLoop::AllEvents, 5);
      if (!panel().busy()) {
        QApplication::processEvents();
        return true;
      }
    }
    return false;
  }
  /// What the library says of the motion shown with `change`, called directly.
  WhatIfResult direct(const WhatIfChange& change) const {
    const Document& d = window_->document();
    return WhatIf(d.file().motion, d.file().model, d.evaluate_options()).fly(change);
  }
  /// The panel shows exactly the library's answer for its sliders, and the 3D view draws that
  /// flight beside the athlete at the time shown.
  void expect_shows_library_answer() {
    const WhatIfChange change = panel().change();
    const WhatIfResult expected = direct(change);
    ASSERT_TRUE(panel().result());
    const WhatIfResult& shown = *panel().result();
    EXPECT_EQ(shown.change.tuck_later_s, change.tuck_later_s);
    EXPECT_EQ(shown.change.open_later_s, change.open_later_s);
    EXPECT_EQ(shown.change.tuck_scale, change.tuck_scale);
    EXPECT_EQ(panel().sentence().toStdString(), expected.sentence);
    EXPECT_EQ(shown.landing.somersaults, expected.landing.somersaults);
    EXPECT_EQ(shown.landing.twists, expected.landing.twists);
    EXPECT_EQ(shown.somersault_over_deg, expected.somersault_over_deg);
    // The gold figure flies this flight: its trunk at the time shown is the flight's.
    BodyScene& scene = window_->view_widget()->scene();
    ASSERT_TRUE(scene.what_if_shown());
    const std::optional<SampleRecord> pose = scene.what_if_pose();
    ASSERT_TRUE(pose);
    const SampleRecord at = flight_sample_at(expected.flight.samples, window_->time());
    EXPECT_LT(pose->segment_rotation[0].angularDistance(at.segment_rotation[0]), 1e-9);
    EXPECT_EQ(panel().flight_label().toStdString(),
              change.unchanged() ? "flown as it is" : "what if: " + expected.change_words);
  }
  void save_candidate(const QString& name) {
    const QString dir = SALTUS_GUI_CANDIDATE_DIR;
    QDir().mkpath(dir);
    EXPECT_TRUE(window_->grab_window().save(dir + "/" + name));
  }

  std::unique_ptr<MainWindow> window_;
};

TEST_F(WhatIfPanelTest, TheViewMenuShowsThePanelWithTheMotionAsItIs) {
  QAction* action = nullptr;
  for (QAction* m : window_->menuBar()->actions())
    if (m->text().remove('&') == "View")
      for (QAction* a : m->menu()->actions())
        if (a->text().remove('&') == "What if…") action = a;
  ASSERT_NE(action, nullptr);
  ASSERT_NO_FATAL_FAILURE(open(kM7));
  auto* dock = window_->findChild<QDockWidget*>("what_if_dock");
  ASSERT_NE(dock, nullptr);
  EXPECT_TRUE(panel().visibleRegion().isEmpty());  // the Optimise panel is in front
  EXPECT_FALSE(panel().active());
  action->trigger();
  QApplication::processEvents();
  EXPECT_FALSE(panel().visibleRegion().isEmpty());
  EXPECT_TRUE(panel().active());
  ASSERT_TRUE(wait_for_answer());
  expect_shows_library_answer();
  EXPECT_TRUE(panel().sentence().startsWith("Same take-off, as keyframed: "));
  EXPECT_TRUE(panel().subject().contains("interpolated keyframes"));
  // The tuck the library found, in words; all three sliders usable.
  const Document& d = window_->document();
  const WhatIf prepared(d.file().motion, d.file().model, d.evaluate_options());
  EXPECT_EQ(panel().tuck().toStdString(), tuck_text(prepared.tuck()));
  EXPECT_TRUE(panel().tuck_slider()->isEnabled());
  EXPECT_TRUE(panel().open_slider()->isEnabled());
  EXPECT_TRUE(panel().tightness_slider()->isEnabled());
  // Its ranges are the library's, in steps of 0.01 s.
  const SliderSteps open =
      shift_slider_steps(prepared.tuck().open_later_min_s, prepared.tuck().open_later_max_s);
  EXPECT_EQ(panel().open_slider()->minimum(), open.min);
  EXPECT_EQ(panel().open_slider()->maximum(), open.max);
}

TEST_F(WhatIfPanelTest, EachSliderPressedGivesTheLibrarysAnswer) {
  ASSERT_NO_FATAL_FAILURE(open(kM7));
  window_->show_what_if_panel();
  ASSERT_TRUE(wait_for_answer());
  const std::string as_it_is = panel().sentence().toStdString();

  // Opening: Page Up on the slider, one page (5 steps): 0.05 s later.
  QSlider* open = panel().open_slider();
  open->setFocus();
  QTest::keyClick(open, Qt::Key_PageUp);
  EXPECT_EQ(open->value(), 5);
  EXPECT_TRUE(panel().busy());
  ASSERT_TRUE(wait_for_answer());
  expect_shows_library_answer();
  EXPECT_TRUE(panel().sentence().contains("opening 0.05 s later"))
      << panel().sentence().toStdString();
  EXPECT_NE(panel().sentence().toStdString(), as_it_is);

  // Tuck: two steps earlier (Left arrow twice).
  QSlider* tuck = panel().tuck_slider();
  tuck->setFocus();
  QTest::keyClick(tuck, Qt::Key_Left);
  QTest::keyClick(tuck, Qt::Key_Left);
  EXPECT_EQ(tuck->value(), -2);
  ASSERT_TRUE(wait_for_answer());
  expect_shows_library_answer();
  EXPECT_TRUE(panel().sentence().contains("tucking 0.02 s earlier, opening 0.05 s later"))
      << panel().sentence().toStdString();

  // Tightness: ten steps tighter (Page Up twice), seen at another moment of the flight.
  window_->seek(0.6 * window_->document().duration());
  QSlider* tightness = panel().tightness_slider();
  tightness->setFocus();
  QTest::keyClick(tightness, Qt::Key_PageUp);
  QTest::keyClick(tightness, Qt::Key_PageUp);
  EXPECT_EQ(tightness->value(), 110);
  ASSERT_TRUE(wait_for_answer());
  expect_shows_library_answer();
  EXPECT_TRUE(panel().sentence().contains("tuck 10 % tighter")) << panel().sentence().toStdString();
  std::printf("M7: %s\n", panel().sentence().toStdString().c_str());

  // Reset clicked: no change, the motion as it is again.
  QTest::mouseClick(panel().reset_button(), Qt::LeftButton);
  EXPECT_EQ(tuck->value(), 0);
  EXPECT_EQ(open->value(), 0);
  EXPECT_EQ(tightness->value(), 100);
  ASSERT_TRUE(wait_for_answer());
  EXPECT_TRUE(panel().result()->change.unchanged());
  EXPECT_EQ(panel().sentence().toStdString(), as_it_is);
  expect_shows_library_answer();
}

TEST_F(WhatIfPanelTest, AnotherMotionClearsTheAnswerAndBringsItsOwn) {
  ASSERT_NO_FATAL_FAILURE(open(kM7));
  window_->show_what_if_panel();
  ASSERT_TRUE(wait_for_answer());
  panel().open_slider()->setValue(4);
  ASSERT_TRUE(wait_for_answer());
  const std::string m7 = panel().sentence().toStdString();
  ASSERT_TRUE(window_->view_widget()->scene().what_if_shown());

  // M2 opened: M7's answer and figure go at once, the sliders back to the motion as it is.
  ASSERT_NO_FATAL_FAILURE(open(kM2));
  EXPECT_NE(panel().sentence().toStdString(), m7);
  EXPECT_FALSE(panel().result());
  EXPECT_EQ(panel().flight(), nullptr);
  EXPECT_FALSE(window_->view_widget()->scene().what_if_shown());
  EXPECT_EQ(panel().open_slider()->value(), 0);
  EXPECT_FALSE(panel().open_slider()->isEnabled());  // until M2's tuck is found
  ASSERT_TRUE(wait_for_answer());
  expect_shows_library_answer();
  EXPECT_TRUE(panel().open_slider()->isEnabled());
  // M2 is a back somersault without twist: its words have no twist.
  EXPECT_FALSE(panel().sentence().contains("twist")) << panel().sentence().toStdString();

  // M1 is straight: no tuck, the library's reason, no slider to move; it still flies as it is.
  ASSERT_NO_FATAL_FAILURE(open(kM1));
  ASSERT_TRUE(wait_for_answer());
  const Document& d = window_->document();
  const WhatIf m1(d.file().motion, d.file().model, d.evaluate_options());
  ASSERT_FALSE(m1.tuck().found);
  EXPECT_EQ(panel().tuck().toStdString(), m1.tuck().reason);
  EXPECT_FALSE(panel().tuck_slider()->isEnabled());
  EXPECT_FALSE(panel().open_slider()->isEnabled());
  EXPECT_FALSE(panel().tightness_slider()->isEnabled());
  EXPECT_FALSE(panel().reset_button()->isEnabled());
  expect_shows_library_answer();
}

TEST_F(WhatIfPanelTest, AMotionOpenedWhileFlyingNeverShowsTheOldAnswer) {
  ASSERT_NO_FATAL_FAILURE(open(kM7));
  window_->show_what_if_panel();
  ASSERT_TRUE(wait_for_answer());
  panel().tightness_slider()->setValue(115);
  ASSERT_TRUE(panel().busy());
  // Every answer shown from now on must be M2's.
  ASSERT_NO_FATAL_FAILURE(open(kM2));
  std::vector<std::string> shown;
  QObject::connect(&panel(), &WhatIfPanel::result_shown, &panel(),
                   [&] { shown.push_back(panel().sentence().toStdString()); });
  ASSERT_TRUE(wait_for_answer());
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_EQ(shown[0], direct(WhatIfChange{}).sentence);
}

TEST_F(WhatIfPanelTest, ADragIsAnsweredAsItGoesAndTheNewestValueWins) {
  ASSERT_NO_FATAL_FAILURE(open(kM7));
  window_->show_what_if_panel();
  ASSERT_TRUE(wait_for_answer());
  std::vector<double> answered;  // open_later_s of each answer shown, in order
  QObject::connect(&panel(), &WhatIfPanel::result_shown, &panel(), [&] {
    if (panel().result()) answered.push_back(panel().result()->change.open_later_s);
  });
  QSlider* open = panel().open_slider();
  open->setSliderDown(true);
  for (int v = 1; v <= 12; ++v) {
    open->setValue(v);
    QTest::qWait(25);  // a quick drag: a new value every 25 ms
  }
  open->setSliderDown(false);
  ASSERT_TRUE(wait_for_answer());
  ASSERT_FALSE(answered.empty());
  // Answers came while dragging, each for a value the slider had, in the order it had them.
  for (std::size_t i = 1; i < answered.size(); ++i)
    EXPECT_GT(answered[i], answered[i - 1]);
  EXPECT_DOUBLE_EQ(answered.back(), 0.12);
  std::printf("a 12-step drag over 0.3 s was answered %zu times\n", answered.size());
  expect_shows_library_answer();
}

TEST_F(WhatIfPanelTest, OutOfViewItFliesNothingAndDrawsNoFigure) {
  ASSERT_NO_FATAL_FAILURE(open(kM7));
  QApplication::processEvents();
  QTest::qWait(1500);
  EXPECT_TRUE(panel().busy()) << "flew while out of view";
  EXPECT_FALSE(window_->view_widget()->scene().what_if_shown());
  window_->show_what_if_panel();
  ASSERT_TRUE(wait_for_answer());
  EXPECT_TRUE(window_->view_widget()->scene().what_if_shown());
  // Its time to answer counts from when it came into view, not from the opening.
  EXPECT_LT(panel().last_latency_ms(), 1500.0);
  // Another panel in front: the figure goes.
  window_->show_twist_panel();
  QApplication::processEvents();
  EXPECT_FALSE(panel().active());
  EXPECT_FALSE(window_->view_widget()->scene().what_if_shown());
}

TEST_F(WhatIfPanelTest, LatencyFromASliderChangeToItsAnswerOnM7) {
  ASSERT_NO_FATAL_FAILURE(open(kM7));
  window_->show_what_if_panel();
  ASSERT_TRUE(wait_for_answer());
  // One slider change a second, as a coach tries one value after another and looks at each
  // answer: open, tuck, tightness in turn.
  std::vector<double> latencies;
  const std::vector<std::pair<QSlider*, int>> moves = {
      {panel().open_slider(), 3},  {panel().tuck_slider(), 2},  {panel().tightness_slider(), 95},
      {panel().open_slider(), 6},  {panel().tuck_slider(), -4}, {panel().tightness_slider(), 108},
      {panel().open_slider(), -5}, {panel().tuck_slider(), 5},  {panel().tightness_slider(), 112},
      {panel().open_slider(), 10}, {panel().tuck_slider(), -1}, {panel().tightness_slider(), 90},
      {panel().open_slider(), 0},  {panel().tuck_slider(), 0},  {panel().tightness_slider(), 103}};
  for (const auto& [slider, value] : moves) {
    slider->setValue(value);
    ASSERT_TRUE(wait_for_answer());
    latencies.push_back(panel().last_latency_ms());
    std::printf("  %s: %.0f ms (flight %.0f ms)\n", panel().result()->change_words.c_str(),
                panel().last_latency_ms(), panel().last_flight_ms());
    QTest::qWait(1000);
  }
  const double median = median_ms(latencies);
  std::printf(
      "What if on M7: from a slider's change to its answer on screen, median %.0f ms "
      "(%zu changes, %.0f-%.0f ms); the last flight alone %.0f ms\n",
      median, latencies.size(), *std::min_element(latencies.begin(), latencies.end()),
      *std::max_element(latencies.begin(), latencies.end()), panel().last_flight_ms());
  // The target is 100 ms; the test only fails far beyond it (a loaded machine).
  EXPECT_LT(median, 400.0);
}

TEST_F(WhatIfPanelTest, PicturesOfM7AndM2) {
  for (const auto& [name, stem, open_steps, percent] :
       {std::tuple{kM7, "M7", 5, 100}, std::tuple{kM2, "M2", 0, 110}}) {
    ASSERT_NO_FATAL_FAILURE(open(name));
    window_->show_what_if_panel();
    ASSERT_TRUE(wait_for_answer());
    panel().open_slider()->setValue(open_steps);
    panel().tightness_slider()->setValue(percent);
    ASSERT_TRUE(wait_for_answer());
    for (const auto& [at, when] : {std::pair{0.55, "mid"}, std::pair{1.0, "landing"}}) {
      window_->seek(at * window_->document().duration());
      QApplication::processEvents();
      save_candidate(QString("what_if_%1_%2_1366x768.png").arg(stem, when));
    }
  }
}

}  // namespace
}  // namespace saltus::gui
