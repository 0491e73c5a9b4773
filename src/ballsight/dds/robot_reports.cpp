#include "ballsight/dds/robot_reports.hpp"

#include <chrono>
#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/json_fields.hpp"

namespace ballsight::dds {
namespace {

// What a report would change, checked first: a refusal changes nothing.
void check_inside(const std::vector<Vec2>& points, const FieldRect& area, const char* where) {
  for (std::size_t k = 0; k < points.size(); ++k)
    require(points[k].allFinite() && area.contains(points[k]),
            std::string(where) + "[" + std::to_string(k) + "]", "outside the field area");
}

// The balls a report names, each inside the field area.
std::vector<Vec2> reported_balls(const RobotReportMsg& report, const FieldRect& area) {
  require(report.points._length <= kMaxReportPoints, "report.points",
          "more than " + std::to_string(kMaxReportPoints) + " balls");
  std::vector<Vec2> balls = points_from_message(report.points);
  check_inside(balls, area, "report.points");
  return balls;
}

}  // namespace

RobotReportsContext robot_reports_context(CourtService& service, NavigationHub& hub) {
  return {hub, service.site().court.fenced_area(), [&service, &hub] { service.republish(hub); },
          service.simulated_drive()};
}

RobotReports::RobotReports(const Participant& participant, RobotReportsContext context)
    : context_(std::move(context)),
      reports_(participant, kReportsTopic, kReportQos),
      replies_(participant, kRepliesTopic, kReportQos),
      thread_([this] { run(); }) {}

RobotReports::~RobotReports() {
  stop_ = true;
  thread_.join();
}

void RobotReports::run() {
  while (!stop_) {
    if (reports_.wait(std::chrono::milliseconds(100)))
      reports_.take([this](const RobotReportMsg& report) { answer(report); });
  }
}

nlohmann::json RobotReports::apply(const RobotReportMsg& report) {
  switch (static_cast<ReportKind>(report.kind)) {
    case ReportKind::acknowledge:
      context_.hub.acknowledge(report.seq);  // InputError: not published yet
      return {};
    case ReportKind::collected: {
      const std::vector<Vec2> balls = reported_balls(report, context_.area);
      require(report.held >= -1 && report.held <= 1000, "report.held",
              "expected the balls in the basket, 0 to 1000 (-1: not said)");
      if (report.held >= 0) context_.hub.set_basket(report.held);
      context_.hub.add_collected(balls);
      if (context_.on_collected) context_.on_collected();
      return {};
    }
    case ReportKind::unreachable: {
      const std::vector<Vec2> balls = reported_balls(report, context_.area);
      const std::string reason = report.reason ? report.reason : "";
      require(!reason.empty() && reason.size() <= 200, "report.reason",
              "expected why, a text of 1 to 200 characters");
      context_.hub.mark_unreachable(balls, reason);
      if (context_.on_collected) context_.on_collected();
      return {};
    }
    case ReportKind::pose: {
      const Pose2D pose = pose_from_message(report.pose);
      check_inside({pose.position}, context_.area, "report.pose");
      require(std::isfinite(pose.heading_rad), "report.pose.theta", "expected a number");
      context_.hub.set_robot(pose);
      return {};
    }
    case ReportKind::drive:
      require(static_cast<bool>(context_.drive), "service",
              "not a simulated court: there is no simulated robot to drive");
      require(std::isfinite(report.speed_mps) && std::isfinite(report.turn_rate_dps), "report",
              "expected finite speed_mps and turn_rate_dps");
      return context_.drive(report.seq, report.speed_mps, rad_from_deg(report.turn_rate_dps));
  }
  throw InputError("report.kind: unknown: " + std::to_string(report.kind));
}

void RobotReports::answer(const RobotReportMsg& report) {
  std::string error;
  nlohmann::json done;
  try {
    done = apply(report);
  } catch (const InputError& e) {
    error = e.what();
    ++refused_;
  } catch (const std::exception& e) {  // the court's own failure (planning, the drive): said
    error = std::string("the court failed: ") + e.what();
    ++refused_;
  }
  MessageArena arena;
  RobotReplyMsg reply = reply_message(report, error, arena);
  if (done.is_object()) {  // the wheels' answer
    reply.collected = done.value("collected", 0);
    reply.time_s = done.value("time_s", 0.0);
    reply.held = done.value("held", 0);
    // Not a pose: none carried (the robot keeps its prediction).
    if (const std::optional<Pose2D> odometry = json_pose_if_any(done, "odometry")) {
      reply.odometry = pose_2d_message(*odometry);
    }
  }
  ++answered_;  // before the reply: the robot may count on it once answered
  try {
    replies_.write(reply);
  } catch (const std::exception&) {
    // DDS refused the reply: the robot's wait for it runs out and says so.
  }
}

}  // namespace ballsight::dds
