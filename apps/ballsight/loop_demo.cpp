#include "loop_demo.hpp"

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "ballsight/core/child_process.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/eval/loop_eval.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight::app {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

/// Faults of the last run, in simulated seconds.
constexpr int kFailedCamera = 1;
constexpr double kCameraFailsAtS = 8.0;
constexpr double kServiceRestartAtS = 16.0;
constexpr double kRobotRestartAtS = 24.0;
/// Wall seconds without a new tick before a run is given up (a process hung or died).
constexpr double kStallS = 30.0;
/// Wall seconds after which the service and the robot stop by themselves, should the demo that
/// started them be killed before it stops them.
constexpr int kProcessLimitS = 900;

/// Follows the court's record as the service writes it: the last complete tick.
class RecordFollower {
 public:
  explicit RecordFollower(fs::path file) : file_(std::move(file)) {}
  /// Reads what was appended; true when a new tick came.
  bool poll() {
    std::ifstream in(file_);
    if (!in) return false;
    in.seekg(offset_);
    bool fresh = false;
    std::string line;
    while (std::getline(in, line)) {
      if (in.eof()) break;  // no newline yet: the service is still writing it
      offset_ += static_cast<std::streamoff>(line.size() + 1);
      const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
      if (j.is_discarded() || j.value("kind", "") != "tick") continue;
      time_s_ = j.value("time_s", time_s_);
      balls_left_ = j.value("balls_left", balls_left_);
      fresh = true;
    }
    return fresh;
  }
  double time_s() const { return time_s_; }
  int balls_left() const { return balls_left_; }

 private:
  fs::path file_;
  std::streamoff offset_ = 0;
  double time_s_ = 0.0;
  int balls_left_ = -1;
};

struct Plan {
  eval::LoopSystem system;
  std::string name;
  bool faults = false;
};

class DemoRun {
 public:
  DemoRun(const LoopDemoOptions& options, const Plan& plan, const fs::path& dir)
      : options_(options), plan_(plan), dir_(dir), record_(dir / "truth.jsonl") {}

  LoopDemoRun run(const std::function<void(const std::string&)>& progress) {
    const auto started = Clock::now();
    fs::remove(dir_ / "truth.jsonl");
    start_service(false);
    start_robot();
    LoopDemoRun out;
    out.name = plan_.name;
    out.dir = dir_;
    bool service_restarted = false, robot_restarted = false;
    double next_report_s = 0.0;
    auto last_tick = Clock::now();
    // A fault: `process` killed, noted at the record's time, started again by `start`.
    const auto kill_and_restart = [&](ChildProcess& process, const std::string& what,
                                      const auto& start) {
      process.signal(SIGKILL);
      process.wait(5s);
      events_.push_back({record_.time_s(), what});
      start();
      last_tick = Clock::now();
    };
    while (true) {
      if (record_.poll()) last_tick = Clock::now();
      const double t = record_.time_s();
      if (record_.balls_left() == 0 || t >= options_.max_time_s) break;
      if (const std::optional<int> status = robot_->exit_status()) {
        require(
            *status == 0, robot_->log().string(),
            "the robot ended with status " + std::to_string(*status) + ": " + robot_->log_text());
        break;  // it saw no ball for a while: done as far as it knows
      }
      if (const std::optional<int> status = service_->exit_status()) {
        throw InputError(service_->log().string() + ": the service ended with status " +
                         std::to_string(*status) + ": " + service_->log_text());
      }
      require(std::chrono::duration<double>(Clock::now() - last_tick).count() < kStallS, plan_.name,
              "no tick for " + fixed(kStallS, 0) + " s; see " + dir_.string());
      if (plan_.faults && !service_restarted && t >= kServiceRestartAtS) {
        kill_and_restart(*service_, "service killed (SIGKILL) and started again with --resume",
                         [&] { start_service(true); });
        service_restarted = true;
      }
      if (plan_.faults && !robot_restarted && t >= kRobotRestartAtS) {
        kill_and_restart(*robot_, "robot killed (SIGKILL) and started again", [&] {
          collect_robot();
          start_robot();
        });
        robot_restarted = true;
      }
      if (t >= next_report_s && record_.balls_left() >= 0 && progress) {
        progress(plan_.name + ": simulated " + fixed(t, 1) + " s, " +
                 std::to_string(std::max(0, record_.balls_left())) + " balls left");
        next_report_s = t + 10.0;
      }
      std::this_thread::sleep_for(50ms);
    }
    robot_->stop();
    collect_robot();
    service_->stop();
    out.truth = read_loop_truth(dir_ / "truth.jsonl");
    // The simulated court's robot: the site file's defaults.
    out.score = score_loop(out.truth, collector_footprint(SiteRobot{}));
    out.seqs = seqs_;
    out.latency_ms = latency_ms_;
    out.gaps = gaps_;
    out.reconnects = reconnects_;
    out.unreachable = unreachable_;
    out.recordings = recordings_;
    out.events = events_;  // what the demo did first, then what the court recorded of it
    out.events.insert(out.events.end(), out.truth.events.begin(), out.truth.events.end());
    std::stable_sort(out.events.begin(), out.events.end(),
                     [](const TruthEvent& a, const TruthEvent& b) { return a.time_s < b.time_s; });
    out.wall_s = std::chrono::duration<double>(Clock::now() - started).count();
    return out;
  }

 private:
  void start_service(bool resume) {
    std::vector<std::string> args{"serve",        "--sim",
                                  "--seed",       std::to_string(options_.seed),
                                  "--balls",      std::to_string(options_.balls),
                                  "--listen",     "127.0.0.1:" + std::to_string(port_),
                                  "--token-file", (dir_ / "token").string(),
                                  "--planner",    std::string(planner_name(plan_.system.planner)),
                                  "--truth-out",  (dir_ / "truth.jsonl").string(),
                                  "--duration",   std::to_string(kProcessLimitS)};
    // The run in MCAP for Foxglove: every update, and the frames once a second of simulated
    // time (every 10th frame set), which keeps the recorder's JPEG encoding off the loop's CPU.
    recordings_.push_back(dir_ / ("run-" + std::to_string(services_ + 1) + ".mcap"));
    args.insert(args.end(), {"--record", recordings_.back().string(), "--record-every", "10"});
    if (plan_.system.report_pipeline) args.push_back("--report-pipeline");
    if (plan_.faults) {
      args.insert(args.end(), {"--sim-fail-camera",
                               std::to_string(kFailedCamera) + "@" + fixed(kCameraFailsAtS, 1)});
    }
    if (resume) args.push_back("--resume");
    const fs::path log = dir_ / ("serve-" + std::to_string(++services_) + ".log");
    service_.reset();
    service_ = std::make_unique<ChildProcess>(own_executable(), args, log);
    const std::optional<std::string> line = service_->wait_for_line("http://127.0.0.1:", 60s);
    require(line.has_value(), log.string(), "the service did not start: " + service_->log_text());
    const std::size_t at = line->find("127.0.0.1:") + 10;
    port_ = static_cast<int>(std::strtol(line->c_str() + at, nullptr, 10));
    require(port_ > 0, log.string(), "no port in '" + *line + "'");
  }

  void start_robot() {
    const fs::path summary = dir_ / ("robot-" + std::to_string(++robots_) + ".json");
    fs::remove(summary);
    robot_ = std::make_unique<ChildProcess>(
        own_executable(),
        std::vector<std::string>{"robot", "--server", "http://127.0.0.1:" + std::to_string(port_),
                                 "--token-file", (dir_ / "token").string(), "--done-after", "30",
                                 "--max-time", std::to_string(kProcessLimitS), "--summary",
                                 summary.string()},
        dir_ / ("robot-" + std::to_string(robots_) + ".log"));
  }

  /// What the robot process that ended wrote about itself (nothing when it was killed).
  void collect_robot() {
    const fs::path summary = dir_ / ("robot-" + std::to_string(robots_) + ".json");
    if (!fs::exists(summary)) return;
    const nlohmann::json j = nlohmann::json::parse(read_file(summary));
    const auto s = j.at("seqs").get<std::vector<std::uint64_t>>();
    const auto l = j.at("latency_ms").get<std::vector<double>>();
    seqs_.insert(seqs_.end(), s.begin(), s.end());
    latency_ms_.insert(latency_ms_.end(), l.begin(), l.end());
    gaps_ += j.at("gaps").get<std::uint64_t>();
    reconnects_ += j.at("reconnects").get<int>();
    unreachable_ += j.at("unreachable").get<int>();
  }

  const LoopDemoOptions& options_;
  Plan plan_;
  fs::path dir_;
  RecordFollower record_;
  std::vector<fs::path> recordings_;
  int port_ = 0;
  int services_ = 0, robots_ = 0;
  std::unique_ptr<ChildProcess> service_, robot_;
  std::vector<std::uint64_t> seqs_;
  std::vector<double> latency_ms_;
  std::uint64_t gaps_ = 0;
  int reconnects_ = 0;
  int unreachable_ = 0;
  std::vector<TruthEvent> events_;
};

}  // namespace

std::vector<LoopDemoRun> run_loop_demo(const LoopDemoOptions& options, const fs::path& out_dir,
                                       const std::function<void(const std::string&)>& progress) {
  options.validate();
  std::vector<Plan> plans;
  for (const eval::LoopSystem& s : eval::loop_systems()) plans.push_back({s, s.name, false});
  if (options.faults) plans.push_back({plans.back().system, "ballsight-faults", true});
  std::vector<LoopDemoRun> runs;
  for (const Plan& plan : plans) {
    const fs::path dir = out_dir / "loop" / plan.name;
    ensure_directory(dir);
    runs.push_back(DemoRun(options, plan, dir).run(progress));
    if (progress) {
      const LoopScore& s = runs.back().score;
      progress(plan.name + ": " + std::to_string(s.collected) + " of " + std::to_string(s.balls) +
               " balls in " + fixed(s.time_s, 1) + " s simulated, " + fixed(s.distance_m, 1) +
               " m; " + fixed(runs.back().wall_s, 1) + " s wall");
    }
  }
  return runs;
}

}  // namespace ballsight::app
