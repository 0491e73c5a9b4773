// `ballsight sim rings`: the ring image of calibration from one spin with its truth
// (sim/omni_ring_image.hpp), for `ballsight omni rings`.

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/camera/mirror_tracer.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/sim/omni_ring_image.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {

namespace {

constexpr int kTruthDirections = 360;

struct SimRingsArgs {
  std::string out;
  std::optional<std::string> truth;
  sim::RingImageSpec spec;
  std::optional<std::string> center_offset_px;  // "X,Y"
  std::string mirror = "unified";
};

// Per direction (every degree) and ring: where the line's centre lies, or nothing where it is
// out of view; `hidden` 1 where a strut covers it.
std::string truth_csv(const sim::RingImage& image, const sim::RingImageSpec& spec) {
  std::ostringstream csv;
  csv << "theta_deg,distance_cm,radius_px,hidden\n";
  for (int d = 0; d < kTruthDirections; ++d) {
    const double theta = 360.0 * d / kTruthDirections;
    for (std::size_t k = 0; k < spec.distances_m.size(); ++k) {
      const std::optional<double> r = image.true_radius_px(theta, k);
      if (!r) continue;
      csv << fixed(theta, 1) << ',' << fixed(100.0 * spec.distances_m[k], 1) << ',' << fixed(*r, 4)
          << ',' << (image.strut_hides(theta, *r) ? 1 : 0) << '\n';
    }
  }
  return csv.str();
}

void run(SimRingsArgs args) {
  if (args.center_offset_px) {
    args.spec.rig.center_offset_px = parse_pixel_pair(*args.center_offset_px, "--center-offset-px");
  }
  args.spec.rig = with_mirror(args.spec.rig, parse_mirror_kind(args.mirror, "--mirror"));
  const sim::RingImage image(args.spec);
  write_png_atomic(args.out, image.grey());
  if (args.truth) write_file_atomic(*args.truth, truth_csv(image, args.spec));
  std::cout << args.out << ": " << args.spec.distances_m.size() << " rings around "
            << fixed(image.center().x(), 2) << "," << fixed(image.center().y(), 2)
            << " (give it as --center)\n";
}

}  // namespace

void add_sim_rings_command(CLI::App& sim) {
  auto args = std::make_shared<SimRingsArgs>();
  args->spec.rig.width = 480;
  args->spec.rig.height = 480;
  CLI::App* cmd = sim.add_subcommand(
      "rings",
      "Draw the ring image of calibration from one spin (white floor lines at known distances, "
      "seen by a robot turning on the spot) through an omni rig, with its truth, for omni rings");
  cmd->add_option("--out", args->out, "PNG to write")->required()->type_name("PNG");
  cmd->add_option("--truth", args->truth,
                  "Also write each ring's true radius per degree of image angle "
                  "(theta_deg,distance_cm,radius_px,hidden)")
      ->type_name("CSV");
  cmd->add_option("--distances-m", args->spec.distances_m,
                  "The lines' distances from the robot, m, increasing")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--line-widths-m", args->spec.line_widths_m,
                  "The lines' widths, m: one for all, or one per line")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--tilt-deg", args->spec.rig.tilt_deg, "Camera axis tilt, deg")
      ->capture_default_str();
  cmd->add_option("--tilt-azimuth-deg", args->spec.rig.tilt_azimuth_deg,
                  "Robot bearing the axis tilts towards, deg")
      ->capture_default_str();
  cmd->add_option("--center-offset-px", args->center_offset_px,
                  "Mirror centre offset from the image centre X,Y in px")
      ->type_name("X,Y");
  cmd->add_option("--mirror", args->mirror, kMirrorHelp)->capture_default_str();
  cmd->add_option("--struts-deg", args->spec.strut_deg,
                  "Image angles of the robot's struts, deg, comma-separated")
      ->delimiter(',');
  cmd->add_option("--strut-width-px", args->spec.strut_width_px, "The struts' width, px")
      ->capture_default_str();
  cmd->add_option("--carpet-texture", args->spec.carpet_texture,
                  "The carpet's blotches, +- grey levels")
      ->capture_default_str();
  cmd->add_option("--noise", args->spec.noise_sigma, "Gaussian sensor noise sigma, grey levels")
      ->capture_default_str();
  add_seed_option(*cmd, args->spec.seed, "Texture and noise seed");
  cmd->callback([args] { run(*args); });
}

}  // namespace ballsight::app
