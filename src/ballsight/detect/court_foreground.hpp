#pragma once
// What a fixed court camera sees that is not the empty court: background subtraction against a
// view of the court with nothing on it, taken once when the installation is set up (the cameras
// do not move; in the simulator, the court rendered empty under the scene's light and exposure).
// Each blob of changed pixels is reported as an obstacle's view (ObjectClass::obstacle) with its
// pixels as the coverage patch; the world model puts together the views of two or more cameras
// to find what stands on the floor and where (world/floor_obstacles.hpp), as multi-camera
// occupancy maps do (Khan & Shah, "A Multiview Approach to Tracking People in Crowded Scenes
// using a Planar Homography Constraint", ECCV 2006; Fleuret et al., "Multicamera People Tracking
// with a Probabilistic Occupancy Map", PAMI 2008).
//
// Balls, the robot and its markers are blobs too; the world model leaves them out by where they
// are. Work is on every other pixel of every other row (obstacles are large).

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/core/pixel_detection.hpp"

namespace ballsight {

struct ForegroundOptions {
  /// A pixel changed: its B, G and R differ from the empty court's by more than this in sum
  /// (every other pixel of every other row; the sensor's noise is a few levels).
  int threshold = 45;
  double min_area_px = 80;  // smaller blobs (full-resolution pixels) are left out: balls, noise

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class CourtForeground {
 public:
  /// `empty_court`: the camera's 8-bit BGR view of the court with nothing on it.
  CourtForeground(const cv::Mat& empty_court, const ForegroundOptions& options = {});

  /// The blobs of `frame` (the empty court's size and type) that differ from the empty court,
  /// largest first.
  std::vector<PixelDetection> detect(const cv::Mat& frame) const;

 private:
  cv::Mat half(const cv::Mat& bgr) const;  // every other pixel of every other row

  ForegroundOptions options_;
  cv::Size size_;
  cv::Mat background_;  // half(empty_court)
};

}  // namespace ballsight
