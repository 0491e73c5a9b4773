#include "ballsight/dds/detection_messages.hpp"

#include <algorithm>
#include <cctype>

#include "ballsight/core/error.hpp"
#include "ballsight/dds/court_messages.hpp"

namespace ballsight::dds {
namespace {

// A patch larger than any image a camera delivers is not a patch (64 Mpx).
constexpr std::int64_t kMaxPatchPixels = std::int64_t{1} << 26;

PixelDetectionMsg detection_message(const PixelDetection& d, const std::optional<Vec3>& ground,
                                    MessageArena& arena) {
  PixelDetectionMsg m{};
  m.object = static_cast<std::uint8_t>(d.object);
  m.center_x_px = d.center_px.x();
  m.center_y_px = d.center_px.y();
  m.radius_px = d.radius_px;
  m.area_px = d.area_px;
  m.center_sigma_px = d.center_sigma_px;
  m.split_count = d.split_count;
  m.blob_objects = d.blob_objects;
  m.on_ground = ground.has_value();
  if (ground) m.ground = {ground->x(), ground->y(), ground->z()};
  m.patch_x = d.patch.x;
  m.patch_y = d.patch.y;
  m.patch_width = d.patch.width;
  m.patch_height = d.patch.height;
  m.patch_blob = d.patch.blob;
  std::copy(d.patch.coverage.begin(), d.patch.coverage.end(),
            arena.fill(m.patch_coverage, d.patch.coverage.size()));
  return m;
}

PixelDetection detection_from_message(const PixelDetectionMsg& m, const std::string& where) {
  require(m.object <= static_cast<std::uint8_t>(ObjectClass::obstacle), where,
          "object class " + std::to_string(m.object) +
              " is not 0 (ball), 1 or 2 (markers) or 3 (obstacle)");
  require(m.patch_width >= 0 && m.patch_height >= 0 &&
              std::int64_t{m.patch_width} * m.patch_height <= kMaxPatchPixels,
          where,
          "patch size " + std::to_string(m.patch_width) + "x" + std::to_string(m.patch_height) +
              " is out of range");
  require(m.patch_coverage._length == static_cast<std::uint32_t>(m.patch_width * m.patch_height),
          where,
          "patch_coverage holds " + std::to_string(m.patch_coverage._length) + " values, not " +
              std::to_string(m.patch_width) + "x" + std::to_string(m.patch_height));
  require(m.split_count >= 1, where, "split_count must be at least 1");
  PixelDetection d;
  d.object = static_cast<ObjectClass>(m.object);
  d.center_px = {m.center_x_px, m.center_y_px};
  d.radius_px = m.radius_px;
  d.area_px = m.area_px;
  d.center_sigma_px = m.center_sigma_px;
  d.split_count = m.split_count;
  d.blob_objects = m.blob_objects;
  d.patch.x = m.patch_x;
  d.patch.y = m.patch_y;
  d.patch.width = m.patch_width;
  d.patch.height = m.patch_height;
  d.patch.blob = m.patch_blob;
  d.patch.coverage.assign(m.patch_coverage._buffer,
                          m.patch_coverage._buffer + m.patch_coverage._length);
  return d;
}

}  // namespace

std::string detections_topic(const std::string& camera) {
  std::string token = camera;  // a ROS 2 name token: letters, digits and '_'
  for (char& c : token) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  if (token.empty() || std::isdigit(static_cast<unsigned char>(token[0]))) token = "_" + token;
  return "cameras/" + token + "/detections";
}

CameraDetectionsMsg camera_detections_message(const CameraFrameDetections& frame,
                                              MessageArena& arena) {
  CameraDetectionsMsg m{};
  m.header = header_message(frame.capture_ns, frame.camera, arena);
  m.frame = frame.frame;
  m.error = arena.text(frame.error);
  PixelDetectionMsg* out = arena.fill(m.detections, frame.detections.size());
  for (std::size_t k = 0; k < frame.detections.size(); ++k) {
    const std::optional<Vec3> ground = k < frame.ground.size() ? frame.ground[k] : std::nullopt;
    out[k] = detection_message(frame.detections[k], ground, arena);
  }
  return m;
}

CameraFrameDetections camera_detections_from_message(const CameraDetectionsMsg& message) {
  CameraFrameDetections frame;
  frame.camera = message.header.frame_id ? message.header.frame_id : "";
  frame.frame = message.frame;
  frame.capture_ns = stamp_ns(message.header);
  frame.error = message.error ? message.error : "";
  const std::string where =
      "detections of camera '" + frame.camera + "', frame " + std::to_string(frame.frame);
  for (std::uint32_t k = 0; k < message.detections._length; ++k) {
    const PixelDetectionMsg& m = message.detections._buffer[k];
    frame.detections.push_back(
        detection_from_message(m, where + ", detection " + std::to_string(k)));
    frame.ground.push_back(
        m.on_ground ? std::optional<Vec3>(Vec3(m.ground.x, m.ground.y, m.ground.z)) : std::nullopt);
  }
  return frame;
}

}  // namespace ballsight::dds
