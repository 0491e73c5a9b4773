#include "ballsight/pipeline/marker_frame_samples.hpp"

#include <cmath>

#include "ballsight/calib/marker_centroid.hpp"
#include "ballsight/calib/marker_samples.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/detect/marker_matching.hpp"
#include "ballsight/detect/omni_blobs.hpp"
#include "ballsight/pipeline/omni_pipelines.hpp"

namespace ballsight {

std::vector<LayoutMarker> markers_of_diameter(const MarkerLayout& layout, double diameter_m) {
  require(std::isfinite(diameter_m) && diameter_m >= 0.0, "marker diameter",
          "must be a non-negative number of metres");
  std::vector<LayoutMarker> markers = layout_markers(layout);
  for (LayoutMarker& m : markers) m.radius_m = 0.5 * diameter_m;
  return markers;
}

MarkerFrameSamples samples_from_marker_frame(const cv::Mat& bgr,
                                             const std::vector<LayoutMarker>& layout,
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
  std::vector<Vec2> layout_in_robot;
  bool sizes_known = true;
  for (const LayoutMarker& m : layout) {
    layout_in_robot.push_back(m.p_in_robot);
    sizes_known = sizes_known && m.radius_m > 0.0;
  }
  MarkerMatchOptions match_options;
  match_options.image_center = image_center;
  std::vector<FoundDisc> discs;
  for (const MarkerMatch& m : match_markers_to_layout(pixels, layout_in_robot, match_options)) {
    const LayoutMarker& marker = layout[static_cast<size_t>(m.layout_index)];
    discs.push_back({m.pixel, marker.p_in_robot, marker.radius_m});
  }
  const int blob_count = static_cast<int>(blobs.size());
  if (sizes_known && !discs.empty()) {
    return {debiased_disc_samples(discs, {bgr.cols, bgr.rows, image_center}), blob_count};
  }
  std::vector<MarkerObservation> observations;
  for (const FoundDisc& disc : discs) observations.push_back({disc.centroid_px, disc.p_in_robot});
  return {samples_from_markers(observations, image_center), blob_count};
}

}  // namespace ballsight
