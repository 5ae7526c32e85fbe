// Picking a joint in the 3D view: a real mouse click at the on-screen centre of a segment selects
// that segment's joint in the joint-load plot (and shows that tab) and highlights the segment; a
// drag rotates the camera and picks nothing; a click beside the body drops the highlight. The
// centre comes from the library's pose at the shown time and VTK's world-to-display conversion,
// not from the scene's actors, so a wrong actor-to-segment mapping fails here. Which segments are
// clicked is decided from the same poses: the first ones nothing else hides (any test motion).

#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QTabWidget>
#include <QTest>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "app/compare_controller.h"
#include "app/edit_controller.h"
#include "app/file_controller.h"
#include "app/main_window.h"
#include "app/plots_panel.h"
#include "app/run_controller.h"
#include "app/scene_widget.h"
#include "app/view_controller.h"
#include "gui/support/image_checks.h"
#include "gui/support/open_motion_fixture.h"
#include "gui_core/test_motion.h"
#include "saltus/body/segment_names.h"

namespace saltus::gui {
namespace {

class SegmentPickTest : public test::OpenMotionTest {
 protected:
  void SetUp() override {
    test::OpenMotionTest::SetUp();
    if (HasFatalFailure()) return;
    window_->set_camera(CameraPreset::kFollow);
    window_->seek(0.8);
    window_->fix_view_size(QSize(900, 600));
    view_ = window_->findChild<SceneWidget*>();
    ASSERT_NE(view_, nullptr);
    window_->grab_view();  // rendered at its final size: the camera's projection is current
  }

  const BodyModel& model() const { return window_->document().file().model; }

  /// The ends of a segment's capsule axis at the shown time: it spans the segment from its joint
  /// along its y axis (shape.length, signed), with the shape's radius around that.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> axis(int index) const {
    const SampleRecord s = window_->document().sample_at(window_->stage(), window_->time());
    const auto i = static_cast<std::size_t>(index);
    const double length = model().segments[i].shape.length;
    return {s.segment_position[i],
            s.segment_position[i] + s.segment_rotation[i] * Eigen::Vector3d(0, length, 0)};
  }

  Eigen::Vector3d centre(int index) const {
    const auto [a, b] = axis(index);
    return 0.5 * (a + b);
  }

  vtkRenderer* renderer() const {
    return view_->render_window()->GetRenderers()->GetFirstRenderer();
  }

  /// Whether a segment is the first one the line of sight to its centre meets, by the library's
  /// poses and the model's radii. The others count a little thicker, so that one that nearly
  /// covers the centre also rules it out (the drawn capsules are polygons).
  bool in_front(int index) const {
    double eye[3];
    renderer()->GetActiveCamera()->GetPosition(eye);
    const Eigen::Vector3d origin(eye[0], eye[1], eye[2]);
    const Eigen::Vector3d to_centre = centre(index) - origin;
    const Eigen::Vector3d direction = to_centre.normalized();
    // First distance along the sight line (1 mm steps) within `radius` of a segment's axis.
    auto first_hit = [&](int j, double radius) {
      const auto [a, b] = axis(j);
      const Eigen::Vector3d ab = b - a;
      for (double t = 0.0; t <= to_centre.norm(); t += 0.001) {
        const Eigen::Vector3d p = origin + t * direction;
        const double u = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
        if ((p - (a + u * ab)).norm() <= radius) return t;
      }
      return std::numeric_limits<double>::infinity();
    };
    const double own =
        first_hit(index, model().segments[static_cast<std::size_t>(index)].shape.radius);
    for (int j = 0; j < model().size(); ++j) {
      const double r = model().segments[static_cast<std::size_t>(j)].shape.radius;
      if (j != index && first_hit(j, 1.1 * r + 0.01) <= own) return false;
    }
    return true;
  }

  /// Segments the test clicks: the first `count` in front of the others, not the one the joint
  /// plot shows at the start.
  std::vector<int> visible_segments(std::size_t count) const {
    std::vector<int> out;
    for (int i = 0; i < model().size() && out.size() < count; ++i)
      if (i != window_->plots().selected_joint() && in_front(i)) out.push_back(i);
    return out;
  }

  /// Where the centre of a segment's capsule appears in the view (widget coordinates).
  QPoint centre_on_screen(int index) const {
    const Eigen::Vector3d c = centre(index);
    renderer()->SetWorldPoint(c.x(), c.y(), c.z(), 1.0);
    renderer()->WorldToDisplay();
    const double* p = renderer()->GetDisplayPoint();
    // Display: device pixels from the bottom-left; widget: from the top-left.
    const double ratio = view_->devicePixelRatioF();
    const int device_height = view_->render_window()->GetSize()[1];
    return {static_cast<int>(std::lround(p[0] / ratio)),
            static_cast<int>(std::lround((device_height - 1 - p[1]) / ratio))};
  }

  void click(const QPoint& at) {
    QTest::mouseClick(view_, Qt::LeftButton, Qt::NoModifier, at);
    QApplication::processEvents();
  }

  SceneWidget* view_ = nullptr;
};

/// The outline's colour (BodyScene's kOutlineColour, unlit); nothing else in the scene has it.
const QColor kOutline(115, 242, 255);

TEST_F(SegmentPickTest, ClickOnASegmentSelectsItsJointAndHighlightsIt) {
  QTabWidget* tabs = &window_->plots();
  ASSERT_NE(tabs, nullptr);
  // Opened on the root plots, the joint plot at the left knee, nothing highlighted.
  EXPECT_EQ(tabs->currentIndex(), 0);
  EXPECT_EQ(window_->plots().selected_joint(), model().joint_index("knee_l"));
  EXPECT_EQ(window_->view().highlighted_segment(), -1);
  const QImage plain = window_->grab_view();
  EXPECT_LT(test::colour_fraction(plain, kOutline), 1e-5);

  const std::vector<int> targets = visible_segments(2);
  ASSERT_EQ(targets.size(), 2u) << "fewer than two segments in sight at this time";
  auto* joint_list = tabs->widget(1)->findChild<QComboBox*>();
  ASSERT_NE(joint_list, nullptr);
  for (int target : targets) {
    const Segment& s = model().segments[static_cast<std::size_t>(target)];
    SCOPED_TRACE("clicked " + s.name);
    click(centre_on_screen(target));
    EXPECT_EQ(window_->plots().selected_joint(), target);
    EXPECT_EQ(window_->view().highlighted_segment(), target);
    EXPECT_EQ(tabs->currentIndex(), 1) << "the joint-load plot is not shown";
    // Named as people name it ("Left knee (left lower leg)").
    EXPECT_TRUE(joint_list->currentText().startsWith(
        QString::fromStdString(capitalised(joint_label(s.joint)) + " (")))
        << joint_list->currentText().toStdString();
    const QImage picked = window_->grab_view();
    EXPECT_NE(picked, plain);
    EXPECT_GT(test::colour_fraction(picked, kOutline), 1e-4) << "no outline around the segment";
    QDir().mkpath(SALTUS_GUI_CANDIDATE_DIR);
    picked.save(QString(SALTUS_GUI_CANDIDATE_DIR) + "/view_picked_" +
                QString::fromStdString(s.name) + ".png");
  }
}

TEST_F(SegmentPickTest, ADragRotatesTheCameraAndPicksNothing) {
  const int before = window_->plots().selected_joint();
  const QImage plain = window_->grab_view();
  const std::vector<int> targets = visible_segments(1);
  ASSERT_EQ(targets.size(), 1u);
  const QPoint start = centre_on_screen(targets[0]);
  QTest::mousePress(view_, Qt::LeftButton, Qt::NoModifier, start);
  for (int dx = 10; dx <= 60; dx += 10) {
    QMouseEvent move(QEvent::MouseMove, start + QPoint(dx, dx / 2), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QApplication::sendEvent(view_, &move);
  }
  QTest::mouseRelease(view_, Qt::LeftButton, Qt::NoModifier, start + QPoint(60, 30));
  QApplication::processEvents();
  EXPECT_EQ(window_->plots().selected_joint(), before);
  EXPECT_EQ(window_->view().highlighted_segment(), -1);
  EXPECT_NE(window_->grab_view(), plain) << "the drag did not rotate the camera";
}

TEST_F(SegmentPickTest, ClickBesideTheBodyDropsTheHighlightAndKeepsTheJoint) {
  const QImage plain = window_->grab_view();
  const std::vector<int> targets = visible_segments(1);
  ASSERT_EQ(targets.size(), 1u);
  click(centre_on_screen(targets[0]));
  ASSERT_EQ(window_->view().highlighted_segment(), targets[0]);
  // Left edge, half-way down: background only (the follow camera keeps the body centred).
  click(QPoint(20, view_->height() / 2));
  EXPECT_EQ(window_->view().highlighted_segment(), -1);
  EXPECT_EQ(window_->plots().selected_joint(), targets[0]);
  EXPECT_EQ(window_->grab_view(), plain) << "the highlight did not go away";
}

TEST_F(SegmentPickTest, ChoosingAnotherJointInTheListMovesTheHighlight) {
  const std::vector<int> targets = visible_segments(1);
  ASSERT_EQ(targets.size(), 1u);
  click(centre_on_screen(targets[0]));
  QTabWidget* tabs = &window_->plots();
  auto* joint_list = tabs->widget(1)->findChild<QComboBox*>();
  ASSERT_NE(joint_list, nullptr);
  const int other = (targets[0] + 1) % model().size();
  joint_list->setCurrentIndex(other);
  EXPECT_EQ(window_->plots().selected_joint(), other);
  EXPECT_EQ(window_->view().highlighted_segment(), other);
}

}  // namespace
}  // namespace saltus::gui
