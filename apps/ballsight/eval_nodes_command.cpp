// `ballsight eval nodes`: the court on DDS as separate processes (four camera nodes and a court
// node) against the court in one process (`court-node --sim`), one after the other on this
// machine's loopback and on the same simulated court: the latency from a frame set's capture to
// a subscriber holding its world model (p50, p99), the messages and bytes of every topic, and
// each process's CPU (docs/scaling.md).

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <sstream>

#include "ballsight/core/child_process.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/dds/court_messages.hpp"
#include "ballsight/dds/detection_messages.hpp"
#include "ballsight/dds/topic_io.hpp"
#include "ballsight/eval/court_metrics.hpp"
#include "ballsight/service/simulated_court.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct EvalNodesArgs {
  std::uint64_t seed = 3;
  int balls = 30;
  double rate_hz = 10.0;
  double seconds = 20.0;  // measured, per configuration
  double warmup_s = 3.0;  // after the first world model, not measured
  int domain = -1;        // -1: a random one of 100-229
  std::string log_dir;    // "": a temporary folder, removed when the run succeeds
  bool json = false;
};

// A topic read as the bytes that crossed the wire.
struct WatchedTopic {
  std::string name;
  std::function<std::vector<std::vector<std::uint8_t>>()> take;
  dds_entity_t condition = 0;
  std::uint64_t messages = 0;
  std::uint64_t bytes = 0;
};

template <class Msg>
WatchedTopic watch(const dds::Participant& participant, const std::string& ns,
                   const std::string& name, dds::TopicQos qos = {}) {
  auto reader = std::make_shared<dds::Reader<Msg>>(participant, ns + "/" + name, qos);
  return {name, [reader] { return reader->take_serialized(); }, reader->condition()};
}

// CPU time a process has used so far (user + system), seconds: /proc/PID/stat fields 14 and 15.
double cpu_seconds(pid_t pid) {
  const std::string path = "/proc/" + std::to_string(pid) + "/stat";
  std::ifstream in(path);
  const std::string stat((std::istreambuf_iterator<char>(in)), {});
  const std::size_t name_end = stat.rfind(')');  // the command name may hold spaces
  require(name_end != std::string::npos, path, "unreadable: has the process ended?");
  std::istringstream fields(stat.substr(name_end + 1));
  std::string field;
  double ticks = 0.0;
  for (int k = 3; k <= 15 && fields >> field; ++k)
    if (k >= 14) ticks += std::stod(field);
  return ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
}

struct Node {
  std::string name;
  std::unique_ptr<ChildProcess> process;
  double cpu_start_s = 0.0;
};

struct RunReport {
  std::string name;
  std::vector<double> latency_ms;   // capture -> the world model received here
  std::vector<double> camera_ms;    // capture -> a camera's detections received here
  std::vector<double> court_ms;     // the set's last detections -> its world model, both here
  std::vector<double> pipeline_ms;  // the court node's own figures (diagnostics, once a second)
  std::vector<double> plan_ms;
  std::vector<WatchedTopic> topics;
  std::map<std::string, double> cpu_pct;  // per process, of one core
  double seconds = 0.0;
};

class NodesRun {
 public:
  /// Reads the topics of the court under `ns` (the participant's namespace is empty).
  NodesRun(const EvalNodesArgs& args, const dds::Participant& participant, int domain,
           std::string ns, const std::vector<std::string>& cameras)
      : args_(args),
        domain_(domain),
        ns_(std::move(ns)),
        health_(participant, ns_ + "/diagnostics"),
        waitset_(participant) {
    const dds::TopicQos latest{true, 1};
    topics_.push_back(watch<dds::BallArrayMsg>(participant, ns_, "ball_estimates", latest));
    topics_.push_back(watch<dds::PoseArrayMsg>(participant, ns_, "balls", latest));
    topics_.push_back(watch<dds::PathMsg>(participant, ns_, "route", latest));
    topics_.push_back(watch<dds::PoseStampedMsg>(participant, ns_, "robot_pose"));
    topics_.push_back(watch<dds::DiagnosticArrayMsg>(participant, ns_, "diagnostics"));
    for (const std::string& camera : cameras)
      topics_.push_back(
          watch<dds::CameraDetectionsMsg>(participant, ns_, dds::detections_topic(camera)));
    for (const WatchedTopic& topic : topics_) waitset_.attach(topic.condition);
  }

  void start(const std::string& name, std::vector<std::string> node_args, const fs::path& log) {
    std::vector<std::string> all = std::move(node_args);
    for (const std::string& option :
         {std::string("--sim"), std::string("--seed"), std::to_string(args_.seed),
          std::string("--balls"), std::to_string(args_.balls), std::string("--rate"),
          fixed(args_.rate_hz, 3), std::string("--loopback"), std::string("--domain"),
          std::to_string(domain_), std::string("--namespace"), ns_, std::string("--duration"),
          fixed(limit_s(), 0)})
      all.push_back(option);
    camera_nodes_ = camera_nodes_ || all.front() == "camera-node";
    nodes_.push_back({name, std::make_unique<ChildProcess>(own_executable(), all, log), 0.0});
  }

  RunReport measure(const std::string& name) {
    RunReport report{name, {}, {}, {}, {}, {}, {}, {}, args_.seconds};
    // Until the first world model, then the warm-up: received, not counted.
    const auto first_by = Clock::now() + std::chrono::seconds(60);
    while (!receive(nullptr)) {
      for (const Node& node : nodes_)
        require(!node.process->exit_status(), node.process->log().string(),
                node.name + " ended before the court published (its log)");
      require(Clock::now() < first_by, nodes_.front().process->log().string(),
              "no world model within 60 s (the court node's log)");
    }
    const auto warm_until = Clock::now() + std::chrono::duration<double>(args_.warmup_s);
    while (Clock::now() < warm_until) receive(nullptr);
    for (WatchedTopic& topic : topics_) topic.messages = topic.bytes = 0;
    for (Node& node : nodes_) node.cpu_start_s = cpu_seconds(node.process->pid());
    const auto until = Clock::now() + std::chrono::duration<double>(args_.seconds);
    while (Clock::now() < until) receive(&report);
    for (const Node& node : nodes_)
      report.cpu_pct[node.name] =
          100.0 * (cpu_seconds(node.process->pid()) - node.cpu_start_s) / args_.seconds;
    report.topics = topics_;
    return report;
  }

 private:
  // How long a node may run: the whole run and a margin, so that no node outlives an eval that
  // was killed (its destructors stop them otherwise).
  double limit_s() const { return 60.0 + args_.warmup_s + args_.seconds + 60.0; }

  // Takes what arrived within 100 ms; whether a world model did. Figures go into `report`.
  bool receive(RunReport* report) {
    waitset_.wait(std::chrono::milliseconds(100));
    const std::int64_t now_ns = utc_now_ns();
    const auto ms = [](std::int64_t ns) { return static_cast<double>(ns) * 1e-6; };
    bool world = false;
    for (WatchedTopic& topic : topics_) {
      const bool detections = topic.name.rfind("cameras/", 0) == 0;
      for (const std::vector<std::uint8_t>& cdr : topic.take()) {
        ++topic.messages;
        topic.bytes += cdr.size();
        if (!detections && topic.name != "ball_estimates") continue;
        const std::int64_t stamp = dds::serialized_stamp_ns(cdr);
        if (detections) {
          last_detections_ns_[stamp] = now_ns;
          if (report && camera_nodes_) report->camera_ms.push_back(ms(now_ns - stamp));
          continue;
        }
        world = true;
        if (!report) continue;
        report->latency_ms.push_back(ms(now_ns - stamp));
        const auto it = last_detections_ns_.find(stamp);
        if (camera_nodes_ && it != last_detections_ns_.end())
          report->court_ms.push_back(ms(now_ns - it->second));
        last_detections_ns_.erase(last_detections_ns_.begin(),
                                  last_detections_ns_.upper_bound(stamp));
      }
    }
    health_.take([&](const dds::DiagnosticArrayMsg& m) {
      if (!report || m.status._length == 0) return;
      const dds::DiagnosticStatusMsg& pipeline = m.status._buffer[m.status._length - 1];
      for (std::uint32_t k = 0; k < pipeline.values._length; ++k) {
        const std::string key = pipeline.values._buffer[k].key;
        if (key == "pipeline_ms" || key == "plan_ms")
          (key == "plan_ms" ? report->plan_ms : report->pipeline_ms)
              .push_back(std::stod(pipeline.values._buffer[k].value));
      }
    });
    return world;
  }

  const EvalNodesArgs& args_;
  int domain_;
  std::string ns_;
  dds::Reader<dds::DiagnosticArrayMsg> health_;  // the court node's pipeline and plan times
  std::vector<WatchedTopic> topics_;
  dds::WaitSet waitset_;
  bool camera_nodes_ = false;  // the detections come from camera nodes, before the world model
  std::vector<Node> nodes_;    // stopped as this run ends
  std::map<std::int64_t, std::int64_t> last_detections_ns_;  // capture -> received (UTC)
};

struct Percentiles {
  double p50 = 0.0;
  double p99 = 0.0;
  double max = 0.0;
  std::size_t count = 0;
};

Percentiles percentiles(const std::vector<double>& values) {
  if (values.empty()) return {};
  return {quantile(values, 0.5), quantile(values, 0.99), quantile(values, 1.0), values.size()};
}

nlohmann::json percentiles_json(const Percentiles& p) {
  return {{"p50", p.p50}, {"p99", p.p99}, {"max", p.max}, {"count", p.count}};
}

nlohmann::json run_json(const RunReport& run) {
  nlohmann::json topics = nlohmann::json::object();
  for (const WatchedTopic& topic : run.topics) {
    const double messages = static_cast<double>(topic.messages);
    topics[topic.name] = {
        {"messages_per_s", messages / run.seconds},
        {"bytes_per_message", topic.messages ? static_cast<double>(topic.bytes) / messages : 0.0},
        {"kbytes_per_s", static_cast<double>(topic.bytes) / run.seconds / 1000.0}};
  }
  nlohmann::json out = {{"latency_ms", percentiles_json(percentiles(run.latency_ms))},
                        {"topics", topics},
                        {"cpu_pct", run.cpu_pct},
                        {"court_node_pipeline_ms", percentiles_json(percentiles(run.pipeline_ms))},
                        {"court_node_plan_ms", percentiles_json(percentiles(run.plan_ms))}};
  if (!run.camera_ms.empty()) {
    out["camera_ms"] = percentiles_json(percentiles(run.camera_ms));
    out["court_ms"] = percentiles_json(percentiles(run.court_ms));
  }
  return out;
}

std::string percentiles_line(const std::string& what, const std::vector<double>& values) {
  const Percentiles p = percentiles(values);
  std::string line = "  " + what;
  line.resize(52, ' ');
  return line + fixed(p.p50, 2) + "  " + fixed(p.p99, 2) + "  " + fixed(p.max, 2) + "  (" +
         std::to_string(p.count) + ")\n";
}

std::string run_text(const RunReport& run) {
  std::string text =
      run.name + "\n" + percentiles_line("capture -> world model here", run.latency_ms);
  if (!run.camera_ms.empty()) {
    text += percentiles_line("capture -> a camera's detections here", run.camera_ms);
    text += percentiles_line("last detections -> world model here", run.court_ms);
  }
  text += percentiles_line("the court node's pipeline, once a second", run.pipeline_ms);
  text += percentiles_line("the court node's planning, once a second", run.plan_ms);
  for (const WatchedTopic& topic : run.topics) {
    if (topic.messages == 0) continue;
    std::string line = "  /" + topic.name;
    line.resize(40, ' ');
    const double messages = static_cast<double>(topic.messages);
    text += line + fixed(messages / run.seconds, 1) + " msg/s  " +
            fixed(static_cast<double>(topic.bytes) / messages, 0) + " B/msg  " +
            fixed(static_cast<double>(topic.bytes) / run.seconds / 1000.0, 1) + " kB/s\n";
  }
  for (const auto& [process, pct] : run.cpu_pct)
    text += "  CPU " + process + ": " + fixed(pct, 1) + " % of a core\n";
  return text;
}

void run_eval_nodes(const EvalNodesArgs& args) {
  require(args.seconds > 0.0 && args.seconds <= 3600.0, "--seconds", "must be in (0, 3600]");
  require(args.warmup_s >= 0.0 && args.warmup_s <= 600.0, "--warmup", "must be in [0, 600]");
  require(args.rate_hz > 0.0 && args.rate_hz <= 30.0, "--rate", "must be in (0, 30] Hz");
  require(args.balls >= 0, "--balls", "must not be negative");
  dds::DomainOptions domain;
  domain.loopback = true;
  domain.domain =
      args.domain >= 0 ? args.domain : 100 + static_cast<int>(std::random_device()() % 130);
  domain.validate();
  const bool temporary = args.log_dir.empty();
  const fs::path logs = temporary
                            ? fs::temp_directory_path() / ("ballsight-eval-nodes-" + random_hex(8))
                            : fs::path(args.log_dir);
  fs::create_directories(logs);
  const std::vector<std::string> cameras = [&] {
    SimulatedCourtOptions options;
    options.seed = args.seed;
    options.balls = args.balls;
    const SimulatedCourt court(options);
    std::vector<std::string> names;
    for (const SiteCamera& camera : court.site().cameras) names.push_back(camera.name);
    return names;
  }();
  const dds::Participant participant(domain);
  const std::string ns = "eval_" + random_hex(8);

  std::vector<RunReport> runs;
  {
    NodesRun run(args, participant, *domain.domain, ns + "/one_process", cameras);
    run.start("court-node --sim", {"court-node"}, logs / "one-process-court.log");
    runs.push_back(
        run.measure("one process: court-node --sim (cameras rendered and detected in it)"));
  }
  {
    NodesRun run(args, participant, *domain.domain, ns + "/camera_nodes", cameras);
    run.start("court-node --camera-nodes", {"court-node", "--camera-nodes"},
              logs / "nodes-court.log");
    for (std::size_t k = 0; k < cameras.size(); ++k)
      run.start("camera-node " + std::to_string(k), {"camera-node", "--camera", std::to_string(k)},
                logs / ("nodes-camera" + std::to_string(k) + ".log"));
    runs.push_back(run.measure("camera nodes: four camera-node processes and a court-node"));
  }
  if (temporary) fs::remove_all(logs);

  const Percentiles one = percentiles(runs[0].latency_ms);
  const Percentiles nodes = percentiles(runs[1].latency_ms);
  if (args.json) {
    const nlohmann::json out = {
        {"seed", args.seed},
        {"balls", args.balls},
        {"rate_hz", args.rate_hz},
        {"seconds", args.seconds},
        {"domain", *domain.domain},
        {"one_process", run_json(runs[0])},
        {"camera_nodes", run_json(runs[1])},
        {"added_ms", {{"p50", nodes.p50 - one.p50}, {"p99", nodes.p99 - one.p99}}}};
    std::cout << out.dump(2) << "\n";
    return;
  }
  std::cout << "ballsight eval nodes: seed " << args.seed << ", " << args.balls << " balls, "
            << fixed(args.rate_hz, 1) << " Hz, " << fixed(args.seconds, 0)
            << " s measured per configuration, DDS domain " << *domain.domain
            << " on loopback\n  latency (ms)                                      p50   p99   max  "
               "(sets)\n";
  for (const RunReport& run : runs) std::cout << run_text(run);
  std::cout << "added by the camera nodes: p50 " << fixed(nodes.p50 - one.p50, 2) << " ms, p99 "
            << fixed(nodes.p99 - one.p99, 2) << " ms\n";
}

}  // namespace

void add_eval_nodes_command(CLI::App& eval) {
  auto args = std::make_shared<EvalNodesArgs>();
  CLI::App* cmd = eval.add_subcommand(
      "nodes",
      "The court on DDS against the court in one process, on this machine's loopback: latency "
      "from capture to a subscriber's world model (p50, p99), messages and bytes per topic, CPU "
      "per process (docs/scaling.md)");
  add_seed_option(*cmd, args->seed, "Simulated court: seed of the rig and the scene");
  cmd->add_option("--balls", args->balls, "Simulated court: tennis balls on it")
      ->capture_default_str();
  cmd->add_option("--rate", args->rate_hz, "Frame sets per second")->capture_default_str();
  cmd->add_option("--seconds", args->seconds, "Measured per configuration")->capture_default_str();
  cmd->add_option("--warmup", args->warmup_s, "Seconds after the first world model, not measured")
      ->capture_default_str();
  cmd->add_option("--domain", args->domain, "DDS domain id (default: a random one of 100-229)");
  cmd->add_option("--log-dir", args->log_dir,
                  "Keep the nodes' logs here (default: a temporary folder, removed after)");
  cmd->add_flag("--json", args->json,
                "JSON: {\"one_process\": {\"latency_ms\", \"topics\", \"cpu_pct\"}, "
                "\"camera_nodes\": {... \"camera_ms\", \"court_ms\"}, \"added_ms\"}");
  cmd->callback([args] { run_eval_nodes(*args); });
}

}  // namespace ballsight::app
