#pragma once
// A ball colour model learned from a few clicked ball pixels: the coloured pixels around each
// click (a 5x5 disc, those of the click's own hue: a click on a seam or at the rim still
// counts), grouped by hue (a stage ball's orange and yellow become two colours), and per group
// a seed band a little wider than what was seen and a growth band wider again (the ball's shade,
// its pale top and its rim).

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/detect/ball_colours.hpp"

namespace ballsight {

/// Throws InputError when a click lies outside the image or no clicked pixel has a colour.
BallColours learn_ball_colours(const cv::Mat& bgr, const std::vector<Vec2>& clicks);

}  // namespace ballsight
