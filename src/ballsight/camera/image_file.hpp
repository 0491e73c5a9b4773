#pragma once
// Reading an image file a user named: a missing or unreadable file is an InputError naming it
// (cv::imread alone returns an empty image and prints a warning).

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

namespace ballsight {

/// cv::imread with `flags`; throws InputError "<file>: does not exist" or "<file>: cannot read
/// the image".
cv::Mat read_image(const std::filesystem::path& file, int flags = cv::IMREAD_COLOR);

}  // namespace ballsight
