#include "ballsight/detect/omni_rings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "shared_data.hpp"
#include "skip.hpp"

namespace ballsight {
namespace {

struct Summary {
  std::size_t count = 0;
  double median = 0.0, p95 = 0.0, max = 0.0;
};

Summary summarize(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  if (v.empty()) return {};
  return {v.size(), v[v.size() / 2], v[v.size() * 95 / 100], v.back()};
}

const Vec2 kConfiguredCenter{200.0, 200.0};
const Vec2 kRingCenter{201.5, 199.0};  // the rings' true centre, off the configured one
const std::vector<double> kRadii{60.0, 90.0, 115.0, 135.0};
constexpr double kStrutThetaDeg[] = {30.0, 150.0, 270.0};

// Rings 3 px wide, antialiased, around kRingCenter; three dark struts from the centre; noise.
cv::Mat1b ring_image() {
  cv::Mat1b image(400, 400, uchar{20});
  constexpr int shift = 4;  // sub-pixel drawing
  const auto fixed_point = [](double v) { return static_cast<int>(std::lround(v * (1 << shift))); };
  for (const double r : kRadii) {
    cv::circle(image, {fixed_point(kRingCenter.x()), fixed_point(kRingCenter.y())}, fixed_point(r),
               220, 3, cv::LINE_AA, shift);
  }
  for (const double theta : kStrutThetaDeg) {
    const Vec2 end = pixel_from_image_polar({theta, 190.0}, kConfiguredCenter);
    cv::line(image, {200, 200}, {static_cast<int>(end.x()), static_cast<int>(end.y())}, 5, 9);
  }
  cv::Mat1b noise(image.size());
  cv::randn(noise, 0, 4);
  cv::add(image, noise, image);
  return image;
}

// Where ring `radius` crosses the ray from kConfiguredCenter at image angle theta.
double true_radius(double theta_deg, double radius) {
  const Vec2 u = pixel_from_image_polar({theta_deg, 1.0}, kConfiguredCenter) - kConfiguredCenter;
  const Vec2 c = kConfiguredCenter - kRingCenter;
  const double b = u.dot(c);
  return -b + std::sqrt(b * b - c.squaredNorm() + radius * radius);
}

RingSearchOptions four_rings() {
  RingSearchOptions options;
  options.distances_m = {1.0, 2.0, 3.0, 4.0};
  return options;
}

TEST(OmniRings, FindsEveryRingAtItsTrueRadius) {
  const RingSearch search = find_omni_rings(ring_image(), kConfiguredCenter, four_rings());
  ASSERT_EQ(search.rings.size(), kRadii.size());
  std::vector<double> errors;
  for (const RingDirection& d : search.directions) {
    for (std::size_t k = 0; k < kRadii.size(); ++k) {
      if (d.radius_px[k]) {
        errors.push_back(std::abs(*d.radius_px[k] - true_radius(d.theta_deg, kRadii[k])));
      }
    }
  }
  const Summary e = summarize(errors);
  EXPECT_LT(e.median, 0.1);
  EXPECT_LT(e.max, 0.5);
  EXPECT_GT(e.count, 9 * 180 * kRadii.size() / 10);
}

TEST(OmniRings, RejectsTheDirectionsTheStrutsHide) {
  const RingSearch search = find_omni_rings(ring_image(), kConfiguredCenter, four_rings());
  for (const RingDirection& d : search.directions) {
    for (const double strut : kStrutThetaDeg) {
      if (std::abs(d.theta_deg - strut) < 0.5) {
        for (std::size_t k = 0; k < kRadii.size(); ++k) {
          EXPECT_FALSE(d.radius_px[k].has_value()) << d.theta_deg << " deg, ring " << k;
          EXPECT_EQ(d.miss[k], RingMiss::kHidden);
        }
      }
    }
  }
  EXPECT_GT(search.hidden, 0u);
}

TEST(OmniRings, TooManyRingsAskedIsAnError) {
  RingSearchOptions options = four_rings();
  options.distances_m = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0};
  try {
    find_omni_rings(ring_image(), kConfiguredCenter, options);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("shows 4 rings"), std::string::npos) << e.what();
  }
}

// The cnc-msl team's own line detector on its ring image (clearedLP, one row per direction:
// the team's angle and the ring radii, cut at the first ring it missed). In the directions where
// it found one of the five certain rings (1 to 3 m), ballsight finds that ring in at least 90 %
// of them, within 1 px of the team's radius (median over all rings; issue 44's target). Ring by
// ring the median is within 1.1 px: the team's radii of the thin far rings lie about 1 px outside
// the rings' brightness peaks (docs/RESULTS.md, "Calibration from one spin"), where ballsight's
// lie on the simulator's rings within 0.2 px (OmniRingImages). The team's point at angle a,
// radius r is at row 230 + r cos a, column 230 + r sin a.
TEST(OmniRings, AgreesWithTheCncMslLineDetector) {
  const auto dir = test::shared_data_dir() / "real/omni/cnc-msl-nase-2016-03";
  if (!std::filesystem::exists(dir / "clearedLP_nase_2016-03-30.txt")) {
    BALLSIGHT_SKIP() << "no " << dir << " (../shared/data absent)";
  }
  std::ifstream rows(dir / "clearedLP_nase_2016-03-30.txt");
  std::vector<double> thetas;
  std::vector<std::vector<double>> team;
  for (std::string line; std::getline(rows, line);) {
    std::istringstream fields(line);
    double a = 0.0;
    std::vector<double> radii;
    fields >> a;
    for (double r; fields >> r;) radii.push_back(r);
    const double row = std::cos(a), column = std::sin(a);
    thetas.push_back(
        image_polar_from_pixel(kConfiguredCenter + Vec2(column, row), kConfiguredCenter).theta_deg);
    team.push_back(radii);
  }
  ASSERT_GE(thetas.size(), 80u);
  cv::Mat1b grey =
      cv::imread((dir / "CarpetCalibImage_nase_2016-03-30.png").string(), cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(grey.empty());
  RingSearchOptions options;
  options.distances_m = {1.0, 1.5, 2.0, 2.5, 3.0};
  const RingSearch search = find_omni_rings(grey, {230.0, 230.0}, options, thetas);
  std::vector<double> all;
  for (std::size_t k = 0; k < 5; ++k) {
    std::vector<double> differences;
    std::size_t theirs = 0;
    for (std::size_t d = 0; d < thetas.size(); ++d) {
      if (team[d].size() <= k) continue;
      ++theirs;
      const auto& ours = search.directions[d].radius_px[k];
      if (ours) differences.push_back(std::abs(*ours - team[d][k]));
    }
    const Summary e = summarize(differences);
    const double found = static_cast<double>(e.count) / static_cast<double>(theirs);
    std::cout << "cnc-msl ring " << k + 1 << ": the team's " << theirs << " directions, ours in "
              << e.count << " (" << std::lround(100.0 * found) << " %); |ballsight - team| median "
              << e.median << " px, p95 " << e.p95 << " px, max " << e.max << " px\n";
    EXPECT_GE(found, 0.9) << "ring " << k + 1;
    EXPECT_LE(e.median, 1.1) << "ring " << k + 1;
    all.insert(all.end(), differences.begin(), differences.end());
  }
  const Summary e = summarize(all);
  std::cout << "cnc-msl rings: " << e.count << " compared; |ballsight - team| median " << e.median
            << " px, p95 " << e.p95 << " px\n";
  EXPECT_LE(e.median, 1.0);
}

}  // namespace
}  // namespace ballsight
