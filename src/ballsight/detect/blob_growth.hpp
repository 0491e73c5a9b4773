#pragma once
// Region growing through a colour-class table: from one seed pixel, the 4-connected pixels whose
// class is in a mask. Through the table, only the pixels of the region and its border are ever
// classified, which is what lets a detector look at a sparse grid of seeds instead of the whole
// image (the court detector, the omni blobs); through a class image of the whole image
// (classify_rows), no pixel is classified twice (the photo detector, which looks at every pixel).

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/detect/color_classes.hpp"

namespace ballsight {

/// A grown region: pixel indices (y * width + x), a row's run of them after another, and their
/// bounding box.
struct GrownBlob {
  std::vector<int> pixels;
  cv::Rect bbox;
};

/// Reusable buffers for grow_blob: `visited` has one byte per pixel of the image (zero at the
/// start of an image); grown pixels are marked so that a later seed inside them is skipped.
struct BlobGrowthBuffers {
  std::vector<std::uint8_t> visited;
  std::vector<cv::Point> stack;  // (x, y): where a run of pixels to grow begins

  void reset(int pixel_count) { visited.assign(static_cast<std::size_t>(pixel_count), 0); }
};

/// Grows the region of `mask` pixels 4-connected to `seed` in the continuous 8-bit BGR image
/// `bgr` into `blob`. Returns false (blob untouched) when the seed is visited or not in `mask`.
bool grow_blob(const cv::Mat& bgr, const ColorClassTable& table, ColorClassMask mask, int seed,
               BlobGrowthBuffers& buffers, GrownBlob& blob);

/// The same on a continuous class image (classify_rows) of the whole image.
bool grow_blob(const cv::Mat1b& classes, ColorClassMask mask, int seed, BlobGrowthBuffers& buffers,
               GrownBlob& blob);

}  // namespace ballsight
