#pragma once
// The robot's side of the navigation service over DDS (docs/ros2.md, "The robot link"): every
// navigation update of the court's `navigation` topic, in order; acknowledgements, collected
// balls, the robot's pose and the simulated court's wheels as reports on `robot/reports`, each
// waiting for the court's reply on `robot/replies`. DDS itself finds the court and finds it again
// when it comes back; a restarted court (a new service id) is followed from its latest update.
// Thread-safe; the receiving runs on a thread of its own.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "ballsight/dds/robot_messages.hpp"
#include "ballsight/dds/topic_io.hpp"
#include "ballsight/robot/link_inbox.hpp"
#include "ballsight/robot/robot_link.hpp"

namespace ballsight::dds {

struct DdsRobotLinkOptions {
  std::chrono::milliseconds reply_timeout{2000};  // a report not answered within it failed
  std::size_t keep = 256;  // updates delivered but not yet taken, at most (oldest dropped)

  void validate() const;
};

class DdsRobotLink : public RobotLink {
 public:
  /// Throws InputError for invalid options, std::runtime_error when DDS refuses.
  explicit DdsRobotLink(const Participant& participant, const DdsRobotLinkOptions& options = {});
  ~DdsRobotLink() override;  // stops
  DdsRobotLink(const DdsRobotLink&) = delete;
  DdsRobotLink& operator=(const DdsRobotLink&) = delete;

  std::optional<LinkUpdate> next(std::chrono::milliseconds timeout) override;
  std::optional<LinkUpdate> latest(std::chrono::milliseconds timeout) override;

  bool acknowledge(std::uint64_t seq) override;
  bool report_collected(const std::vector<Vec2>& positions, std::optional<int> held) override;
  bool report_unreachable(const std::vector<Vec2>& positions, const std::string& reason) override;
  bool set_pose(const Pose2D& pose) override;
  std::optional<nlohmann::json> drive_simulated(std::uint64_t seq, double speed_mps,
                                                double turn_rate_dps) override;

  /// "connected" while the court's navigation writer is matched; transport "dds".
  LinkStatus status() const override;
  void stop() override;

 private:
  struct Reply {
    bool answered = false;  // false: its request still waits
    bool ok = false;
    std::string error;
    int collected = 0;
    double time_s = 0.0;
    Pose2D odometry;
    int held = 0;
  };
  void receive();
  /// Writes a report of `kind` (`fill` adds what it carries) and waits for its reply; nullopt
  /// (and last_error says why) when refused or not answered in time.
  std::optional<Reply> request(ReportKind kind,
                               const std::function<void(RobotReportMsg&, MessageArena&)>& fill);

  DdsRobotLinkOptions options_;
  std::string client_;  // this link's id in reports and replies
  LinkInbox inbox_;
  Reader<NavigationUpdateMsg> navigation_;
  Writer<RobotReportMsg> reports_;
  Reader<RobotReplyMsg> replies_;
  WaitSet waitset_;
  std::mutex replies_mutex_;
  std::condition_variable replied_;
  std::map<std::uint64_t, Reply> answered_;  // the requests waiting, guarded by replies_mutex_
  std::atomic<std::uint64_t> next_request_{1};
  std::atomic<bool> stopping_{false};  // set under replies_mutex_
  std::thread thread_;
};

}  // namespace ballsight::dds
