// `ballsight court run`: the site's cameras captured in parallel (one thread each), every frame
// set turned into a world model (balls, collection sites, robot pose, contributing cameras).

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/utc_clock.hpp"
#include "ballsight/pipeline/capture.hpp"
#include "ballsight/pipeline/court_pipeline.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/pipeline/world_model_json.hpp"
#include "ballsight/world/site.hpp"
#include "commands.hpp"

namespace ballsight::app {
namespace {

struct CourtRunArgs {
  std::string site;
  int frames = 0;  // 0: until every source has ended
  bool json = false;
  std::string method = "ballsight";
  double wait_s = 2.0;
};

void print_text(int index, const FrameSetResult& result, const std::vector<std::string>& names) {
  const WorldModel& world = result.world;
  std::string cameras;
  for (int c : world.cameras)
    cameras += (cameras.empty() ? "" : ",") + names[static_cast<size_t>(c)];
  std::printf("frame set %d: cameras %s; %zu balls in %zu collection sites; ", index,
              cameras.empty() ? "none" : cameras.c_str(), world.balls.size(), world.sites.size());
  if (world.robot) {
    std::printf("robot at (%.3f, %.3f) m heading %.1f deg\n", world.robot->pose.position.x(),
                world.robot->pose.position.y(), deg_from_rad(world.robot->pose.heading_rad));
  } else {
    std::printf("robot not found\n");
  }
  for (const CollectionSite& site : world.sites) {
    std::printf("  site (%.3f, %.3f) m:", site.center_m.x(), site.center_m.y());
    for (int b : site.balls) {
      const Vec2& p = world.balls[static_cast<size_t>(b)].position_m;
      std::printf(" (%.3f, %.3f)", p.x(), p.y());
    }
    std::printf("\n");
  }
}

void run_court(const CourtRunArgs& args) {
  require(args.frames >= 0, "--frames", "must be non-negative, got " + std::to_string(args.frames));
  require(args.method == "ballsight" || args.method == "seed", "--method",
          "must be 'ballsight' or 'seed', got '" + args.method + "'");
  require(args.wait_s > 0.0, "--wait", "must be positive");
  const Site site = read_site(args.site);
  std::vector<FieldCamera> cameras = site_field_cameras(site);
  std::unique_ptr<CourtPipeline> pipeline =
      args.method == "seed" ? make_seed_pipeline(cameras, seed_options_for_site(site))
                            : make_ballsight_pipeline(cameras, ballsight_options_for_site(site));
  std::vector<std::string> names;
  std::vector<std::unique_ptr<CameraCapture>> captures;
  std::vector<CameraCapture*> capture_list;
  const auto log = [](const std::string& message) {
    std::cerr << "ballsight: " << message << "\n";
  };
  for (const SiteCamera& camera : site.cameras) {
    names.push_back(camera.name);
    captures.push_back(std::make_unique<CameraCapture>(camera.name, site_frame_source(camera),
                                                       CaptureOptions{}, log));
    capture_list.push_back(captures.back().get());
  }
  for (auto& capture : captures) capture->start();
  const std::int64_t start_ns = utc_now_ns();
  const auto wait = std::chrono::milliseconds(static_cast<int>(1000.0 * args.wait_s));
  for (int index = 0; args.frames == 0 || index < args.frames; ++index) {
    const std::optional<FrameSet> set = next_frame_set(capture_list, wait);
    if (!set) break;
    const FrameSetResult result = pipeline->process(*set);
    for (size_t c = 0; c < set->cameras.size(); ++c) {
      if (!set->cameras[c].image.empty() && !result.camera_errors[c].empty())
        std::cerr << "ballsight: camera " << names[c] << ": " << result.camera_errors[c]
                  << "; frame not used\n";
    }
    if (args.json) {
      nlohmann::json j = world_model_json(result.world, names);
      j["frame_set"] = index;
      nlohmann::json frames_json = nlohmann::json::object();
      for (const CameraFrame& frame : set->cameras) {
        frames_json[names[frame.camera]] =
            frame.image.empty()
                ? nlohmann::json(nullptr)
                : nlohmann::json{
                      {"sequence", frame.sequence},
                      {"time_ms", 1e-6 * static_cast<double>(frame.capture_time_ns - start_ns)},
                      {"used", result.camera_errors[frame.camera].empty()}};
      }
      j["frames"] = frames_json;
      std::cout << j.dump() << "\n";
    } else {
      print_text(index, result, names);
    }
    std::cout.flush();
  }
  for (auto& capture : captures) capture->stop();
}

}  // namespace

void add_court_run_command(CLI::App& court) {
  auto args = std::make_shared<CourtRunArgs>();
  CLI::App* cmd = court.add_subcommand(
      "run",
      "Capture every camera of the site in parallel and print the world model of each frame set: "
      "balls, collection sites, robot pose, contributing cameras");
  cmd->add_option("--site", args->site, "Site file (docs/site-file.md)")->required();
  cmd->add_option("--frames", args->frames,
                  "Frame sets to process (default 0: until every source has ended)")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "One JSON object per frame set, one per line");
  cmd->add_option("--method", args->method, "ballsight or seed (the report's pipeline)")
      ->capture_default_str();
  cmd->add_option("--wait", args->wait_s,
                  "Seconds to wait for every camera's frame before a frame set goes without it")
      ->capture_default_str();
  cmd->callback([args] { run_court(*args); });
}

}  // namespace ballsight::app
