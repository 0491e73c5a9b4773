#include "ballsight/sim/chessboard.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"

namespace ballsight::sim {

void ChessboardSpec::validate() const {
  require(inner_cols >= 2 && inner_cols <= 50, "board.inner_cols", "must be in [2, 50]");
  require(inner_rows >= 2 && inner_rows <= 50, "board.inner_rows", "must be in [2, 50]");
  require(std::isfinite(square_m) && square_m > 0.0 && square_m <= 1.0, "board.square_m",
          "must be in (0, 1] m");
  require(std::isfinite(border_m) && border_m >= 0.0 && border_m <= 1.0, "board.border_m",
          "must be in [0, 1] m");
}

std::vector<Vec3> ChessboardSpec::inner_corners() const {
  std::vector<Vec3> corners;
  for (int r = 0; r < inner_rows; ++r) {
    for (int c = 0; c < inner_cols; ++c) corners.emplace_back(c * square_m, r * square_m, 0.0);
  }
  return corners;
}

cv::Rect2d ChessboardSpec::outline() const {
  const double margin = square_m + border_m;
  return {-margin, -margin, (inner_cols - 1) * square_m + 2.0 * margin,
          (inner_rows - 1) * square_m + 2.0 * margin};
}

void ChessboardRenderOptions::validate() const {
  require(samples_per_axis >= 1 && samples_per_axis <= 16, "samples_per_axis",
          "must be in [1, 16]");
  for (const double v : {black, white, background}) {
    require(std::isfinite(v) && v >= 0.0 && v <= 255.0, "grey levels", "must be in [0, 255]");
  }
  effects.validate();
}

std::optional<std::vector<Vec2>> chessboard_corner_pixels(const PinholeCamera& camera,
                                                          const ChessboardSpec& board,
                                                          const Rigid3& camera_from_board) {
  std::vector<Vec2> pixels;
  for (const Vec3& corner : board.inner_corners()) {
    const std::optional<Vec2> pixel = camera.project(camera_from_board * corner);
    if (!pixel) return std::nullopt;
    pixels.push_back(*pixel);
  }
  return pixels;
}

std::optional<std::vector<Vec2>> chessboard_outline_pixels(const PinholeCamera& camera,
                                                           const ChessboardSpec& board,
                                                           const Rigid3& camera_from_board,
                                                           int per_side) {
  const cv::Rect2d r = board.outline();
  const Vec2 corners[] = {
      {r.x, r.y}, {r.x + r.width, r.y}, {r.x + r.width, r.y + r.height}, {r.x, r.y + r.height}};
  std::vector<Vec2> pixels;
  for (int side = 0; side < 4; ++side) {
    const Vec2& a = corners[side];
    const Vec2& b = corners[(side + 1) % 4];
    for (int k = 0; k < per_side; ++k) {
      const Vec2 p = a + (b - a) * (static_cast<double>(k) / per_side);
      const std::optional<Vec2> pixel = camera.project(camera_from_board * Vec3(p.x(), p.y(), 0));
      if (!pixel) return std::nullopt;
      pixels.push_back(*pixel);
    }
  }
  return pixels;
}

cv::Mat render_chessboard(const PinholeCamera& camera, const RayTable& rays,
                          const ChessboardSpec& board, const Rigid3& camera_from_board,
                          const ChessboardRenderOptions& options, std::uint64_t noise_seed) {
  board.validate();
  options.validate();
  require(rays.width() == camera.width() && rays.height() == camera.height(), "ray table",
          "must be the camera's");
  cv::Mat1f grey(camera.height(), camera.width(), static_cast<float>(options.background));

  // Supersample only the board's bounding box (the whole image if its outline fails to project).
  cv::Rect box(0, 0, camera.width(), camera.height());
  if (const auto outline = chessboard_outline_pixels(camera, board, camera_from_board)) {
    std::vector<cv::Point2f> points;
    for (const Vec2& p : *outline) {
      points.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
    }
    box = (cv::boundingRect(points) + cv::Size(4, 4) - cv::Point(2, 2)) & box;
  }

  const Rigid3 board_from_camera = camera_from_board.inverse();
  const Vec3 origin = board_from_camera.translation;
  const cv::Rect2d outline = board.outline();
  const double s = board.square_m;
  const double squares_max_x = board.inner_cols * s, squares_max_y = board.inner_rows * s;
  const int n = options.samples_per_axis;
  const auto sample = [&](const Vec3& ray_in_camera) {
    const Vec3 d = board_from_camera.rotation * ray_in_camera;
    if (d.z() == 0.0) return options.background;
    const double t = -origin.z() / d.z();
    if (!(t > 0.0)) return options.background;
    const double x = origin.x() + t * d.x(), y = origin.y() + t * d.y();
    if (!outline.contains(cv::Point2d(x, y))) return options.background;
    if (x < -s || y < -s || x >= squares_max_x || y >= squares_max_y) return options.white;
    const auto i = static_cast<long>(std::floor(x / s)), j = static_cast<long>(std::floor(y / s));
    return ((i + j) & 1) == 0 ? options.black : options.white;
  };
  for (int y = box.y; y < box.y + box.height; ++y) {
    for (int x = box.x; x < box.x + box.width; ++x) {
      double sum = 0.0;
      for (int sy = 0; sy < n; ++sy) {
        for (int sx = 0; sx < n; ++sx) {
          sum += sample(rays.interpolate(x + (sx + 0.5) / n - 0.5, y + (sy + 0.5) / n - 0.5));
        }
      }
      grey(y, x) = static_cast<float>(sum / (n * n));
    }
  }
  cv::Mat bgr;
  cv::Mat grey8;
  grey.convertTo(grey8, CV_8U);
  cv::cvtColor(grey8, bgr, cv::COLOR_GRAY2BGR);
  apply_image_effects(bgr, options.effects, noise_seed);
  return bgr;
}

}  // namespace ballsight::sim
