#include "ballsight/detect/blob_growth.hpp"

#include <algorithm>
#include <cassert>

namespace ballsight {

namespace {

// Grows from `seed` through the pixels for which in(index) holds, over an image of width x
// height, a row's run at a time: a run is extended left and right from a pixel known to be in,
// then the first pixel of every run of unvisited in-pixels beside it, above and below, is stacked.
// The blob's pixels come run after run.
template <class In>
bool grow(int width, int height, In in, int seed, BlobGrowthBuffers& buffers, GrownBlob& blob) {
  assert(buffers.visited.size() == static_cast<std::size_t>(width) * height);
  std::uint8_t* visited = buffers.visited.data();
  if (visited[seed] || !in(seed)) return false;
  const auto open = [&](int index) { return !visited[index] && in(index); };
  blob.pixels.clear();
  buffers.stack.assign(1, cv::Point(seed % width, seed / width));
  int min_x = width, min_y = height, max_x = -1, max_y = -1;
  while (!buffers.stack.empty()) {
    const auto [x, y] = buffers.stack.back();
    buffers.stack.pop_back();
    const int row = y * width;
    if (visited[row + x]) continue;  // a run grown since it was stacked
    int left = x, right = x;
    while (left > 0 && open(row + left - 1)) --left;
    while (right + 1 < width && open(row + right + 1)) ++right;
    for (int i = row + left; i <= row + right; ++i) {
      visited[i] = 1;
      blob.pixels.push_back(i);
    }
    min_x = std::min(min_x, left), max_x = std::max(max_x, right);
    min_y = std::min(min_y, y), max_y = std::max(max_y, y);
    for (const int beside : {y - 1, y + 1}) {
      if (beside < 0 || beside >= height) continue;
      bool in_run = false;
      for (int bx = left; bx <= right; ++bx) {
        const bool next = open(beside * width + bx);
        if (next && !in_run) buffers.stack.emplace_back(bx, beside);
        in_run = next;
      }
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
