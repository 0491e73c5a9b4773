#pragma once
// `ballsight omni-node`: the on-board omni camera of a ball-playing robot on DDS. Each frame's ball
// (the omni run time: colour blob, lookup table, ball-radius correction) is written
// robot-relative on `ball` (geometry_msgs/PointStamped, frame `base_link`, metres, z the ball's
// centre height) and, while the robot's pose comes in on `robot_pose` (geometry_msgs/PoseStamped
// from its localisation, or a court node), on the field as `ball_field` in the pose's frame. A
// frame without a ball writes nothing (as a ROS 2 detector does).

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "ballsight/dds/topic_io.hpp"
#include "ballsight/pipeline/omni_pipelines.hpp"

namespace ballsight::dds {

struct OmniNodeOptions {
  std::string robot_frame = "base_link";  // ROS's name of the robot's body frame (REP-105)
  /// A pose stamped further than this from the frame's capture is not used for `ball_field`.
  std::chrono::milliseconds pose_tolerance{500};
};

/// One frame's ball as the node wrote it.
struct OmniBallReport {
  Vec3 in_robot_m = Vec3::Zero();
  std::optional<Vec3> in_field_m;  // when a robot pose near the capture time was known
  std::string field_frame;         // the pose's frame_id
};

class OmniNode {
 public:
  /// `pipeline` must outlive the node.
  OmniNode(const Participant& participant, const BallsightOmniPipeline& pipeline,
           double ball_radius_m, const OmniNodeOptions& options = {});

  /// Finds the ball in `frame` (captured at `capture_ns`, UTC) and writes it; nullopt when there
  /// is none.
  std::optional<OmniBallReport> publish(const cv::Mat& frame, std::int64_t capture_ns);

 private:
  struct StampedPose {
    Pose2D pose;
    std::int64_t stamp_ns = 0;
    std::string frame;
  };

  const BallsightOmniPipeline& pipeline_;
  double ball_radius_m_;
  OmniNodeOptions options_;
  Reader<PoseStampedMsg> robot_pose_;
  Writer<PointStampedMsg> ball_;
  Writer<PointStampedMsg> ball_field_;
  std::optional<StampedPose> pose_;  // the latest received
};

}  // namespace ballsight::dds
