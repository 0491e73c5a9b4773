#include "ballsight/sim/chessboard.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/chessboard_poses.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/ray_table.hpp"

namespace ballsight::sim {
namespace {

/// A strongly distorted court camera, as the calibration will meet it.
PinholeCamera court_camera() {
  return make_court_rig({}, {}, 11).cameras[0].camera;
}

/// Corners found by OpenCV (findChessboardCorners + cornerSubPix) in truth order, or nothing.
std::optional<std::vector<Vec2>> find_corners(const cv::Mat& bgr, const ChessboardSpec& board,
                                              const std::vector<Vec2>& truth) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  std::vector<cv::Point2f> found;
  if (!cv::findChessboardCorners(grey, cv::Size(board.inner_cols, board.inner_rows), found,
                                 cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE)) {
    return std::nullopt;
  }
  cv::cornerSubPix(grey, found, cv::Size(5, 5), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 50, 1e-3));
  std::vector<Vec2> corners;
  for (const cv::Point2f& p : found) corners.emplace_back(p.x, p.y);
  // OpenCV may start from the opposite corner of the board.
  if ((corners.front() - truth.front()).norm() > (corners.front() - truth.back()).norm()) {
    std::reverse(corners.begin(), corners.end());
  }
  return corners;
}

/// The default board seen through the court camera with a given sensor noise.
struct BoardSession {
  explicit BoardSession(double noise_sigma) : camera(court_camera()), rays(camera) {
    options.effects.noise_sigma = noise_sigma;
  }

  /// Corners found by OpenCV in the rendered view (nothing if not found) and the truth.
  std::pair<std::optional<std::vector<Vec2>>, std::vector<Vec2>> view(const Rigid3& pose,
                                                                      std::uint64_t seed) const {
    const cv::Mat bgr = render_chessboard(camera, rays, board, pose, options, seed);
    std::vector<Vec2> truth = chessboard_corner_pixels(camera, board, pose).value();
    return {find_corners(bgr, board, truth), truth};
  }

  PinholeCamera camera;
  RayTable rays;
  ChessboardSpec board;
  ChessboardRenderOptions options;
};

TEST(Chessboard, OpenCVFindsTheCornersWhereTheTruthSaysTheyAre) {
  const BoardSession session(0.0);
  double worst = 0.0;
  Vec2 offset_sum = Vec2::Zero();
  int count = 0;
  for (const std::uint64_t seed : {1u, 2u}) {
    const auto poses = make_chessboard_poses(session.camera, session.board, 6, {}, seed);
    for (size_t v = 0; v < poses.size(); ++v) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " view " + std::to_string(v));
      const auto [found, truth] = session.view(poses[v], v);
      ASSERT_TRUE(found);
      ASSERT_EQ(found->size(), truth.size());
      for (size_t i = 0; i < found->size(); ++i) {
        const Vec2 offset = (*found)[i] - truth[i];
        EXPECT_LT(offset.norm(), 0.3) << "corner " << i;
        worst = std::max(worst, offset.norm());
        offset_sum += offset;
        ++count;
      }
    }
  }
  EXPECT_LT((offset_sum / count).norm(), 0.02) << "unbiased corners";
  std::cout << "worst corner error " << worst << " px, mean offset "
            << (offset_sum / count).transpose() << " px\n";
}

TEST(Chessboard, FifteenNoisyViewsCalibrateTheFocalLengthToAFewTenthsOfAPercent) {
  const BoardSession session(2.0);
  std::vector<cv::Point3f> object;
  for (const Vec3& c : session.board.inner_corners()) {
    object.emplace_back(static_cast<float>(c.x()), static_cast<float>(c.y()), 0.0f);
  }
  std::vector<std::vector<cv::Point3f>> objects;
  std::vector<std::vector<cv::Point2f>> images;
  const auto poses = make_chessboard_poses(session.camera, session.board, 15, {}, 3);
  for (size_t v = 0; v < poses.size(); ++v) {
    const auto found = session.view(poses[v], v).first;
    ASSERT_TRUE(found) << "view " << v;
    std::vector<cv::Point2f> points;
    for (const Vec2& p : *found) {
      points.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
    }
    objects.push_back(object);
    images.push_back(points);
  }
  const PinholeParams& truth = session.camera.params();
  cv::Mat k, distortion;
  std::vector<cv::Mat> rvecs, tvecs;
  // The simulated lens has k3 = 0; left free, OpenCV's optimiser can stall in a wrong minimum
  // under this strong barrel distortion (seen with other seeds).
  const double rms = cv::calibrateCamera(objects, images, {truth.width, truth.height}, k,
                                         distortion, rvecs, tvecs, cv::CALIB_FIX_K3);
  EXPECT_LT(rms, 0.2);
  EXPECT_NEAR(k.at<double>(0, 0) / truth.fx, 1.0, 0.002);
  EXPECT_NEAR(k.at<double>(1, 1) / truth.fy, 1.0, 0.002);
  EXPECT_NEAR(distortion.at<double>(0), truth.distortion[0], 0.01);
}

TEST(Chessboard, PosesKeepTheBoardInViewTiltedAndSized) {
  const PinholeCamera camera = court_camera();
  const ChessboardSpec board;
  const ChessboardPoseOptions options;
  const auto poses = make_chessboard_poses(camera, board, 40, options, 5);
  ASSERT_EQ(poses.size(), 40u);
  double max_tilt = 0.0;
  Eigen::AlignedBox2d centres;
  for (const Rigid3& pose : poses) {
    const auto outline = chessboard_outline_pixels(camera, board, pose);
    ASSERT_TRUE(outline);
    for (const Vec2& p : *outline) EXPECT_TRUE(camera.in_image(p)) << p.transpose();
    const double fill = chessboard_fill(camera, *outline);
    EXPECT_GE(fill, options.min_fill);
    EXPECT_LE(fill, options.max_fill);
    const double tilt = deg_from_rad(std::acos((pose.rotation * Vec3::UnitZ()).z()));
    EXPECT_LE(tilt, options.max_tilt_deg + 1e-9);
    max_tilt = std::max(max_tilt, tilt);
    centres.extend(*camera.project(pose * Vec3(0.2, 0.125, 0.0)));
  }
  EXPECT_GT(max_tilt, 30.0) << "varied tilts";
  // Spread over the image, towards its distorted corners.
  EXPECT_GT(centres.sizes().x(), 0.6 * camera.width());
  EXPECT_GT(centres.sizes().y(), 0.5 * camera.height());
}

TEST(Chessboard, SameSeedSameViews) {
  const PinholeCamera camera = court_camera();
  const RayTable rays(camera);
  const auto a = make_chessboard_poses(camera, {}, 2, {}, 9);
  const auto b = make_chessboard_poses(camera, {}, 2, {}, 9);
  const auto c = make_chessboard_poses(camera, {}, 2, {}, 10);
  EXPECT_EQ(a[1].translation, b[1].translation);
  EXPECT_NE(a[1].translation, c[1].translation);
  const cv::Mat image_a = render_chessboard(camera, rays, {}, a[0], {}, 3);
  const cv::Mat image_b = render_chessboard(camera, rays, {}, b[0], {}, 3);
  EXPECT_EQ(cv::norm(image_a, image_b, cv::NORM_INF), 0.0);
}

TEST(Chessboard, InvalidSpecsAndOptionsAreNamed) {
  const PinholeCamera camera = court_camera();
  ChessboardSpec board;
  board.inner_cols = 1;
  EXPECT_THROW(board.validate(), InputError);
  board = {};
  board.square_m = 0.0;
  EXPECT_THROW(make_chessboard_poses(camera, board, 1, {}, 1), InputError);
  ChessboardPoseOptions options;
  options.max_fill = 0.1;  // below min_fill
  EXPECT_THROW(make_chessboard_poses(camera, {}, 1, options, 1), InputError);
  // A board far too large to fit in view at the asked size.
  board = {};
  options = {};
  options.min_fill = 0.99;
  options.max_fill = 1.0;
  options.max_tilt_deg = 0.0;
  EXPECT_THROW(make_chessboard_poses(camera, board, 1, options, 1), InputError);
}

}  // namespace
}  // namespace ballsight::sim
