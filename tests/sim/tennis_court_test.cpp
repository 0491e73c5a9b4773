#include "ballsight/sim/tennis_court.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"

namespace ballsight::sim {
namespace {

cv::Vec3f as_float(const cv::Vec3b& c) {
  return {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
}

TEST(TennisCourt, LinesFollowTheItfLayout) {
  const TennisCourtSpec court;
  const auto lines = court.line_rects();
  const auto at = [&](double x, double y) {
    return floor_albedo(court, lines, {x, y}, Vec2::Zero());
  };
  const cv::Vec3f line = as_float(court.line_bgr), surface = as_float(court.court_bgr);
  // Outer edges of the lines at the ITF dimensions, from the centre of the court.
  EXPECT_EQ(at(11.86, 3.0), line) << "baseline";
  EXPECT_EQ(at(11.80, 3.0), surface);
  EXPECT_EQ(at(5.0, 5.46), line) << "doubles sideline";
  EXPECT_EQ(at(5.0, -4.09), line) << "singles sideline";
  EXPECT_EQ(at(5.0, 4.80), surface) << "doubles alley";
  EXPECT_EQ(at(6.38, 2.0), line) << "service line";
  EXPECT_EQ(at(6.33, 2.0), surface);
  EXPECT_EQ(at(-6.38, 4.5), surface) << "service lines stop at the singles sidelines";
  EXPECT_EQ(at(3.0, 0.0), line) << "centre service line";
  EXPECT_EQ(at(8.0, 0.0), surface) << "no centre line behind the service line";
  EXPECT_EQ(at(-11.80, 0.0), line) << "centre mark";
  EXPECT_EQ(at(-11.70, 0.0), surface) << "centre mark is 10 cm long";
  EXPECT_EQ(at(0.0, 0.0), line) << "the centre service line runs on under the net";
  EXPECT_EQ(at(15.0, 0.0), as_float(court.surround_bgr));
  EXPECT_EQ(at(0.0, 8.9), as_float(court.surround_bgr));
  EXPECT_EQ(at(18.5, 0.0), as_float(court.ground_bgr));
}

TEST(TennisCourt, FootprintAveragesTheLineByItsShare) {
  const TennisCourtSpec court;
  const auto lines = court.line_rects();
  // A 0.5 m footprint across the 5 cm centre service line: 10% line, 90% court.
  const cv::Vec3f mixed = floor_albedo(court, lines, {2.0, 0.0}, {0.01, 0.25});
  const cv::Vec3f expected =
      as_float(court.court_bgr) + 0.1f * (as_float(court.line_bgr) - as_float(court.court_bgr));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mixed[c], expected[c], 1e-3) << c;
  // Half a footprint over the court's outer edge: half run-off, half court-with-line.
  const cv::Vec3f edge = floor_albedo(court, lines, {11.885, 3.0}, {0.02, 0.01});
  const cv::Vec3f half = 0.5f * (as_float(court.surround_bgr) + as_float(court.line_bgr));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(edge[c], half[c], 1e-3) << c;
}

TEST(TennisCourt, InvalidSpecsAreNamed) {
  TennisCourtSpec court;
  court.singles_width_m = 12.0;
  EXPECT_THROW(court.validate(), InputError);
  court = {};
  court.length_m = -1.0;
  try {
    court.validate();
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("court.length_m"), std::string::npos) << e.what();
  }
  court = {};
  court.surround_length_m = 20.0;
  EXPECT_THROW(court.validate(), InputError);
}

}  // namespace
}  // namespace ballsight::sim
