#include "ballsight/eval/omni_auto_calibration.hpp"

#include "ballsight/calib/marker_samples.hpp"
#include "ballsight/detect/marker_matching.hpp"
#include "ballsight/detect/omni_blobs.hpp"
#include "ballsight/pipeline/omni_pipelines.hpp"

namespace ballsight {

MarkerFrameSamples samples_from_marker_frame(const cv::Mat& bgr,
                                             const std::vector<Vec2>& layout_in_robot,
                                             const cv::Vec3b& marker_bgr,
                                             const Vec2& image_center) {
  constexpr ColorClassMask kMarker = 1;
  const ColorClassTable table({{kMarker, yuv_range_around(marker_bgr, 0.6)}});
  OmniBlobOptions options;
  options.image_center = image_center;
  options.min_radius_px = 20.0;
  options.max_radius_px = 0.5 * std::min(bgr.cols, bgr.rows);
  const std::vector<OmniBlob> blobs = OmniBlobFinder(bgr.size(), options).find(bgr, table, kMarker);

  std::vector<Vec2> pixels;
  for (const OmniBlob& blob : blobs) pixels.push_back(blob.centroid_px);
  MarkerMatchOptions match_options;
  match_options.image_center = image_center;
  std::vector<MarkerObservation> observations;
  for (const MarkerMatch& m : match_markers_to_layout(pixels, layout_in_robot, match_options)) {
    observations.push_back({m.pixel, layout_in_robot[static_cast<size_t>(m.layout_index)]});
  }
  return {samples_from_markers(observations, image_center), static_cast<int>(blobs.size())};
}

}  // namespace ballsight
