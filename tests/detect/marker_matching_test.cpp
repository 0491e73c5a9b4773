#include "ballsight/detect/marker_matching.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/core/conventions.hpp"

namespace ballsight {
namespace {

constexpr unsigned kMatchingSeed = 4242;

// The omnivision paper's layout: rays every 10 degrees, markers every 50 cm from 60 to 460 cm.
std::vector<Vec2> paper_layout() {
  std::vector<Vec2> layout;
  for (int bearing = 0; bearing < 360; bearing += 10)
    for (int cm = 60; cm <= 460; cm += 50)
      layout.push_back(robot_point_from_bearing(bearing, cm / 100.0));
  return layout;
}

struct Detections {
  std::vector<Vec2> pixels;
  std::vector<int> truth;  // layout index per pixel, -1 for clutter
};

Detections observe(const OmniRig& rig, const std::vector<Vec2>& layout, std::mt19937& rng) {
  Detections d;
  std::normal_distribution<double> noise(0.0, 0.5);
  for (int i = 0; i < static_cast<int>(layout.size()); ++i) {
    const auto pixel = rig.pixel_from_point(
        {layout[static_cast<size_t>(i)].x(), layout[static_cast<size_t>(i)].y(), 0.0});
    if (!pixel) continue;
    d.pixels.push_back(*pixel + Vec2(noise(rng), noise(rng)));
    d.truth.push_back(i);
  }
  return d;
}

OmniRig misaligned_rig() {
  OmniRigParams params;
  params.tilt_deg = 2.0;
  params.tilt_azimuth_deg = 70.0;
  params.center_offset_px = {5.0, -3.0};
  return OmniRig(params);
}

TEST(MarkerMatching, MatchesEveryMarkerOfAMisalignedRig) {
  SCOPED_TRACE("seed " + std::to_string(kMatchingSeed));
  std::mt19937 rng(kMatchingSeed);
  const std::vector<Vec2> layout = paper_layout();
  const Detections d = observe(misaligned_rig(), layout, rng);
  ASSERT_EQ(d.pixels.size(), layout.size());
  const auto matches = match_markers_to_layout(d.pixels, layout);
  ASSERT_EQ(matches.size(), layout.size());
  for (const MarkerMatch& m : matches) {
    const auto it = std::find(d.pixels.begin(), d.pixels.end(), m.pixel);
    ASSERT_NE(it, d.pixels.end());
    EXPECT_EQ(d.truth[static_cast<size_t>(it - d.pixels.begin())], m.layout_index);
  }
}

TEST(MarkerMatching, SurvivesMissingMarkersAndClutter) {
  SCOPED_TRACE("seed " + std::to_string(kMatchingSeed));
  std::mt19937 rng(kMatchingSeed);
  const std::vector<Vec2> layout = paper_layout();
  const OmniRig rig = misaligned_rig();
  Detections d = observe(rig, layout, rng);
  // Drop 10 markers (hidden), add 5 clutter blobs between rays.
  for (int k = 0; k < 10; ++k) {
    const size_t i = (static_cast<size_t>(k) * 37 + 11) % d.pixels.size();
    d.pixels.erase(d.pixels.begin() + static_cast<long>(i));
    d.truth.erase(d.truth.begin() + static_cast<long>(i));
  }
  for (int k = 0; k < 5; ++k) {
    d.pixels.push_back(
        pixel_from_image_polar({95.0 + 10.0 * k, 120.0 + 15.0 * k}, rig.principal_point()));
    d.truth.push_back(-1);
  }
  const auto matches = match_markers_to_layout(d.pixels, layout);
  int correct = 0;
  for (const MarkerMatch& m : matches) {
    const auto it = std::find(d.pixels.begin(), d.pixels.end(), m.pixel);
    ASSERT_NE(it, d.pixels.end());
    const int truth = d.truth[static_cast<size_t>(it - d.pixels.begin())];
    EXPECT_EQ(truth, m.layout_index) << "a wrong match poisons the calibration";
    correct += truth == m.layout_index;
  }
  EXPECT_GE(correct, static_cast<int>(layout.size()) - 10 - 5);
}

}  // namespace
}  // namespace ballsight
