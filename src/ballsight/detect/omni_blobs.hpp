#pragma once
// ballsight's omni blob finder (balls and calibration markers): seeds on a sparse grid inside the
// mirror annulus, grows each seed into a 4-connected blob through the colour-class table (only
// pixels near a blob are ever classified) and measures the whole blob: area, sub-pixel centroid,
// angular position and the radial extent of the silhouette around the image centre.

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/detect/color_classes.hpp"

namespace ballsight {

struct OmniBlobOptions {
  Vec2 image_center{319.5, 239.5};
  double min_radius_px = 40.0;   // inside: the robot's own body
  double max_radius_px = 240.0;  // outside: beyond the mirror
  int seed_step_px = 2;          // a blob at least this wide in x and y is always seeded
  int min_area_px = 3;
  int max_area_px = 40000;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct OmniBlob {
  Vec2 centroid_px = Vec2::Zero();  // mean of the blob's pixel centres
  int area_px = 0;
  cv::Rect bbox;
  Polar centroid_polar;          // image polar coordinates of the centroid (Algorithm 2)
  double inner_radius_px = 0.0;  // silhouette extent along the centroid's ray
  double outer_radius_px = 0.0;
  std::vector<cv::Point> pixels;  // every pixel of the blob
};

class OmniBlobFinder {
 public:
  OmniBlobFinder(cv::Size image_size, const OmniBlobOptions& options);

  /// Every blob of the given colour classes, largest first.
  std::vector<OmniBlob> find(const cv::Mat& bgr, const ColorClassTable& table,
                             ColorClassMask mask) const;

 private:
  cv::Size size_;
  OmniBlobOptions options_;
  std::vector<int> seeds_;  // pixel indices on the seed grid inside the annulus
};

}  // namespace ballsight
