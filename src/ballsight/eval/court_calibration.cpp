#include "ballsight/eval/court_calibration.hpp"

#include <algorithm>
#include <opencv2/imgcodecs.hpp>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

namespace fs = std::filesystem;

std::filesystem::path first_source_image(const SiteCamera& camera) {
  const CameraSource& source = camera.source;
  const std::string where = "camera '" + camera.name + "'";
  switch (source.kind) {
    case CameraSource::Kind::file:
      return source.path;
    case CameraSource::Kind::folder: {
      std::error_code ec;
      require(fs::is_directory(source.path, ec), where,
              "source folder " + source.path.string() + " does not exist");
      std::vector<fs::path> images;
      for (const fs::directory_entry& entry : fs::directory_iterator(source.path, ec)) {
        if (entry.is_regular_file(ec) && cv::haveImageReader(entry.path().string())) {
          images.push_back(entry.path());
        }
      }
      require(!images.empty(), where, "no image in source folder " + source.path.string());
      return *std::min_element(images.begin(), images.end());
    }
    case CameraSource::Kind::device:
    case CameraSource::Kind::url:
      break;
  }
  throw InputError(where + ": calibration reads a still image; a " +
                   std::string(camera_source_kind_name(source.kind)) +
                   " source is not supported yet (save a frame and use a file source)");
}

std::vector<ReferencePoint> site_references(const Site& site) {
  std::vector<ReferencePoint> references;
  for (const ReferenceBall& ball : site.reference_balls) {
    references.push_back({ball.name, site.reference_center_in_field(ball)});
  }
  return references;
}

CameraPoseReport calibrate_site_camera(const Site& site, const SiteCamera& camera,
                                       const cv::Mat& image, const fs::path& image_file,
                                       const CameraCalibration& calibration,
                                       const CourtCalibrationOptions& options) {
  const std::string where = "camera '" + camera.name + "' (" + image_file.string() + ")";
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
  report.image = image_file;
  report.calibration_file = camera.calibration_file;
  report.blob_count = static_cast<int>(blobs.size());
  report.references = site_references(site);
  try {
    report.pose = estimate_reference_pose(PinholeCamera(intrinsics), report.references, candidates,
                                          camera.position_hint_m, options.pose);
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

std::vector<CameraPoseReport> calibrate_site(const Site& site,
                                             const CourtCalibrationOptions& options) {
  std::vector<CameraPoseReport> reports;
  for (const SiteCamera& camera : site.cameras) {
    const fs::path image_file = first_source_image(camera);
    cv::Mat image;
    CameraCalibration calibration;
    try {
      image = read_image_bgr(image_file);
      calibration = read_camera_file(camera.calibration_file);
    } catch (const InputError& e) {
      throw InputError("camera '" + camera.name + "': " + e.what());
    }
    reports.push_back(calibrate_site_camera(site, camera, image, image_file, calibration, options));
  }
  for (const CameraPoseReport& report : reports) {
    write_camera_file(report.calibration_file, report.calibration);
  }
  return reports;
}

}  // namespace ballsight
