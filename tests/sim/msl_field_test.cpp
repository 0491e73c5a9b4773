#include "ballsight/sim/msl_field.hpp"

#include <gtest/gtest.h>

#include <random>

#include "ballsight/core/error.hpp"

namespace ballsight::sim {
namespace {

TEST(MslField, PaintsTheMarkingsOfThePapersTestField) {
  const MslField field;
  const MslFieldSpec& s = field.spec();
  EXPECT_EQ(s.center_spot(), Vec2(4.0, 6.0));  // the paper's ball position (400, 600) cm
  const Vec2 on_lines[] = {
      {4.0, 6.0},                            // centre spot
      {0.5, 6.05},                           // halfway line, 5 cm off its centre line
      {0.05, 3.0},                           // touch line
      {7.95, 9.0},                           // other touch line
      {2.0, 0.0},                            // goal line
      {5.0, 12.05},                          // other goal line
      {4.0 + 1.3, 6.0},                      // centre circle
      {4.0, 6.0 - 1.34},                     // centre circle, inner half of the line
      {4.0 - 1.25, 0.3},                     // goal area side line (2.5 m wide)
      {3.0, 0.5},                            // goal area front line
      {4.0 + 2.25, 11.0},                    // penalty area side line (4.5 m wide)
      {5.0, 12.0 - 1.5},                     // penalty area front line
      {4.0, 2.0},                            // penalty spot
      {4.0, 10.0},                           // other penalty spot
      {0.5 / 1.41421356, 0.5 / 1.41421356},  // corner arc
  };
  for (const Vec2& p : on_lines) {
    EXPECT_TRUE(field.on_line(p)) << p.transpose();
    EXPECT_EQ(field.colour_at(p), s.line_bgr) << p.transpose();
  }
  const Vec2 off_lines[] = {{2.0, 3.0},   {4.0, 6.25}, {4.0, 6.0 - 1.4}, {0.2, 6.0 - 0.2},
                            {-0.3, -0.3}, {4.0, 2.2},  {8.5, 6.0}};
  for (const Vec2& p : off_lines) EXPECT_FALSE(field.on_line(p)) << p.transpose();
}

TEST(MslField, CarpetIsTexturedGreenAndEndsAMetreBeyondTheLines) {
  const MslField field;
  const MslFieldSpec& s = field.spec();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(0.2, 3.0), y(2.5, 5.0);  // a patch without lines
  int differing = 0;
  for (int i = 0; i < 500; ++i) {
    const cv::Vec3b c = field.colour_at({x(rng), y(rng)});
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_LE(std::abs(c[ch] - s.carpet_bgr[ch]), s.carpet_texture_levels);
    }
    differing += c != s.carpet_bgr ? 1 : 0;
  }
  EXPECT_GT(differing, 300);                                            // textured, not flat
  EXPECT_EQ(field.colour_at({3.0, 4.0}), field.colour_at({3.0, 4.0}));  // deterministic
  EXPECT_TRUE(field.on_carpet({-1.0, 6.0}));
  EXPECT_FALSE(field.on_carpet({-1.1, 6.0}));
  EXPECT_TRUE(field.on_carpet({8.0 + 1.0, 13.0}));
  EXPECT_EQ(field.colour_at({-1.2, 6.0}), s.floor_bgr);
  EXPECT_EQ(field.colour_at({4.0, 13.2}), s.floor_bgr);
}

TEST(MslField, ValidateNamesTheBadField) {
  const auto message = [](const MslFieldSpec& spec) {
    try {
      spec.validate();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  MslFieldSpec spec;
  EXPECT_EQ(message(spec), "no error");
  spec.penalty_area_width_m = 9.0;
  EXPECT_NE(message(spec).find("field.penalty_area_width_m"), std::string::npos);
  spec = {};
  spec.line_width_m = -0.1;
  EXPECT_NE(message(spec).find("field.line_width_m"), std::string::npos);
  spec = {};
  spec.width_m = std::nan("");
  EXPECT_NE(message(spec).find("field.width_m"), std::string::npos);
  spec = {};
  spec.goal_area_depth_m = 2.0;  // deeper than the penalty area
  EXPECT_NE(message(spec).find("field.goal_area_depth_m"), std::string::npos);
  EXPECT_THROW(MslField{spec}, InputError);
}

}  // namespace
}  // namespace ballsight::sim
