#include "ballsight/dds/omni_node.hpp"

#include <cstdlib>

#include "ballsight/core/conventions.hpp"
#include "ballsight/dds/court_messages.hpp"

namespace ballsight::dds {
namespace {

PointStampedMsg point_message(const Vec3& p, std::int64_t stamp_ns, const std::string& frame,
                              MessageArena& arena) {
  PointStampedMsg message{};
  message.header = header_message(stamp_ns, frame, arena);
  message.point.x = p.x();
  message.point.y = p.y();
  message.point.z = p.z();
  return message;
}

}  // namespace

OmniNode::OmniNode(const Participant& participant, const BallsightOmniPipeline& pipeline,
                   double ball_radius_m, const OmniNodeOptions& options)
    : pipeline_(pipeline),
      ball_radius_m_(ball_radius_m),
      options_(options),
      robot_pose_(participant, "robot_pose"),
      ball_(participant, "ball"),
      ball_field_(participant, "ball_field") {}

std::optional<OmniBallReport> OmniNode::publish(const cv::Mat& frame, std::int64_t capture_ns) {
  robot_pose_.take([&](const PoseStampedMsg& m) {
    pose_ = StampedPose{pose_from_message(m.pose), stamp_ns(m.header), m.header.frame_id};
  });
  const std::optional<Vec2> in_robot_cm = pipeline_.locate_in_robot_cm(frame);
  if (!in_robot_cm) return std::nullopt;
  OmniBallReport report;
  const Vec2 in_robot_m = *in_robot_cm / 100.0;
  report.in_robot_m = Vec3(in_robot_m.x(), in_robot_m.y(), ball_radius_m_);
  MessageArena arena;
  ball_.write(point_message(report.in_robot_m, capture_ns, options_.robot_frame, arena));
  const auto tolerance_ns =
      std::chrono::duration_cast<std::chrono::nanoseconds>(options_.pose_tolerance).count();
  if (pose_ && std::llabs(capture_ns - pose_->stamp_ns) <= tolerance_ns) {
    const Vec2 field = field_from_robot_point(pose_->pose, in_robot_m);
    report.in_field_m = Vec3(field.x(), field.y(), ball_radius_m_);
    report.field_frame = pose_->frame;
    ball_field_.write(point_message(*report.in_field_m, capture_ns, pose_->frame, arena));
  }
  return report;
}

}  // namespace ballsight::dds
