#include "ballsight/dds/dds_robot_link.hpp"

#include <stdexcept>

#include "ballsight/core/error.hpp"
#include "ballsight/core/json_fields.hpp"
#include "ballsight/core/utc_clock.hpp"
#include "ballsight/service/navigation_hub.hpp"

namespace ballsight::dds {
namespace {

constexpr std::chrono::milliseconds kPoll{100};  // the receiver looks at `stopping` this often

}  // namespace

void DdsRobotLinkOptions::validate() const {
  require(reply_timeout.count() >= 1, "reply_timeout", "must be at least 1 ms");
  require(keep >= 1, "keep", "must be at least 1");
}

DdsRobotLink::DdsRobotLink(const Participant& participant, const DdsRobotLinkOptions& options)
    : options_((options.validate(), options)),
      client_(random_hex(16)),
      inbox_(options.keep),
      navigation_(participant, kNavigationTopic, kNavigationQos),
      reports_(participant, kReportsTopic, kReportQos),
      replies_(participant, kRepliesTopic, kReportQos),
      waitset_(participant) {
  inbox_.update_status([](LinkStatus& status) { status.transport = "dds"; });
  waitset_.attach(navigation_.condition());
  waitset_.attach(replies_.condition());
  thread_ = std::thread([this] { receive(); });
}

DdsRobotLink::~DdsRobotLink() {
  stop();
}

void DdsRobotLink::stop() {
  {
    const std::lock_guard lock(replies_mutex_);  // a request waiting for its reply sees it
    if (stopping_) return;
    stopping_ = true;
  }
  replied_.notify_all();
  thread_.join();
  inbox_.close();
}

void DdsRobotLink::receive() {
  bool found = false;  // the court's writer was matched once
  while (!stopping_) {
    waitset_.wait(kPoll);
    navigation_.take([this](const NavigationUpdateMsg& message) {
      LinkUpdate update = link_update_from_message(message);
      update.received_ns = utc_now_ns();
      inbox_.deliver(std::move(update));
    });
    int mine = 0;
    replies_.take([&](const RobotReplyMsg& message) {
      if (!message.client || client_ != message.client) return;  // another robot's
      const std::lock_guard lock(replies_mutex_);
      const auto waiting = answered_.find(message.request);
      if (waiting == answered_.end()) return;  // its request stopped waiting
      waiting->second = Reply{true,
                              message.ok,
                              message.error ? message.error : "",
                              message.collected,
                              message.time_s,
                              pose_from_message(message.odometry),
                              message.held};
      ++mine;
    });
    if (mine > 0) replied_.notify_all();
    const bool matched = navigation_.matched_writers() > 0;
    inbox_.update_status([&](LinkStatus& status) {
      if (matched && !status.connected && found) ++status.reconnects;
      status.connected = matched;
    });
    found = found || matched;
  }
}

std::optional<DdsRobotLink::Reply> DdsRobotLink::request(
    ReportKind kind, const std::function<void(RobotReportMsg&, MessageArena&)>& fill) {
  const std::uint64_t id = next_request_++;
  const auto deadline = std::chrono::steady_clock::now() + options_.reply_timeout;
  std::string error;
  try {
    // A report written before the court's reader is found is lost (volatile): wait for it.
    while (reports_.matched_readers() == 0 || replies_.matched_writers() == 0) {
      if (stopping_ || std::chrono::steady_clock::now() >= deadline)
        throw std::runtime_error("no court found on robot/reports within " +
                                 std::to_string(options_.reply_timeout.count()) + " ms");
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    MessageArena arena;
    RobotReportMsg report = report_message(kind, client_, id, arena);
    fill(report, arena);
    std::unique_lock lock(replies_mutex_);
    answered_[id] = Reply{};  // waiting
    lock.unlock();
    reports_.write(report);
    lock.lock();
    replied_.wait_until(lock, deadline, [&] { return answered_[id].answered || stopping_; });
    const Reply reply = answered_.extract(id).mapped();
    if (reply.answered && reply.ok) return reply;
    if (reply.answered) {
      error = "the court refused: " + reply.error;
    } else {
      error = stopping_ ? "the link was stopped"
                        : "no reply from the court within " +
                              std::to_string(options_.reply_timeout.count()) + " ms";
    }
  } catch (const std::exception& e) {  // no court, or DDS refused the write
    const std::lock_guard lock(replies_mutex_);
    answered_.erase(id);
    error = e.what();
  }
  inbox_.update_status([&error](LinkStatus& status) { status.last_error = error; });
  return std::nullopt;
}

std::optional<LinkUpdate> DdsRobotLink::next(std::chrono::milliseconds timeout) {
  return inbox_.take(timeout, false);
}

std::optional<LinkUpdate> DdsRobotLink::latest(std::chrono::milliseconds timeout) {
  return inbox_.take(timeout, true);
}

bool DdsRobotLink::acknowledge(std::uint64_t seq) {
  return request(ReportKind::acknowledge, [seq](RobotReportMsg& r, MessageArena&) { r.seq = seq; })
      .has_value();
}

bool DdsRobotLink::report_collected(const std::vector<Vec2>& positions, std::optional<int> held) {
  return request(ReportKind::collected,
                 [&](RobotReportMsg& r, MessageArena& arena) {
                   fill_points(r.points, positions, arena);
                   r.held = held.value_or(-1);
                 })
      .has_value();
}

bool DdsRobotLink::report_unreachable(const std::vector<Vec2>& positions,
                                      const std::string& reason) {
  return request(ReportKind::unreachable,
                 [&](RobotReportMsg& r, MessageArena& arena) {
                   fill_points(r.points, positions, arena);
                   r.reason = arena.text(reason);
                 })
      .has_value();
}

bool DdsRobotLink::set_pose(const Pose2D& pose) {
  return request(ReportKind::pose,
                 [&pose](RobotReportMsg& r, MessageArena&) { r.pose = pose_2d_message(pose); })
      .has_value();
}

std::optional<nlohmann::json> DdsRobotLink::drive_simulated(std::uint64_t seq, double speed_mps,
                                                            double turn_rate_dps) {
  const std::optional<Reply> reply =
      request(ReportKind::drive, [&](RobotReportMsg& r, MessageArena&) {
        r.seq = seq;
        r.speed_mps = speed_mps;
        r.turn_rate_dps = turn_rate_dps;
      });
  if (!reply) return std::nullopt;
  return nlohmann::json{{"collected", reply->collected},
                        {"held", reply->held},
                        {"time_s", reply->time_s},
                        {"odometry", pose_json(reply->odometry)}};
}

LinkStatus DdsRobotLink::status() const {
  return inbox_.status();
}

}  // namespace ballsight::dds
