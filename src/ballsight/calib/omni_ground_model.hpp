#pragma once
// The one interface every omni pixel -> ground mapping implements (the paper's polynomial, the
// paper's MLP and ballsight's own model), used by the run time and the lookup-table builder.
// Queries are the paper's image polar coordinates (Algorithm 4) around the model's image centre.

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <span>
#include <string_view>

#include "ballsight/calib/polar_sample.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// The camera image a model belongs to: its size and the centre the polar coordinates use.
struct OmniImage {
  int width = 640;
  int height = 480;
  Vec2 center_px{319.5, 239.5};

  /// Throws InputError naming the field: size in [16, 16384] px, centre inside the image.
  void validate() const;
  /// Whether image polar (theta, radius) around the centre falls inside the image.
  bool contains(double theta_deg, double radius_px) const;
};

/// Pixel radii (around the image centre) where a model is backed by its samples.
struct RadiusRange {
  double min_px = 0.0;
  double max_px = 0.0;

  bool contains(double radius_px) const { return radius_px >= min_px && radius_px <= max_px; }
};

/// Where a model may be queried: the image and the valid radius range.
struct OmniModelDomain {
  OmniImage image;
  RadiusRange valid_radius;

  bool contains(double theta_deg, double radius_px) const {
    return valid_radius.contains(radius_px) && image.contains(theta_deg, radius_px);
  }
};

/// The samples' radius range widened by `margin_fraction` of its span (at least 1 px) each side.
RadiusRange valid_radius_from_samples(std::span<const PolarSample> samples,
                                      double margin_fraction = 0.03);

/// An image that covers the samples' radii with margin around `center_px` (or, when absent, a
/// square image centred on them); `size` (width, height) is used when given. Throws InputError
/// when the result is not a valid image or the samples reach past every image border.
OmniImage omni_image_for_samples(std::span<const PolarSample> samples,
                                 const std::optional<Vec2>& center_px,
                                 const std::optional<Eigen::Vector2i>& size);

/// One mapped query.
struct GroundPrediction {
  double distance_cm = 0.0;  // ground distance from the robot centre; NaN when not on the floor
  /// True ground bearing in the paper's image-angle convention when the model maps direction;
  /// absent when it takes the image direction as the bearing (the paper's Algorithm 5).
  std::optional<double> bearing_deg;
  bool in_range = false;  // inside the model's valid domain
};

class OmniGroundModel {
 public:
  virtual ~OmniGroundModel() = default;

  /// The method's name as the command line spells it: "poly", "paper-mlp", "ballsight".
  virtual std::string_view name() const = 0;
  virtual const OmniModelDomain& domain() const = 0;
  /// Maps an image polar query; out-of-domain queries are flagged, not refused.
  virtual GroundPrediction predict(double theta_deg, double radius_px) const = 0;
  /// The fitted parameters (without domain), as model_json stores them.
  virtual nlohmann::json parameters_json() const = 0;
  /// Height of the camera's effective viewpoint above the floor, when the model knows it.
  virtual std::optional<double> viewpoint_height_cm() const { return std::nullopt; }

  /// Pixel -> ground point in the robot frame (x forward, y left), cm; nullopt out of range.
  std::optional<Vec2> robot_point_cm(const Vec2& pixel) const;
};

/// Ground point in the robot frame (cm) from a prediction for image angle `theta_deg`.
Vec2 robot_point_cm_from_prediction(const GroundPrediction& prediction, double theta_deg);

}  // namespace ballsight
