#include "ballsight/calib/omni_ground_model.hpp"

#include <gtest/gtest.h>

#include "ballsight/calib/model_ground_map.hpp"
#include "ballsight/calib/omni_model_fit.hpp"
#include "calib/calib_fixtures.hpp"

namespace ballsight {
namespace {

const std::vector<PolarSample> kSamples = {
    {0, 81, 60, {}}, {90, 150, 200, {}}, {180, 173, 260, {}}};

TEST(OmniImage, DefaultsCoverTheSamplesRadiiWithMargin) {
  const OmniImage square = omni_image_for_samples(kSamples, std::nullopt, std::nullopt);
  EXPECT_EQ(square.width, square.height);
  EXPECT_DOUBLE_EQ(square.center_px.x(), 0.5 * (square.width - 1));
  EXPECT_GT(0.5 * square.width, 1.1 * 173.0);
  for (const PolarSample& s : kSamples) EXPECT_TRUE(square.contains(s.theta_deg, s.radius_px));

  const OmniImage sized = omni_image_for_samples(kSamples, std::nullopt, Eigen::Vector2i(640, 480));
  EXPECT_EQ(sized.center_px, Vec2(319.5, 239.5));
  const OmniImage centred = omni_image_for_samples(kSamples, Vec2(300.0, 250.0), std::nullopt);
  EXPECT_EQ(centred.center_px, Vec2(300.0, 250.0));
  EXPECT_GT(centred.width, 300 + 173);
}

TEST(OmniImage, RejectsImagesThatDoNotFit) {
  EXPECT_NE(test::input_error([] {
              omni_image_for_samples(kSamples, std::nullopt, Eigen::Vector2i(0, 480));
            }).find("image size"),
            std::string::npos);
  EXPECT_NE(test::input_error([] {
              omni_image_for_samples(kSamples, Vec2(700.0, 10.0), Eigen::Vector2i(640, 480));
            }).find("image centre"),
            std::string::npos);
  EXPECT_NE(test::input_error([] {
              omni_image_for_samples(kSamples, std::nullopt, Eigen::Vector2i(64, 48));
            }).find("beyond every corner"),
            std::string::npos);
}

TEST(OmniGroundModel, ValidRadiusRangeHasMargin) {
  const RadiusRange range = valid_radius_from_samples(kSamples, 0.05);
  EXPECT_DOUBLE_EQ(range.min_px, 81.0 - 0.05 * 92.0);
  EXPECT_DOUBLE_EQ(range.max_px, 173.0 + 0.05 * 92.0);
}

// A fitted model baked into a lookup table converts pixels as the model does.
TEST(ModelGroundMap, TableAgreesWithTheModel) {
  const OmniRig rig(test::paper_misaligned_rig());
  SimulatedCalibrationOptions markers = test::paper_markers(5);
  const auto model =
      fit_omni_model(OmniMethod::kBallsight, simulate_calibration(rig, markers).samples, {});
  const GroundMap map = ground_map_from_model(*model);
  EXPECT_EQ(map.info().method, "ballsight");
  EXPECT_EQ(map.info().min_radius_px, model->domain().valid_radius.min_px);
  int compared = 0;
  for (int y = 0; y < map.height(); y += 7) {
    for (int x = 0; x < map.width(); x += 7) {
      const auto expected = model->robot_point_cm({x, y});
      if (!expected) continue;
      const auto from_table = map.robot_point_cm({x, y});
      ASSERT_TRUE(from_table) << x << "," << y;
      EXPECT_NEAR((*from_table - *expected).norm(), 0.0, 1e-3 * expected->norm()) << x << "," << y;
      ++compared;
    }
  }
  EXPECT_GT(compared, 1000);
}

}  // namespace
}  // namespace ballsight
