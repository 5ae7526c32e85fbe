// The cameras frame the athlete: in every preset the standing body fills about 60 % of the
// view's height, the centre of mass stays in the middle as time goes on (the camera follows),
// and zooming with the wheel closes in on the body, not on the flight path. Positions come from
// the library's poses and VTK's world-to-display conversion, not from the scene's actors.

#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include <gtest/gtest.h>

#include <QApplication>
#include <QTest>
#include <QWheelEvent>
#include <algorithm>
#include <limits>

#include "app/main_window.h"
#include "app/scene_widget.h"
#include "gui/support/open_motion_fixture.h"

namespace saltus::gui {
namespace {

class CameraTest : public test::OpenMotionTest {
 protected:
  void SetUp() override {
    test::OpenMotionTest::SetUp();
    if (HasFatalFailure()) return;
    window_->fix_view_size(QSize(900, 600));
    window_->grab_view();
  }
  vtkRenderer* renderer() const {
    return window_->view_widget()->render_window()->GetRenderers()->GetFirstRenderer();
  }
  Eigen::Vector2d on_screen(const Eigen::Vector3d& p) const {
    renderer()->SetWorldPoint(p.x(), p.y(), p.z(), 1.0);
    renderer()->WorldToDisplay();
    const double* d = renderer()->GetDisplayPoint();
    return {d[0], d[1]};
  }
  /// Where the CoM is in the view, as a share of its width and height from the centre.
  Eigen::Vector2d com_offset(double t) {
    window_->seek(t);
    window_->grab_view();
    const SampleRecord s = window_->document().sample_at(window_->stage(), t);
    const Eigen::Vector2d p = on_screen(s.com);
    return {p.x() / 900.0 - 0.5, p.y() / 600.0 - 0.5};
  }
  /// The body's height on the screen at take-off (the athlete stands), share of the view.
  double body_share_at_takeoff() {
    window_->seek(0.0);
    window_->grab_view();
    const SampleRecord s = window_->document().sample_at(window_->stage(), 0.0);
    const BodyModel& model = window_->document().file().model;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < s.segment_position.size(); ++i) {
      const Eigen::Vector3d end =
          s.segment_position[i] +
          s.segment_rotation[i] * Eigen::Vector3d(0, model.segments[i].shape.length, 0);
      for (const Eigen::Vector3d& p : {s.segment_position[i], end}) {
        const double y = on_screen(p).y();
        lo = std::min(lo, y);
        hi = std::max(hi, y);
      }
    }
    return (hi - lo) / 600.0;
  }
};

TEST_F(CameraTest, SideAndFrontFrameTheStandingBodyAtAboutSixtyPercent) {
  for (CameraPreset preset : {CameraPreset::kSide, CameraPreset::kFront, CameraPreset::kFollow}) {
    SCOPED_TRACE(camera_preset_name(preset));
    window_->set_camera(preset);
    const double share = body_share_at_takeoff();
    // The model's extent (1.70 m; the drawn feet add a little) at 60 % of the height; the
    // follow camera looks from a little above, which shortens it.
    EXPECT_GT(share, preset == CameraPreset::kFollow ? 0.45 : 0.5);
    EXPECT_LT(share, 0.7);
  }
}

TEST_F(CameraTest, EveryCameraFollowsTheCentreOfMass) {
  for (CameraPreset preset : camera_presets()) {
    SCOPED_TRACE(camera_preset_name(preset));
    window_->set_camera(preset);
    for (double t : {0.0, 0.6, 1.0, 1.9}) {
      const Eigen::Vector2d offset = com_offset(t);
      EXPECT_LT(offset.norm(), 0.02) << "t = " << t;
    }
  }
}

TEST_F(CameraTest, TheWheelZoomsTowardsTheBodyAndTheCameraKeepsFollowing) {
  window_->set_camera(CameraPreset::kSide);
  const double before = body_share_at_takeoff();
  SceneWidget* view = window_->view_widget();
  // Zoom in where the mouse is off centre: VTK's dolly moves towards the focal point, the CoM.
  const QPoint at(700, 150);
  for (int i = 0; i < 3; ++i) {
    QWheelEvent wheel(at, view->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view, &wheel);
  }
  QApplication::processEvents();
  EXPECT_GT(body_share_at_takeoff(), 1.2 * before);
  // Later in the flight the body is still in the middle, at the zoom the user chose.
  EXPECT_LT(com_offset(1.2).norm(), 0.02);
}

}  // namespace
}  // namespace saltus::gui
