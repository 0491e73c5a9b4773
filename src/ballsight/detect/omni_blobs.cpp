#include "ballsight/detect/omni_blobs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/detect/blob_growth.hpp"

namespace ballsight {

void OmniBlobOptions::validate() const {
  require(image_center.allFinite(), "blob options", "image_center must be finite");
  require(min_radius_px >= 0.0 && max_radius_px > min_radius_px, "blob options",
          "need 0 <= min_radius_px < max_radius_px");
  require(seed_step_px >= 1 && seed_step_px <= 8, "blob options", "seed_step_px must be 1..8");
  require(min_area_px >= 1 && max_area_px >= min_area_px, "blob options",
          "need 1 <= min_area_px <= max_area_px");
}

OmniBlobFinder::OmniBlobFinder(cv::Size image_size, const OmniBlobOptions& options)
    : size_(image_size), options_(options) {
  options_.validate();
  require(image_size.width > 0 && image_size.height > 0, "blob finder", "empty image size");
  for (int y = 0; y < size_.height; y += options_.seed_step_px) {
    for (int x = 0; x < size_.width; x += options_.seed_step_px) {
      const double r = (Vec2(x, y) - options_.image_center).norm();
      if (r >= options_.min_radius_px && r <= options_.max_radius_px)
        seeds_.push_back(y * size_.width + x);
    }
  }
}

namespace {

// Radial extent of the blob's pixels along the ray through its centroid: pixels whose centre
// lies within a pixel of that ray, extended by half a pixel on either side.
void measure_radial_extent(const std::vector<int>& pixels, int width, const Vec2& center,
                           OmniBlob& blob) {
  const Vec2 direction = (blob.centroid_px - center).normalized();
  double inner = std::numeric_limits<double>::max(), outer = 0.0;
  for (int index : pixels) {
    const Vec2 d = Vec2(index % width, index / width) - center;
    const double along = d.dot(direction);
    const double across = std::abs(d.x() * direction.y() - d.y() * direction.x());
    if (across > 1.0) continue;
    inner = std::min(inner, along - 0.5);
    outer = std::max(outer, along + 0.5);
  }
  blob.inner_radius_px = inner;
  blob.outer_radius_px = outer;
}

}  // namespace

std::vector<OmniBlob> OmniBlobFinder::find(const cv::Mat& bgr, const ColorClassTable& table,
                                           ColorClassMask mask) const {
  require(bgr.type() == CV_8UC3 && bgr.size() == size_, "blob finder",
          "expected a " + std::to_string(size_.width) + "x" + std::to_string(size_.height) +
              " BGR image, got " + std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows));
  require(bgr.isContinuous(), "blob finder", "expected a continuous image");
  const int width = size_.width;
  BlobGrowthBuffers buffers;
  buffers.reset(size_.area());
  std::vector<OmniBlob> blobs;
  GrownBlob grown;
  for (int seed : seeds_) {
    if (!grow_blob(bgr, table, mask, seed, buffers, grown)) continue;
    const std::vector<int>& members = grown.pixels;
    double sum_x = 0.0, sum_y = 0.0;
    for (int index : members) {
      sum_x += index % width;
      sum_y += index / width;
    }
    const int area = static_cast<int>(members.size());
    if (area < options_.min_area_px || area > options_.max_area_px) continue;
    OmniBlob blob;
    blob.area_px = area;
    blob.centroid_px = Vec2(sum_x / area, sum_y / area);
    blob.bbox = grown.bbox;
    blob.centroid_polar = image_polar_from_pixel(blob.centroid_px, options_.image_center);
    measure_radial_extent(members, width, options_.image_center, blob);
    blob.pixels.reserve(members.size());
    for (int index : members) blob.pixels.emplace_back(index % width, index / width);
    blobs.push_back(std::move(blob));
  }
  std::sort(blobs.begin(), blobs.end(),
            [](const OmniBlob& a, const OmniBlob& b) { return a.area_px > b.area_px; });
  return blobs;
}

}  // namespace ballsight
