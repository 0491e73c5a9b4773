#include "ballsight/dds/message_types.hpp"

#include <vector>

#include "ballsight/dds/type_hash.hpp"

namespace ballsight::dds {
namespace {

FieldDescription field(std::string name, FieldType type) {
  return {std::move(name), type, FieldShape::single, 0, ""};
}
FieldDescription nested(std::string name, std::string type, FieldShape shape = FieldShape::single) {
  return {std::move(name), FieldType::nested, shape, 0, std::move(type)};
}
FieldDescription sequence(std::string name, FieldType type) {
  return {std::move(name), type, FieldShape::sequence, 0, ""};
}

FieldDescription points(std::string name) {
  return nested(std::move(name), "geometry_msgs/msg/Point", FieldShape::sequence);
}

// The field lists of idl/*.idl, as rosidl describes them.
std::vector<TypeDescription> descriptions() {
  using F = FieldType;
  const auto header = nested("header", "std_msgs/msg/Header");
  return {
      {"builtin_interfaces/msg/Time", {field("sec", F::int32), field("nanosec", F::uint32)}},
      {"std_msgs/msg/Header",
       {nested("stamp", "builtin_interfaces/msg/Time"), field("frame_id", F::string)}},
      {"geometry_msgs/msg/Point",
       {field("x", F::float64), field("y", F::float64), field("z", F::float64)}},
      {"geometry_msgs/msg/Pose2D",
       {field("x", F::float64), field("y", F::float64), field("theta", F::float64)}},
      {"geometry_msgs/msg/Quaternion",
       {field("x", F::float64), field("y", F::float64), field("z", F::float64),
        field("w", F::float64)}},
      {"geometry_msgs/msg/Pose",
       {nested("position", "geometry_msgs/msg/Point"),
        nested("orientation", "geometry_msgs/msg/Quaternion")}},
      {"geometry_msgs/msg/PointStamped", {header, nested("point", "geometry_msgs/msg/Point")}},
      {"geometry_msgs/msg/PoseStamped", {header, nested("pose", "geometry_msgs/msg/Pose")}},
      {"geometry_msgs/msg/PoseArray",
       {header, nested("poses", "geometry_msgs/msg/Pose", FieldShape::sequence)}},
      {"nav_msgs/msg/Path",
       {header, nested("poses", "geometry_msgs/msg/PoseStamped", FieldShape::sequence)}},
      {"diagnostic_msgs/msg/KeyValue", {field("key", F::string), field("value", F::string)}},
      {"diagnostic_msgs/msg/DiagnosticStatus",
       {field("level", F::byte), field("name", F::string), field("message", F::string),
        field("hardware_id", F::string),
        nested("values", "diagnostic_msgs/msg/KeyValue", FieldShape::sequence)}},
      {"diagnostic_msgs/msg/DiagnosticArray",
       {header, nested("status", "diagnostic_msgs/msg/DiagnosticStatus", FieldShape::sequence)}},
      {"ballsight_msgs/msg/Ball",
       {nested("position", "geometry_msgs/msg/Point"),
        {"covariance", F::float64, FieldShape::array, 4, ""},
        sequence("cameras", F::int32)}},
      {"ballsight_msgs/msg/BallArray",
       {header, field("seq", F::uint64),
        nested("balls", "ballsight_msgs/msg/Ball", FieldShape::sequence)}},
      {"ballsight_msgs/msg/PixelDetection",
       {field("object", F::uint8), field("center_x_px", F::float64),
        field("center_y_px", F::float64), field("radius_px", F::float64),
        field("area_px", F::float64), field("center_sigma_px", F::float64),
        field("split_count", F::int32), field("blob_objects", F::float64),
        field("on_ground", F::boolean), nested("ground", "geometry_msgs/msg/Point"),
        field("patch_x", F::int32), field("patch_y", F::int32), field("patch_width", F::int32),
        field("patch_height", F::int32), field("patch_blob", F::int32),
        sequence("patch_coverage", F::float32)}},
      {"ballsight_msgs/msg/CameraDetections",
       {header, field("frame", F::uint64), field("error", F::string),
        nested("detections", "ballsight_msgs/msg/PixelDetection", FieldShape::sequence)}},
      {"ballsight_msgs/msg/NavigationUpdate",
       {header, field("seq", F::uint64), field("service_id", F::string),
        nested("published", "builtin_interfaces/msg/Time"), field("has_robot", F::boolean),
        nested("robot", "geometry_msgs/msg/Pose2D"), points("balls"), points("visits"),
        points("waypoints"), field("unload_first", F::boolean),
        nested("unload", "geometry_msgs/msg/Point")}},
      {"ballsight_msgs/msg/RobotReport",
       {header, field("client", F::string), field("request", F::uint64), field("kind", F::uint8),
        field("seq", F::uint64), points("points"), nested("pose", "geometry_msgs/msg/Pose2D"),
        field("speed_mps", F::float64), field("turn_rate_dps", F::float64), field("held", F::int32),
        field("reason", F::string)}},
      {"ballsight_msgs/msg/RobotReply",
       {header, field("client", F::string), field("request", F::uint64), field("ok", F::boolean),
        field("error", F::string), field("collected", F::int32), field("time_s", F::float64),
        nested("odometry", "geometry_msgs/msg/Pose2D"), field("held", F::int32)}},
  };
}

}  // namespace

std::string message_type_hash(const std::string& ros_name) {
  static const std::vector<TypeDescription> types = descriptions();
  return ros_type_hash(ros_name, types);
}

}  // namespace ballsight::dds
