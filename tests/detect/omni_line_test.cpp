#include "ballsight/detect/omni_line.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/statistics.hpp"
#include "shared_data.hpp"
#include "skip.hpp"

namespace ballsight {
namespace {

const Vec2 kLineImageCenter{200.0, 200.0};
constexpr double kNormalDeg = 80.0;
constexpr double kLineCm = 100.0;

// A saturating mirror: the image radius of ground distance D (cm).
double mirror_radius(double distance_cm) {
  return 190.0 * distance_cm / (distance_cm + 60.0);
}

double line_rad(double deg) {
  return deg * std::numbers::pi / 180.0;
}

// A white line 3 px wide at kLineCm, its normal at kNormalDeg, on a dark floor with noise; a
// bright speck inside its course and a dark strut across it.
cv::Mat1b line_image() {
  cv::Mat1b image(400, 400, uchar{40});
  constexpr int shift = 4;
  std::vector<cv::Point> curve;
  for (double a = -80.0; a <= 80.0; a += 0.25) {
    const Vec2 p = pixel_from_image_polar(
        {kNormalDeg + a, mirror_radius(kLineCm / std::cos(line_rad(a)))}, kLineImageCenter);
    curve.emplace_back(static_cast<int>(std::lround(p.x() * (1 << shift))),
                       static_cast<int>(std::lround(p.y() * (1 << shift))));
  }
  cv::polylines(image, curve, false, 220, 3, cv::LINE_AA, shift);
  const Vec2 speck = pixel_from_image_polar({kNormalDeg + 3.0, 60.0}, kLineImageCenter);
  cv::circle(image, {static_cast<int>(speck.x()), static_cast<int>(speck.y())}, 1, 230, -1);
  const Vec2 strut = pixel_from_image_polar({kNormalDeg + 40.0, 195.0}, kLineImageCenter);
  cv::line(image, {200, 200}, {static_cast<int>(strut.x()), static_cast<int>(strut.y())}, 10, 7);
  cv::Mat1b noise(image.size());
  cv::randn(noise, 0, 4);
  cv::add(image, noise, image);
  return image;
}

LineSearchOptions toward(double deg) {
  LineSearchOptions options;
  options.toward_deg = deg;
  options.min_radius_px = 40.0;
  return options;
}

TEST(OmniLine, FindsTheNormalAndEveryPointOfADrawnLine) {
  const LineSearch search = find_omni_line(line_image(), kLineImageCenter, toward(95.0));
  EXPECT_NEAR(search.normal_deg, kNormalDeg, 0.3);
  EXPECT_NEAR(search.nearest_radius_px, mirror_radius(kLineCm), 0.3);
  std::vector<double> errors;
  for (const LinePoint& p : search.points) {
    EXPECT_NEAR(p.off_normal_deg, p.theta_deg - search.normal_deg, 1e-9);
    errors.push_back(std::abs(
        p.radius_px - mirror_radius(kLineCm / std::cos(line_rad(p.theta_deg - kNormalDeg)))));
  }
  EXPECT_LT(median(errors), 0.2);
  EXPECT_LT(*std::max_element(errors.begin(), errors.end()), 1.0);
  // Both ways to 70 deg off the normal, across the strut (its few directions are left out).
  EXPECT_LT(search.points.front().off_normal_deg, -65.0);
  EXPECT_GT(search.points.back().off_normal_deg, 65.0);
  EXPECT_LT(search.points.size(), 141u);
  EXPECT_GT(search.points.size(), 125u);
}

TEST(OmniLine, DirectionsAreImageAnglesWhateverTurnTheyAreGivenIn) {
  const LineSearch search = find_omni_line(line_image(), kLineImageCenter, toward(95.0 - 720.0));
  EXPECT_NEAR(search.normal_deg, kNormalDeg, 0.3);
  for (const LinePoint& p : search.points) {
    EXPECT_GE(p.theta_deg, 0.0);
    EXPECT_LT(p.theta_deg, 360.0);
  }
}

// The robot's bright rim, a full circle nearer than the line, is no line: the line behind it is
// found.
TEST(OmniLine, ANearerRingIsPassedOver) {
  cv::Mat1b image = line_image();
  cv::circle(image, {200, 200}, 70, 230, 3, cv::LINE_AA);
  const LineSearch search = find_omni_line(image, kLineImageCenter, toward(95.0));
  EXPECT_NEAR(search.normal_deg, kNormalDeg, 0.3);
  EXPECT_NEAR(search.nearest_radius_px, mirror_radius(kLineCm), 0.3);
}

TEST(OmniLine, NoLineNearTheDirectionGivenIsAnError) {
  try {
    find_omni_line(line_image(), kLineImageCenter, toward(260.0));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no bright line"), std::string::npos) << e.what();
  }
}

// MinhoTeam's frames of a straight field line at 0.5 to 2 m (its centre assumed at the image's
// (240, 240), as the team's image.cfg says). Measured: the line's radius at its normal is within
// 0.6-5.6 px of the team's hand-read profile 4; every point off the normal (at d / cos) lies
// within 1.8 px (median) of the radius the other frames' normals give at that distance.
TEST(OmniLine, MinhoTeamFramesAgreeWithEachOtherAndTheTeamsProfile) {
  const auto dir = test::shared_data_dir() / "real/omni/minhoteam";
  if (!std::filesystem::exists(dir / "mirror_profiles.csv")) {
    BALLSIGHT_SKIP() << "no " << dir << " (../shared/data absent)";
  }
  std::map<double, double> profile;  // cm -> px, profile 4
  std::ifstream csv(dir / "mirror_profiles.csv");
  for (std::string row; std::getline(csv, row);) {
    std::vector<std::string> f;
    std::istringstream fields(row);
    for (std::string s; std::getline(fields, s, ',');) f.push_back(s);
    if (f.size() == 8 && f[0] == "4") profile[100.0 * std::stod(f[6])] = std::stod(f[7]);
  }
  ASSERT_GE(profile.size(), 10u);
  const auto interpolate = [](const std::map<double, double>& curve, double d) {
    const auto hi = curve.lower_bound(d);
    if (hi == curve.begin() || hi == curve.end()) return std::numeric_limits<double>::quiet_NaN();
    const auto lo = std::prev(hi);
    return lo->second + (hi->second - lo->second) * (d - lo->first) / (hi->first - lo->first);
  };
  std::map<double, LineSearch> frames;
  for (const char* name : {"0.50", "0.75", "1.00", "1.25", "1.50", "1.75", "2.00"}) {
    const cv::Mat1b grey =
        cv::imread((dir / "images" / ("line_at_" + std::string(name) + "m.png")).string(),
                   cv::IMREAD_GRAYSCALE);
    ASSERT_FALSE(grey.empty()) << name;
    LineSearchOptions options = toward(90.0);
    options.min_radius_px = 70.0;  // the robot
    frames[100.0 * std::stod(name)] = find_omni_line(grey, {240.0, 240.0}, options);
  }
  std::map<double, double> normals;
  for (const auto& [d, search] : frames) {
    EXPECT_NEAR(search.nearest_radius_px, profile.at(d), 6.0) << d << " cm";
    // The robot faced each line roughly: its normals lie between 84 and 91 deg (the radii either
    // side of the nearest point say so; the robot was not placed identically each time).
    EXPECT_NEAR(search.normal_deg, 90.0, 7.0) << d << " cm";
    normals[d] = search.nearest_radius_px;
  }
  std::vector<double> differences;
  for (const auto& [d, search] : frames) {
    std::map<double, double> others = normals;
    others.erase(d);
    for (const LinePoint& p : search.points) {
      const double r = interpolate(others, d / std::cos(line_rad(p.off_normal_deg)));
      if (std::abs(p.off_normal_deg) > 10.0 && std::isfinite(r))
        differences.push_back(std::abs(p.radius_px - r));
    }
  }
  ASSERT_GT(differences.size(), 300u);
  std::cout << "MinhoTeam lines: " << differences.size() << " points off the normal, median |r - "
            << "other frames' r| " << median(differences) << " px\n";
  EXPECT_LT(median(differences), 2.5);
}

}  // namespace
}  // namespace ballsight
