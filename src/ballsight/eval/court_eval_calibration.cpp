#include "ballsight/eval/court_eval_calibration.hpp"

#include <algorithm>
#include <opencv2/calib3d.hpp>
#include <string>

#include "ballsight/calib/chessboard_corners.hpp"
#include "ballsight/calib/intrinsics.hpp"
#include "ballsight/calib/reference_pose.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/detect/seed_detector.hpp"
#include "ballsight/pipeline/court_calibration.hpp"
#include "ballsight/sim/chessboard.hpp"
#include "ballsight/sim/chessboard_poses.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/ray_table.hpp"
#include "ballsight/sim/seeding.hpp"

namespace ballsight {

namespace {

enum CalibrationStream : std::uint64_t {
  kBoardStream = 1,
  kReferenceSceneStream,
  kNoiseStream = 100
};

const sim::ChessboardSpec kBoard;  // 9 x 6 inner corners, 5 cm squares

ChessboardPattern board_pattern() {
  ChessboardPattern pattern;
  pattern.inner_cols = kBoard.inner_cols;
  pattern.inner_rows = kBoard.inner_rows;
  pattern.square_m = kBoard.square_m;
  return pattern;
}

std::vector<ChessboardView> find_views(const std::vector<cv::Mat>& images, size_t camera) {
  std::vector<ChessboardView> views;
  for (size_t v = 0; v < images.size(); ++v) {
    const auto corners = find_chessboard_corners(images[v], board_pattern());
    if (corners)
      views.push_back(
          {"camera " + std::to_string(camera) + " board " + std::to_string(v), *corners});
  }
  return views;
}

}  // namespace

CalibrationImages render_calibration_images(const sim::CourtRig& rig, int views, double noise_sigma,
                                            std::uint64_t seed) {
  CalibrationImages images;
  sim::ChessboardRenderOptions board_options;
  board_options.effects.noise_sigma = noise_sigma;
  sim::CourtScenarioOptions empty;
  empty.ball_count = 0;
  empty.noise_sigma = noise_sigma;
  const sim::CourtScene reference_scene =
      sim::make_court_scene(rig.court, empty, sim::derive_seed(seed, kReferenceSceneStream));
  for (size_t c = 0; c < rig.cameras.size(); ++c) {
    const PinholeCamera& camera = rig.cameras[c].camera;
    const std::uint64_t camera_seed = sim::derive_seed(sim::derive_seed(seed, kBoardStream), c);
    const sim::RayTable rays(camera);
    std::vector<cv::Mat> boards;
    for (const Rigid3& pose : sim::make_chessboard_poses(camera, kBoard, views, {}, camera_seed)) {
      boards.push_back(
          sim::render_chessboard(camera, rays, kBoard, pose, board_options,
                                 sim::derive_seed(camera_seed, kNoiseStream + boards.size())));
    }
    images.chessboards.push_back(std::move(boards));
    images.reference_views.push_back(sim::CourtRenderer(rig.cameras[c], rig.court)
                                         .render(reference_scene, sim::derive_seed(seed, c))
                                         .bgr);
  }
  return images;
}

HsvRange report_reference_box(const Rgb& colour) {
  const int hue = opencv_hue(colour.bgr());
  return {{std::max(0, hue - 12), 70, 40}, {std::min(179, hue + 12), 255, 255}};
}

EvalCalibration calibrate_ballsight_cameras(const CalibrationImages& images, const Site& site) {
  EvalCalibration out;
  for (size_t c = 0; c < images.chessboards.size(); ++c) {
    const cv::Size size = images.reference_views[c].size();
    const IntrinsicsResult intrinsics =
        calibrate_intrinsics(find_views(images.chessboards[c], c), board_pattern(), size);
    CameraCalibration calibration;
    calibration.intrinsics = intrinsics.camera;
    calibration.avg_reprojection_error_px = intrinsics.rms_px;
    const CameraPoseReport report = calibrate_site_camera(
        site, site.cameras[c], images.reference_views[c], "reference view", calibration);
    out.cameras.push_back({PinholeCamera(intrinsics.camera), report.pose.camera_from_field});
    out.intrinsics_rms_px.push_back(intrinsics.rms_px);
    out.pose_rms_px.push_back(report.pose.rms_px);
  }
  return out;
}

EvalCalibration calibrate_seed_cameras(const CalibrationImages& images, const Site& site) {
  // The report's reference balls are orange table-tennis balls (report_reference_box); no median
  // filter: it would erase balls of one or two pixels in radius. Saturation from 70: the balls
  // are small, their pixels mixed with the court.
  const HsvRange box = report_reference_box(site.colours.reference_ball);
  const std::vector<ReferencePoint> references = site_references(site);
  EvalCalibration out;
  for (size_t c = 0; c < images.chessboards.size(); ++c) {
    const cv::Size size = images.reference_views[c].size();
    const std::vector<ChessboardView> views = find_views(images.chessboards[c], c);
    require(views.size() >= 4, "seed calibration camera " + std::to_string(c),
            "fewer than four chessboard views found");
    std::vector<std::vector<cv::Point3f>> object_points(views.size(),
                                                        board_pattern().object_points());
    std::vector<std::vector<cv::Point2f>> image_points;
    for (const ChessboardView& view : views) image_points.push_back(view.corners);
    cv::Mat k, distortion;
    std::vector<cv::Mat> rvecs, tvecs;
    const double rms = cv::calibrateCamera(object_points, image_points, size, k, distortion, rvecs,
                                           tvecs, cv::CALIB_FIX_K3 | cv::CALIB_ZERO_TANGENT_DIST);
    const PinholeCamera camera = PinholeCamera::from_opencv(cv::Matx33d(k), distortion, size);

    std::vector<Vec2> candidates;
    for (const PixelDetection& d :
         detect_seed_colour(images.reference_views[c], box, 1, ObjectClass::ball))
      candidates.push_back(d.center_px);
    ReferencePose matched;
    try {
      matched =
          estimate_reference_pose(camera, references, candidates, site.cameras[c].position_hint_m);
    } catch (const InputError& e) {
      throw InputError("seed calibration, camera " + std::to_string(c) + " (fx " +
                       std::to_string(camera.params().fx) + ", " +
                       std::to_string(candidates.size()) +
                       " blobs of the reference colour): " + e.what());
    }
    std::vector<cv::Point3d> points;
    std::vector<cv::Point2d> pixels;
    for (const ReferenceMatch& m : matched.matches) {
      const Vec3& p = references[m.reference].p_in_field;
      points.emplace_back(p.x(), p.y(), p.z());
      pixels.emplace_back(candidates[m.candidate].x(), candidates[m.candidate].y());
    }
    cv::Mat rvec, tvec;
    require(cv::solvePnP(points, pixels, k, distortion, rvec, tvec, false, cv::SOLVEPNP_ITERATIVE),
            "seed calibration camera " + std::to_string(c), "solvePnP found no pose");
    std::vector<cv::Point2d> projected;
    cv::projectPoints(points, rvec, tvec, k, distortion, projected);
    double sum2 = 0.0;
    for (size_t i = 0; i < points.size(); ++i) {
      const cv::Point2d d = projected[i] - pixels[i];
      sum2 += d.dot(d);
    }
    const Rigid3 pose =
        Rigid3::from_rvec_tvec(Vec3(rvec.at<double>(0), rvec.at<double>(1), rvec.at<double>(2)),
                               Vec3(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2)));
    out.cameras.push_back({camera, pose});
    out.intrinsics_rms_px.push_back(rms);
    out.pose_rms_px.push_back(std::sqrt(sum2 / static_cast<double>(points.size())));
  }
  return out;
}

}  // namespace ballsight
