#include "ballsight/calib/ballsight_model.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/json_fields.hpp"
#include "ballsight/core/statistics.hpp"

namespace ballsight {

namespace {

constexpr std::size_t kMinSamples = 8;
constexpr std::size_t kMinDistances = 3;
using ParamArray = std::array<double, CatadioptricFloorParams::kSize>;

// The floor profile of an ideally mounted rig: r = f sin(phi) / (cos(phi) + xi) for a floor point
// seen at angle phi from the axis, tan(phi) = d / h (the unified model's projection).
struct RadialProfile {
  double xi = 0.0;
  double focal_px = 0.0;
  double height_cm = 0.0;

  static double shape(double distance_cm, double xi, double height_cm) {
    const double phi = std::atan2(distance_cm, height_cm);
    return std::sin(phi) / (std::cos(phi) + xi);
  }
  double radius_px(double distance_cm) const {
    return focal_px * shape(distance_cm, xi, height_cm);
  }
};

// Start values by grid search over xi and height (only the measured height when there is one),
// the focal length by least squares for each, scored by the sum of absolute radius errors
// (robust to a few mislabelled samples).
RadialProfile initial_profile(std::span<const PolarSample> samples,
                              std::optional<double> measured_height_cm) {
  std::vector<double> heights_cm;
  if (measured_height_cm) {
    heights_cm.push_back(*measured_height_cm);
  } else {
    for (double h = 5.0; h <= 500.0; h *= 1.1) heights_cm.push_back(h);
  }
  RadialProfile best;
  double best_cost = INFINITY;
  for (double xi = 0.0; xi <= 2.0 + 1e-9; xi += 0.05) {
    for (double height_cm : heights_cm) {
      double gr = 0.0, gg = 0.0;
      for (const PolarSample& s : samples) {
        const double g = RadialProfile::shape(s.distance_cm, xi, height_cm);
        gr += g * s.radius_px;
        gg += g * g;
      }
      const RadialProfile profile{xi, gr / gg, height_cm};
      double cost = 0.0;
      for (const PolarSample& s : samples) {
        cost += std::abs(profile.radius_px(s.distance_cm) - s.radius_px);
      }
      if (cost < best_cost) {
        best_cost = cost;
        best = profile;
      }
    }
  }
  return best;
}

// How a sample enters the fit. A marker with known bearing under a model without distortion
// gives its reprojection error in pixels (the maximum-likelihood residual for click noise); with
// distortion (whose inverse has no closed form) its floor error scaled to pixel-like units; a
// sample without bearing its distance error, scaled alike.
enum class ResidualKind { kReprojection, kFloorPoint, kDistance };

// One sample as the fit sees it. The floor residuals are in cm scaled by the pixels-per-cm of the
// image around the sample (radially and tangentially), so they are comparable across distances.
struct SampleTerm {
  Vec2 pixel;
  Vec2 target_cm;  // floor point when the bearing is known
  double distance_cm = 0.0;
  ResidualKind kind = ResidualKind::kDistance;
  double inv_radial_cm = 1.0;      // pixels per cm, radially
  double inv_tangential_cm = 1.0;  // pixels per cm, across
};

// The model's floor point at a sample's pixel, a grazing one above the horizon; false where the
// pixel lies beyond the model's image (xi > 1): the residual cannot be evaluated there, and Ceres
// takes a smaller step.
template <typename T>
bool floor_at(const SampleTerm& term, const T* p, T* floor) {
  return floor_point_from_pixel(p, T(term.pixel.x()), T(term.pixel.y()), floor, true);
}

struct ReprojectionResidual {
  const SampleTerm* term;
  template <typename T>
  bool operator()(const T* p, T* residual) const {
    const T floor[2] = {T(term->target_cm.x()), T(term->target_cm.y())};
    T pixel[2];
    if (!pixel_from_floor_point(p, floor, pixel)) return false;
    residual[0] = pixel[0] - T(term->pixel.x());
    residual[1] = pixel[1] - T(term->pixel.y());
    return true;
  }
};

struct PointResidual {
  const SampleTerm* term;
  template <typename T>
  bool operator()(const T* p, T* residual) const {
    T floor[2];
    if (!floor_at(*term, p, floor)) return false;
    const Vec2 radial = term->target_cm.normalized();
    const T ex = floor[0] - T(term->target_cm.x());
    const T ey = floor[1] - T(term->target_cm.y());
    residual[0] = (ex * radial.x() + ey * radial.y()) * term->inv_radial_cm;
    residual[1] = (ey * radial.x() - ex * radial.y()) * term->inv_tangential_cm;
    return true;
  }
};

struct DistanceResidual {
  const SampleTerm* term;
  template <typename T>
  bool operator()(const T* p, T* residual) const {
    T floor[2];
    if (!floor_at(*term, p, floor)) return false;
    using std::sqrt;
    residual[0] = (sqrt(floor[0] * floor[0] + floor[1] * floor[1]) - T(term->distance_cm)) *
                  term->inv_radial_cm;
    return true;
  }
};

// Weak priors: the principal point near the image centre, the mount near the ideal, no
// distortion. They decide what the samples cannot (the yaw without bearings) and barely move
// what they can. The viewpoint height, when measured, with its uncertainty: floor markers
// determine it poorly (docs/omni-calibration.md).
struct PriorResidual {
  static constexpr int kCount = 9;
  Vec2 center_px;
  double inv_center_px;
  double inv_rotation_rad;
  double inv_distortion;
  double height_cm = 0.0;
  double inv_height_cm = 0.0;  // 0: no measured height
  template <typename T>
  bool operator()(const T* p, T* residual) const {
    residual[0] = (p[2] - T(center_px.x())) * inv_center_px;
    residual[1] = (p[3] - T(center_px.y())) * inv_center_px;
    for (int i = 0; i < 3; ++i) residual[2 + i] = p[5 + i] * inv_rotation_rad;
    for (int i = 0; i < 3; ++i) residual[5 + i] = p[8 + i] * inv_distortion;
    residual[8] = (p[4] - T(height_cm)) * inv_height_cm;
    return true;
  }
};

std::vector<SampleTerm> sample_terms(std::span<const PolarSample> samples, const Vec2& center_px,
                                     const RadialProfile& profile, bool distortion) {
  std::vector<SampleTerm> terms;
  terms.reserve(samples.size());
  for (const PolarSample& s : samples) {
    SampleTerm term;
    term.pixel = pixel_from_image_polar({s.theta_deg, s.radius_px}, center_px);
    term.distance_cm = s.distance_cm;
    if (s.bearing_deg) {
      term.kind = distortion ? ResidualKind::kFloorPoint : ResidualKind::kReprojection;
      term.target_cm = robot_point_from_bearing(
          robot_bearing_deg_from_image_theta_deg(*s.bearing_deg), s.distance_cm);
    }
    const double step_cm = 0.5;
    const double px_per_cm = (profile.radius_px(s.distance_cm + step_cm) -
                              profile.radius_px(std::max(0.0, s.distance_cm - step_cm))) /
                             (2.0 * step_cm);
    term.inv_radial_cm = std::isfinite(px_per_cm) && px_per_cm > 1e-4 ? px_per_cm : 1e-4;
    term.inv_tangential_cm = s.radius_px / s.distance_cm;
    terms.push_back(term);
  }
  return terms;
}

// The term's residual block: its cost function and its number of components.
std::pair<ceres::CostFunction*, int> cost_function(const SampleTerm& term) {
  constexpr int n = CatadioptricFloorParams::kSize;
  switch (term.kind) {
    case ResidualKind::kReprojection:
      return {new ceres::AutoDiffCostFunction<ReprojectionResidual, 2, n>(
                  new ReprojectionResidual{&term}),
              2};
    case ResidualKind::kFloorPoint:
      return {new ceres::AutoDiffCostFunction<PointResidual, 2, n>(new PointResidual{&term}), 2};
    case ResidualKind::kDistance:
      break;
  }
  return {new ceres::AutoDiffCostFunction<DistanceResidual, 1, n>(new DistanceResidual{&term}), 1};
}

// The pixel-like residual components of every sample at `p`.
std::vector<double> residual_components(const std::vector<SampleTerm>& terms, const double* p) {
  std::vector<double> components;
  const double* parameters[] = {p};
  for (const SampleTerm& term : terms) {
    const auto [cost, count] = cost_function(term);
    const std::unique_ptr<ceres::CostFunction> owned(cost);
    double r[2];
    if (cost->Evaluate(parameters, r, nullptr)) components.insert(components.end(), r, r + count);
  }
  return components;
}

double robust_sigma(std::vector<double> components) {
  for (double& c : components) c = std::abs(c);
  return 1.4826 * median(std::move(components));  // the MAD of a normal distribution
}

void solve(const std::vector<SampleTerm>& terms, const PriorResidual& prior, const OmniImage& image,
           ceres::LossFunction* loss, const BallsightFitOptions& options, ParamArray& params) {
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  double* p = params.data();
  for (const SampleTerm& term : terms) problem.AddResidualBlock(cost_function(term).first, loss, p);
  problem.AddResidualBlock(
      new ceres::AutoDiffCostFunction<PriorResidual, PriorResidual::kCount,
                                      CatadioptricFloorParams::kSize>(new PriorResidual(prior)),
      nullptr, p);
  // Bounds in to_array() order: xi, focal, principal point, height, rotation (20 deg),
  // distortion.
  const double lower[] = {0.0, 1.0, 0.0, 0.0, 1.0, -0.35, -0.35, -0.35, -1.0, -1.0, -1.0};
  const double upper[] = {
      50.0, 1e5, image.width - 1.0, image.height - 1.0, 1e5, 0.35, 0.35, 0.35, 1.0, 1.0, 1.0};
  for (int i = 0; i < CatadioptricFloorParams::kSize; ++i) {
    problem.SetParameterLowerBound(p, i, lower[i]);
    problem.SetParameterUpperBound(p, i, upper[i]);
  }
  std::vector<int> fixed;  // the distortion terms not fitted stay zero
  for (int i = CatadioptricFloorParams::kDistortionIndex + options.distortion_terms;
       i < CatadioptricFloorParams::kSize; ++i) {
    fixed.push_back(i);
  }
  if (!fixed.empty()) {
    problem.SetManifold(p, new ceres::SubsetManifold(CatadioptricFloorParams::kSize, fixed));
  }
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = options.max_iterations;
  solver.function_tolerance = 1e-12;
  solver.parameter_tolerance = 1e-12;
  solver.logging_type = ceres::SILENT;
  solver.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  // A pass that stops at max_iterations still holds a usable (if unfinished) solution: the next
  // pass or the cross-validation judges it. One the solver could not make is never taken.
  require(summary.IsSolutionUsable(), "ballsight fit",
          "the solver found no usable solution (" + summary.message + ")");
}

// Mean of (bearing - image angle): where the mount's yaw starts.
double initial_yaw_rad(std::span<const PolarSample> samples) {
  double c = 0.0, s = 0.0;
  for (const PolarSample& sample : samples) {
    if (!sample.bearing_deg) continue;
    const double d = rad_from_deg(*sample.bearing_deg - sample.theta_deg);
    c += std::cos(d);
    s += std::sin(d);
  }
  return c == 0.0 && s == 0.0 ? 0.0 : std::atan2(s, c);
}

}  // namespace

void BallsightFitOptions::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require(positive(huber_px), "ballsight huber_px", "expected a positive number");
  require(positive(min_cauchy_px), "ballsight min_cauchy_px", "expected a positive number");
  require(positive(prior_center_px), "ballsight prior_center_px", "expected a positive number");
  require(positive(prior_rotation_deg), "ballsight prior_rotation_deg",
          "expected a positive number");
  require(positive(prior_distortion), "ballsight prior_distortion", "expected a positive number");
  require(
      !viewpoint_height_cm || (std::isfinite(*viewpoint_height_cm) && *viewpoint_height_cm > 0.0),
      "ballsight viewpoint_height_cm", "expected a positive number");
  require(positive(viewpoint_height_sigma_cm), "ballsight viewpoint_height_sigma_cm",
          "expected a positive number");
  require(max_iterations >= 1, "ballsight max_iterations", "expected a positive integer");
  require(distortion_terms >= 0 && distortion_terms <= 3, "ballsight distortion_terms",
          "expected an integer in [0, 3]");
  require(std::isfinite(range_margin_fraction) && range_margin_fraction >= 0.0 &&
              range_margin_fraction <= 0.5,
          "ballsight range_margin_fraction", "expected a number in [0, 0.5]");
}

BallsightGroundModel::BallsightGroundModel(const CatadioptricFloorParams& params,
                                           const OmniModelDomain& domain,
                                           std::optional<RadialWarp> warp)
    : params_(params), domain_(domain), warp_(std::move(warp)) {}

GroundPrediction BallsightGroundModel::predict(double theta_deg, double radius_px) const {
  const double read_px = warp_ ? radius_px + (*warp_)(theta_deg, radius_px) : radius_px;
  const Vec2 pixel = pixel_from_image_polar({theta_deg, read_px}, domain_.image.center_px);
  const ParamArray p = params_.to_array();
  double floor[2];
  if (!floor_point_from_pixel(p.data(), pixel.x(), pixel.y(), floor)) {
    return {std::numeric_limits<double>::quiet_NaN(), std::nullopt, false};
  }
  const Polar ground = polar_from_cartesian({floor[0], floor[1]});
  return {ground.radius, wrap_deg_360(image_theta_deg_from_robot_bearing_deg(ground.theta_deg)),
          domain_.contains(theta_deg, radius_px)};
}

nlohmann::json BallsightGroundModel::parameters_json() const {
  nlohmann::json parameters = {
      {"model", "unified-catadioptric-floor"},
      {"xi", params_.xi},
      {"focal_px", params_.focal_px},
      {"principal_px", {params_.principal_px.x(), params_.principal_px.y()}},
      {"height_cm", params_.height_cm},
      {"rotation_rad",
       {params_.rotation_rad.x(), params_.rotation_rad.y(), params_.rotation_rad.z()}},
      {"distortion", {params_.distortion.x(), params_.distortion.y(), params_.distortion.z()}}};
  if (warp_) parameters["radial_warp"] = warp_->to_json();
  return parameters;
}

BallsightGroundModel BallsightGroundModel::from_parameters_json(const nlohmann::json& parameters,
                                                                const OmniModelDomain& domain) {
  const std::string where = "parameters";
  json_require_string(parameters, "model", where, "unified-catadioptric-floor");
  CatadioptricFloorParams params;
  params.xi = json_number(parameters, "xi", where);
  params.focal_px = json_number(parameters, "focal_px", where);
  params.height_cm = json_number(parameters, "height_cm", where);
  require(params.xi >= 0.0, where + ".xi", "expected a number >= 0");
  require(params.focal_px > 0.0, where + ".focal_px", "expected a positive number");
  require(params.height_cm > 0.0, where + ".height_cm", "expected a positive number");
  const std::vector<double> principal = json_numbers(parameters, "principal_px", where, 2);
  params.principal_px = {principal[0], principal[1]};
  const std::vector<double> rotation = json_numbers(parameters, "rotation_rad", where, 3);
  params.rotation_rad = {rotation[0], rotation[1], rotation[2]};
  const std::vector<double> distortion = json_numbers(parameters, "distortion", where, 3);
  params.distortion = {distortion[0], distortion[1], distortion[2]};
  std::optional<RadialWarp> warp;
  if (parameters.contains("radial_warp")) {
    warp = RadialWarp::from_json(parameters["radial_warp"], where + ".radial_warp");
  }
  return {params, domain, std::move(warp)};
}

RadiusRange monotone_radius_range(const OmniGroundModel& model, const RadiusRange& range, int rays,
                                  double step_px) {
  const double middle = 0.5 * (range.min_px + range.max_px);
  RadiusRange result = range;
  for (int ray = 0; ray < rays; ++ray) {
    const double theta_deg = 360.0 * ray / rays;
    const auto distance = [&](double r) { return model.predict(theta_deg, r).distance_cm; };
    double previous = distance(middle);
    if (!std::isfinite(previous)) return {middle, middle};
    for (double r = middle + step_px; r <= result.max_px; r += step_px) {
      const double d = distance(r);
      if (!(d > previous)) {
        result.max_px = r - step_px;
        break;
      }
      previous = d;
    }
    previous = distance(middle);
    for (double r = middle - step_px; r >= result.min_px; r -= step_px) {
      const double d = distance(r);
      if (!(d < previous)) {
        result.min_px = r + step_px;
        break;
      }
      previous = d;
    }
  }
  return result;
}

BallsightGroundModel fit_physical_ballsight_model(std::span<const PolarSample> samples,
                                                  const OmniImage& image,
                                                  const BallsightFitOptions& options) {
  options.validate();
  image.validate();
  std::set<double> distances;
  for (const PolarSample& s : samples) distances.insert(s.distance_cm);
  require(samples.size() >= kMinSamples && distances.size() >= kMinDistances, "samples",
          "ballsight needs at least " + std::to_string(kMinSamples) + " samples at " +
              std::to_string(kMinDistances) + " distinct distances, got " +
              std::to_string(samples.size()) + " at " + std::to_string(distances.size()));

  const RadialProfile profile = initial_profile(samples, options.viewpoint_height_cm);
  const std::vector<SampleTerm> terms =
      sample_terms(samples, image.center_px, profile, options.distortion_terms > 0);
  CatadioptricFloorParams start;
  start.xi = profile.xi;
  start.focal_px = profile.focal_px;
  start.height_cm = profile.height_cm;
  start.principal_px = image.center_px;
  start.rotation_rad = {0.0, 0.0, initial_yaw_rad(samples)};
  ParamArray params = start.to_array();

  PriorResidual prior{image.center_px, 1.0 / options.prior_center_px,
                      1.0 / rad_from_deg(options.prior_rotation_deg),
                      1.0 / options.prior_distortion};
  if (options.viewpoint_height_cm) {
    prior.height_cm = *options.viewpoint_height_cm;
    prior.inv_height_cm = 1.0 / options.viewpoint_height_sigma_cm;
  }
  ceres::HuberLoss huber(options.huber_px);
  solve(terms, prior, image, &huber, options, params);
  const double sigma = robust_sigma(residual_components(terms, params.data()));
  ceres::CauchyLoss cauchy(std::max(options.min_cauchy_px, 2.5 * sigma));
  solve(terms, prior, image, &cauchy, options, params);

  const CatadioptricFloorParams fitted = CatadioptricFloorParams::from_array(params);
  const RadiusRange sampled = valid_radius_from_samples(samples, options.range_margin_fraction);
  const RadiusRange monotone =
      monotone_radius_range(BallsightGroundModel(fitted, {image, sampled}), sampled);
  require(monotone.max_px > monotone.min_px, "samples",
          "the fitted ballsight model maps no radius range monotonically; check the samples");
  return {fitted, {image, monotone}};
}

}  // namespace ballsight
