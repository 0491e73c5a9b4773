#pragma once
// From a world model to the update the service publishes: the route is planned from the robot as
// the cameras saw it (or as a client set it, if that is newer), over the balls the cameras saw
// (or a client's list, if newer) less those the robot reported collected, warm-started from the
// previous route so that the robot's target does not flap. With more balls left than the robot's
// basket has room for (site robot.capacity, less the balls it reported holding) the route goes
// to the unload point when the basket is full. Balls the robot marked unreachable stay out of
// the route, and the update lists the marks.

#include <cstdint>

#include "ballsight/plan/planning_problem.hpp"
#include "ballsight/service/navigation_hub.hpp"
#include "ballsight/world/site.hpp"
#include "ballsight/world/world_model.hpp"

namespace ballsight {

/// The update for `world` (its capture time the update's) and what clients reported; `previous`
/// is the last published route (nullptr for the first). With no robot pose known the route is
/// empty. A function of its arguments only.
NavigationUpdate plan_update(const Site& site, const WorldModel& world,
                             const ClientReports& reports, const Route* previous,
                             const PlannerOptions& options);

/// What the service publishes: plan_update's update, or, when the world cannot be planned (an
/// InputError: a pose the cameras put inside the net), the world with no route, and `error` says
/// why ("" when it was planned).
NavigationUpdate publishable_update(const Site& site, const WorldModel& world,
                                    const ClientReports& reports, const Route* previous,
                                    const PlannerOptions& options, std::string& error);

}  // namespace ballsight
