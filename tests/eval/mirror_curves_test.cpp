#include "ballsight/eval/mirror_curves.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <tuple>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

// Every simulated mirror's radius rises with the distance over the distances it images; the
// unified mirror's agrees with its rig's projection, and the cone images only a narrow band.
TEST(MirrorCurves, SimulatedMirrorsRiseWithTheDistance) {
  const std::vector<MirrorCurve> curves = simulated_mirror_curves();
  ASSERT_EQ(curves.size(), 4u);
  for (const MirrorCurve& c : curves) {
    SCOPED_TRACE(c.name);
    EXPECT_TRUE(c.simulated);
    ASSERT_GE(c.distance_m.size(), 10u);
    for (std::size_t i = 1; i < c.radius_px.size(); ++i) {
      EXPECT_GT(c.distance_m[i], c.distance_m[i - 1]);
      EXPECT_GT(c.radius_px[i], c.radius_px[i - 1]);
    }
  }
  const OmniRig unified(with_mirror(OmniRigParams{}, MirrorKind::kUnified));
  const Vec2 pixel = *unified.pixel_from_point({1.5, 0.0, 0.0});
  EXPECT_NEAR(*curves[0].radius_at(1.5), (pixel - unified.principal_point()).norm(), 1e-6);
  EXPECT_EQ(curves[2].name, "sim cone");
  EXPECT_GT(curves[2].distance_m.front(), 1.5);
  EXPECT_LT(curves[2].distance_m.back(), 3.5);
}

// A real set's curve is the mean radius of each distance; between its distances the table reads
// it linearly and marks it, beyond them it leaves the cell blank.
TEST(MirrorCurves, ARealSetIsTheMeanRadiusOfEachDistance) {
  RealOmniSet set;
  set.name = "team";
  for (const auto& [theta, radius, distance] : {std::tuple{0.0, 100.0, 100.0},
                                                {90.0, 104.0, 100.0},
                                                {0.0, 150.0, 200.0},
                                                {180.0, 152.0, 200.0},
                                                {270.0, 154.0, 200.0}})
    set.samples.push_back({theta, radius, distance, std::nullopt});
  const std::vector<MirrorCurve> curves = real_mirror_curves({set});
  ASSERT_EQ(curves.size(), 1u);
  const MirrorCurve& c = curves[0];
  EXPECT_FALSE(c.simulated);
  EXPECT_EQ(c.distance_m, (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(c.radius_px, (std::vector<double>{102.0, 152.0}));
  EXPECT_DOUBLE_EQ(*c.radius_at(1.5), 127.0);
  EXPECT_FALSE(c.radius_at(2.5));
  EXPECT_FALSE(c.radius_sampled_at(1.5));
  EXPECT_DOUBLE_EQ(*c.radius_sampled_at(2.0), 152.0);
  const std::string table = mirror_curves_table(curves, {1.0, 1.5, 2.5});
  EXPECT_NE(table.find("team"), std::string::npos) << table;
  EXPECT_NE(table.find("102.0"), std::string::npos) << table;
  EXPECT_NE(table.find("~127.0"), std::string::npos) << table;
  const nlohmann::json json = mirror_curves_json(curves);
  EXPECT_EQ(json.at("curves").at(0).at("radius_px").at(1), 152.0);
}

// Edge cases: a curve of one point reads only there; an empty one nowhere; a bad range throws.
TEST(MirrorCurves, OnePointAndEmptyCurves) {
  const MirrorCurve one{"one", false, {2.0}, {150.0}};
  EXPECT_DOUBLE_EQ(*one.radius_at(2.0), 150.0);
  EXPECT_FALSE(one.radius_at(2.1));
  EXPECT_FALSE(MirrorCurve{}.radius_at(1.0));
  EXPECT_DOUBLE_EQ(*simulated_mirror_curves()[0].radius_at(7.0),
                   simulated_mirror_curves()[0].radius_px.back());
  EXPECT_THROW(simulated_mirror_curves(1.0, 2.0, 0.0), InputError);
  EXPECT_THROW(simulated_mirror_curves(2.0, 1.0, 0.1), InputError);
  EXPECT_FALSE(plot_mirror_curves({}).empty());
  EXPECT_FALSE(plot_mirror_curves({one}).empty());  // no 1 m radius: the shape panel stays empty
}

// Both panels show the curves: against the figure without them, each half differs by the lines
// (four simulated mirrors, 2 px wide, hundreds of pixels long).
TEST(MirrorCurves, ThePlotDrawsTheCurvesInBothPanels) {
  const cv::Mat plot = plot_mirror_curves(simulated_mirror_curves());
  const cv::Mat empty = plot_mirror_curves({});
  ASSERT_EQ(plot.type(), CV_8UC3);
  ASSERT_EQ(plot.cols, empty.cols);
  const int rows = std::min(plot.rows, empty.rows) - 200;  // above the legends
  cv::Mat differs;
  cv::cvtColor(
      cv::abs(plot(cv::Rect(0, 0, plot.cols, rows)) - empty(cv::Rect(0, 0, plot.cols, rows))),
      differs, cv::COLOR_BGR2GRAY);
  const int half = plot.cols / 2;
  for (const cv::Rect side : {cv::Rect(0, 0, half, rows), cv::Rect(half, 0, half, rows)})
    EXPECT_GT(cv::countNonZero(differs(side) > 40), 1500);
}

}  // namespace
}  // namespace ballsight
