#pragma once
// Calibration without clicking: the floor markers in an omni calibration frame are found by
// colour (detect/omni_blobs.hpp), matched to the known layout (detect/marker_matching.hpp) and
// turned into polar samples (Algorithm 2), ready for any mapping method.

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/calib/polar_sample.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct MarkerFrameSamples {
  std::vector<PolarSample> samples;  // one per matched marker
  int blobs = 0;                     // marker-coloured blobs found
};

/// `layout_in_robot`: the markers' positions in the robot frame (m); `marker_bgr`: their colour.
MarkerFrameSamples samples_from_marker_frame(const cv::Mat& bgr,
                                             const std::vector<Vec2>& layout_in_robot,
                                             const cv::Vec3b& marker_bgr, const Vec2& image_center);

}  // namespace ballsight
