#pragma once
// The court's side of the robot link on DDS (docs/ros2.md): reads the robot's reports on
// `robot/reports` (ballsight_msgs/RobotReport: an update read, balls collected, its pose, the
// simulated court's wheels), hands each to the hub or the service as API v1's routes do, and
// answers every one on `robot/replies` (ballsight_msgs/RobotReply), from a thread of its own.
// The updates themselves go out on `navigation` with the court's other topics (CourtTopics).

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <thread>

#include "ballsight/core/field_rect.hpp"
#include "ballsight/dds/robot_messages.hpp"
#include "ballsight/dds/topic_io.hpp"
#include "ballsight/service/court_service.hpp"

namespace ballsight::dds {

struct RobotReportsContext {
  NavigationHub& hub;
  FieldRect area;                      // positions reported lie in it (else refused)
  std::function<void()> on_collected;  // balls were reported collected: plan again now
  CourtService::SimulatedDrive drive;  // the simulated court's wheels; empty elsewhere
};

/// `service`'s context: its court's area, its republish and its simulated drive.
RobotReportsContext robot_reports_context(CourtService& service, NavigationHub& hub);

class RobotReports {
 public:
  /// Answers reports until destroyed; the context's hub and service must outlive this.
  RobotReports(const Participant& participant, RobotReportsContext context);
  ~RobotReports();
  RobotReports(const RobotReports&) = delete;
  RobotReports& operator=(const RobotReports&) = delete;

  /// Reports answered so far; those refused (answered with an error).
  std::uint64_t answered() const { return answered_; }
  std::uint64_t refused() const { return refused_; }

 private:
  void run();
  /// Does what `report` asks; the wheels' answer for a drive, null otherwise. Throws InputError
  /// when it is refused (nothing changed).
  nlohmann::json apply(const RobotReportMsg& report);
  void answer(const RobotReportMsg& report);

  RobotReportsContext context_;
  Reader<RobotReportMsg> reports_;
  Writer<RobotReplyMsg> replies_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> answered_{0};
  std::atomic<std::uint64_t> refused_{0};
  std::thread thread_;
};

}  // namespace ballsight::dds
