#include "ballsight/detect/blob_circles.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <opencv2/imgproc.hpp>

namespace ballsight {

namespace {

constexpr int kMaxCirclesPerBlob = 16;

// Squared distances are compared with this relative margin before a square root settles the few
// near a bound, so that every test gives what the distance itself would.
constexpr double kSquareMargin = 1e-9;

// Whether d.norm() < limit (limit > 0).
bool shorter_than(const Vec2& d, double limit) {
  const double squared = d.squaredNorm(), bound = limit * limit;
  if (squared < bound * (1.0 - kSquareMargin)) return true;
  if (squared > bound * (1.0 + kSquareMargin)) return false;
  return d.norm() < limit;
}

// Local maxima of the distance transform (image coordinates), largest first.
std::vector<BlobCircle> distance_maxima(const cv::Mat1f& distance, const BlobMask& blob,
                                        double min_radius) {
  std::vector<BlobCircle> maxima;
  for (int y = 0; y < distance.rows; ++y) {
    for (int x = 0; x < distance.cols; ++x) {
      const double d = distance(y, x);
      if (d < min_radius) continue;
      bool peak = true;
      for (int dy = -1; dy <= 1 && peak; ++dy)
        for (int dx = -1; dx <= 1 && peak; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx >= 0 && ny >= 0 && nx < distance.cols && ny < distance.rows &&
              distance(ny, nx) > distance(y, x))
            peak = false;
        }
      if (peak) maxima.push_back({blob.to_image(x, y), d, 0.0});
    }
  }
  std::stable_sort(maxima.begin(), maxima.end(), [](const BlobCircle& a, const BlobCircle& b) {
    return a.radius_px > b.radius_px;
  });
  return maxima;
}

// Proposals: the largest maximum, then every maximum that lies outside the circles taken so far
// by at least half its own radius (touching balls, a ball partly hidden by another).
std::vector<BlobCircle> propose(const std::vector<BlobCircle>& maxima,
                                const BlobCircleOptions& options) {
  std::vector<BlobCircle> taken;
  for (const BlobCircle& m : maxima) {
    if (m.radius_px > 1.1 * options.max_radius_px + 1.0) continue;
    const bool explained = std::any_of(taken.begin(), taken.end(), [&m](const BlobCircle& t) {
      return (m.center_px - t.center_px).norm() < t.radius_px + 0.5 * m.radius_px;
    });
    if (explained) continue;
    taken.push_back(m);
    if (taken.size() == kMaxCirclesPerBlob) break;
  }
  return taken;
}

// Points of the blob's outline, halfway between a blob pixel and a neighbour outside it; the
// image border is not an outline.
std::vector<Vec2> outline(const BlobMask& blob) {
  static constexpr int kStep[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  const cv::Mat1b& mask = blob.mask;
  // A neighbour (nx, ny) of the mask lies in the image when min_x <= nx <= max_x and the same in
  // y (image pixel origin + (nx, ny), its centre within half a pixel of the image).
  const auto min_x = static_cast<int>(std::ceil(-0.5 - blob.origin.x()));
  const auto max_x = static_cast<int>(std::floor(blob.image_size.width - 0.5 - blob.origin.x()));
  const auto min_y = static_cast<int>(std::ceil(-0.5 - blob.origin.y()));
  const auto max_y = static_cast<int>(std::floor(blob.image_size.height - 0.5 - blob.origin.y()));
  std::vector<Vec2> points;
  for (int y = 0; y < mask.rows; ++y) {
    const std::uint8_t* row = mask.ptr<std::uint8_t>(y);
    const std::uint8_t* above = y > 0 ? mask.ptr<std::uint8_t>(y - 1) : nullptr;
    const std::uint8_t* below = y + 1 < mask.rows ? mask.ptr<std::uint8_t>(y + 1) : nullptr;
    for (int x = 0; x < mask.cols; ++x) {
      if (!row[x]) continue;
      // In kStep's order: whether that neighbour is in the blob.
      const bool inside[4] = {x + 1 < mask.cols && row[x + 1], x > 0 && row[x - 1],
                              below && below[x], above && above[x]};
      if (inside[0] && inside[1] && inside[2] && inside[3]) continue;
      for (int k = 0; k < 4; ++k) {
        const int nx = x + kStep[k][0], ny = y + kStep[k][1];
        if (inside[k] || nx < min_x || ny < min_y || nx > max_x || ny > max_y) continue;
        points.push_back(blob.to_image(x + 0.5 * kStep[k][0], y + 0.5 * kStep[k][1]));
      }
    }
  }
  return points;
}

// Least-squares circle through `points`: algebraic (Kasa) start, then Gauss-Newton on the
// geometric distances. False when the points do not determine a circle.
bool fit_circle(const std::vector<Vec2>& points, Vec2& center, double& radius) {
  if (points.size() < 5) return false;
  Vec2 mean = Vec2::Zero();
  for (const Vec2& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::MatrixX3d a(static_cast<Eigen::Index>(points.size()), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec2 q = points[i] - mean;
    const auto row = static_cast<Eigen::Index>(i);
    a.row(row) << q.x(), q.y(), 1.0;
    b(row) = -q.squaredNorm();
  }
  const Eigen::Vector3d abc = a.colPivHouseholderQr().solve(b);
  Vec2 c = mean - 0.5 * abc.head<2>();
  double r2 = 0.25 * abc.head<2>().squaredNorm() - abc(2);
  if (!(r2 > 0.0) || !std::isfinite(r2)) return false;
  double r = std::sqrt(r2);
  for (int iteration = 0; iteration < 5; ++iteration) {
    Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
    Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
    for (const Vec2& p : points) {
      const Vec2 d = p - c;
      const double n = d.norm();
      if (n < 1e-9) continue;
      const Eigen::Vector3d j(-d.x() / n, -d.y() / n, -1.0);
      jtj += j * j.transpose();
      jtr += j * (n - r);
    }
    const Eigen::Vector3d step = jtj.ldlt().solve(-jtr);
    if (!step.allFinite()) return false;
    c += step.head<2>();
    r += step(2);
    if (step.norm() < 1e-4) break;
  }
  if (!(r > 0.0) || !c.allFinite()) return false;
  center = c;
  radius = r;
  return true;
}

double tolerance(double radius, bool first) {
  return first ? std::max(1.5, 0.25 * radius) : std::max(1.0, 0.12 * radius);
}

// The outline points nearest each circle (within its tolerance). A point outside a circle's
// annulus of squared distances is passed over without a square root.
std::vector<std::vector<Vec2>> assign(const std::vector<Vec2>& points,
                                      const std::vector<BlobCircle>& circles, bool first) {
  struct Annulus {
    double tolerance, min_squared, max_squared;
  };
  std::vector<Annulus> annuli;
  for (const BlobCircle& circle : circles) {
    // The margins are relative to the circle's size, not to the inner bound (near 0 when the
    // tolerance is near the radius).
    const double r = circle.radius_px, t = tolerance(r, first),
                 inner = std::max(0.0, r - t - kSquareMargin * (r + t)), outer = r + t;
    annuli.push_back({t, inner * inner, outer * outer * (1.0 + kSquareMargin)});
  }
  std::vector<std::vector<Vec2>> parts(circles.size());
  for (const Vec2& p : points) {
    std::size_t best = circles.size();
    double best_residual = 0.0;
    for (std::size_t k = 0; k < circles.size(); ++k) {
      const double squared = (p - circles[k].center_px).squaredNorm();
      if (squared < annuli[k].min_squared || squared > annuli[k].max_squared) continue;
      const double residual = std::abs(std::sqrt(squared) - circles[k].radius_px);
      if (residual <= annuli[k].tolerance && (best == circles.size() || residual < best_residual))
        best = k, best_residual = residual;
    }
    if (best < circles.size()) parts[best].push_back(p);
  }
  return parts;
}

// Mean resultant length of the directions from `center` to `points`: 0 for a full circle, near 1
// for a short arc.
double arc_concentration(const std::vector<Vec2>& points, const Vec2& center) {
  Vec2 sum = Vec2::Zero();
  for (const Vec2& p : points) sum += (p - center).normalized();
  return points.empty() ? 1.0 : sum.norm() / static_cast<double>(points.size());
}

void refine(const std::vector<Vec2>& points, std::vector<BlobCircle>& circles) {
  const std::vector<BlobCircle> proposed = circles;
  for (int iteration = 0; iteration < 3; ++iteration) {
    const auto parts = assign(points, circles, iteration == 0);
    for (std::size_t k = 0; k < circles.size(); ++k) {
      Vec2 c = Vec2::Zero();
      double r = 0.0;
      if (arc_concentration(parts[k], circles[k].center_px) > 0.85 || !fit_circle(parts[k], c, r))
        continue;
      const BlobCircle& start = proposed[k];
      if (r < 0.6 * start.radius_px || r > 1.6 * start.radius_px + 1.0 ||
          (c - start.center_px).norm() > 0.6 * start.radius_px + 1.0)
        continue;
      circles[k].center_px = c;
      circles[k].radius_px = r;
    }
  }
}

bool inside_other(const std::vector<BlobCircle>& circles, std::size_t self, const Vec2& q,
                  double margin) {
  for (std::size_t j = 0; j < circles.size(); ++j)
    if (j != self && shorter_than(q - circles[j].center_px, circles[j].radius_px + margin))
      return true;
  return false;
}

// Share of the circle's outline bins holding an outline point, among the bins that are neither
// outside the image nor hidden by another circle (at least 30 % of all bins count).
double outline_support(const std::vector<Vec2>& part, const std::vector<BlobCircle>& circles,
                       std::size_t self, cv::Size image_size) {
  const BlobCircle& circle = circles[self];
  const int bins = std::clamp(static_cast<int>(std::numbers::pi * circle.radius_px), 12, 72);
  std::vector<char> hit(static_cast<std::size_t>(bins), 0);
  for (const Vec2& p : part) {
    const Vec2 d = p - circle.center_px;
    const double angle = std::atan2(d.y(), d.x()) + std::numbers::pi;
    hit[static_cast<std::size_t>(
        std::min(bins - 1, static_cast<int>(angle / (2.0 * std::numbers::pi) * bins)))] = 1;
  }
  int supported = 0, neutral = 0;
  for (int b = 0; b < bins; ++b) {
    if (hit[static_cast<std::size_t>(b)]) {
      ++supported;
      continue;
    }
    const double angle = (b + 0.5) / bins * 2.0 * std::numbers::pi - std::numbers::pi;
    const Vec2 q = circle.center_px + circle.radius_px * Vec2(std::cos(angle), std::sin(angle));
    if (q.x() < -0.5 || q.y() < -0.5 || q.x() > image_size.width - 0.5 ||
        q.y() > image_size.height - 0.5 || inside_other(circles, self, q, 0.5))
      ++neutral;
  }
  return supported / std::max(static_cast<double>(bins - neutral), 0.3 * bins);
}

// Share of blob pixels in the disc (fill) and in the ring just outside it (ring), over pixels
// inside the image and, for the ring, not inside another circle.
void fill_and_ring(const BlobMask& blob, const std::vector<BlobCircle>& circles, std::size_t self,
                   double& fill, double& ring) {
  const cv::Size image_size = blob.image_size;
  const BlobCircle& circle = circles[self];
  const double r = circle.radius_px;
  const double ring_in = r + std::max(1.0, 0.15 * r), ring_out = r + std::max(2.5, 0.5 * r);
  const int step = std::max(1, static_cast<int>(r / 12.0));
  const auto x0 = static_cast<int>(std::floor(circle.center_px.x() - ring_out));
  const auto y0 = static_cast<int>(std::floor(circle.center_px.y() - ring_out));
  const auto x1 = static_cast<int>(std::ceil(circle.center_px.x() + ring_out));
  const auto y1 = static_cast<int>(std::ceil(circle.center_px.y() + ring_out));
  int disc = 0, disc_in = 0, around = 0, around_in = 0;
  for (int y = std::max(0, y0); y <= std::min(image_size.height - 1, y1); y += step) {
    for (int x = std::max(0, x0); x <= std::min(image_size.width - 1, x1); x += step) {
      const Vec2 q(x, y);
      const double d = (q - circle.center_px).norm();
      if (d <= r) {
        ++disc;
        disc_in += blob.contains(q);
      } else if (d >= ring_in && d <= ring_out &&
                 !inside_other(circles, self, q, std::max(1.0, 0.15 * r))) {
        ++around;
        around_in += blob.contains(q);
      }
    }
  }
  fill = disc > 0 ? static_cast<double>(disc_in) / disc : 0.0;
  ring = around > 0 ? static_cast<double>(around_in) / around : 0.0;
}

// The blob's width at `at` across the unit direction `across`, probed every half pixel.
double width_across(const BlobMask& blob, const Vec2& at, const Vec2& across, double reach) {
  double width = 0.0;
  for (const double side : {1.0, -1.0})
    for (double t = 0.5; t <= reach && blob.contains(at + side * t * across); t += 0.5)
      width += 0.5;
  return width;
}

}  // namespace

bool is_clump(const BlobMask& blob, const std::vector<BlobCircle>& circles) {
  bool touching = false;
  for (std::size_t i = 0; i < circles.size(); ++i) {
    for (std::size_t j = i + 1; j < circles.size(); ++j) {
      const BlobCircle &a = circles[i], &b = circles[j];
      const Vec2 join = b.center_px - a.center_px;
      const double d = join.norm();
      if (d < 1e-9 || d > a.radius_px + b.radius_px + 1.0) continue;
      touching = true;
      // The neck lies where the two circles' outlines cross (their radical line).
      const double from_a = std::clamp(
          (d * d + a.radius_px * a.radius_px - b.radius_px * b.radius_px) / (2.0 * d), 0.0, d);
      const Vec2 along = join / d, across(-along.y(), along.x());
      const double reach = 2.0 * std::max(a.radius_px, b.radius_px);
      const double neck = width_across(blob, a.center_px + from_a * along, across, reach);
      const double narrowest = std::min(width_across(blob, a.center_px, across, reach),
                                        width_across(blob, b.center_px, across, reach));
      if (neck > kClumpNeck * narrowest) return false;
    }
  }
  return touching;
}

bool BlobMask::contains(const Vec2& q) const {
  const Vec2 m = q - origin;
  const auto x = static_cast<int>(std::lround(m.x())), y = static_cast<int>(std::lround(m.y()));
  return x >= 0 && y >= 0 && x < mask.cols && y < mask.rows && mask(y, x);
}

std::vector<BlobCircle> circles_in_blob(const BlobMask& blob, const BlobCircleOptions& options) {
  cv::Mat1f distance;
  cv::distanceTransform(blob.mask, distance, cv::DIST_L2, cv::DIST_MASK_5);
  std::vector<BlobCircle> circles =
      propose(distance_maxima(distance, blob, options.min_radius_px - 0.5), options);
  if (circles.empty()) return circles;
  const std::vector<Vec2> points = outline(blob);
  const cv::Size image_size = blob.image_size;
  refine(points, circles);
  const auto parts = assign(points, circles, false);
  std::vector<BlobCircle> kept;
  for (std::size_t k = 0; k < circles.size(); ++k) {
    double fill = 0.0, ring = 0.0;
    fill_and_ring(blob, circles, k, fill, ring);
    BlobCircle circle = circles[k];
    circle.score = outline_support(parts[k], circles, k, image_size) * fill * (1.0 - ring);
    // The size bounds are what is looked for; a measured radius may pass them by 5 %.
    if (circle.score >= options.min_score && circle.radius_px >= 0.95 * options.min_radius_px &&
        circle.radius_px <= 1.05 * options.max_radius_px)
      kept.push_back(circle);
  }
  return kept;
}

}  // namespace ballsight
