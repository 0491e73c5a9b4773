// `ballsight omni-node`: the on-board omni camera on DDS (dds/omni_node.hpp). Frames come from a
// camera source (an image file, a folder of images, a video device or a stream) or from the
// simulator (--sim: the omni scenes of `sim omni`, a new robot pose and ball every frame).

#include <atomic>
#include <iostream>
#include <memory>

#include "ballsight/camera/ground_map_io.hpp"
#include "ballsight/camera/rig_ground_map.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/dds/omni_node.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/sim/omni_renderer.hpp"
#include "ballsight/sim/omni_scenario.hpp"
#include "commands.hpp"
#include "node_options.hpp"
#include "option_parsing.hpp"
#include "stop_signals.hpp"

namespace ballsight::app {
namespace {

struct OmniNodeArgs : DdsArgs {
  std::string lut;
  std::string camera;
  bool sim = false;
  std::uint64_t seed = 1;
  int scenes = 20;
  double rate_hz = 10.0;
  std::string ball_bgr = "0,110,255";
  double ball_radius_cm = 11.0;
};

// "3" (a video device), "rtsp://..." (a stream), a folder of images or an image file.
CameraSource camera_source(const std::string& text) {
  CameraSource source;
  if (!text.empty() && text.find_first_not_of("0123456789") == std::string::npos) {
    source.kind = CameraSource::Kind::device;
    source.device = std::stoi(text);
  } else if (text.find("://") != std::string::npos) {
    source.kind = CameraSource::Kind::url;
    source.url = text;
  } else {
    require(std::filesystem::exists(text), "--camera",
            "'" + text + "' is no file, folder, device index or URL");
    source.kind =
        std::filesystem::is_directory(text) ? CameraSource::Kind::folder : CameraSource::Kind::file;
    source.path = text;
  }
  return source;
}

// The simulated robot's own camera: its rig, and a scene per frame.
struct SimulatedOmni {
  explicit SimulatedOmni(const OmniNodeArgs& args)
      : scenario(sim::make_omni_scenario([&] {
          sim::OmniScenarioOptions options;
          options.seed = args.seed;
          options.frames = args.scenes;
          options.calibration_frame = false;
          return options;
        }())),
        renderer(scenario.rig) {}

  // The rig's exact table over the mirror's image (the simulator's truth, as eval omni's oracle).
  GroundMap exact_table() const {
    GroundMapInfo info;
    info.width = scenario.rig.width;
    info.height = scenario.rig.height;
    info.image_center_px = renderer.rig().principal_point();
    info.max_radius_px = scenario.rig.mirror_radius_px;
    info.method = "simulator";
    return ground_map_from_rig(renderer.rig(), info);
  }

  sim::OmniScenario scenario;
  sim::OmniRenderer renderer;
};

void run_omni_node(const OmniNodeArgs& args) {
  validate(args);
  require(args.sim != !args.camera.empty(), "--camera",
          "give the camera (--camera SOURCE) or --sim, not both");
  require(args.sim || !args.lut.empty(), "--lut", "the camera's lookup table is needed");
  require(args.rate_hz > 0.0 && args.rate_hz <= 120.0, "--rate", "must be in (0, 120] Hz");
  require(args.scenes >= 1 && args.scenes <= 1000, "--scenes", "must be in [1, 1000]");
  BallOnFloor ball;
  ball.radius_cm = args.ball_radius_cm;
  ball.validate();
  const cv::Vec3b ball_bgr = parse_bgr(args.ball_bgr, "--ball-bgr");
  SiteCamera camera{"omni", args.sim ? CameraSource{} : camera_source(args.camera), {}, {}};
  const StopSignals signals;  // before DDS starts its threads
  const std::unique_ptr<SimulatedOmni> simulated =
      args.sim ? std::make_unique<SimulatedOmni>(args) : nullptr;
  const GroundMap map = args.lut.empty() ? simulated->exact_table() : load_ground_map(args.lut);
  const BallsightOmniPipeline pipeline(yuv_range_around(ball_bgr), map, ball);
  const dds::Participant participant(args.domain_options());
  dds::OmniNode node(participant, pipeline, args.ball_radius_cm / 100.0);
  std::cout << "ballsight omni-node: " << topic_prefix(args) << "{ball,ball_field} from "
            << (args.sim ? "the simulated robot" : args.camera) << ", " << topic_prefix(args)
            << "robot_pose read (DDS domain " << dds::domain_id(args.domain_options()) << ")"
            << std::endl;
  std::uint64_t frames = 0;
  std::uint64_t balls = 0;
  std::uint64_t misfits = 0;  // a camera's frames of another size than the table's: skipped
  const FramePublisher publish = [&](const cv::Mat& frame, std::uint64_t, std::int64_t capture_ns) {
    ++frames;
    if (frame.cols != map.width() || frame.rows != map.height()) {
      const std::string problem = "a frame of " + std::to_string(frame.cols) + "x" +
                                  std::to_string(frame.rows) + " px, the lookup table is " +
                                  std::to_string(map.width()) + "x" + std::to_string(map.height());
      require(!args.sim, "--lut", problem);  // the simulated camera's size is fixed
      if (misfits++ == 0)
        std::cerr << "ballsight omni-node: --camera: " << problem << "; skipped\n";
      return;
    }
    if (node.publish(frame, capture_ns)) ++balls;
  };
  signals.run_until_stopped(args.duration_s, [&](const std::atomic<bool>& stop) {
    if (simulated) {  // scene k of the scenario at tick k, in turn
      publish_ticks(
          args.rate_hz, stop,
          [&](std::uint64_t tick) {
            const std::size_t scene = tick % static_cast<std::uint64_t>(args.scenes);
            return simulated->renderer.render(simulated->scenario.scenes[scene]).bgr;
          },
          publish);
    } else {
      publish_captured("ballsight omni-node", camera.name, site_frame_source(camera), stop,
                       publish);
    }
  });
  std::cout << "ballsight omni-node: stopped after " << frames << " frames (" << misfits
            << " of another size than the table), a ball in " << balls << std::endl;
}

}  // namespace

void add_omni_node_command(CLI::App& app) {
  auto args = std::make_shared<OmniNodeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "omni-node",
      "A robot's omni camera on DDS: the ball robot-relative (ball) and, from the robot's pose "
      "(robot_pose), on the field (ball_field), as geometry_msgs/PointStamped");
  cmd->add_option("--lut", args->lut,
                  "Lookup table of the camera (omni fit --out); --sim: the simulator's exact one "
                  "when not given");
  cmd->add_option("--camera", args->camera,
                  "The camera: an image file, a folder of images, a video device index or a "
                  "stream URL");
  cmd->add_flag("--sim", args->sim,
                "The simulated robot's camera (the scenes of sim omni: a robot pose and a ball "
                "per frame)");
  add_seed_option(*cmd, args->seed, "Simulated robot: seed of the rig and the scenes");
  cmd->add_option("--scenes", args->scenes, "Simulated robot: scenes, shown in turn")
      ->capture_default_str();
  cmd->add_option("--rate", args->rate_hz, "Simulated robot: frames per second")
      ->capture_default_str();
  cmd->add_option("--ball-bgr", args->ball_bgr, "Ball colour B,G,R (thresholds around it in YUV)")
      ->capture_default_str();
  cmd->add_option("--ball-radius-cm", args->ball_radius_cm, "Ball radius in cm")
      ->capture_default_str();
  add_dds_options(*cmd, *args, "robot's topics");
  cmd->callback([args] { run_omni_node(*args); });
}

}  // namespace ballsight::app
