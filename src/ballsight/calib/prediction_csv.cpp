#include "ballsight/calib/prediction_csv.hpp"

#include <cmath>

#include "ballsight/calib/sample_csv.hpp"

namespace ballsight {

std::string format_prediction_csv(const OmniGroundModel& model,
                                  std::span<const PolarSample> samples) {
  const bool with_bearing = any_bearing(samples);
  std::string text = polar_samples_csv_header(with_bearing) +
                     ",predicted_distance_cm,predicted_bearing_deg,in_range\n";
  for (const PolarSample& s : samples) {
    const GroundPrediction p = model.predict(s.theta_deg, s.radius_px);
    text += polar_sample_csv_row(s, with_bearing) + ",";
    if (std::isfinite(p.distance_cm)) text += format_csv_number(p.distance_cm);
    text += ",";
    if (p.bearing_deg) text += format_csv_number(*p.bearing_deg);
    text += p.in_range ? ",1\n" : ",0\n";
  }
  return text;
}

}  // namespace ballsight
