// `ballsight court calibrate`: every camera of a site finds the reference balls in its first
// image and its pose goes into its calibration file (docs/site-file.md).

#include <iostream>
#include <memory>
#include <string>

#include "ballsight/core/text_format.hpp"
#include "ballsight/eval/court_calibration.hpp"
#include "ballsight/world/site.hpp"
#include "commands.hpp"

namespace ballsight::app {
namespace {

void print_report(const CameraPoseReport& r) {
  const Vec3 center = r.pose.camera_from_field.inverse().translation;
  std::cout << "camera " << r.camera << " (" << r.image.string() << "): " << r.blob_count
            << " blobs, " << r.pose.matches.size() << " of " << r.references.size()
            << " reference balls, reprojection rms " << fixed(r.pose.rms_px, 3) << " px (max "
            << fixed(r.pose.max_px, 3) << "); camera at (" << fixed(center.x(), 3) << ", "
            << fixed(center.y(), 3) << ", " << fixed(center.z(), 3) << ") m\n";
  std::cout << "  matched:";
  for (const ReferenceMatch& m : r.pose.matches) {
    std::cout << " " << r.references[m.reference].name << " " << fixed(m.residual_px, 2) << " px";
  }
  std::cout << "\n  not found:";
  for (std::size_t i : r.pose.unmatched) std::cout << " " << r.references[i].name;
  std::cout << (r.pose.unmatched.empty() ? " none" : "") << "\n";
}

}  // namespace

void add_court_calibrate_command(CLI::App& court) {
  auto site_file = std::make_shared<std::string>();
  CLI::App* cmd = court.add_subcommand(
      "calibrate",
      "Pose of every site camera from the reference balls in its first image, written into its "
      "calibration file");
  cmd->add_option("--site", *site_file, "Site file (YAML, docs/site-file.md)")->required();
  cmd->callback([site_file] {
    const Site site = read_site(*site_file);
    const std::vector<CameraPoseReport> reports = calibrate_site(site);
    for (const CameraPoseReport& report : reports) {
      print_report(report);
      std::cout << "  wrote " << report.calibration_file.string() << "\n";
    }
  });
}

}  // namespace ballsight::app
