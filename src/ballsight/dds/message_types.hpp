#pragma once
// The messages ballsight writes and reads, as idlc generates them from idl/*.idl (C structs in
// ROS 2's DDS naming), each with its ROS 2 name, topic descriptor and type hash.

#include <string>

#include "ballsight_messages.h"

namespace ballsight::dds {

using TimeMsg = builtin_interfaces_msg_dds__Time_;
using HeaderMsg = std_msgs_msg_dds__Header_;
using PoseMsg = geometry_msgs_msg_dds__Pose_;
using PointStampedMsg = geometry_msgs_msg_dds__PointStamped_;
using PoseStampedMsg = geometry_msgs_msg_dds__PoseStamped_;
using PoseArrayMsg = geometry_msgs_msg_dds__PoseArray_;
using PathMsg = nav_msgs_msg_dds__Path_;
using KeyValueMsg = diagnostic_msgs_msg_dds__KeyValue_;
using DiagnosticStatusMsg = diagnostic_msgs_msg_dds__DiagnosticStatus_;
using DiagnosticArrayMsg = diagnostic_msgs_msg_dds__DiagnosticArray_;
using BallMsg = ballsight_msgs_msg_dds__Ball_;
using BallArrayMsg = ballsight_msgs_msg_dds__BallArray_;
using PixelDetectionMsg = ballsight_msgs_msg_dds__PixelDetection_;
using CameraDetectionsMsg = ballsight_msgs_msg_dds__CameraDetections_;
using Pose2DMsg = geometry_msgs_msg_dds__Pose2D_;
using NavigationUpdateMsg = ballsight_msgs_msg_dds__NavigationUpdate_;
using RobotReportMsg = ballsight_msgs_msg_dds__RobotReport_;
using RobotReplyMsg = ballsight_msgs_msg_dds__RobotReply_;

/// A message type a topic carries: specialised for each top-level message below.
template <class Msg>
struct MessageType;

#define BALLSIGHT_DDS_MESSAGE(Msg, ros, desc)                          \
  template <>                                                          \
  struct MessageType<Msg> {                                            \
    static constexpr const char* ros_name = ros;                       \
    static const dds_topic_descriptor_t& descriptor() { return desc; } \
  };
BALLSIGHT_DDS_MESSAGE(PointStampedMsg, "geometry_msgs/msg/PointStamped",
                      geometry_msgs_msg_dds__PointStamped__desc)
BALLSIGHT_DDS_MESSAGE(PoseStampedMsg, "geometry_msgs/msg/PoseStamped",
                      geometry_msgs_msg_dds__PoseStamped__desc)
BALLSIGHT_DDS_MESSAGE(PoseArrayMsg, "geometry_msgs/msg/PoseArray",
                      geometry_msgs_msg_dds__PoseArray__desc)
BALLSIGHT_DDS_MESSAGE(PathMsg, "nav_msgs/msg/Path", nav_msgs_msg_dds__Path__desc)
BALLSIGHT_DDS_MESSAGE(DiagnosticArrayMsg, "diagnostic_msgs/msg/DiagnosticArray",
                      diagnostic_msgs_msg_dds__DiagnosticArray__desc)
BALLSIGHT_DDS_MESSAGE(BallArrayMsg, "ballsight_msgs/msg/BallArray",
                      ballsight_msgs_msg_dds__BallArray__desc)
BALLSIGHT_DDS_MESSAGE(CameraDetectionsMsg, "ballsight_msgs/msg/CameraDetections",
                      ballsight_msgs_msg_dds__CameraDetections__desc)
BALLSIGHT_DDS_MESSAGE(NavigationUpdateMsg, "ballsight_msgs/msg/NavigationUpdate",
                      ballsight_msgs_msg_dds__NavigationUpdate__desc)
BALLSIGHT_DDS_MESSAGE(RobotReportMsg, "ballsight_msgs/msg/RobotReport",
                      ballsight_msgs_msg_dds__RobotReport__desc)
BALLSIGHT_DDS_MESSAGE(RobotReplyMsg, "ballsight_msgs/msg/RobotReply",
                      ballsight_msgs_msg_dds__RobotReply__desc)
#undef BALLSIGHT_DDS_MESSAGE

/// The REP-2011 type hash ("RIHS01_...") of a message ballsight knows by its ROS 2 name
/// ("geometry_msgs/msg/PoseStamped"); throws std::logic_error for another name.
std::string message_type_hash(const std::string& ros_name);

}  // namespace ballsight::dds
