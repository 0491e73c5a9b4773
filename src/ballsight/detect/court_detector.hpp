#pragma once
// ballsight's detector for a fixed court camera: tennis balls and the robot's two colour markers.
//
// - Colour classes from a table (one read per pixel, hue bands: sun, shade and exposure changes
//   keep the hue), seeded on a sparse grid whose step follows the smallest object's apparent size
//   at each place of the image, and only where the camera sees the field area: the sky, the
//   distant ground and places where a ball would be too small to see are never read.
// - Each seed is grown through a looser class (mixed rim pixels), then measured by its colour
//   evidence above the local background: a sub-pixel centre (centroid of the coverage).
// - Size and shape are checked against the size the object must have at that place
//   (ApparentSizeMap): blobs much larger than a few objects or thinner than one are rejected;
//   blobs of touching balls are counted by their evidence and elongation and split (k-means).
// - Every detection carries its blob's coverage patch (the world model fits merged clusters of
//   balls to it) and the expected error of its centre: noise, shading, splitting and
//   partial occlusion, from which world gates and weights observations.

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/camera/field_camera.hpp"
#include "ballsight/core/field_rect.hpp"
#include "ballsight/core/pixel_detection.hpp"
#include "ballsight/detect/apparent_size.hpp"
#include "ballsight/detect/blob_growth.hpp"
#include "ballsight/detect/colour_cast.hpp"
#include "ballsight/detect/hue_classes.hpp"

namespace ballsight {

/// An object the detector looks for: a sphere of known size at a known centre height, of one
/// colour.
struct CourtObjectSpec {
  ObjectClass object = ObjectClass::ball;
  double radius_m = 0.0335;
  double center_height_m = 0.0335;
  HueBand seed_colour;                       // a seed pixel must be in it (or in shade_seed_colour)
  std::optional<HueBand> shade_seed_colour;  // the same hues in deep shade: less chroma
  HueBand grow_colour;  // the blob grows through it (wider: the mixed pixels of the rim)
  cv::Vec3f evidence_bgr{-2.0f, 1.0f, 1.0f};  // weights of B, G, R; they sum to 0
  int max_split = 6;                          // touching objects one blob may hold (1: never split)

  /// Throws InputError naming `name` and the first invalid field.
  void validate(const char* name) const;
  /// Whether `bgr` is of the object's own colour (seed_colour or shade_seed_colour).
  bool is_own_colour(const cv::Vec3b& bgr) const {
    return seed_colour.contains(bgr) || (shade_seed_colour && shade_seed_colour->contains(bgr));
  }
};

/// The colours of what the detector looks for, 8-bit BGR as the cameras see them in daylight.
struct CourtObjectColours {
  cv::Vec3b ball{45, 250, 225};          // fluorescent yellow tennis ball, hue about 68 deg
  cv::Vec3b front_marker{180, 80, 255};  // pink, hue about 326 deg
  cv::Vec3b back_marker{220, 80, 30};    // blue, hue about 224 deg
};

/// The court's objects: tennis balls (split when touching) and the robot's front and back marker
/// balls. Each colour gives its hue bands (seeds within 20 deg of its hue, growth within 32 deg)
/// and its evidence weights (the colour's own chroma direction: its B, G, R minus their mean).
std::vector<CourtObjectSpec> court_objects(const CourtObjectColours& colours = {},
                                           double ball_radius_m = 0.0335,
                                           double marker_radius_m = 0.045,
                                           double marker_height_m = 0.345);

struct CourtDetectorOptions {
  std::vector<CourtObjectSpec> objects = court_objects();
  FieldRect area{{-19.5, -10.5}, {19.5, 10.5}};  // where objects may be (field frame)
  double min_radius_px = 0.7;         // where the smallest object looks smaller: not searched
  double seed_step_per_radius = 1.0;  // seed grid step: this times the smallest apparent radius
  int max_seed_step_px = 8;
  int size_cell_px = 16;             // resolution of the apparent-size maps
  double max_objects_in_blob = 8.0;  // blobs holding more (by evidence) are not objects
  double min_thickness = 0.35;       // minor axis / expected, below: a line, not an object
  double saturation = 0.5;           // centre weights saturate at this share of the blob peak
  /// A blob of m objects' evidence is split into floor(m + split_rounding) parts (0.5: rounding;
  /// more: splits sooner, the world model removes parts the other cameras do not need).
  double split_rounding = 0.5;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class CourtDetector {
 public:
  CourtDetector(const FieldCamera& camera, const CourtDetectorOptions& options = {});

  /// Every object found in an 8-bit BGR image of the camera's size (InputError otherwise).
  /// Reuses internal buffers: one detector per thread.
  std::vector<PixelDetection> detect(const cv::Mat& bgr);

  const CourtDetectorOptions& options() const { return options_; }
  cv::Size image_size() const { return size_; }
  /// Pixels the detector classifies on its seed grid (the work it does on an empty court).
  std::size_t seed_count() const { return seeds_.size(); }

 private:
  void measure(const cv::Mat& bgr, const GrownBlob& blob, size_t spec_index, int blob_index,
               std::vector<PixelDetection>& out) const;

  CourtDetectorOptions options_;
  cv::Size size_;
  CastCorrectedTable table_;            // the objects' colours, corrected for a warm cast
  std::vector<ApparentSizeMap> sizes_;  // one per object spec
  std::vector<int> seeds_;              // pixel indices of the seed grid
  BlobGrowthBuffers buffers_;
  GrownBlob blob_;
  std::vector<int> touched_;  // pixels marked visited in the current image
};

}  // namespace ballsight
