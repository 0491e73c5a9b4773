#pragma once
// Tennis balls in any photo, with no camera model: a court camera's frame or the view ahead of a
// robot. Pixels are classified by the ball colour model (one table read each), blobs grown from
// the seed colour through the growth colour, their holes (seams, logos, highlights) filled, and
// each blob's balls found as circles (blob_circles.hpp): touching balls apart, balls cut by the
// image border with their whole circle. A circle is kept when it is mostly of a seed colour,
// smooth (a ball's felt, not a patch of weeds) and stands out from its ring; a small one also
// when nothing of a ball's colour lies around it but its own clump (docs/detect-balls.md).

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/detect/ball_colours.hpp"
#include "ballsight/detect/blob_circles.hpp"
#include "ballsight/detect/blob_growth.hpp"
#include "ballsight/detect/colour_cast.hpp"
#include "ballsight/detect/contrast_split.hpp"
#include "ballsight/detect/floor_colours.hpp"

namespace ballsight {

struct PhotoBall {
  Vec2 center_px = Vec2::Zero();
  double radius_px = 0.0;
  double score = 0.0;  // 0-1
};

struct PhotoBallOptions {
  BallColours colours = default_ball_colours();
  BlobCircleOptions circles;
  /// A blob that is not of balls alone (a floor, a wall, a court of the balls' own hue) is
  /// searched for the balls on it split by contrast (contrast_split.hpp).
  ContrastSplit split;
  /// Horizontal bands of the image searched in parallel (cv::parallel_for_); 0: one per OpenCV
  /// thread. The balls found, and their order, do not depend on it: a blob belongs to the band of
  /// its first seed pixel (row by row).
  int bands = 0;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class PhotoBallDetector {
 public:
  explicit PhotoBallDetector(const PhotoBallOptions& options = {});

  /// Every ball in an 8-bit BGR image, best score first. Reuses internal buffers: one detector
  /// per thread (it runs its bands on OpenCV's threads itself).
  std::vector<PhotoBall> detect(const cv::Mat& bgr);

  const PhotoBallOptions& options() const { return options_; }

 private:
  // A ball, the blob it was found in, and whether that blob's balls are a clump of touching
  // balls (is_clump).
  struct Found {
    PhotoBall ball;
    double hue_deg = 0.0;  // of its seed pixels
    // The least yellowness (min(R, G) - B) of a pixel of its colour: 0, or the threshold of the
    // contrast split it was found in (its surroundings are of its hue, but less yellow).
    int min_yellowness = 0;
    int blob = 0;
    bool clump = false;
  };
  // What one band's search works with, and the balls of the blobs it owns (first seed first;
  // the blobs that hold a ball numbered from 0).
  struct Band {
    BlobGrowthBuffers buffers;
    GrownBlob blob;
    cv::Mat1b patch;
    int blobs = 0;
    std::vector<Found> found;
    std::vector<int> floor;  // the pixels of the floor blobs it grew (find_circles)
  };

  // One search of the whole image with the table active(): the balls of every band, and the
  // floor blobs' pixels.
  void search(const cv::Mat& bgr);
  void scan_band(const cv::Mat& bgr, cv::Range rows, Band& band) const;
  void find_circles(const cv::Mat& bgr, Band& band) const;
  // The balls of `grown` into band.found (Found::min_yellowness); returns the area of their
  // discs.
  double fit_blob(const cv::Mat& bgr, const GrownBlob& grown, int min_yellowness, Band& band) const;
  // The balls of band.blob, which is not of balls alone, apart by their contrast with the rest
  // (contrast_split.hpp), when it is large and smooth enough.
  void find_balls_by_contrast(const cv::Mat& bgr, Band& band) const;
  // The share of `blob`'s pixels of a seed colour.
  double seed_share(const GrownBlob& blob) const;
  // Takes the colours that make up the floor blobs out of the ball classes (into floor_table_,
  // then active); false when there is none to take.
  bool exclude_floor_colours(const cv::Mat& bgr);
  // The balls found (best score first), less the small ones that do not stand apart.
  std::vector<PhotoBall> keep_isolated(const cv::Mat& bgr, const std::vector<Found>& found) const;
  // The table the search classifies with: the colour model's (corrected for a warm cast), or
  // that less the floor's colours.
  const ColorClassTable& active() const { return floor_excluded_ ? *floor_table_ : base(); }
  // The colour model's table, corrected for this photo's warm cast if it has one.
  const ColorClassTable& base() const { return table_.current(); }

  PhotoBallOptions options_;
  CastCorrectedTable table_;
  std::optional<ColorClassTable> floor_table_;  // base() less this image's floor colours
  bool floor_excluded_ = false;                 // whether the search uses floor_table_
  FloorColours floor_colours_;
  std::vector<Band> bands_;
  cv::Mat1b classes_;  // the image's pixels classified by active() (search)
};

}  // namespace ballsight
