#pragma once
// The pixel cluster fit's model (pixel_cluster_fit.hpp): how much of each patch pixel balls at
// given positions cover, against what the cameras saw, and its fit on Ceres' TinySolver. Inside
// the world layer only.

#include <Eigen/Dense>
#include <algorithm>
#include <optional>
#include <vector>

#include "ballsight/world/pixel_cluster_fit.hpp"

namespace ballsight {

// One blob seen by one camera: its coverage and where plane points fall in it.
struct CoverageView {
  const CoveragePatch* patch = nullptr;
  int camera = 0;
  Vec2 origin_px = Vec2::Zero();  // a detection's centre ...
  Vec2 origin_m = Vec2::Zero();   // ... and its point on the plane
  Eigen::Matrix2d pixel_per_plane = Eigen::Matrix2d::Identity();
  double radius_px = 0.0;      // a ball's disc in the coverage model
  std::vector<float> visible;  // per pixel: share left uncovered by the balls outside the group
  std::vector<bool> hidden;    // per pixel, if not empty: in the fit or not (HiddenPixel)

  Vec2 pixel(const Vec2& x) const { return origin_px + pixel_per_plane * (x - origin_m); }
  bool contains(const Vec2& q) const {
    return q.x() >= patch->x - 0.5 && q.y() >= patch->y - 0.5 &&
           q.x() < patch->x + patch->width - 0.5 && q.y() < patch->y + patch->height - 0.5;
  }
};

// A pixel's share covered by a disc of `radius` at distance `d`: a ramp one pixel wide.
inline double disc_share(double d, double radius) {
  return std::clamp(radius + 0.5 - d, 0.0, 1.0);
}

class CoverageModel {
 public:
  CoverageModel(std::vector<CoverageView> views, double ball_radius_m,
                const PixelFitOptions& options);

  const std::vector<CoverageView>& views() const { return views_; }

  Eigen::Index residual_count(std::size_t balls) const {
    return fitted_ + static_cast<Eigen::Index>(balls * (balls - 1) / 2);
  }

  // The residuals: per fitted patch pixel, predicted - observed coverage; then per pair of balls
  // their overlap over overlap_sigma_m (0 when apart). `jacobian` (if given): their derivatives by
  // the balls' positions, a row per residual and two columns per ball (column-major, as Eigen
  // and Ceres' TinySolver keep it).
  void residuals(const std::vector<Vec2>& balls, double* residuals_out, double* jacobian_out) const;

  // The sum of squared residuals.
  double cost(const std::vector<Vec2>& balls) const {
    Eigen::VectorXd r(residual_count(balls.size()));
    residuals(balls, r.data(), nullptr);
    return r.squaredNorm();
  }

  // Levenberg-Marquardt (Ceres' TinySolver) from `balls`, at most `iterations` steps; returns the
  // final cost with `balls` moved to the optimum, or nullopt (`balls` as they were) when the
  // solution is not finite. One that ran out of steps is used: each step it took lowered the cost.
  std::optional<double> fit(std::vector<Vec2>& balls, int iterations) const;

  // J^T J at `balls`: the information the pixels hold about the positions.
  Eigen::MatrixXd information(const std::vector<Vec2>& balls) const;

  // Per pixel of the group's patches: the residual variance one ball's fit leaves.
  double residual_variance(double cost, std::size_t balls) const {
    const double dof =
        std::max(1.0, static_cast<double>(fitted_) - 2.0 * static_cast<double>(balls));
    return std::max(cost / dof, 1e-3);
  }

 private:
  std::vector<CoverageView> views_;
  Eigen::Index fitted_ = 0;  // patch pixels in the fit (not hidden)
  double radius_;
  const PixelFitOptions& options_;
};

}  // namespace ballsight
