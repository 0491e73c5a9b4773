// `ballsight serve`: the navigation service (HTTP API v1, docs/robot-link.md) on the site's
// cameras (--site) or the simulated court (--sim): every frame set through the court pipeline,
// planned and published.

#include <atomic>
#include <chrono>
#include <iostream>
#include <memory>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/eval/simulated_service.hpp"
#include "ballsight/net/court_calibration_api.hpp"
#include "ballsight/net/http_server.hpp"
#include "ballsight/net/omni_calibration_api.hpp"
#include "ballsight/net/site_service.hpp"
#include "ballsight/sim/omni_dataset.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"
#include "stop_signals.hpp"

namespace ballsight::app {
namespace {

struct ServeArgs {
  bool sim = false;
  std::string site;
  std::string listen = "127.0.0.1:8080";
  std::string token_file = "ballsight-token";
  std::string web = BALLSIGHT_WEB_DIR;                    // "": no pages
  std::string node_modules = BALLSIGHT_NODE_MODULES_DIR;  // the pages' libraries (npm)
  std::string planner = "ballsight";
  bool open_reads = false;
  int balls = -1;           // simulated court: tennis balls (-1: the scenario's)
  double duration_s = 0.0;  // 0: until SIGINT or SIGTERM
  std::string fail_camera;  // K@T
  std::string omni_frames;  // the omni calibration page's folder of images
  SimulatedServiceOptions service;
};

void run_serve(const ServeArgs& args) {
  require(args.sim != !args.site.empty(), "--site",
          "give the site file (--site SITE.yml) or --sim, not both");
  require(args.duration_s >= 0.0, "--duration", "must not be negative");
  const std::size_t colon = args.listen.rfind(':');
  require(colon != std::string::npos, "--listen", "expected HOST:PORT, got '" + args.listen + "'");
  const std::vector<double> port =
      parse_numbers(args.listen.substr(colon + 1), 1, "--listen", "HOST:PORT");
  require(port[0] >= 0 && port[0] <= 65535 && port[0] == std::floor(port[0]), "--listen",
          "port must be an integer in [0, 65535]");
  const std::optional<PlannerKind> kind = planner_from_name(args.planner);
  require(kind && *kind != PlannerKind::exact, "--planner",
          "expected priority, nearest or ballsight, got '" + args.planner + "'");
  std::unique_ptr<CourtService> court;
  if (args.sim) {
    SimulatedServiceOptions options = args.service;
    options.planner.kind = *kind;
    if (args.balls >= 0) options.balls = args.balls;
    if (!args.fail_camera.empty()) {
      const std::size_t at = args.fail_camera.find('@');
      require(at != std::string::npos, "--sim-fail-camera",
              "expected K@T (camera index @ simulated seconds), got '" + args.fail_camera + "'");
      const std::vector<double> k =
          parse_numbers(args.fail_camera.substr(0, at), 1, "--sim-fail-camera", "K@T");
      const std::vector<double> t =
          parse_numbers(args.fail_camera.substr(at + 1), 1, "--sim-fail-camera", "K@T");
      require(k[0] == std::floor(k[0]), "--sim-fail-camera", "camera K must be an integer");
      options.fail_camera = CameraFailure{static_cast<int>(k[0]), t[0]};
    }
    court = std::make_unique<SimulatedCourtService>(options);
  } else {
    SiteServiceOptions options;
    options.planner.kind = *kind;
    court = std::make_unique<SiteCourtService>(read_site(args.site), options);
  }
  CourtService& service = *court;

  const StopSignals signals;  // before any thread starts

  HttpServerOptions server_options;
  server_options.address = args.listen.substr(0, colon);
  server_options.port = static_cast<unsigned short>(port[0]);
  server_options.token = read_or_create_token(args.token_file);
  server_options.open_reads = args.open_reads;
  server_options.web_root = args.web;
  server_options.node_modules = args.node_modules;
  server_options.body_limit = 16u << 20;  // the calibration pages upload images
  OmniCalibrationOptions omni_options;
  omni_options.frames_dir = args.omni_frames;
  if (args.sim) {
    omni_options.simulated_frame = [seed = args.service.seed] {
      sim::OmniScenarioOptions scenario;
      scenario.seed = seed;
      return sim::render_calibration_frame(scenario);
    };
  }
  OmniCalibrationApi omni(omni_options);
  CourtCalibrationApiOptions court_options;
  court_options.site = service.site();
  for (const FieldCamera& camera : service.cameras())
    court_options.intrinsics.push_back(camera.camera.params());
  court_options.latest_frame = [&service](std::size_t camera) -> std::optional<cv::Mat> {
    if (std::optional<CameraView> view = service.camera_view(camera)) return view->frame;
    return std::nullopt;
  };
  court_options.write_files = !args.sim;  // the simulated court's calibration is the simulator's
  if (!args.sim) court_options.on_saved = [&service] { service.reload_calibration(); };
  CourtCalibrationApi court_calibration(std::move(court_options));
  NavigationHub hub;
  const auto started = std::chrono::steady_clock::now();
  std::atomic<HttpServer*> server{nullptr};  // health is asked on the server's thread
  ApiContext context = service.api_context(hub);
  context.omni = &omni;
  context.court_calibration = &court_calibration;
  context.health = [&] {
    nlohmann::json h = service.health();
    h["uptime_s"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const HttpServer* serving = server;
    h["connections"] = serving ? serving->connections() : 0;
    h["clients"] = serving ? clients_json(serving->clients()) : nlohmann::json::array();
    h["acknowledged_seq"] = hub.acknowledged();
    h["service_id"] = hub.service_id();
    return h;
  };
  HttpServer http(server_options, context);
  server = &http;
  std::cout << "ballsight serve: http://" << server_options.address << ":" << http.port()
            << "/api/v1/ (token in " << args.token_file << ")" << std::endl;
  if (!args.web.empty())
    std::cout << "ballsight serve: dashboard at http://" << server_options.address << ":"
              << http.port() << "/" << std::endl;
  // A failure of the court service ends the command with its message (the server stops as it
  // goes out of scope).
  signals.run_until_stopped(args.duration_s,
                            [&](const std::atomic<bool>& stop) { service.run(hub, stop); });
  http.stop();
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
  add_seed_option(*cmd, args->service.seed, "Simulated court: seed of the rig and the scene");
  cmd->add_option("--listen", args->listen, "HOST:PORT to listen on (port 0: a free one)")
      ->capture_default_str();
  cmd->add_option("--web", args->web,
                  "Folder of the web pages served at / (the dashboard) and /web/; \"\": none")
      ->capture_default_str();
  cmd->add_option("--node-modules", args->node_modules,
                  "npm folder of the pages' libraries (scripts/setup installs them)")
      ->capture_default_str();
  cmd->add_option("--omni-frames", args->omni_frames,
                  "Folder of omni images the calibration page may open by name")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--token-file", args->token_file,
                  "Bearer token for writes; created (mode 0600) when missing")
      ->capture_default_str();
  cmd->add_flag("--open-reads", args->open_reads, "Reads from other hosts need no token");
  cmd->add_option("--planner", args->planner, "priority, nearest or ballsight")
      ->capture_default_str();
  cmd->add_option("--rate", args->service.vision_hz,
                  "Simulated court: frame sets per second of simulated time")
      ->capture_default_str();
  cmd->add_option("--balls", args->balls, "Simulated court: tennis balls on it (default 20-60)");
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
                  "on (K@T)");
  cmd->add_option("--duration", args->duration_s, "Stop after this many seconds (0: on a signal)")
      ->capture_default_str();
  cmd->callback([args] { run_serve(*args); });
}

}  // namespace ballsight::app
