#pragma once
// What a detector reports for one object in one image: the value passed from `detect` to
// `world` (pixel -> field). Plain data; no image, no camera.

#include <cstdint>
#include <string_view>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// What a detection is of: a ball to collect or one of the robot's two colour markers.
enum class ObjectClass : std::uint8_t { ball, robot_front_marker, robot_back_marker };

/// "ball", "robot_front_marker", "robot_back_marker".
std::string_view object_class_name(ObjectClass object);

struct PixelDetection {
  ObjectClass object = ObjectClass::ball;
  Vec2 center_px = Vec2::Zero();  // centre of the object's outline (x right, y down)
  double radius_px = 0.0;         // apparent radius (from the area)
  double area_px = 0.0;           // apparent area, pixels (fractional where the detector is)
  double center_sigma_px = 0.5;   // the detector's expected error of center_px, one sigma
  int split_count = 1;        // objects in the blob this one was split from (1: a blob of its own)
  double blob_objects = 1.0;  // how many objects the whole blob's size amounts to
};

}  // namespace ballsight
