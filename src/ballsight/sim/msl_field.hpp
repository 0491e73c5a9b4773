#pragma once
// A RoboCup Middle Size League field as the simulators' floor: green carpet with white lines,
// carpet continuing a margin beyond the lines, then a darker floor.
//
// Field frame: origin at the corner where the centre lines of a touch line and a goal line meet,
// x across the width, y along the length, z up, metres. The defaults are the omnivision paper's
// test field, 8 m x 12 m, so that its ball position (400, 600) cm is the centre spot.

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight::sim {

struct MslFieldSpec {
  double width_m = 8.0;                 // x: touch line to touch line (line centres)
  double length_m = 12.0;               // y: goal line to goal line (line centres)
  double line_width_m = 0.12;           // MSL rules: 12 cm white lines
  double center_circle_radius_m = 1.3;  // to the line centre
  double spot_radius_m = 0.1;           // centre and penalty spots
  double goal_area_width_m = 2.5;
  double goal_area_depth_m = 0.5;
  double penalty_area_width_m = 4.5;
  double penalty_area_depth_m = 1.5;
  double penalty_spot_distance_m = 2.0;  // from the goal line
  double corner_arc_radius_m = 0.5;
  double carpet_margin_m = 1.0;  // carpet beyond the lines, then the darker floor

  cv::Vec3b carpet_bgr{40, 135, 45};
  cv::Vec3b line_bgr{235, 240, 240};
  cv::Vec3b floor_bgr{70, 78, 84};
  int carpet_texture_levels = 6;  // +- grey levels of the carpet's fibre texture

  /// Throws InputError naming the first invalid field.
  void validate() const;
  Vec2 center_spot() const { return {0.5 * width_m, 0.5 * length_m}; }
};

/// The field's markings as primitives, built once; colour lookups are cheap enough to shade every
/// pixel of a frame (no allocation, a few comparisons per marking).
class MslField {
 public:
  explicit MslField(const MslFieldSpec& spec = {});

  const MslFieldSpec& spec() const { return spec_; }
  /// Colour of the floor at a point of the field frame (metres).
  cv::Vec3b colour_at(const Vec2& p_in_field) const;
  /// True where a white line is painted.
  bool on_line(const Vec2& p_in_field) const;
  /// True on the carpet (inside the lines' rectangle grown by the carpet margin).
  bool on_carpet(const Vec2& p_in_field) const;

 private:
  struct Box {  // axis-aligned painted rectangle
    double x0, y0, x1, y1;
  };
  struct Ring {  // painted annulus (inner 0 = disc), clipped to a box
    Vec2 center;
    double inner2, outer2;
    Box clip;
  };

  MslFieldSpec spec_;
  std::vector<Box> boxes_;
  std::vector<Ring> rings_;
  Box carpet_;
};

}  // namespace ballsight::sim
