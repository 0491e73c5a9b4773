// `ballsight sim omni`: renders a deterministic omni scenario to PNG images and truth JSON files.

#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "ballsight/core/error.hpp"
#include "ballsight/sim/omni_dataset.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {

namespace {

struct SimOmniArgs {
  std::filesystem::path out;
  sim::OmniScenarioOptions scenario;
  std::optional<std::string> center_offset_px;  // "X,Y"
  std::string mirror = "unified";
  bool no_markers = false;
};

void run(SimOmniArgs args) {
  if (args.center_offset_px) {
    args.scenario.center_offset_px = parse_pixel_pair(*args.center_offset_px, "--center-offset-px");
  }
  args.scenario.calibration_frame = !args.no_markers;
  args.scenario.mirror = parse_mirror_kind(args.mirror, "--mirror");
  for (const std::string& name : sim::write_omni_dataset(args.scenario, args.out)) {
    std::cout << (args.out / name).string() << "\n";
  }
}

}  // namespace

void add_sim_omni_command(CLI::App& sim) {
  auto args = std::make_shared<SimOmniArgs>();
  CLI::App* cmd = sim.add_subcommand(
      "omni",
      "Render an omnidirectional-camera scenario on an MSL field: omni_NNNN.png images and one "
      "truth JSON per image (docs/sim-omni.md). Frame 0 shows the calibration markers unless "
      "--no-markers; the others a ball 0.5-5 m from the robot. Same seed, same bytes.");
  cmd->add_option("--out", args->out, "Output folder (created if missing)")
      ->required()
      ->type_name("DIR");
  add_seed_option(*cmd, args->scenario.seed, "Scenario seed");
  cmd->add_option("--frames", args->scenario.frames, "Number of frames, 1..10000")
      ->capture_default_str();
  cmd->add_option("--tilt-deg", args->scenario.tilt_deg,
                  "Camera axis tilt, 0..10 deg (default: 1-2 deg drawn from the seed)");
  cmd->add_option("--tilt-azimuth-deg", args->scenario.tilt_azimuth_deg,
                  "Robot bearing the axis tilts towards, deg (default: drawn from the seed)");
  cmd->add_option("--center-offset-px", args->center_offset_px,
                  "Mirror centre offset from the image centre X,Y in px, at most 50 px "
                  "(default: 3-7 px drawn from the seed)")
      ->type_name("X,Y");
  cmd->add_option("--mirror", args->mirror, kMirrorHelp)->capture_default_str();
  cmd->add_option("--noise", args->scenario.effects.noise_sigma,
                  "Gaussian sensor noise sigma, 0..64 grey levels")
      ->capture_default_str();
  cmd->add_option("--blur", args->scenario.effects.blur_sigma_px, "Gaussian blur sigma, 0..10 px")
      ->capture_default_str();
  cmd->add_option("--brightness", args->scenario.effects.brightness_gain, "Brightness gain, (0, 4]")
      ->capture_default_str();
  cmd->add_flag("--no-markers", args->no_markers, "No calibration frame: every frame has a ball");
  cmd->callback([args] { run(*args); });
}

}  // namespace ballsight::app
