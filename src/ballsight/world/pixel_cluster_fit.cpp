#include "ballsight/world/pixel_cluster_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "ballsight/core/error.hpp"
#include "ballsight/world/cluster_refinement.hpp"
#include "ballsight/world/coverage_model.hpp"

namespace ballsight {

void PixelFitOptions::validate() const {
  require(link_distance_radii > 0.0, "pixel fit link_distance_radii", "must be positive");
  require(radius_scale > 0.0 && blur_px >= 0.0 && coverage_gain > 0.0, "pixel fit",
          "radius_scale and coverage_gain must be positive, blur_px non-negative");
  require(ball_penalty > 0.0, "pixel fit ball_penalty", "must be positive");
  require(min_separation_radii >= 0.0, "pixel fit min_separation_radii", "must be non-negative");
  require(overlap_sigma_m > 0.0, "pixel fit overlap_sigma_m", "must be positive");
  require(max_added >= 0 && max_added <= 8, "pixel fit max_added", "must be within [0, 8]");
  require(iterations >= 1, "pixel fit iterations", "must be at least 1");
}

namespace {

// The cost of a hypothesis whose fit the solver could not make: never the best.
constexpr double kUnusable = std::numeric_limits<double>::infinity();

struct Hypothesis {
  std::vector<Vec2> balls;
  double cost = kUnusable;
};

// Where one more ball may start, two kinds. Touching one of the balls, in eight directions:
std::vector<Vec2> touching_one_starts(const std::vector<Vec2>& balls, double radius_m) {
  std::vector<Vec2> starts;
  for (const Vec2& b : balls)
    for (int k = 0; k < 8; ++k) {
      const double angle = k * std::numbers::pi / 4.0;
      starts.push_back(b + 2.0 * radius_m * Vec2(std::cos(angle), std::sin(angle)));
    }
  return starts;
}

// Touching two of the balls at once, on either side of the pair (every start 2 radii from both):
// the gap of a packed cluster, which the eight directions of one ball miss by more than the fit
// recovers.
std::vector<Vec2> touching_two_starts(const std::vector<Vec2>& balls, double radius_m) {
  const double touching = 2.0 * radius_m;
  std::vector<Vec2> starts;
  for (size_t i = 0; i < balls.size(); ++i)
    for (size_t j = i + 1; j < balls.size(); ++j) {
      const Vec2 chord = balls[j] - balls[i];
      const double half = 0.5 * chord.norm();
      if (half >= touching || half == 0.0) continue;
      const Vec2 normal = Vec2(-chord.y(), chord.x()) / (2.0 * half);
      const double height = std::sqrt(touching * touching - half * half);
      for (double side : {-1.0, 1.0})
        starts.push_back(0.5 * (balls[i] + balls[j]) + side * height * normal);
    }
  return starts;
}

// The hypotheses with one ball more started at `starts` (those that keep the balls apart), the
// `count` that explain most before fitting first.
std::vector<Hypothesis> best_starts(const CoverageModel& model, const Hypothesis& current,
                                    const std::vector<Vec2>& starts, double radius_m,
                                    size_t count) {
  std::vector<Hypothesis> out;
  for (const Vec2& start : starts) {
    Hypothesis h{current.balls, 0.0};
    h.balls.push_back(start);
    if (min_separation(h.balls) < 1.9 * radius_m) continue;
    h.cost = model.cost(h.balls);
    out.push_back(std::move(h));
  }
  std::sort(out.begin(), out.end(),
            [](const Hypothesis& a, const Hypothesis& b) { return a.cost < b.cost; });
  out.resize(std::min(out.size(), count));
  return out;
}

// The best fit with one more ball: the two best starts touching one ball and the best touching
// two are fitted.
Hypothesis with_one_more(const CoverageModel& model, const Hypothesis& current, double radius_m,
                         const PixelFitOptions& options) {
  std::vector<Hypothesis> starts =
      best_starts(model, current, touching_one_starts(current.balls, radius_m), radius_m, 2);
  for (Hypothesis& h :
       best_starts(model, current, touching_two_starts(current.balls, radius_m), radius_m, 1))
    starts.push_back(std::move(h));
  Hypothesis best;
  for (Hypothesis& h : starts) {
    h.cost = model.fit(h.balls, options.iterations).value_or(kUnusable);
    if (h.cost < best.cost) best = std::move(h);
  }
  return best;
}

// The best fit with one ball less: the ball whose removal costs least before fitting is removed.
Hypothesis with_one_less(const CoverageModel& model, const Hypothesis& current,
                         const PixelFitOptions& options) {
  Hypothesis best;
  for (size_t i = 0; i < current.balls.size(); ++i) {
    Hypothesis h{current.balls, 0.0};
    h.balls.erase(h.balls.begin() + static_cast<std::ptrdiff_t>(i));
    h.cost = model.cost(h.balls);
    if (h.cost < best.cost) best = std::move(h);
  }
  best.cost = model.fit(best.balls, options.iterations).value_or(kUnusable);
  return best;
}

// The detection an observation was placed from; nullptr where its camera has no frame.
const PixelDetection* detection_of(
    const FieldObservation& o,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections) {
  const auto& list = detections[static_cast<size_t>(o.camera)];
  return list ? &(*list)[static_cast<size_t>(o.detection)] : nullptr;
}

// The blobs (camera, blob index) a fused ball's observations were cut from, ascending.
std::vector<std::pair<int, int>> blobs_of(
    const FusedObject& ball, const std::vector<FieldObservation>& observations,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections) {
  std::vector<std::pair<int, int>> blobs;
  for (int m : ball.observations) {
    const FieldObservation& o = observations[static_cast<size_t>(m)];
    const PixelDetection* d = detection_of(o, detections);
    if (d && d->patch.width > 0) blobs.emplace_back(o.camera, d->patch.blob);
  }
  std::sort(blobs.begin(), blobs.end());
  return blobs;
}

// Groups of balls to fit together: balls near each other, and balls cut from one blob (a blob is
// one coverage patch, fitted once: two groups fitting it apart would each explain its pixels with
// a ball of their own, two estimates of one ball).
std::vector<std::vector<int>> fit_groups(
    const std::vector<FusedObject>& balls, const std::vector<FieldObservation>& observations,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections, double link_m) {
  std::vector<std::vector<std::pair<int, int>>> blobs;
  for (const FusedObject& ball : balls) blobs.push_back(blobs_of(ball, observations, detections));
  return linked_groups(balls.size(), [&](size_t i, size_t j) {
    if ((balls[i].position_m - balls[j].position_m).norm() < link_m) return true;
    // A blob in common: both lists ascending.
    auto a = blobs[i].begin(), b = blobs[j].begin();
    while (a != blobs[i].end() && b != blobs[j].end()) {
      if (*a == *b) return true;
      *a < *b ? ++a : ++b;
    }
    return false;
  });
}

// The views of one group: one per blob its observations `members` come from, where balls outside
// the group cover their share (`visible`) and the robot hides pixels (`hidden`).
std::vector<CoverageView> group_views(
    const std::vector<int>& group, const std::vector<int>& members,
    const std::vector<FieldObservation>& observations, const std::vector<FusedObject>& balls,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections, double ball_radius_m,
    const PixelFitOptions& options, const HiddenPixel& hidden) {
  std::vector<CoverageView> views;
  for (int m : members) {
    const FieldObservation& o = observations[static_cast<size_t>(m)];
    const PixelDetection* found = detection_of(o, detections);
    if (!found || found->patch.width == 0) continue;
    const PixelDetection& d = *found;
    if (std::any_of(views.begin(), views.end(), [&](const CoverageView& v) {
          return v.camera == o.camera && v.patch->blob == d.patch.blob;
        }))
      continue;
    CoverageView v;
    v.patch = &d.patch;
    v.camera = o.camera;
    v.origin_px = d.center_px;
    v.origin_m = o.position_m;
    v.pixel_per_plane = o.plane_per_pixel.inverse();
    const Eigen::JacobiSVD<Eigen::Matrix2d> svd(o.plane_per_pixel);
    v.radius_px = options.radius_scale * ball_radius_m / svd.singularValues()(1) + options.blur_px;
    views.push_back(std::move(v));
  }
  for (CoverageView& v : views) {
    const CoveragePatch& p = *v.patch;
    if (hidden) {
      v.hidden.assign(p.coverage.size(), false);
      for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x)
          v.hidden[static_cast<size_t>(y * p.width + x)] = hidden(v.camera, Vec2(p.x + x, p.y + y));
    }
    v.visible.assign(p.coverage.size(), 1.0f);
    for (size_t b = 0; b < balls.size(); ++b) {
      if (std::find(group.begin(), group.end(), static_cast<int>(b)) != group.end()) continue;
      const Vec2 q = v.pixel(balls[b].position_m);
      if ((q - v.origin_px).norm() > p.width + p.height + v.radius_px) continue;
      for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x)
          v.visible[static_cast<size_t>(y * p.width + x)] *= static_cast<float>(
              1.0 - disc_share((Vec2(p.x + x, p.y + y) - q).norm(), v.radius_px));
    }
  }
  return views;
}

// The balls that explain the views best from `start` (the fusion's), balls removed and added
// while that lowers the cost by more than a ball's penalty; nullopt when the solver found no
// usable fit.
std::optional<Hypothesis> best_hypothesis(const CoverageModel& model, Hypothesis start,
                                          double ball_radius_m, const PixelFitOptions& options) {
  Hypothesis best = start;
  const std::optional<double> fitted = model.fit(best.balls, options.iterations);
  if (!fitted) return std::nullopt;
  best.cost = *fitted;
  const auto remove_unneeded = [&] {
    while (best.balls.size() > 1) {
      Hypothesis fewer = with_one_less(model, best, options);
      if (fewer.cost - best.cost >= options.ball_penalty) break;
      best = std::move(fewer);
    }
  };
  remove_unneeded();
  const size_t wanted = start.balls.size() + static_cast<size_t>(options.max_added);
  const size_t before_adding = best.balls.size();
  // A further ball lowers the cost by at most all of it.
  while (best.balls.size() < wanted && best.cost >= options.ball_penalty) {
    Hypothesis more = with_one_more(model, best, ball_radius_m, options);
    if (best.cost - more.cost < options.ball_penalty) break;
    if (min_separation(more.balls) < options.min_separation_radii * ball_radius_m) break;
    best = std::move(more);
  }
  // A ball added moves its neighbours; one of them may no longer be needed.
  if (best.balls.size() > before_adding) remove_unneeded();
  // The last fit moves the balls a ball added or removed moved; it failing leaves them as the
  // last usable fit had them.
  best.cost = model.fit(best.balls, options.iterations).value_or(best.cost);
  return best;
}

// One group's balls after the fit (the fusion's where there is nothing to fit).
std::vector<FusedObject> fit_group(
    const std::vector<int>& group, const std::vector<FieldObservation>& observations,
    const std::vector<FusedObject>& balls,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections, double ball_radius_m,
    const PixelFitOptions& options, const HiddenPixel& hidden) {
  std::vector<int> members;
  Hypothesis start;
  bool split = false;
  std::vector<FusedObject> as_fused;
  for (int g : group) {
    const FusedObject& ball = balls[static_cast<size_t>(g)];
    members.insert(members.end(), ball.observations.begin(), ball.observations.end());
    start.balls.push_back(ball.position_m);
    as_fused.push_back(ball);
    for (int o : ball.observations)
      split = split || observations[static_cast<size_t>(o)].split_count > 1;
  }
  if (group.size() < 2 && !split) return as_fused;
  std::sort(members.begin(), members.end());
  members.erase(std::unique(members.begin(), members.end()), members.end());
  std::vector<CoverageView> views =
      group_views(group, members, observations, balls, detections, ball_radius_m, options, hidden);
  // One view is enough where a blob was split: its pixels alone say whether it holds the balls
  // it was split into (a far ball seen by one camera only, split in two along its line of sight).
  if (views.empty() || (views.size() < 2 && !split)) return as_fused;
  const CoverageModel model(std::move(views), ball_radius_m, options);
  const std::optional<Hypothesis> best = best_hypothesis(model, start, ball_radius_m, options);
  if (!best) return as_fused;  // the solver found no usable solution: the fusion's balls stay
  const Eigen::MatrixXd information = model.information(best->balls);
  const Eigen::MatrixXd covariance =
      model.residual_variance(best->cost, best->balls.size()) *
      (information + 1e-9 * Eigen::MatrixXd::Identity(information.rows(), information.cols()))
          .inverse();
  std::vector<FusedObject> out;
  for (size_t i = 0; i < best->balls.size(); ++i) {
    FusedObject object;
    object.position_m = best->balls[i];
    object.covariance_m2 =
        covariance.block<2, 2>(2 * static_cast<Eigen::Index>(i), 2 * static_cast<Eigen::Index>(i));
    // Its observations: those whose blob's patch its centre falls into.
    for (int m : members) {
      const FieldObservation& o = observations[static_cast<size_t>(m)];
      const int blob = detection_of(o, detections)->patch.blob;
      const bool inside =
          std::any_of(model.views().begin(), model.views().end(), [&](const CoverageView& v) {
            return v.camera == o.camera && v.patch->blob == blob &&
                   v.contains(v.pixel(object.position_m));
          });
      if (!inside) continue;
      object.observations.push_back(m);
      if (std::find(object.cameras.begin(), object.cameras.end(), o.camera) == object.cameras.end())
        object.cameras.push_back(o.camera);
    }
    std::sort(object.cameras.begin(), object.cameras.end());
    out.push_back(std::move(object));
  }
  return out;
}

}  // namespace

std::vector<FusedObject> fit_clusters_to_pixels(
    const std::vector<FieldObservation>& observations, const std::vector<FusedObject>& balls,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections, double ball_radius_m,
    const PixelFitOptions& options, const HiddenPixel& hidden) {
  options.validate();
  if (!options.enabled) return balls;
  return fit_groups_in_parallel(
      fit_groups(balls, observations, detections, options.link_distance_radii * ball_radius_m),
      [&](const std::vector<int>& group) {
        return fit_group(group, observations, balls, detections, ball_radius_m, options, hidden);
      });
}

}  // namespace ballsight
