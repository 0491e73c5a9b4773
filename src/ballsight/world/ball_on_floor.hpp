#pragma once
// A ball resting on the floor seen by a camera with a single viewpoint: the ray through the
// ball's centre meets the floor *behind* the ball, so a pixel -> floor table read at the ball's
// centre pixel overshoots. With the viewpoint at height h above the robot origin and a ball of
// radius R, that floor hit is F = C h / (h - R) for the ball centre C (both horizontal, robot
// frame), so C = F (h - R) / h. The omnivision paper reads the table at the first ball pixel of
// the last scan ray meeting the ball (Algorithm 3 as printed), a side pixel near the centre's
// radius, and so overshoots by up to F - C.

#include <opencv2/core.hpp>
#include <optional>
#include <span>

#include "ballsight/camera/ground_map.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct BallOnFloor {
  double radius_cm = 11.0;            // size-5 football
  double viewpoint_height_cm = 60.0;  // the camera's effective viewpoint above the floor

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// The ball's centre (horizontal position, robot frame, cm) from the floor point seen through the
/// ball's centre.
Vec2 ball_center_from_floor_hit_cm(const Vec2& floor_hit_cm, const BallOnFloor& ball);

/// The ball's centre from its centre pixel through a ground map (sub-pixel read); nullopt where
/// the map has no value.
std::optional<Vec2> ball_center_in_robot_cm(const GroundMap& map, const Vec2& ball_center_px,
                                            const BallOnFloor& ball);

/// The ball's centre from its whole silhouette: the rays of a sphere's silhouette fill a circular
/// cone around the ray through its centre, so the solid-angle-weighted mean of the silhouette
/// pixels' rays (each from the map's floor point and the viewpoint height) is the centre ray;
/// the centre lies on it at the ball's radius above the floor. Unlike the pixel centroid this is
/// unbiased by the mirror's radial compression (about 1.5 px at 1 m on the default rig).
/// nullopt when no silhouette pixel has a map value.
std::optional<Vec2> ball_center_from_silhouette_cm(const GroundMap& map,
                                                   std::span<const cv::Point> silhouette,
                                                   const BallOnFloor& ball);

}  // namespace ballsight
