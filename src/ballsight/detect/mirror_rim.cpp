#include "ballsight/detect/mirror_rim.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace ballsight {
namespace {

struct Circle {
  Vec2 center = Vec2::Zero();
  double radius = 0.0;
};

/// Kasa's fit: x^2 + y^2 + a x + b y + c = 0 in least squares; nullopt for a degenerate set.
std::optional<Circle> algebraic_circle(const std::vector<Vec2>& points) {
  if (points.size() < 3) return std::nullopt;
  Eigen::MatrixXd a(points.size(), 3);
  Eigen::VectorXd b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    a.row(static_cast<Eigen::Index>(i)) << points[i].x(), points[i].y(), 1.0;
    b(static_cast<Eigen::Index>(i)) = -points[i].squaredNorm();
  }
  const Eigen::Vector3d p = a.colPivHouseholderQr().solve(b);
  const Vec2 center(-0.5 * p(0), -0.5 * p(1));
  const double r2 = center.squaredNorm() - p(2);
  if (!std::isfinite(r2) || r2 <= 0.0) return std::nullopt;
  return Circle{center, std::sqrt(r2)};
}

double distance_to(const Circle& c, const Vec2& p) {
  return std::abs((p - c.center).norm() - c.radius);
}

}  // namespace

std::optional<MirrorRim> find_mirror_rim(const cv::Mat& bgr, const MirrorRimOptions& options) {
  if (bgr.empty() || bgr.type() != CV_8UC3) return std::nullopt;
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::GaussianBlur(grey, grey, cv::Size(5, 5), 0.0);
  cv::Mat bright;
  cv::threshold(grey, bright, 0.0, 255.0, cv::THRESH_BINARY | cv::THRESH_OTSU);
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(bright, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  const auto largest = std::max_element(
      contours.begin(), contours.end(),
      [](const auto& a, const auto& b) { return cv::contourArea(a) < cv::contourArea(b); });
  if (largest == contours.end()) return std::nullopt;

  // The outline where it is the rim, not the image border.
  constexpr int kBorderPx = 2;
  std::vector<Vec2> rim;
  for (const cv::Point& p : *largest) {
    if (p.x >= kBorderPx && p.y >= kBorderPx && p.x < bgr.cols - kBorderPx &&
        p.y < bgr.rows - kBorderPx) {
      rim.emplace_back(p.x, p.y);
    }
  }
  std::optional<Circle> circle = algebraic_circle(rim);
  if (!circle) return std::nullopt;
  constexpr double kInlierPx = 3.0;
  std::vector<Vec2> inliers;
  for (const Vec2& p : rim) {
    if (distance_to(*circle, p) <= kInlierPx) inliers.push_back(p);
  }
  circle = algebraic_circle(inliers);
  if (!circle) return std::nullopt;

  double sum_sq = 0.0;
  for (const Vec2& p : inliers) sum_sq += std::pow(distance_to(*circle, p), 2);
  MirrorRim result;
  result.center_px = circle->center;
  result.radius_px = circle->radius;
  result.rms_px = std::sqrt(sum_sq / static_cast<double>(inliers.size()));
  // Contour points are about one pixel apart along the outline (8-connected: up to sqrt 2).
  result.coverage = std::min(
      1.0, static_cast<double>(inliers.size()) / (2.0 * std::numbers::pi * circle->radius));
  const bool inside = circle->center.x() >= 0.0 && circle->center.y() >= 0.0 &&
                      circle->center.x() < bgr.cols && circle->center.y() < bgr.rows;
  if (!inside || result.coverage < options.min_coverage || result.rms_px > options.max_rms_px) {
    return std::nullopt;
  }
  return result;
}

}  // namespace ballsight
