#pragma once
// The figure of `ballsight omni inspect --plot`: ground distance against pixel radius for
// several directions with the monotonic limit marked, and a heat map of the ground distance
// over the image with a scale bar.

#include <filesystem>
#include <opencv2/core.hpp>

#include "ballsight/calib/lut_inspect.hpp"

namespace ballsight {

/// A BGR figure of `lut` and its inspection.
cv::Mat plot_lut_inspection(const InspectedLut& lut, const LutInspection& inspection);

}  // namespace ballsight
