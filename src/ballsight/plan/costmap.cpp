#include "ballsight/plan/costmap.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

constexpr double kBeyondGridM = -1.0;  // what a point off the grid reads: lethal
constexpr double kMarginM = 0.5;       // the grid reaches this far beyond the fence

/// Signed distance from `p` to the axis-aligned box of half extents `half` centred at 0.
double box_distance(const Vec2& p, const Vec2& half) {
  const Vec2 q = p.cwiseAbs() - half;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

/// Signed distance to the nearest obstacle of `court`, exactly.
double obstacle_distance(const DrivableCourt& court, const Vec2& p) {
  double d = std::min({p.x() - court.area_min_m.x(), court.area_max_m.x() - p.x(),
                       p.y() - court.area_min_m.y(), court.area_max_m.y() - p.y()});
  if (court.net) {
    const CourtNet& net = *court.net;
    d = std::min(d, box_distance(p, Vec2(net.body_half_m, net.half_length_m + net.body_half_m)));
  }
  return d;
}

}  // namespace

Costmap::Costmap(const DrivableCourt& court, double resolution_m) : resolution_m_(resolution_m) {
  court.validate();
  require(std::isfinite(resolution_m) && resolution_m >= 0.005 && resolution_m <= 0.5,
          "costmap resolution", "must be in [0.005, 0.5] m");
  if (court.obstacles) discs_ = court.obstacles->discs();
  origin_ = court.area_min_m - Vec2::Constant(kMarginM);
  const Vec2 size = court.area_max_m - court.area_min_m + Vec2::Constant(2.0 * kMarginM);
  cols_ = static_cast<int>(std::ceil(size.x() / resolution_m)) + 1;
  rows_ = static_cast<int>(std::ceil(size.y() / resolution_m)) + 1;
  distance_m_.resize(static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_));
  for (int row = 0; row < rows_; ++row) {
    for (int col = 0; col < cols_; ++col) {
      const Vec2 p = origin_ + resolution_m * Vec2(col, row);
      distance_m_[index(col, row)] = static_cast<float>(obstacle_distance(court, p));
    }
  }
}

std::size_t Costmap::index(int col, int row) const {
  return static_cast<std::size_t>(row) * static_cast<std::size_t>(cols_) +
         static_cast<std::size_t>(col);
}

double Costmap::cell(int col, int row) const {
  return distance_m_[index(col, row)];
}

double Costmap::clearance(const Vec2& p) const {
  const Vec2 g = (p - origin_) / resolution_m_;
  if (!g.allFinite() || g.x() < 0.0 || g.y() < 0.0 || g.x() > cols_ - 1 || g.y() > rows_ - 1) {
    return kBeyondGridM;
  }
  const int col = std::min(static_cast<int>(g.x()), cols_ - 2);
  const int row = std::min(static_cast<int>(g.y()), rows_ - 2);
  const double u = g.x() - col, v = g.y() - row;
  double nearest = (1.0 - v) * ((1.0 - u) * cell(col, row) + u * cell(col + 1, row)) +
                   v * ((1.0 - u) * cell(col, row + 1) + u * cell(col + 1, row + 1));
  for (const ObstacleDisc& d : discs_)
    nearest = std::min(nearest, (p - d.center_m).norm() - d.radius_m);
  return nearest;
}

}  // namespace ballsight
