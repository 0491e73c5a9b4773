#pragma once
// Tennis balls in any photo, with no camera model: a court camera's frame or the view ahead of a
// robot. Pixels are classified by the ball colour model (one table read each), blobs grown from
// the seed colour through the growth colour, their holes (seams, logos, highlights) filled, and
// each blob's balls found as circles (blob_circles.hpp): touching balls apart, balls cut by the
// image border with their whole circle.

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/detect/ball_colours.hpp"
#include "ballsight/detect/blob_circles.hpp"
#include "ballsight/detect/blob_growth.hpp"

namespace ballsight {

struct PhotoBall {
  Vec2 center_px = Vec2::Zero();
  double radius_px = 0.0;
  double score = 0.0;  // 0-1
};

struct PhotoBallOptions {
  BallColours colours = default_ball_colours();
  BlobCircleOptions circles;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class PhotoBallDetector {
 public:
  explicit PhotoBallDetector(const PhotoBallOptions& options = {});

  /// Every ball in an 8-bit BGR image, best score first. Reuses internal buffers: one detector
  /// per thread.
  std::vector<PhotoBall> detect(const cv::Mat& bgr);

  const PhotoBallOptions& options() const { return options_; }

 private:
  void find_circles(const cv::Mat& bgr, std::vector<PhotoBall>& out);

  PhotoBallOptions options_;
  ColorClassTable table_;
  BlobGrowthBuffers buffers_;
  GrownBlob blob_;
  cv::Mat1b patch_;
};

}  // namespace ballsight
