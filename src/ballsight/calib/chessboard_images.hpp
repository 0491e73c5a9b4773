#pragma once
// A calibration session on disk: load every image, check they share one size, find the board in
// each and say where it was not found.

#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ballsight/calib/chessboard_corners.hpp"
#include "ballsight/calib/intrinsics.hpp"

namespace ballsight {

struct ChessboardImages {
  cv::Size image_size;
  std::vector<ChessboardView> found;   // named by file
  std::vector<std::string> not_found;  // files where the whole board was not found
};

/// Throws InputError naming the file when an image cannot be read or its size differs from the
/// first image's.
ChessboardImages find_chessboards_in_images(const std::vector<std::filesystem::path>& files,
                                            const ChessboardPattern& pattern);

}  // namespace ballsight
