#pragma once
// How far a model's ground points are from the truth: error statistics in cm.

#include <cstddef>
#include <span>
#include <vector>

#include "ballsight/calib/omni_ground_model.hpp"
#include "ballsight/calib/simulated_calibration.hpp"

namespace ballsight {

struct ErrorSummary {
  std::size_t count = 0;
  double median = 0.0;
  double mean = 0.0;
  double p95 = 0.0;
  double max = 0.0;
};

/// Statistics of non-negative errors (nearest-rank percentiles); all zero when empty.
ErrorSummary summarize_errors(std::vector<double> errors);

struct GroundErrors {
  ErrorSummary position_cm;      // ground point error (the model's bearing, or the image angle)
  ErrorSummary distance_cm;      // ground distance error
  std::size_t out_of_range = 0;  // queries the model flagged; their errors are counted too
  std::size_t unmapped = 0;      // queries with no finite distance, not counted
};

/// Errors at held-out pixels with known floor points.
GroundErrors ground_errors(const OmniGroundModel& model, std::span<const FloorTruth> truth);

/// Errors on samples: distance always; position only for samples with a bearing.
GroundErrors sample_errors(const OmniGroundModel& model, std::span<const PolarSample> samples);

}  // namespace ballsight
