// `ballsight serve`: the navigation service (HTTP API v1, docs/robot-link.md) on the site's
// cameras (--site) or the simulated court (--sim): every frame set through the court pipeline,
// planned and published.

#include <atomic>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "ballsight/core/error.hpp"
#include "ballsight/service/replay_service.hpp"
#include "ballsight/service/simulated_service.hpp"
#include "ballsight/service/site_service.hpp"
#include "commands.hpp"
#include "http_service.hpp"
#include "option_parsing.hpp"
#include "record_options.hpp"
#include "stop_signals.hpp"

namespace ballsight::app {
namespace {

struct ServeArgs {
  bool sim = false;
  std::string site;
  std::string replay;
  ReplayServiceOptions replay_options;
  bool planner_given = false;
  HttpServiceArgs http;
  std::string planner = "ballsight";
  int balls = -1;                        // simulated court: tennis balls (-1: the scenario's)
  double duration_s = 0.0;               // 0: until SIGINT or SIGTERM
  std::vector<std::string> fail_camera;  // K@T or K@T-U, each
  std::string obstacles = "none";
  SimulatedServiceOptions service;
  RecordArgs record;
};

// K@T (camera K fails at simulated second T for good) or K@T-U (and returns at U).
CameraOutage parse_camera_outage(const std::string& text) {
  const std::string expected =
      "expected K@T or K@T-U (camera index @ simulated seconds), got '" + text + "'";
  const auto number = [&](const std::string& piece) {
    try {
      return parse_numbers(piece, 1, "--sim-fail-camera", expected)[0];
    } catch (const InputError&) {
      throw InputError("--sim-fail-camera: " + expected);
    }
  };
  const std::size_t at = text.find('@');
  require(at != std::string::npos, "--sim-fail-camera", expected);
  const double k = number(text.substr(0, at));
  require(k == std::floor(k), "--sim-fail-camera", "camera K must be an integer");
  const std::string when = text.substr(at + 1);
  const std::size_t dash = when.find('-');
  CameraOutage outage{static_cast<int>(k), number(when.substr(0, dash))};
  if (dash != std::string::npos) outage.until_s = number(when.substr(dash + 1));
  return outage;
}

void run_serve(const ServeArgs& args) {
  require(int{args.sim} + int{!args.site.empty()} + int{!args.replay.empty()} == 1, "--site",
          "give the site file (--site SITE.yml), --sim or --replay FILE.mcap: one of them");
  require(args.duration_s >= 0.0, "--duration", "must not be negative");
  validate(args.http);
  record_options(args.record);  // a bad option ends the command before anything starts
  const std::optional<PlannerKind> kind = planner_from_name(args.planner);
  require(kind && *kind != PlannerKind::exact, "--planner",
          "expected priority, nearest or ballsight, got '" + args.planner + "'");
  std::unique_ptr<CourtService> court;
  if (!args.replay.empty()) {
    ReplayServiceOptions options = args.replay_options;
    if (args.planner_given) options.planner = *kind;
    court = std::make_unique<ReplayCourtService>(args.replay, options);
  } else if (args.sim) {
    SimulatedServiceOptions options = args.service;
    options.planner.kind = *kind;
    if (args.balls >= 0) options.balls = args.balls;
    options.obstacles = sim::parse_obstacles(args.obstacles, "--obstacles");
    for (const std::string& text : args.fail_camera) {
      options.camera_outages.push_back(parse_camera_outage(text));
    }
    court = std::make_unique<SimulatedCourtService>(options);
  } else {
    SiteServiceOptions options;
    options.planner.kind = *kind;
    court = std::make_unique<SiteCourtService>(read_site(args.site), options);
  }
  CourtService& service = *court;

  const StopSignals signals;  // before any thread starts

  NavigationHub hub;
  const std::unique_ptr<RunRecorder> recorder = start_recording(args.record, hub, service);
  // A replay's calibration is the recording's: like the simulator's, never saved to files.
  const bool simulated = args.sim || !args.replay.empty();
  HttpService http(args.http, service, hub, {simulated, true, args.service.seed},
                   "ballsight serve");
  // A failure of the court service ends the command with its message (the server stops as it
  // goes out of scope).
  signals.run_until_stopped(args.duration_s,
                            [&](const std::atomic<bool>& stop) { service.run(hub, stop); });
  http.stop();
  finish_recording(recorder.get(), args.record, "ballsight serve");
  std::cout << "ballsight serve: stopped after " << service.health()["frame_sets"] << " updates"
            << std::endl;
}

}  // namespace

void add_serve_command(CLI::App& app) {
  auto args = std::make_shared<ServeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "serve",
      "The navigation service: the court pipeline on every frame set, a route for every world "
      "model, served over HTTP (API v1, docs/robot-link.md) to the robot and any client");
  cmd->add_option("--site", args->site, "Site file: serve its cameras");
  cmd->add_flag("--sim", args->sim, "Serve the built-in simulated court (rendered frames)");
  cmd->add_option("--replay", args->replay,
                  "Serve a recorded run (serve --record FILE.mcap) as if live: its frames "
                  "through this build's pipeline and planner, its robot reports");
  cmd->add_option("--speed", args->replay_options.speed,
                  "Replay: times the recorded pace (0: as fast as it goes)")
      ->capture_default_str();
  add_seed_option(*cmd, args->service.seed, "Simulated court: seed of the rig and the scene");
  add_http_service_options(*cmd, args->http);
  add_record_options(*cmd, args->record);
  cmd->add_option("--planner", args->planner,
                  "priority, nearest or ballsight (replay: instead of the recorded one)")
      ->capture_default_str();
  cmd->add_option("--rate", args->service.vision_hz,
                  "Simulated court: frame sets per second of simulated time")
      ->capture_default_str();
  cmd->add_option("--balls", args->balls, "Simulated court: tennis balls on it (default 20-60)");
  cmd->add_option("--capacity", args->service.capacity,
                  "Simulated court: balls the collector's basket holds (default 60)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--obstacles", args->obstacles,
                  "Simulated court: people and bags on it, a comma-separated list of person, "
                  "bag and walker (a person walking across and back), or none")
      ->capture_default_str();
  cmd->add_option("--cluster-share", args->service.cluster_share,
                  "Simulated court: of the balls, the share in clusters of 2-4 touching balls")
      ->capture_default_str();
  cmd->add_flag("--realtime", args->service.realtime,
                "Simulated court: simulated time at wall time (default: as fast as it goes)");
  cmd->add_flag("--report-pipeline", args->service.report_pipeline,
                "Simulated court: the report's court pipeline instead of ballsight's");
  cmd->add_option("--truth-out", args->service.truth_out,
                  "Simulated court: write every tick's truth here (JSON lines; "
                  "docs/robot-link.md)");
  cmd->add_flag("--resume", args->service.resume,
                "Simulated court: continue the court recorded in --truth-out (a restarted "
                "service; the robot where it stood, collected balls gone)");
  cmd->add_option("--sim-fail-camera", args->fail_camera,
                  "Simulated court: camera K (0-3) delivers no frames from simulated second T "
                  "on (K@T), or until second U (K@T-U); may be given several times");
  cmd->add_option("--duration", args->duration_s, "Stop after this many seconds (0: on a signal)")
      ->capture_default_str();
  cmd->callback([args, cmd] {
    args->planner_given = cmd->count("--planner") > 0;
    run_serve(*args);
  });
}

}  // namespace ballsight::app
