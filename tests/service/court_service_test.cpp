#include "ballsight/service/court_service.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "example_site.hpp"

namespace ballsight {
namespace {

using test::kExampleSite;

std::vector<FieldCamera> rig_cameras(const sim::CourtRig& rig) {
  std::vector<FieldCamera> cameras;
  for (const sim::CourtCamera& c : rig.cameras) cameras.push_back({c.camera, c.camera_from_field});
  return cameras;
}

// Each camera's last frame and detections are kept with the update they went into; a camera
// whose frame is missing keeps none. A new pipeline (a camera re-calibrated) runs from the next
// frame set on; one for another number of cameras is refused.
TEST(UpdatePublisher, CameraViewsAndANewPipeline) {
  const Site site = read_site(kExampleSite.string());
  const sim::CourtRig rig = sim::make_court_rig({}, {}, 3);
  const sim::CourtScene scene = sim::make_court_scene(rig.court, {}, 3);
  UpdatePublisher publisher(site, {CourtMethod::ballsight, rig_cameras(rig), {}}, {});
  NavigationHub hub;
  EXPECT_FALSE(publisher.camera_view(0));
  std::vector<cv::Mat> frames(4);
  frames[1] = sim::CourtRenderer(rig.cameras[1], rig.court).render(scene, 3).bgr;
  const std::uint64_t seq = publisher.publish(frame_set_of(frames, 1000), hub);
  ASSERT_EQ(seq, 1u);
  const std::optional<CameraView> view = publisher.camera_view(1);
  ASSERT_TRUE(view);
  EXPECT_EQ(view->seq, seq);
  EXPECT_EQ(view->capture_ns, 1000);
  EXPECT_EQ(hub.latest()->capture_time_ns, 1000);  // the frames', carried by the world model
  EXPECT_EQ(view->frame.data, frames[1].data);     // the frame itself, not a copy
  EXPECT_GT(view->detections.size(), 3u);
  EXPECT_FALSE(publisher.camera_view(0));  // no frame from it yet
  EXPECT_FALSE(publisher.camera_view(9));

  std::vector<FieldCamera> moved = rig_cameras(rig);
  moved[1].camera_from_field.translation += Vec3(0.5, 0.0, 0.0);
  publisher.replace_pipeline({CourtMethod::ballsight, moved, {}});
  EXPECT_EQ(publisher.cameras()[1].camera_from_field.translation,
            moved[1].camera_from_field.translation);
  EXPECT_EQ(publisher.publish(frame_set_of(frames, 2000), hub), 2u);
  EXPECT_EQ(publisher.camera_view(1)->seq, 2u);

  moved.pop_back();
  EXPECT_THROW(publisher.replace_pipeline({CourtMethod::ballsight, moved, {}}), InputError);
  EXPECT_EQ(publisher.cameras().size(), 4u);

  // The planner is read at once and used from the next plan on.
  PlannerOptions nearest;
  nearest.kind = PlannerKind::nearest;
  publisher.set_planner(nearest);
  EXPECT_EQ(publisher.planner().kind, PlannerKind::nearest);
  publisher.republish(hub);
  EXPECT_EQ(hub.latest()->route.planner, "nearest");
}

}  // namespace
}  // namespace ballsight
