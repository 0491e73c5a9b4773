#include "ballsight/pipeline/court_calibration.hpp"

#include "ballsight/core/error.hpp"
#include "ballsight/pipeline/site_setup.hpp"

namespace ballsight {

std::vector<ReferencePoint> site_references(const Site& site) {
  std::vector<ReferencePoint> references;
  for (const ReferenceBall& ball : site.reference_balls) {
    references.push_back({ball.name, site.reference_center_in_field(ball)});
  }
  return references;
}

CameraPoseReport calibrate_site_camera(const Site& site, const SiteCamera& camera,
                                       const cv::Mat& image, const std::string& source,
                                       const CameraCalibration& calibration,
                                       const CourtCalibrationOptions& options,
                                       const ReferenceCorrections& corrections) {
  const std::string where = "camera '" + camera.name + "' (" + source + ")";
  const PinholeParams& intrinsics = calibration.intrinsics;
  require(image.cols == intrinsics.width && image.rows == intrinsics.height, where,
          "image is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
              ", its calibration " + camera.calibration_file.string() + " is for " +
              std::to_string(intrinsics.width) + "x" + std::to_string(intrinsics.height));
  ColorBlobOptions blob_options = options.blobs;
  blob_options.target_bgr = site.colours.reference_ball.bgr();
  const std::vector<ColorBlob> blobs = find_color_blobs(image, blob_options);
  std::vector<Vec2> candidates;
  for (const ColorBlob& blob : blobs) candidates.push_back(blob.centroid_px);

  CameraPoseReport report;
  report.camera = camera.name;
  report.source = source;
  report.calibration_file = camera.calibration_file;
  report.blob_count = static_cast<int>(blobs.size());
  report.candidates_px = candidates;
  report.references = site_references(site);
  try {
    report.pose = estimate_reference_pose(PinholeCamera(intrinsics), report.references, candidates,
                                          camera.position_hint_m, options.pose, corrections);
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what() + " [" + std::to_string(blobs.size()) +
                     " blobs of the reference-ball colour]");
  }
  report.calibration = calibration;
  report.calibration.extrinsics =
      CameraExtrinsics{report.pose.camera_from_field, report.pose.rms_px,
                       static_cast<int>(report.pose.matches.size())};
  return report;
}

namespace {

// One camera's pose; throws InputError naming the camera.
CameraPoseReport calibrate_one(const Site& site, const SiteCamera& camera,
                               const CourtCalibrationOptions& options) {
  CameraCalibration calibration;
  cv::Mat image;
  const std::unique_ptr<FrameSource> source = site_frame_source(camera);
  try {
    calibration = read_camera_file(camera.calibration_file);
    image = read_still_frame(*source, options.frame);
  } catch (const InputError& e) {
    throw InputError("camera '" + camera.name + "': " + e.what());
  }
  return calibrate_site_camera(site, camera, image, source->describe(), calibration, options);
}

}  // namespace

SiteCalibration calibrate_site(const Site& site, const CourtCalibrationOptions& options) {
  options.frame.validate();
  SiteCalibration result;
  for (const SiteCamera& camera : site.cameras) {
    try {
      result.calibrated.push_back(calibrate_one(site, camera, options));
    } catch (const InputError& e) {
      result.failed.push_back({camera.name, e.what()});
    }
  }
  if (!result.failed.empty()) return result;
  for (const CameraPoseReport& report : result.calibrated) {
    write_camera_file(report.calibration_file, report.calibration);
  }
  result.written = true;
  return result;
}

}  // namespace ballsight
