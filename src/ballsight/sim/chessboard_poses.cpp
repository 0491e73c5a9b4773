#include "ballsight/sim/chessboard_poses.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/seeding.hpp"

namespace ballsight::sim {
namespace {

/// One candidate pose, or nothing when it breaks a constraint.
std::optional<Rigid3> try_pose(const PinholeCamera& camera, const ChessboardSpec& board,
                               const ChessboardPoseOptions& options, std::mt19937_64& rng) {
  const cv::Rect2d outline = board.outline();
  const double fill = uniform(rng, options.min_fill, options.max_fill);
  const Vec2 centre_px(uniform(rng, 0.0, camera.width() - 1.0),
                       uniform(rng, 0.0, camera.height() - 1.0));
  const std::optional<Vec3> ray = camera.unproject(centre_px);
  if (!ray) return std::nullopt;
  // Distance at which a frontal board spans `fill` of the image width (or height).
  const double distance = std::max(camera.params().fx * outline.width / (fill * camera.width()),
                                   camera.params().fy * outline.height / (fill * camera.height()));

  const double tilt_axis = uniform(rng, -kPi, kPi);
  const double tilt = rad_from_deg(uniform(rng, 0.0, options.max_tilt_deg));
  const double spin = rad_from_deg(uniform(rng, -options.max_spin_deg, options.max_spin_deg));
  const Mat3 rotation =
      (Eigen::AngleAxisd(tilt, Vec3(std::cos(tilt_axis), std::sin(tilt_axis), 0.0)) *
       Eigen::AngleAxisd(spin, Vec3::UnitZ()))
          .toRotationMatrix();
  const Vec3 centre_in_board(outline.x + outline.width / 2.0, outline.y + outline.height / 2.0,
                             0.0);
  const Rigid3 camera_from_board{rotation, *ray * distance - rotation * centre_in_board};

  // The printed side faces the camera at a usable angle.
  const Vec3 normal = rotation * Vec3::UnitZ();
  if (ray->dot(normal) < std::cos(rad_from_deg(options.max_view_angle_deg))) return std::nullopt;
  const auto pixels = chessboard_outline_pixels(camera, board, camera_from_board);
  if (!pixels) return std::nullopt;
  for (const Vec2& p : *pixels) {
    if (p.x() < options.margin_px || p.y() < options.margin_px ||
        p.x() > camera.width() - 1.0 - options.margin_px ||
        p.y() > camera.height() - 1.0 - options.margin_px) {
      return std::nullopt;
    }
  }
  const double actual_fill = chessboard_fill(camera, *pixels);
  if (actual_fill < options.min_fill || actual_fill > options.max_fill) return std::nullopt;
  return camera_from_board;
}

}  // namespace

void ChessboardPoseOptions::validate() const {
  require(std::isfinite(max_tilt_deg) && max_tilt_deg >= 0.0 && max_tilt_deg <= 70.0,
          "max_tilt_deg", "must be in [0, 70]");
  require(std::isfinite(max_spin_deg) && max_spin_deg >= 0.0 && max_spin_deg <= 180.0,
          "max_spin_deg", "must be in [0, 180]");
  require(std::isfinite(min_fill) && min_fill > 0.0, "min_fill", "must be positive");
  require(std::isfinite(max_fill) && max_fill >= min_fill && max_fill <= 1.0, "max_fill",
          "must be in [min_fill, 1]");
  require(std::isfinite(margin_px) && margin_px >= 0.0, "margin_px", "must be non-negative");
  require(
      std::isfinite(max_view_angle_deg) && max_view_angle_deg > 0.0 && max_view_angle_deg < 90.0,
      "max_view_angle_deg", "must be in (0, 90)");
}

double chessboard_fill(const PinholeCamera& camera, const std::vector<Vec2>& outline_pixels) {
  Eigen::AlignedBox2d box;
  for (const Vec2& p : outline_pixels) box.extend(p);
  const Vec2 size = box.sizes();
  return std::max(size.x() / camera.width(), size.y() / camera.height());
}

std::vector<Rigid3> make_chessboard_poses(const PinholeCamera& camera, const ChessboardSpec& board,
                                          int count, const ChessboardPoseOptions& options,
                                          std::uint64_t seed) {
  board.validate();
  options.validate();
  require(count >= 0, "chessboard views", "must be non-negative");
  constexpr int kAttemptsPerPose = 2000;
  std::mt19937_64 rng(seed);
  std::vector<Rigid3> poses;
  while (static_cast<int>(poses.size()) < count) {
    std::optional<Rigid3> pose;
    for (int attempt = 0; attempt < kAttemptsPerPose && !pose; ++attempt) {
      pose = try_pose(camera, board, options, rng);
    }
    require(pose.has_value(), "chessboard poses",
            "cannot fit the board in view as asked after " + std::to_string(kAttemptsPerPose) +
                " attempts");
    poses.push_back(*pose);
  }
  return poses;
}

}  // namespace ballsight::sim
