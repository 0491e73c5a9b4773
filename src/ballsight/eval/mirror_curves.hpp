#pragma once
// How the simulator's mirrors compare with real ones: the image radius of a floor point against
// its distance, for each simulated mirror kind (straight ahead, the rig untilted and centred)
// and each real calibration set (the mean over its directions at each calibrated distance).
// `ballsight eval mirror-curves` prints them as a table and draws them (docs/sim-omni.md).

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/eval/omni_real.hpp"

namespace ballsight {

struct MirrorCurve {
  std::string name;  // "sim unified", ..., or the real set's name
  bool simulated = false;
  std::vector<double> distance_m;  // increasing
  std::vector<double> radius_px;   // from the image centre (a real set's) or principal point

  /// The radius at distance `d_m`: linear between the curve's points; nullopt outside them.
  std::optional<double> radius_at(double d_m) const;
  /// The radius where the curve has a point within 1 mm of `d_m`, else nullopt.
  std::optional<double> radius_sampled_at(double d_m) const;
};

/// Every simulated mirror kind (camera/mirror_tracer.hpp), from `min_m` to `max_m` every `step_m`
/// (points the mirror does not image left out). Throws InputError for a bad range or step.
std::vector<MirrorCurve> simulated_mirror_curves(double min_m = 0.3, double max_m = 7.0,
                                                 double step_m = 0.05);

/// One curve per real set: its distances and the mean radius of each.
std::vector<MirrorCurve> real_mirror_curves(const std::vector<RealOmniSet>& sets);

/// Two panels: the radius in pixels against the distance, and the radius over each curve's own
/// radius at 1 m (the shapes, whatever the image's scale). Simulated curves are lines, real sets
/// points joined by thin lines.
cv::Mat plot_mirror_curves(const std::vector<MirrorCurve>& curves);

/// A text table: one row per curve, one column per distance of `columns_m` (the radius, px; a
/// real set's between its distances linear and marked "~"; blank beyond a curve's ends).
std::string mirror_curves_table(const std::vector<MirrorCurve>& curves,
                                const std::vector<double>& columns_m);

/// {"curves": [{"name", "simulated", "distance_m": [...], "radius_px": [...]}]}.
nlohmann::json mirror_curves_json(const std::vector<MirrorCurve>& curves);

}  // namespace ballsight
