#include "ballsight/eval/court_eval_calibration.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"
#include "ballsight/detect/court_detector.hpp"
#include "ballsight/detect/seed_detector.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight {
namespace {

// The simulated site names the colour the simulator paints its reference balls, and the report's
// HSV box follows it: 0-22 for the orange balls (the box of before), 124-148 for violet.
TEST(CourtEvalCalibration, TheSiteAndTheReportsBoxFollowTheReferenceColour) {
  for (const sim::CourtSurface surface : {sim::CourtSurface::green, sim::CourtSurface::red}) {
    sim::TennisCourtSpec court;
    sim::set_court_surface(court, surface);
    const Site site = simulated_site(sim::make_court_rig(court, {}, 1));
    EXPECT_EQ(site.colours.reference_ball.bgr(), court.reference_ball_bgr);
  }
  const HsvRange orange = report_reference_box(SiteColours().reference_ball);
  EXPECT_EQ(orange.min, (std::array<int, 3>{0, 70, 40}));
  EXPECT_EQ(orange.max, (std::array<int, 3>{22, 255, 255}));
  const HsvRange box = report_reference_box(Rgb::from_bgr(sim::kVioletBgr));
  EXPECT_EQ(box.min[0], 124);
  EXPECT_EQ(box.max[0], 148);
}

// The simulated site names the robot's marker colours, and the report's marker boxes follow them:
// the boxes of before for the pink and blue markers, moved to violet's hue (136) for a violet
// back marker (a blue court's).
TEST(CourtEvalCalibration, TheReportsMarkerBoxesFollowTheSitesMarkerColours) {
  sim::TennisCourtSpec court;
  sim::set_court_surface(court, sim::CourtSurface::blue);
  const Site site = simulated_site(sim::make_court_rig(court, {}, 1));
  EXPECT_EQ(site.colours.robot_back.bgr(), sim::kVioletBgr);
  EXPECT_EQ(site.colours.robot_front.bgr(), sim::kPinkMarkerBgr);

  const SeedDetectorOptions report;
  const SeedDetectorOptions plain = seed_options_for_site(Site{}).detector;
  EXPECT_EQ(plain.front_marker.min, report.front_marker.min);
  EXPECT_EQ(plain.front_marker.max, report.front_marker.max);
  EXPECT_EQ(plain.back_marker.min, report.back_marker.min);
  EXPECT_EQ(plain.back_marker.max, report.back_marker.max);
  const SeedDetectorOptions blue_court = seed_options_for_site(site).detector;
  EXPECT_EQ(blue_court.front_marker.min, report.front_marker.min);
  EXPECT_EQ(blue_court.back_marker.min, (std::array<int, 3>{124, 120, 30}));
  EXPECT_EQ(blue_court.back_marker.max, (std::array<int, 3>{149, 255, 255}));
  // ballsight's detector looks for the site's violet, not for blue.
  for (const CourtObjectSpec& object : ballsight_options_for_site(site).detector.objects) {
    if (object.object != ObjectClass::robot_back_marker) continue;
    EXPECT_TRUE(object.is_own_colour(sim::kVioletBgr));
    EXPECT_FALSE(object.is_own_colour(sim::kBlueMarkerBgr));
  }
  // A grey marker, or a red one whose box would cross hue 0, is refused by name.
  for (const Rgb colour : {Rgb{128, 128, 128}, Rgb{230, 30, 40}}) {
    Site odd;
    odd.colours.robot_back = colour;
    try {
      seed_options_for_site(odd);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("colours.robot_back"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace ballsight
