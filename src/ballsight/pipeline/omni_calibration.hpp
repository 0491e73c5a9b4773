#pragma once
// The omni calibration's steps as one library for the command line (`ballsight omni fit`) and the
// calibration page (`/api/v1/omni/...`, net/omni_calibration_api.hpp): the omnivision paper's
// Figures 5-7, clicked (or found) markers -> polar samples -> a fitted model -> a lookup table,
// with what a user needs to judge the fit: every sample's residual and the distance-vs-radius
// curve of every direction. A frame's image centre is suggested by its mirror's rim
// (find_mirror_rim).

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "ballsight/calib/ground_error.hpp"
#include "ballsight/calib/omni_model_fit.hpp"
#include "ballsight/camera/ground_map.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/core/marker_layout.hpp"
#include "ballsight/detect/mirror_rim.hpp"  // a frame's suggested image centre

namespace ballsight {

/// A point on the floor seen at a pixel: a clicked or found marker.
struct MarkerPoint {
  Vec2 pixel = Vec2::Zero();
  double distance_cm = 0.0;
  std::optional<double> bearing_deg;  // robot bearing, counter-clockwise from forward
};

/// Algorithm 2 of the omnivision paper for every point: polar samples around `image_center`
/// (bearings turned to the image-angle convention of PolarSample).
std::vector<PolarSample> polar_samples_of(std::span<const MarkerPoint> points,
                                          const Vec2& image_center);
/// The inverse: the points of samples taken around `image_center`.
std::vector<MarkerPoint> marker_points_of(std::span<const PolarSample> samples,
                                          const Vec2& image_center);

/// One sample's fit.
struct SampleResidual {
  double predicted_distance_cm = 0.0;       // NaN where the model has no floor point
  double distance_error_cm = 0.0;           // predicted - true
  std::optional<double> bearing_error_deg;  // predicted - true, when both are known
  bool in_range = false;
};

/// Every point's residual under a table made before (checked against new points): the distance
/// and bearing of the table's floor point at the point's pixel (bilinear, as at run time).
std::vector<SampleResidual> table_residuals(const GroundMap& table,
                                            std::span<const MarkerPoint> points);

/// A direction's distance-vs-radius curve over the model's valid radius range.
struct RadialCurve {
  double theta_deg = 0.0;  // image angle
  std::vector<double> radius_px;
  std::vector<double> distance_cm;  // NaN where the model has no floor point
};

struct OmniCalibration {
  std::unique_ptr<OmniGroundModel> model;
  GroundMap table;  // the model baked into ballsight's lookup table
  GroundErrors errors;
  std::vector<SampleResidual> residuals;  // one per sample, in order
};

/// Fits `method` to the samples and bakes the table (what `ballsight omni fit` writes). Throws
/// InputError for bad options, a bad image or too few samples.
OmniCalibration calibrate_omni(OmniMethod method, std::span<const PolarSample> samples,
                               const OmniImage& image, const OmniFitOptions& options = {});

/// `directions` curves, every 360 / directions deg from 0, `points` radii each.
std::vector<RadialCurve> radial_curves(const OmniGroundModel& model, int directions = 12,
                                       int points = 64);

/// The layout's place for points without one: the ray whose bearing is nearest the point's
/// image direction (the paper's convention: image up is forward), and the ring nearest the
/// model's distance when a model is given, else the ring of the point's rank by radius among the
/// points on its ray (nearest first). Points are pixels around `image_center`.
std::vector<MarkerPoint> suggest_layout_places(std::span<const Vec2> pixels,
                                               const Vec2& image_center, const MarkerLayout& layout,
                                               const OmniGroundModel* model = nullptr);

}  // namespace ballsight
