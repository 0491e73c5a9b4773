#include "ballsight/sim/omni_truth.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/omni_scenario.hpp"
#include "ballsight/sim/omni_truth_json.hpp"

namespace ballsight::sim {
namespace {

OmniScene calibration_scene() {
  OmniScene scene;
  scene.rig.tilt_deg = 1.5;
  scene.rig.tilt_azimuth_deg = 200.0;
  scene.rig.center_offset_px = {-5.0, 2.0};
  scene.robot_pose = {{2.5, 7.0}, rad_from_deg(-60.0)};
  scene.markers = calibration_markers(scene.robot_pose);
  scene.ball = OmniBall{field_from_robot_point(scene.robot_pose, {1.2, 0.3})};
  return scene;
}

TEST(OmniTruth, TrueMappingAtAMarkersPixelReturnsTheMarker) {
  const OmniScene scene = calibration_scene();
  const OmniRig rig(scene.rig);
  const OmniTruth truth = make_omni_truth(scene, rig);
  ASSERT_EQ(truth.markers.size(), 36u * 9u);
  const OmniRig reproduced(truth.rig);  // the truth alone reproduces the mapping
  for (const OmniMarkerTruth& m : truth.markers) {
    SCOPED_TRACE(testing::Message() << "marker " << m.id);
    EXPECT_LT((robot_from_field_point(truth.robot_pose, m.position_in_field) - m.position_in_robot)
                  .norm(),
              1e-12);
    ASSERT_TRUE(m.pixel);
    const std::optional<Vec2> ground = reproduced.ground_from_pixel(*m.pixel);
    ASSERT_TRUE(ground);
    EXPECT_LT((*ground - m.position_in_robot).norm(), 1e-3);
    EXPECT_NEAR(m.range.distance_m, m.position_in_robot.norm(), 1e-12);
  }
  // Ids are ray-major: marker 9 * k + j lies on bearing 10 k deg at 0.6 + 0.5 j m.
  EXPECT_NEAR(truth.markers[9 * 3 + 2].range.bearing_deg, 30.0, 1e-9);
  EXPECT_NEAR(truth.markers[9 * 3 + 2].range.distance_m, 1.6, 1e-9);
  EXPECT_NEAR(truth.markers[9 * 20 + 8].range.bearing_deg, -160.0, 1e-9);
}

TEST(OmniTruth, BallIsImagedWhereTheRigProjectsIt) {
  const OmniScene scene = calibration_scene();
  const OmniRig rig(scene.rig);
  const OmniTruth truth = make_omni_truth(scene, rig);
  ASSERT_TRUE(truth.ball && truth.ball->visible);
  const OmniBallTruth& b = *truth.ball;
  EXPECT_LT((b.position_in_robot - Vec2(1.2, 0.3)).norm(), 1e-12);
  EXPECT_NEAR(b.range.bearing_deg, deg_from_rad(std::atan2(0.3, 1.2)), 1e-9);
  const Vec2 center = *rig.pixel_from_point({1.2, 0.3, 0.11});
  EXPECT_LT((*b.center_px - center).norm(), 1e-9);
  // The silhouette's centroid is near, not at, the centre's image (perspective and the mirror
  // shift it a little), and lies between the centre's image and the contact point's image.
  const Vec2 contact = *rig.pixel_from_point({1.2, 0.3, 0.0});
  EXPECT_LT((*b.silhouette_centroid_px - center).norm(), 2.0);
  EXPECT_LT((*b.silhouette_centroid_px - contact).norm(), (center - contact).norm() + 2.0);
  // The ball (1.24 m away) hides the markers right behind it from the camera.
  int hidden = 0;
  for (const OmniMarkerTruth& m : truth.markers) hidden += m.visible ? 0 : 1;
  EXPECT_GT(hidden, 0);
  EXPECT_LT(hidden, 6);
}

TEST(OmniTruth, MappingTableFollowsTheRig) {
  OmniRigParams aligned;
  const OmniMappingTable table = sample_omni_mapping(OmniRig(aligned));
  ASSERT_EQ(table.samples.size(), 72u * 23u);  // 10..230 px, inside the 240 px mirror
  for (std::size_t i = 0; i < table.samples.size(); ++i) {
    const OmniMappingSample& s = table.samples[i];
    ASSERT_TRUE(s.ground) << s.theta_deg << " deg " << s.radius_px << " px";
    // Aligned: the robot bearing is the image angle - 90 deg (the paper's convention).
    EXPECT_NEAR(
        wrap_deg_180(s.ground->bearing_deg - robot_bearing_deg_from_image_theta_deg(s.theta_deg)),
        0.0, 1e-6);
    if (i > 0 && table.samples[i - 1].theta_deg == s.theta_deg) {
      EXPECT_GT(s.ground->distance_m, table.samples[i - 1].ground->distance_m);  // monotonic
    }
  }
}

TEST(OmniTruthJson, RoundTripsEveryField) {
  const OmniScene scene = calibration_scene();
  const OmniTruth truth = make_omni_truth(scene, OmniRig(scene.rig));
  const std::string text = omni_truth_json_text(truth);
  const OmniTruth back = omni_truth_from_json(Json::parse(text), "test");
  // Everything but the table's distances (cm in the file, m in memory) comes back bit for bit.
  Json original = omni_truth_to_json(truth);
  Json again = omni_truth_to_json(back);
  original.erase("mapping");
  again.erase("mapping");
  EXPECT_EQ(again, original);
  ASSERT_EQ(back.mapping.samples.size(), truth.mapping.samples.size());
  for (std::size_t i = 0; i < truth.mapping.samples.size(); ++i) {
    const OmniMappingSample& a = truth.mapping.samples[i];
    const OmniMappingSample& b = back.mapping.samples[i];
    EXPECT_EQ(a.theta_deg, b.theta_deg);
    EXPECT_EQ(a.radius_px, b.radius_px);
    ASSERT_EQ(a.ground.has_value(), b.ground.has_value());
    if (a.ground) {
      EXPECT_NEAR(a.ground->distance_m, b.ground->distance_m, 1e-12);
    }
  }
  EXPECT_EQ(back.rig.center_offset_px, scene.rig.center_offset_px);
  EXPECT_NEAR(back.robot_pose.heading_rad, scene.robot_pose.heading_rad, 1e-15);
  ASSERT_EQ(back.markers.size(), truth.markers.size());
  EXPECT_EQ(back.markers[17].pixel, truth.markers[17].pixel);
  EXPECT_EQ(back.ball->silhouette_centroid_px, truth.ball->silhouette_centroid_px);
}

TEST(OmniTruthJson, NamesTheBadOrMissingKey) {
  const OmniScene scene = calibration_scene();
  const Json good = omni_truth_to_json(make_omni_truth(scene, OmniRig(scene.rig)));
  const auto message = [](const Json& doc) {
    try {
      omni_truth_from_json(doc, "scene.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  Json doc = good;
  doc["robot"].erase("heading_deg");
  EXPECT_EQ(message(doc), "scene.json: truth.robot.heading_deg: missing");
  doc = good;
  doc["markers"][3]["pixel"] = "here";
  EXPECT_EQ(message(doc), "scene.json: truth.markers[3].pixel: expected [x, y]");
  doc = good;
  doc["version"] = 99;
  EXPECT_NE(message(doc).find("truth.version"), std::string::npos);
  EXPECT_NE(message(Json::array()).find("expected an object"), std::string::npos);
}

}  // namespace
}  // namespace ballsight::sim
