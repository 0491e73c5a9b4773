#include "ballsight/detect/court_detector.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "court_scene_support.hpp"
#include "sim/court_test_support.hpp"

namespace ballsight {
namespace {

using test::Disc;

std::vector<PixelDetection> balls_only(std::vector<PixelDetection> detections) {
  std::erase_if(detections, [](const PixelDetection& d) { return d.object != ObjectClass::ball; });
  return detections;
}

// One ball anywhere in the image, at any sub-pixel phase: its centre to a few hundredths of a
// pixel.
TEST(CourtDetector, SingleBallCentreIsSubPixel) {
  CourtDetector detector(test::overhead_camera());
  const double r = test::overhead_ball_radius_px();
  double worst = 0.0;
  for (int i = 0; i < 12; ++i) {
    const Vec2 center(100.0 + 37.3 * i + 0.13 * i, 80.0 + 29.1 * i + 0.07 * i);
    SCOPED_TRACE("ball at " + std::to_string(center.x()) + ", " + std::to_string(center.y()));
    const auto found =
        balls_only(detector.detect(test::draw_discs({{center, r, test::kBallYellow}}, 2.0, i)));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].split_count, 1);
    EXPECT_NEAR(found[0].radius_px, r, 0.5);
    worst = std::max(worst, (found[0].center_px - center).norm());
  }
  EXPECT_LT(worst, 0.1);
}

// Two balls touching (2 mm apart) become one blob; it is split, each centre within a tenth of a
// pixel, whatever the direction of the pair.
TEST(CourtDetector, TouchingBallsAreSplit) {
  CourtDetector detector(test::overhead_camera());
  const double r = test::overhead_ball_radius_px();
  const double gap_px = 2.0 * r * (1.0 + 0.002 / 0.067);
  for (int k = 0; k < 6; ++k) {
    const double angle = 0.5 * k;
    SCOPED_TRACE("pair direction " + std::to_string(angle) + " rad");
    const Vec2 a(320.3, 240.6);
    const Vec2 b = a + gap_px * Vec2(std::cos(angle), std::sin(angle));
    const auto found = balls_only(detector.detect(
        test::draw_discs({{a, r, test::kBallYellow}, {b, r, test::kBallYellow}}, 2.0, k)));
    ASSERT_EQ(found.size(), 2u);
    for (const Vec2& truth : {a, b}) {
      const auto nearest =
          std::min_element(found.begin(), found.end(), [&](const auto& p, const auto& q) {
            return (p.center_px - truth).norm() < (q.center_px - truth).norm();
          });
      EXPECT_LT((nearest->center_px - truth).norm(), 0.15);
      EXPECT_EQ(nearest->split_count, 2);
    }
  }
}

// Things of the ball's colour that are not balls: a painted line and a blob ten balls large.
TEST(CourtDetector, RejectsShapesThatAreNotBalls) {
  CourtDetector detector(test::overhead_camera());
  cv::Mat image = test::draw_discs({}, 2.0);
  cv::line(image, {100, 100}, {400, 130}, cv::Scalar(45, 250, 225), 2, cv::LINE_AA);
  cv::circle(image, {500, 350}, 15, cv::Scalar(45, 250, 225), cv::FILLED, cv::LINE_AA);
  EXPECT_TRUE(balls_only(detector.detect(image)).empty());
}

// An orange reference ball is not a tennis ball, though its rim on green looks yellowish.
TEST(CourtDetector, RejectsOrangeBalls) {
  CourtDetector detector(test::overhead_camera());
  const double r = test::overhead_ball_radius_px();
  for (double radius : {0.7 * r, 0.4 * r, 0.25 * r}) {
    SCOPED_TRACE("orange ball of radius " + std::to_string(radius) + " px");
    const cv::Mat image = test::draw_discs({{{200.4, 200.2}, radius, {20, 100, 255}}}, 2.0);
    EXPECT_TRUE(balls_only(detector.detect(image)).empty());
  }
}

// A worn ball (its felt paled 40 % towards grey) in a building's hard shadow (a quarter of the
// light): chroma 31, below the seed band's 35, but as saturated as in the sun.
TEST(CourtDetector, FindsAWornBallInAHardShadow) {
  CourtDetector detector(test::overhead_camera());
  const double r = test::overhead_ball_radius_px();
  const cv::Vec3b worn(96, 219, 204);
  for (int i = 0; i < 4; ++i) {
    const Vec2 center(150.3 + 97.1 * i, 120.6 + 61.7 * i);
    SCOPED_TRACE("ball at " + std::to_string(center.x()) + ", " + std::to_string(center.y()));
    cv::Mat shaded = test::draw_discs({{center, r, worn}}) * 0.25;
    cv::Mat noise(shaded.size(), CV_16SC3);
    cv::theRNG().state = static_cast<std::uint64_t>(i + 1);
    cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(2));  // sensor noise after the shade
    cv::add(shaded, noise, shaded, cv::noArray(), CV_8UC3);
    const auto found = balls_only(detector.detect(shaded));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_LT((found[0].center_px - center).norm(), 0.3);
  }
}

// Balls lit from one side on a light wooden floor, which is of the ball's hues' side (hue about
// 32 deg): each ball's shaded half (a quarter of the light) is darker than the floor around it.
// A lone ball is one ball at its centre (measured within 0.12 r, allowed 0.2 r; 0.3 r towards
// the light, the shift of its sunlit part, when the floor's evidence was only subtracted); two
// touching balls are two.
TEST(CourtDetector, FindsShadedBallsOnAWoodenFloor) {
  CourtDetector detector(test::overhead_camera());
  const cv::Vec3b wood(100, 150, 195);
  const double r = test::overhead_ball_radius_px();
  const cv::Vec3b shade(11, 62, 56);  // test::kBallYellow at a quarter of the light
  // A ball: its shaded disc, and its sunlit part, a disc shifted towards the light.
  const auto ball = [&](const Vec2& center, const Vec2& light) {
    return std::vector<test::Disc>{{center, r, shade},
                                   {center + 0.3 * r * light, 0.7 * r, test::kBallYellow}};
  };
  for (int k = 0; k < 4; ++k) {
    const double angle = 0.8 * k;
    const Vec2 light(std::cos(angle), std::sin(angle)), across(-light.y(), light.x());
    SCOPED_TRACE("light from " + std::to_string(angle) + " rad");
    const Vec2 lone(200.3 + 20.0 * k, 150.7), a(400.2, 300.6 + 10.0 * k);
    const Vec2 b = a + 2.02 * r * across;
    std::vector<test::Disc> discs = ball(lone, light);
    for (const Vec2& c : {a, b}) {
      const std::vector<test::Disc> more = ball(c, light);
      discs.insert(discs.end(), more.begin(), more.end());
    }
    const auto found = balls_only(detector.detect(
        test::draw_discs(discs, 2.0, static_cast<std::uint64_t>(k + 1), {640, 480}, wood)));
    ASSERT_EQ(found.size(), 3u);
    for (const Vec2& truth : {lone, a, b}) {
      const auto nearest =
          std::min_element(found.begin(), found.end(), [&](const auto& p, const auto& q) {
            return (p.center_px - truth).norm() < (q.center_px - truth).norm();
          });
      EXPECT_LT((nearest->center_px - truth).norm(), 0.2 * r);
      EXPECT_EQ(nearest->split_count, truth == lone ? 1 : 2);
    }
  }
}

TEST(CourtDetector, FindsBothMarkersAndNamesThem) {
  CourtDetector detector(test::overhead_camera());
  // Markers (4.5 cm) 34.5 cm high: a little larger than a ball on the floor.
  const double r = 800.0 * 0.045 / (6.0 - 0.345);
  const auto found = detector.detect(test::draw_discs(
      {{{300.2, 200.7}, r, {180, 80, 255}}, {{300.2, 260.3}, r, {220, 80, 30}}}, 2.0));
  ASSERT_EQ(found.size(), 2u);
  for (const PixelDetection& d : found) {
    const Vec2 truth =
        d.object == ObjectClass::robot_front_marker ? Vec2(300.2, 200.7) : Vec2(300.2, 260.3);
    EXPECT_NE(d.object, ObjectClass::ball);
    EXPECT_LT((d.center_px - truth).norm(), 0.1);
  }
}

// Why a blue court's robot wears a violet back marker (sim/tennis_court.hpp): on a blue floor
// (hue 209) a blue marker (224) grows into the floor's blob and is not found (this test fails
// with it), a violet one is, beside the pink one. That the site's colours reach the detector is
// CourtEvalCalibration.TheReportsMarkerBoxesFollowTheSitesMarkerColours.
TEST(CourtDetector, FindsAVioletBackMarkerOnABlueCourt) {
  const cv::Vec3b blue_court{150, 100, 45}, violet{230, 40, 140};
  CourtObjectColours colours;
  colours.back_marker = violet;
  CourtDetectorOptions options;
  options.objects = court_objects(colours);
  CourtDetector detector(test::overhead_camera(), options);
  const double r = 800.0 * 0.045 / (6.0 - 0.345);
  const cv::Mat image =
      test::draw_discs({{{300.2, 200.7}, r, colours.front_marker}, {{300.2, 260.3}, r, violet}},
                       2.0, 1, {640, 480}, blue_court);
  const auto found = detector.detect(image);
  ASSERT_EQ(found.size(), 2u);
  for (const PixelDetection& d : found) {
    const bool front = d.object == ObjectClass::robot_front_marker;
    EXPECT_TRUE(front || d.object == ObjectClass::robot_back_marker);
    EXPECT_LT((d.center_px - (front ? Vec2(300.2, 200.7) : Vec2(300.2, 260.3))).norm(), 0.1);
  }
}

TEST(CourtDetector, ImageOfAnotherSizeThanTheCalibrationIsAnError) {
  CourtDetector detector(test::overhead_camera());
  try {
    detector.detect(cv::Mat3b(240, 320, cv::Vec3b(88, 128, 70)));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("320x240"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("640x480"), std::string::npos) << e.what();
  }
}

// What the detector finds on three simulated scenes of the court (seeds 11-13), four cameras.
struct SimulatedCourtResult {
  int visible = 0;     // lone fully visible balls of at least 0.8 px radius
  int found = 0;       // of those, found within max(1 px, radius) of their silhouette centroid
  int detections = 0;  // ball detections
  int unmatched = 0;   // of those, not near a true ball
  double median_error_px = 0.0;
};

SimulatedCourtResult detect_on_simulated_court(const sim::CourtScenarioOptions& options) {
  // The detector alone, on the scenes it was first measured on: the court without its net, where
  // every ball can be seen (the net hides a sixth of them from some camera, and the stray count,
  // a dozen far reference balls at ~1 px, would be judged against fewer detections; the net is
  // the world model's business: CourtNet tests, eval court).
  const auto& court = sim::test_support::shared_court_without_net();
  SimulatedCourtResult result;
  std::vector<double> errors;
  for (std::uint64_t seed = 11; seed <= 13; ++seed) {
    const sim::CourtScene scene = sim::make_court_scene(court.rig.court, options, seed);
    const auto rendered = sim::test_support::render_in_all_cameras(court, scene, seed);
    for (std::size_t c = 0; c < court.rig.cameras.size(); ++c) {
      SCOPED_TRACE("scene seed " + std::to_string(seed) + " camera " + std::to_string(c));
      const sim::CourtCamera& camera = court.rig.cameras[c];
      CourtDetector detector(FieldCamera{camera.camera, camera.camera_from_field});
      const auto balls = balls_only(detector.detect(rendered.renders[c].bgr));
      result.detections += static_cast<int>(balls.size());
      std::vector<Vec2> truth_px;
      for (const sim::SphereTruth& t : rendered.truth)
        if (t.sphere.kind == sim::ObjectKind::tennis_ball && t.views[c].silhouette_centroid_px)
          truth_px.push_back(*t.views[c].silhouette_centroid_px);
      for (const PixelDetection& d : balls) {
        const bool near = std::any_of(truth_px.begin(), truth_px.end(), [&](const Vec2& t) {
          return (t - d.center_px).norm() < std::max(1.5, 1.5 * d.radius_px);
        });
        result.unmatched += !near;
      }
      for (const sim::SphereTruth& t : rendered.truth) {
        const sim::SphereViewTruth& v = t.views[c];
        if (t.sphere.kind != sim::ObjectKind::tennis_ball || v.visible_fraction < 0.999) continue;
        const double r = camera.camera.params().fx * t.sphere.radius_m /
                         (camera.center_in_field() - t.sphere.center_in_field).norm();
        const bool alone = std::all_of(truth_px.begin(), truth_px.end(), [&](const Vec2& o) {
          return o == *v.silhouette_centroid_px ||
                 (o - *v.silhouette_centroid_px).norm() > 4 * r + 2;
        });
        if (r < 0.8 || !alone) continue;
        ++result.visible;
        double best = 1e9;
        for (const PixelDetection& d : balls)
          best = std::min(best, (d.center_px - *v.silhouette_centroid_px).norm());
        if (best < std::max(1.0, r)) {
          ++result.found;
          errors.push_back(best);
        }
      }
    }
  }
  std::sort(errors.begin(), errors.end());
  if (!errors.empty()) result.median_error_px = errors[errors.size() / 2];
  std::cout << result.found << " of " << result.visible
            << " lone visible balls found, median centre error " << result.median_error_px
            << " px; " << result.unmatched << " of " << result.detections
            << " detections not near a true ball\n";
  return result;
}

// The simulated court, four cameras, three noisy shadowed scenes: every fully visible ball of at
// least 0.8 px radius that stands alone is found, to about a tenth of a pixel of its analytic
// silhouette centroid, and fewer than 3% of the detections (parts of clusters split too often)
// are not near a true ball.
TEST(CourtDetector, FindsTheSimulatedBalls) {
  const SimulatedCourtResult result = detect_on_simulated_court({});
  ASSERT_GT(result.visible, 0);
  EXPECT_EQ(result.found, result.visible);
  EXPECT_LT(result.median_error_px, 0.15);
  EXPECT_LT(result.unmatched, result.detections * 3 / 100);
}

// The same scenes in a hall under warm lamps: the white lines turn the yellow of a ball's rim and
// the green court a yellower green. The cast is read off each frame and the colours corrected
// (detect/colour_cast.hpp); without it, 318 of the 329 balls were found and 853 of 1350
// detections were not near a ball.
TEST(CourtDetector, FindsTheSimulatedBallsUnderAHallsWarmLamps) {
  sim::CourtScenarioOptions options;
  options.light = sim::LightCondition::indoor;
  const SimulatedCourtResult result = detect_on_simulated_court(options);
  ASSERT_GT(result.visible, 0);
  EXPECT_GE(result.found, result.visible * 99 / 100);
  EXPECT_LT(result.median_error_px, 0.15);
  EXPECT_LT(result.unmatched, result.detections * 3 / 100);
}

}  // namespace
}  // namespace ballsight
