#include "ballsight/world/coverage_model.hpp"

#include <ceres/tiny_solver.h>

#include <cmath>

namespace ballsight {

CoverageModel::CoverageModel(std::vector<CoverageView> views, double ball_radius_m,
                             const PixelFitOptions& options)
    : views_(std::move(views)), radius_(ball_radius_m), options_(options) {
  for (const CoverageView& v : views_)
    for (std::size_t k = 0; k < v.patch->coverage.size(); ++k)
      fitted_ += v.hidden.empty() || !v.hidden[k] ? 1 : 0;
}

void CoverageModel::residuals(const std::vector<Vec2>& balls, double* residuals_out,
                              double* jacobian_out) const {
  const Eigen::Index rows = residual_count(balls.size());
  Eigen::Map<Eigen::VectorXd> r(residuals_out, rows);
  Eigen::Map<Eigen::MatrixXd> jacobian_map(jacobian_out, jacobian_out ? rows : 0,
                                           2 * static_cast<Eigen::Index>(balls.size()));
  Eigen::Map<Eigen::MatrixXd>* jacobian = jacobian_out ? &jacobian_map : nullptr;
  if (jacobian) jacobian->setZero();
  std::vector<Vec2> q(balls.size());
  std::vector<std::size_t> rim(balls.size());
  std::vector<double> rim_share(balls.size());
  std::vector<Eigen::RowVector2d> slope(balls.size());  // d share / d ball position
  Eigen::Index row = 0;
  for (const CoverageView& v : views_) {
    for (std::size_t i = 0; i < balls.size(); ++i) q[i] = v.pixel(balls[i]);
    const double reach2 = (v.radius_px + 0.5) * (v.radius_px + 0.5);  // beyond: share 0
    const CoveragePatch& p = *v.patch;
    for (int y = 0; y < p.height; ++y) {
      for (int x = 0; x < p.width; ++x) {
        const auto k = static_cast<std::size_t>(y * p.width + x);
        if (!v.hidden.empty() && v.hidden[k]) continue;
        const Vec2 pixel(p.x + x, p.y + y);
        double free = v.visible[k];
        std::size_t rims = 0;  // the balls whose rim crosses the pixel: rim[0, rims)
        for (std::size_t i = 0; i < balls.size(); ++i) {
          const Vec2 d = pixel - q[i];
          const double d2 = d.squaredNorm();
          if (d2 >= reach2) continue;  // share 0
          const double dist = std::sqrt(d2);
          const double share = disc_share(dist, v.radius_px);
          free *= 1.0 - share;
          if (share >= 1.0 || dist <= 1e-9) continue;  // inside the disc: flat
          rim[rims] = i;
          rim_share[rims] = share;
          slope[rims++] = (d / dist).transpose() * v.pixel_per_plane;
        }
        const double predicted = options_.coverage_gain * (1.0 - free);
        r(row) = std::min(predicted, 1.0) - p.coverage[k];
        if (jacobian && predicted < 1.0) {
          for (std::size_t a = 0; a < rims; ++a)  // d residual / d ball: the others' free share
            jacobian->block<1, 2>(row, 2 * static_cast<Eigen::Index>(rim[a])) =
                options_.coverage_gain * free / (1.0 - rim_share[a]) * slope[a];
        }
        ++row;
      }
    }
  }
  const double touching = 2.0 * radius_;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    for (std::size_t j = i + 1; j < balls.size(); ++j, ++row) {
      const Vec2 d = balls[i] - balls[j];
      const double dist = d.norm();
      r(row) = std::max(0.0, touching - dist) / options_.overlap_sigma_m;
      if (!jacobian || dist >= touching || dist < 1e-9) continue;
      const Eigen::RowVector2d s = -(d / dist).transpose() / options_.overlap_sigma_m;
      jacobian->block<1, 2>(row, 2 * static_cast<Eigen::Index>(i)) = s;
      jacobian->block<1, 2>(row, 2 * static_cast<Eigen::Index>(j)) = -s;
    }
  }
}

Eigen::MatrixXd CoverageModel::information(const std::vector<Vec2>& balls) const {
  const Eigen::Index rows = residual_count(balls.size());
  Eigen::VectorXd r(rows);
  Eigen::MatrixXd jacobian(rows, 2 * static_cast<Eigen::Index>(balls.size()));
  residuals(balls, r.data(), jacobian.data());
  return jacobian.transpose() * jacobian;
}

namespace {

// The coverage residuals as Ceres' TinySolver sees them: the balls' positions as one vector.
// TinySolver, not ceres::Solve: a frame set fits a few dozen hypotheses of a few balls each, and
// the general solver's set-up per solve cost more than the fits themselves (10 ms a frame set
// against 3.8 ms).
struct CoverageResiduals {
  using Scalar = double;
  enum { NUM_RESIDUALS = Eigen::Dynamic, NUM_PARAMETERS = Eigen::Dynamic };

  int NumResiduals() const { return static_cast<int>(model.residual_count(balls)); }
  int NumParameters() const { return static_cast<int>(2 * balls); }
  // TinySolver evaluates a trial step without the Jacobian, then, when it takes the step, the
  // same positions again with it: the Jacobian is made with the residuals and kept for that.
  bool operator()(const double* x, double* residuals, double* jacobian) const {
    const Eigen::Map<const Eigen::VectorXd> at(x, NumParameters());
    if (kept_at.size() != at.size() || kept_at != at) {
      std::vector<Vec2> positions(balls);
      for (std::size_t i = 0; i < balls; ++i) positions[i] = Vec2(x[2 * i], x[2 * i + 1]);
      kept_residuals.resize(NumResiduals());
      kept_jacobian.resize(NumResiduals(), NumParameters());
      model.residuals(positions, kept_residuals.data(), kept_jacobian.data());
      kept_at = at;
    }
    Eigen::Map<Eigen::VectorXd>(residuals, kept_residuals.size()) = kept_residuals;
    if (jacobian)
      Eigen::Map<Eigen::MatrixXd>(jacobian, kept_jacobian.rows(), kept_jacobian.cols()) =
          kept_jacobian;
    return true;
  }

  const CoverageModel& model;
  std::size_t balls;
  mutable Eigen::VectorXd kept_at, kept_residuals;
  mutable Eigen::MatrixXd kept_jacobian;
};

}  // namespace

std::optional<double> CoverageModel::fit(std::vector<Vec2>& balls, int iterations) const {
  const CoverageResiduals function{*this, balls.size(), {}, {}, {}};
  Eigen::VectorXd x(function.NumParameters());
  for (std::size_t i = 0; i < balls.size(); ++i)
    x.segment<2>(2 * static_cast<Eigen::Index>(i)) = balls[i];
  ceres::TinySolver<CoverageResiduals> solver;
  // At most `iterations` steps; stops early when a step lowers the sum of squares by less than a
  // millionth of where it started, or moves the balls by less than a millionth of the norm of
  // their stacked coordinates (10-60 um on a court). The start's residuals are kept for the
  // solver's first step.
  Eigen::VectorXd start(function.NumResiduals());
  function(x.data(), start.data(), nullptr);
  solver.options.max_num_iterations = iterations + 1;  // its count includes the start
  solver.options.function_tolerance = 1e-6 * start.squaredNorm() + 1e-9;
  solver.options.parameter_tolerance = 1e-6;
  const auto& summary = solver.Solve(function, &x);
  // TinySolver reports no failure of its own: a solution that is not finite is none.
  if (!std::isfinite(summary.final_cost) || !x.allFinite()) return std::nullopt;
  for (std::size_t i = 0; i < balls.size(); ++i)
    balls[i] = x.segment<2>(2 * static_cast<Eigen::Index>(i));
  return 2.0 * summary.final_cost;  // Ceres' cost is half the sum of squares
}

}  // namespace ballsight
