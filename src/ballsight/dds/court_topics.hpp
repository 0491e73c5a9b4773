#pragma once
// A court's navigation updates on DDS, as ROS 2 topics under the participant's namespace:
// `robot_pose` (geometry_msgs/PoseStamped), `balls` (geometry_msgs/PoseArray), `ball_estimates`
// (ballsight_msgs/BallArray), `route` (nav_msgs/Path), `navigation`
// (ballsight_msgs/NavigationUpdate, the robot link's: robot_messages.hpp) and `diagnostics`
// (diagnostic_msgs/DiagnosticArray, once a second). The balls and the route are transient-local,
// keep last 1: a subscriber that joins late gets the latest at once. Every update the hub
// publishes is written, in order, from a thread of this object's (the hub's listener only hands
// it over).

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "ballsight/dds/detection_messages.hpp"
#include "ballsight/dds/topic_io.hpp"
#include "ballsight/service/navigation_hub.hpp"

namespace ballsight::dds {

struct CourtTopicsOptions {
  double ball_radius_m = 0.0335;
  std::string diagnostics_prefix = "ballsight";  // status names: "<prefix>/camera/<name>", ...
  std::chrono::milliseconds health_period{1000};
  /// A court node that detects its cameras itself (no camera nodes): each update's detections
  /// per camera, written on the `cameras/<camera>/detections` of `detection_cameras` (the site's
  /// camera names) as a camera node would.
  std::function<std::vector<CameraFrameDetections>(const NavigationUpdate&)> camera_detections;
  std::vector<std::string> detection_cameras;
  /// A write DDS refused (the update or the diagnostics are then skipped; the next are written).
  std::function<void(const std::string& message)> on_error;
};

class CourtTopics {
 public:
  /// Writes `hub`'s updates and `health()` (CourtService::health()) until destroyed; `hub` and
  /// `health` must outlive this.
  CourtTopics(const Participant& participant, NavigationHub& hub,
              std::function<nlohmann::json()> health, const CourtTopicsOptions& options = {});
  ~CourtTopics();
  CourtTopics(const CourtTopics&) = delete;
  CourtTopics& operator=(const CourtTopics&) = delete;

  /// Updates written so far, and writes DDS refused.
  std::uint64_t written() const { return written_; }
  std::uint64_t failed() const { return failed_; }

 private:
  void run();
  void write(const NavigationUpdate& update);
  void write_health();
  void write_detections(const NavigationUpdate& update);
  void guarded(const std::string& what, const std::function<void()>& write);

  NavigationHub& hub_;
  std::function<nlohmann::json()> health_;
  CourtTopicsOptions options_;
  Writer<PoseStampedMsg> robot_pose_;
  Writer<PoseArrayMsg> balls_;
  Writer<BallArrayMsg> ball_estimates_;
  Writer<PathMsg> route_;
  Writer<NavigationUpdateMsg> navigation_;
  Writer<DiagnosticArrayMsg> diagnostics_;
  std::map<std::string, std::unique_ptr<Writer<CameraDetectionsMsg>>> detections_;  // by camera
  std::mutex mutex_;
  std::condition_variable wake_;
  std::uint64_t pending_seq_ = 0;  // guarded by mutex_
  bool stop_ = false;              // guarded by mutex_
  std::atomic<std::uint64_t> written_{0};
  std::atomic<std::uint64_t> failed_{0};
  int listener_ = 0;
  std::thread thread_;
};

}  // namespace ballsight::dds
