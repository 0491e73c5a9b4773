#include "http_service.hpp"

#include <cmath>
#include <iostream>

#include "ballsight/core/error.hpp"
#include "ballsight/net/bearer_token.hpp"
#include "ballsight/sim/omni_dataset.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {
namespace {

struct ListenAddress {
  std::string host;
  unsigned short port = 0;
};

ListenAddress listen_address(const std::string& listen) {
  const std::size_t colon = listen.rfind(':');
  require(colon != std::string::npos, "--listen", "expected HOST:PORT, got '" + listen + "'");
  const std::vector<double> port =
      parse_numbers(listen.substr(colon + 1), 1, "--listen", "HOST:PORT");
  require(port[0] >= 0 && port[0] <= 65535 && port[0] == std::floor(port[0]), "--listen",
          "port must be an integer in [0, 65535]");
  return {listen.substr(0, colon), static_cast<unsigned short>(port[0])};
}

OmniCalibrationOptions omni_options(const HttpServiceArgs& args, const ServedCourt& court) {
  OmniCalibrationOptions options;
  options.frames_dir = args.omni_frames;
  if (court.simulated) {
    options.simulated_frame = [seed = court.seed] {
      sim::OmniScenarioOptions scenario;
      scenario.seed = seed;
      return sim::render_calibration_frame(scenario);
    };
  }
  return options;
}

CourtCalibrationApiOptions court_calibration_options(CourtService& service,
                                                     const ServedCourt& court) {
  CourtCalibrationApiOptions options;
  options.site = service.site();
  for (const FieldCamera& camera : service.cameras())
    options.intrinsics.push_back(camera.camera.params());
  options.latest_frame = [&service](std::size_t camera) -> std::optional<cv::Mat> {
    if (std::optional<CameraView> view = service.camera_view(camera)) return view->frame;
    return std::nullopt;
  };
  // The simulated court's calibration is the simulator's; a court fed by camera nodes would not
  // apply one (its camera nodes place the detections): neither saves.
  options.write_files = !court.simulated && court.frames;
  if (options.write_files) options.on_saved = [&service] { service.reload_calibration(); };
  return options;
}

}  // namespace

std::vector<CLI::Option*> add_http_service_options(CLI::App& command, HttpServiceArgs& args) {
  std::vector<CLI::Option*> options;
  options.push_back(
      command.add_option("--listen", args.listen, "HOST:PORT to listen on (port 0: a free one)")
          ->capture_default_str());
  options.push_back(
      command
          .add_option("--web", args.web,
                      "Folder of the web pages served at / (the dashboard) and /web/; \"\": none")
          ->capture_default_str());
  options.push_back(
      command
          .add_option("--node-modules", args.node_modules,
                      "npm folder of the pages' libraries (scripts/setup installs them)")
          ->capture_default_str());
  options.push_back(command
                        .add_option("--omni-frames", args.omni_frames,
                                    "Folder of omni images the calibration page may open by name")
                        ->check(CLI::ExistingDirectory));
  options.push_back(command
                        .add_option("--token-file", args.token_file,
                                    "Bearer token for writes; created (mode 0600) when missing")
                        ->capture_default_str());
  options.push_back(
      command.add_flag("--open-reads", args.open_reads, "Reads from other hosts need no token"));
  return options;
}

void validate(const HttpServiceArgs& args) {
  listen_address(args.listen);
}

HttpService::HttpService(const HttpServiceArgs& args, CourtService& service, NavigationHub& hub,
                         const ServedCourt& court, const std::string& program)
    : omni_(omni_options(args, court)),
      court_calibration_(court_calibration_options(service, court)),
      started_(std::chrono::steady_clock::now()),
      context_(api_context(service, hub)) {
  const ListenAddress address = listen_address(args.listen);
  HttpServerOptions options;
  options.address = address.host;
  options.port = address.port;
  options.token = read_or_create_token(args.token_file);
  options.open_reads = args.open_reads;
  options.web_root = args.web;
  options.node_modules = args.node_modules;
  options.body_limit = 16u << 20;  // the calibration pages upload images
  context_.health = [this, &service, &hub] {
    nlohmann::json h = service.health();
    h["uptime_s"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    const HttpServer* serving = server_;
    h["connections"] = serving ? serving->connections() : 0;
    h["clients"] = serving ? clients_json(serving->clients()) : nlohmann::json::array();
    h["acknowledged_seq"] = hub.acknowledged();
    h["service_id"] = hub.service_id();
    return h;
  };
  ApiRoutes routes = api_v1_routes(context_);
  omni_.register_routes(routes);
  court_calibration_.register_routes(routes);
  http_ = std::make_unique<HttpServer>(options, std::move(routes));
  server_ = http_.get();
  std::cout << program << ": http://" << options.address << ":" << http_->port()
            << "/api/v1/ (token in " << args.token_file << ")" << std::endl;
  if (!args.web.empty())
    std::cout << program << ": dashboard at http://" << options.address << ":" << http_->port()
              << "/" << std::endl;
}

}  // namespace ballsight::app
