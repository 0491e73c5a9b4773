#pragma once
// A tennis court's dimensions and net as a site file gives them (docs/site-file.md, `court:`):
// plain numbers that the site file (world/site.hpp) reads and the planners
// (plan/drivable_court.hpp) and the court drawings use.

#include "ballsight/core/field_rect.hpp"

namespace ballsight {

/// Field frame: origin at the centre of the court on the net line, x along the length, y across,
/// z up (docs/conventions.md).
struct SiteCourt {
  double length_m = 23.77;  // doubles court, outer edges of the lines
  double width_m = 10.97;
  double area_length_m = 36.0;  // the fenced surface around it (run-off included): where balls
  double area_width_m = 18.0;   // may lie and the robot may drive
  /// The net across the court on x = 0, between posts this far outside the doubles sidelines
  /// (ITF: 0.914 m), 1.07 m high at the posts and 0.914 m at the centre: it hides balls from the
  /// cameras across it, and the robot drives round it. `net = false`: a court without one.
  bool net = true;
  double net_posts_outside_m = 0.914;
  double net_height_posts_m = 1.07;
  double net_height_centre_m = 0.914;
  double net_clearance_m = 0.06;       // closest the collector comes to the net's mesh
  double net_post_clearance_m = 0.50;  // room the robot keeps beyond each post
  /// Closest the route comes to the mesh when the robot drives along the net: half its body's
  /// width and room (a ball nearer is reached straight from the lane's edge).
  double net_travel_clearance_m = 0.45;
  /// Along the fence the body has no room to turn: a ball nearer the fence than this is reached
  /// straight, square to the fence, from this far out, and left backwards the same way.
  double fence_lane_m = 0.70;

  /// The fenced area, centred on the court: where a ball or the robot reported may lie.
  FieldRect fenced_area() const {
    const Vec2 half(0.5 * area_length_m, 0.5 * area_width_m);
    return {-half, half};
  }
};

}  // namespace ballsight
