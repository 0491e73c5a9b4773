#include "ballsight/detect/blob_growth.hpp"

#include <algorithm>
#include <cassert>

namespace ballsight {

namespace {

// Grows from `seed` through the pixels for which in(index) holds, over an image of width x
// height.
template <class In>
bool grow(int width, int height, In in, int seed, BlobGrowthBuffers& buffers, GrownBlob& blob) {
  assert(buffers.visited.size() == static_cast<std::size_t>(width) * height);
  auto& visited = buffers.visited;
  if (visited[static_cast<size_t>(seed)] || !in(seed)) return false;
  blob.pixels.clear();
  // Pixels are stacked with their coordinates: no division by the width per pixel.
  buffers.stack.assign(1, cv::Point(seed % width, seed / width));
  visited[static_cast<size_t>(seed)] = 1;
  int min_x = width, min_y = height, max_x = -1, max_y = -1;
  while (!buffers.stack.empty()) {
    const auto [x, y] = buffers.stack.back();
    buffers.stack.pop_back();
    blob.pixels.push_back(y * width + x);
    min_x = std::min(min_x, x), max_x = std::max(max_x, x);
    min_y = std::min(min_y, y), max_y = std::max(max_y, y);
    const int neighbours[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
    for (const auto& [nx, ny] : neighbours) {
      if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
      const int n = ny * width + nx;
      if (visited[static_cast<size_t>(n)] || !in(n)) continue;
      visited[static_cast<size_t>(n)] = 1;
      buffers.stack.emplace_back(nx, ny);
    }
  }
  blob.bbox = cv::Rect(min_x, min_y, max_x - min_x + 1, max_y - min_y + 1);
  return true;
}

}  // namespace

bool grow_blob(const cv::Mat& bgr, const ColorClassTable& table, ColorClassMask mask, int seed,
               BlobGrowthBuffers& buffers, GrownBlob& blob) {
  assert(bgr.type() == CV_8UC3 && bgr.isContinuous());
  const auto* pixels = bgr.ptr<cv::Vec3b>(0);
  return grow(
      bgr.cols, bgr.rows, [&](int index) { return (table.classify(pixels[index]) & mask) != 0; },
      seed, buffers, blob);
}

bool grow_blob(const cv::Mat1b& classes, ColorClassMask mask, int seed, BlobGrowthBuffers& buffers,
               GrownBlob& blob) {
  assert(classes.isContinuous());
  const ColorClassMask* of = classes.ptr<ColorClassMask>(0);
  return grow(
      classes.cols, classes.rows, [&](int index) { return (of[index] & mask) != 0; }, seed, buffers,
      blob);
}

}  // namespace ballsight
