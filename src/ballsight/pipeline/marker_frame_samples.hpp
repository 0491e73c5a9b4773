#pragma once
// Calibration without clicking: the floor markers in an omni calibration frame are found by
// colour (detect/omni_blobs.hpp), matched to the known layout (detect/marker_matching.hpp) and
// turned into polar samples (Algorithm 2), ready for any mapping method. When the markers' sizes
// are known, the perspective shift of each blob centroid is removed (calib/marker_centroid.hpp).

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/calib/polar_sample.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/core/marker_layout.hpp"

namespace ballsight {

struct MarkerFrameSamples {
  std::vector<PolarSample> samples;  // one per matched marker
  int blobs = 0;                     // marker-coloured blobs found
};

/// The markers of `layout`, each `diameter_m` across (0: sizes unknown, the blob centroids keep
/// their perspective shift). Throws InputError for an invalid layout or a negative diameter.
std::vector<LayoutMarker> markers_of_diameter(const MarkerLayout& layout, double diameter_m);

/// `layout`: the markers; `marker_bgr`: their colour. With every radius known, the samples are
/// those of the discs' centres (ballsight's model fitted to predict the centroid shifts).
MarkerFrameSamples samples_from_marker_frame(const cv::Mat& bgr,
                                             const std::vector<LayoutMarker>& layout,
                                             const cv::Vec3b& marker_bgr, const Vec2& image_center);

}  // namespace ballsight
