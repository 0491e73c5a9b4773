#pragma once
// One camera's detections in one frame as a camera node publishes them (ballsight_msgs/
// CameraDetections on `cameras/<camera>/detections`): everything the court's fusion reads of a
// PixelDetection (coverage patch included, so that a court node fuses exactly what one process
// would), and each object's centre on the court where the camera's pose puts it.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/core/pixel_detection.hpp"
#include "ballsight/dds/message_arena.hpp"
#include "ballsight/dds/message_types.hpp"

namespace ballsight::dds {

struct CameraFrameDetections {
  std::string camera;  // the site's name of the camera
  std::uint64_t frame = 0;
  std::int64_t capture_ns = 0;  // UTC
  std::string error;            // why the frame was not used ("": it was)
  std::vector<PixelDetection> detections;
  std::vector<std::optional<Vec3>> ground;  // per detection: its centre, court frame (m)
};

/// The topic of a camera's detections: "cameras/<camera>/detections", the name made a ROS 2
/// token (characters other than letters and digits become '_': "camera 0" -> "camera_0").
std::string detections_topic(const std::string& camera);

CameraDetectionsMsg camera_detections_message(const CameraFrameDetections& frame,
                                              MessageArena& arena);
/// Throws InputError naming the camera, frame and field when the message is not one a camera node
/// writes (an unknown object class, a patch whose size and coverage disagree, ...).
CameraFrameDetections camera_detections_from_message(const CameraDetectionsMsg& message);

}  // namespace ballsight::dds
