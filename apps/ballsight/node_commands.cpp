// `ballsight camera-node` and `ballsight court-node`: the court pipeline spread over processes
// on DDS (docs/ros2.md). A camera node detects one camera's frames and writes its detections; a
// court node fuses its camera nodes' detections (or, with --sim alone, renders the simulated
// court's cameras itself), plans, and writes the court's ROS 2 topics; with --serve it also
// serves the navigation service's HTTP API.

#include <atomic>
#include <iostream>
#include <memory>
#include <optional>

#include "ballsight/core/error.hpp"
#include "ballsight/dds/camera_node.hpp"
#include "ballsight/dds/court_node.hpp"
#include "ballsight/dds/court_topics.hpp"
#include "ballsight/dds/robot_reports.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/service/simulated_court.hpp"
#include "ballsight/service/simulated_service.hpp"
#include "commands.hpp"
#include "http_service.hpp"
#include "node_options.hpp"
#include "option_parsing.hpp"
#include "record_options.hpp"
#include "stop_signals.hpp"

namespace ballsight::app {
namespace {

struct NodeArgs : DdsArgs {
  std::string site;
  bool sim = false;
  SimulatedServiceOptions service;  // the simulated court: seed, balls, rate
  int balls = -1;
  std::string camera;         // camera-node
  bool camera_nodes = false;  // court-node --sim: fuse camera nodes' detections
  bool serve = false;         // court-node: the navigation service's HTTP API inside
  HttpServiceArgs http;
  RecordArgs record;  // court-node: --record

  SimulatedServiceOptions service_options() const {
    SimulatedServiceOptions options = service;
    if (balls >= 0) options.balls = balls;
    return options;
  }
  SimulatedCourtOptions court_options() const {
    const SimulatedServiceOptions options = service_options();
    return {options.seed,   options.balls,     options.cluster_share,
            options.layout, options.obstacles, options.arrange};
  }
};

void add_node_options(CLI::App& cmd, NodeArgs& args) {
  cmd.add_option("--site", args.site, "Site file: its cameras and their calibration");
  cmd.add_flag("--sim", args.sim, "The built-in simulated court (the scenes of serve --sim)");
  add_seed_option(cmd, args.service.seed, "Simulated court: seed of the rig and the scene");
  cmd.add_option("--balls", args.balls, "Simulated court: tennis balls on it (default 20-60)");
  cmd.add_option("--rate", args.service.vision_hz, "Simulated court: frames per second")
      ->capture_default_str();
  add_dds_options(cmd, args, "court's topics");
}

void validate_node(const NodeArgs& args) {
  require(args.sim != !args.site.empty(), "--site",
          "give the site file (--site SITE.yml) or --sim, not both");
  validate(static_cast<const DdsArgs&>(args));
  args.service.validate();
}

void run_camera_node(const NodeArgs& args) {
  validate_node(args);
  const StopSignals signals;  // before DDS starts its threads
  require(!args.camera.empty(), "--camera", "name the camera (--camera NAME)");
  const std::unique_ptr<SimulatedCourt> court =
      args.sim ? std::make_unique<SimulatedCourt>(args.court_options()) : nullptr;
  const Site site = court ? court->site() : read_site(args.site);
  const std::size_t index = dds::site_camera_index(site, args.camera);
  const dds::Participant participant(args.domain_options());
  dds::CameraNode node(participant, site, court ? court->cameras() : site_field_cameras(site),
                       index);
  std::cout << "ballsight camera-node: " << node.camera_name() << " -> " << topic_prefix(args)
            << dds::detections_topic(node.camera_name()) << " (DDS domain "
            << dds::domain_id(args.domain_options()) << ")" << std::endl;
  std::uint64_t frames = 0;
  const FramePublisher publish = [&](const cv::Mat& frame, std::uint64_t k, std::int64_t at_ns) {
    node.publish(frame, k, at_ns);
    ++frames;
  };
  signals.run_until_stopped(args.duration_s, [&](const std::atomic<bool>& stop) {
    if (court) {
      publish_ticks(
          args.service.vision_hz, stop,
          [&](std::uint64_t tick) { return court->render(index, court->scene(), tick); }, publish);
    } else {
      publish_captured("ballsight camera-node", args.camera, site_frame_source(site.cameras[index]),
                       stop, publish);
    }
  });
  std::cout << "ballsight camera-node: stopped after " << frames << " frames" << std::endl;
}

void run_court_node(const NodeArgs& args) {
  validate_node(args);
  const StopSignals signals;  // before DDS starts its threads
  require(!args.camera_nodes || args.sim, "--camera-nodes",
          "is for --sim (a site's court node always fuses its camera nodes)");
  if (args.serve) validate(args.http);
  record_options(args.record);  // a bad option ends the command before anything starts
  const dds::Participant participant(args.domain_options());
  std::unique_ptr<CourtService> service;
  if (args.sim && !args.camera_nodes) {
    service = std::make_unique<SimulatedCourtService>(args.service_options());
  } else {
    dds::CourtNodeOptions options;
    if (args.sim) {
      const SimulatedCourt court(args.court_options());
      service = std::make_unique<dds::CameraFedCourtService>(participant, court.site(),
                                                             court.cameras(), options);
    } else {
      Site site = read_site(args.site);
      std::vector<FieldCamera> cameras = site_field_cameras(site);
      service = std::make_unique<dds::CameraFedCourtService>(participant, std::move(site),
                                                             std::move(cameras), options);
    }
  }
  NavigationHub hub;
  const std::unique_ptr<RunRecorder> recorder = start_recording(args.record, hub, *service);
  // The HTTP service first: a bad --listen ends the command before the topics are up. A court fed
  // by camera nodes holds no frames: no camera views, and no calibration saved from stills.
  const bool frames_here = args.sim && !args.camera_nodes;
  std::optional<HttpService> http;
  if (args.serve)
    http.emplace(args.http, *service, hub, ServedCourt{args.sim, frames_here, args.service.seed},
                 "ballsight court-node");
  dds::CourtTopicsOptions topics_options;
  topics_options.on_error = [](const std::string& message) {
    std::cerr << "ballsight court-node: DDS write failed: " << message << std::endl;
  };
  topics_options.ball_radius_m = service->site().ball_radius_m;
  topics_options.diagnostics_prefix =
      "ballsight" + (args.domain.ns.empty() ? "" : "/" + args.domain.ns);
  if (frames_here) {
    // Its cameras are detected here: their detections are written as camera nodes would.
    for (const SiteCamera& camera : service->site().cameras)
      topics_options.detection_cameras.push_back(camera.name);
    topics_options.camera_detections =
        [&service, cameras = service->cameras(),
         world = service_pipeline_options(service->site()).world](const NavigationUpdate& update) {
          std::vector<dds::CameraFrameDetections> out;
          for (std::size_t k = 0; k < cameras.size(); ++k) {
            std::optional<CameraView> view = service->camera_view(k);
            if (view && view->seq == update.seq)  // else the next frame set has replaced it
              out.push_back(dds::placed_detections(service->site().cameras[k].name, cameras[k],
                                                   world, view->seq, view->capture_ns,
                                                   std::move(view->detections)));
          }
          return out;
        };
  }
  const dds::CourtTopics topics(
      participant, hub, [&] { return service->health(); }, topics_options);
  const dds::RobotReports robot(participant, dds::robot_reports_context(*service, hub));
  std::cout << "ballsight court-node: " << topic_prefix(args)
            << "{robot_pose,balls,ball_estimates,route,navigation,diagnostics}, robot link on "
            << topic_prefix(args) << "robot/{reports,replies} (DDS domain "
            << dds::domain_id(args.domain_options()) << ")" << std::endl;
  signals.run_until_stopped(args.duration_s,
                            [&](const std::atomic<bool>& stop) { service->run(hub, stop); });
  if (http) http->stop();
  finish_recording(recorder.get(), args.record, "ballsight court-node");
  std::cout << "ballsight court-node: stopped after " << topics.written() << " updates ("
            << topics.failed() << " writes refused); " << robot.answered()
            << " robot reports answered (" << robot.refused() << " refused)" << std::endl;
}

}  // namespace

void add_node_commands(CLI::App& app) {
  auto camera = std::make_shared<NodeArgs>();
  CLI::App* camera_cmd = app.add_subcommand(
      "camera-node",
      "One court camera on DDS: its frames detected, the detections written for the court node");
  add_node_options(*camera_cmd, *camera);
  camera_cmd->add_option("--camera", camera->camera, "The site's name of the camera, or its index")
      ->required();
  camera_cmd->callback([camera] { run_camera_node(*camera); });

  auto court = std::make_shared<NodeArgs>();
  CLI::App* court_cmd = app.add_subcommand(
      "court-node",
      "A court on DDS: its camera nodes' detections fused, planned, and published as ROS 2 "
      "topics (robot_pose, balls, ball_estimates, route, diagnostics)");
  add_node_options(*court_cmd, *court);
  court_cmd->add_flag("--camera-nodes", court->camera_nodes,
                      "Simulated court: fuse camera nodes (camera-node --sim, same seed) instead "
                      "of rendering the cameras here");
  court_cmd->add_flag(
      "--serve", court->serve,
      "Also serve the navigation service's HTTP API (as `serve`: docs/robot-link.md)");
  for (CLI::Option* option : add_http_service_options(*court_cmd, court->http))
    option->needs("--serve");
  add_record_options(*court_cmd, court->record);
  court_cmd->callback([court] { run_court_node(*court); });
}

}  // namespace ballsight::app
