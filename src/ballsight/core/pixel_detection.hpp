#pragma once
// What a detector reports for one object in one image: the value passed from `detect` to
// `world` (pixel -> field). Plain data; no image, no camera.

#include <cstdint>
#include <string_view>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// What a detection is of: a ball to collect, one of the robot's two colour markers, or something
/// else that is not the empty court (a person, a bag, the robot's body: an obstacle's view, its
/// pixels as the patch; detect/court_foreground.hpp).
enum class ObjectClass : std::uint8_t { ball, robot_front_marker, robot_back_marker, obstacle };

/// "ball", "robot_front_marker", "robot_back_marker", "obstacle".
std::string_view object_class_name(ObjectClass object);

/// A detection's blob as coverage: each pixel's share covered by objects of the detection's class
/// (0 to 1, saturating where the evidence is half the blob's peak), over the blob's box grown by a
/// margin of uncovered pixels. The parts of a split blob carry the same patch and blob index.
struct CoveragePatch {
  int x = 0, y = 0;             // top-left pixel of the box
  int width = 0, height = 0;    // box size (0: no patch)
  std::vector<float> coverage;  // row-major, width x height
  int blob = -1;                // index of the blob among the image's blobs

  float at(int px, int py) const {
    return coverage[static_cast<size_t>((py - y) * width + px - x)];
  }
};

struct PixelDetection {
  ObjectClass object = ObjectClass::ball;
  Vec2 center_px = Vec2::Zero();  // centre of the object's outline (x right, y down)
  double radius_px = 0.0;         // apparent radius (from the area)
  double area_px = 0.0;           // apparent area, pixels (fractional where the detector is)
  double center_sigma_px = 0.5;   // the detector's expected error of center_px, one sigma
  int split_count = 1;        // objects in the blob this one was split from (1: a blob of its own)
  double blob_objects = 1.0;  // how many objects the whole blob's size amounts to
  CoveragePatch patch;        // the whole blob's coverage (empty from detectors that keep none)
};

}  // namespace ballsight
