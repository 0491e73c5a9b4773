#pragma once
// A warm lamp's colour cast. Under a hall's halogen or warm-white lamps everything white or grey
// (the court's lines, a concrete floor) turns yellow-orange: hue 40-50 deg, saturation 0.2-0.3,
// which is a tennis ball's growth colour, so the floor grows into the balls and the lines count
// as ball-coloured specks around them. The cast is read off the photo's brightest near-neutral
// pixels (white patch: the lines, a wall, a lamp's reflection) and the colour model's table is
// corrected for it, not the image: one table per photo, no pass over the pixels.
//
// Only a warm cast is corrected. Daylight photos hold a bluish or clipped white (the sky, a
// cloud, a white shoe in the sun): their colours are what the default model was made for.

#include <opencv2/core.hpp>
#include <optional>
#include <utility>

#include "ballsight/detect/color_classes.hpp"

namespace ballsight {

/// The gains (B, G, R) that make the brightest near-neutral pixels of `bgr` (8-bit BGR) grey,
/// when they show a warm cast (red above blue by 10 % to 60 %); nullopt when they do not, when
/// too few pixels qualify (clipped highlights, nothing near-neutral) or when the brightest are
/// too dark for white. The gains come in steps of 1/64 (one lamp, one set of gains). An image
/// under about 200 x 200 pixels holds too few samples and is not corrected. Throws InputError
/// for an image that is not 8-bit BGR.
std::optional<cv::Vec3d> warm_cast_gains(const cv::Mat& bgr);

/// The table that classifies a pixel of a photo under the cast as `table` classifies the centre
/// of its cell corrected by `gains` (each channel multiplied, saturated at 255).
ColorClassTable corrected_for_cast(const ColorClassTable& table, const cv::Vec3d& gains);

/// A colour model's table and the same corrected for the warm cast of the photo at hand, for a
/// detector that classifies one camera's frames: the corrected table is kept while the frames
/// give the same gains (one lamp).
class CastCorrectedTable {
 public:
  explicit CastCorrectedTable(ColorClassTable model) : model_(std::move(model)) {}

  /// Reads the warm cast of `bgr` (8-bit BGR; InputError otherwise) and returns the table to
  /// classify its pixels with, which current() returns until the next call.
  const ColorClassTable& update(const cv::Mat& bgr);
  /// The model's table corrected for the cast of the last photo, or the model's own when it
  /// showed none.
  const ColorClassTable& current() const { return corrected_now_ ? *corrected_ : model_; }
  /// The colour model's own table.
  const ColorClassTable& model() const { return model_; }

 private:
  ColorClassTable model_;
  std::optional<ColorClassTable> corrected_;  // model_ corrected by gains_
  cv::Vec3d gains_;
  bool corrected_now_ = false;  // whether the last photo showed a warm cast
};

}  // namespace ballsight
