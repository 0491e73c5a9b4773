#include "ballsight/eval/court_eval_calibration.hpp"

#include <gtest/gtest.h>

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
  const HsvRange box = report_reference_box(Rgb::from_bgr(sim::kVioletReferenceBgr));
  EXPECT_EQ(box.min[0], 124);
  EXPECT_EQ(box.max[0], 148);
}

}  // namespace
}  // namespace ballsight
