#pragma once
// The navigation service's HTTP side (API v1, docs/robot-link.md, the dashboard and the
// calibration pages) on any court service: `serve` runs it, and `court-node --serve` runs it
// inside a court node beside its DDS topics.

#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ballsight/net/api.hpp"
#include "ballsight/net/calibration/court_calibration_api.hpp"
#include "ballsight/net/calibration/omni_calibration_api.hpp"
#include "ballsight/net/http_server.hpp"
#include "ballsight/net/service_api.hpp"
#include "ballsight/service/court_service.hpp"

namespace ballsight::app {

struct HttpServiceArgs {
  std::string listen = "127.0.0.1:8080";
  std::string token_file = "ballsight-token";
  std::string web = BALLSIGHT_WEB_DIR;                    // "": no pages
  std::string node_modules = BALLSIGHT_NODE_MODULES_DIR;  // the pages' libraries (npm)
  bool open_reads = false;
  std::string omni_frames;  // the omni calibration page's folder of images
};

/// --listen, --web, --node-modules, --omni-frames, --token-file, --open-reads; returns them.
std::vector<CLI::Option*> add_http_service_options(CLI::App& command, HttpServiceArgs& args);
/// Throws InputError naming the option at fault (--listen not HOST:PORT, ...).
void validate(const HttpServiceArgs& args);

/// What the court behind the service is, for the calibration pages.
struct ServedCourt {
  bool simulated = false;  // the simulated court: calibration is the simulator's, not saved
  bool frames = true;      // its frames pass through this process (not a court fed by camera
                           // nodes): camera views, and a calibration from stills that applies
  std::uint64_t seed = 1;  // simulated: the seed of the omni calibration page's frame
};

/// The HTTP API on `service` and `hub` (both outlive this), serving from construction until
/// stop() or destruction. Prints where it listens.
class HttpService {
 public:
  HttpService(const HttpServiceArgs& args, CourtService& service, NavigationHub& hub,
              const ServedCourt& court, const std::string& program);
  HttpService(const HttpService&) = delete;
  HttpService& operator=(const HttpService&) = delete;

  unsigned short port() const { return http_->port(); }
  void stop() { http_->stop(); }

 private:
  OmniCalibrationApi omni_;
  CourtCalibrationApi court_calibration_;
  std::chrono::steady_clock::time_point started_;
  ApiContext context_;
  std::atomic<HttpServer*> server_{nullptr};  // health is asked on the server's thread
  std::unique_ptr<HttpServer> http_;          // last: stops serving before the APIs it serves go
};

}  // namespace ballsight::app
