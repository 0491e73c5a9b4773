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

#include "ballsight/detect/color_classes.hpp"

namespace ballsight {

/// The gains (B, G, R) that make the brightest near-neutral pixels of `bgr` (8-bit BGR) grey,
/// when they show a warm cast (red above blue by 10 % to 60 %); nullopt when they do not, when
/// too few pixels qualify (clipped highlights, nothing near-neutral) or when the brightest are
/// too dark for white. The gains come in steps of 1/64 (one lamp, one set of gains). Throws
/// InputError for an image that is not 8-bit BGR.
std::optional<cv::Vec3d> warm_cast_gains(const cv::Mat& bgr);

/// The table that classifies a pixel of a photo under the cast as `table` classifies the centre
/// of its cell corrected by `gains` (each channel multiplied, saturated at 255).
ColorClassTable corrected_for_cast(const ColorClassTable& table, const cv::Vec3d& gains);

}  // namespace ballsight
