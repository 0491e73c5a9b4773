#include "ballsight/detect/contrast_split.hpp"

#include <array>
#include <opencv2/imgproc.hpp>

namespace ballsight {

namespace {

struct OtsuSplit {
  int threshold = 0;         // the upper class is [threshold, 255]
  double upper_share = 1.0;  // of the pixels
  double contrast = 0.0;     // the classes' means apart
};

// Otsu's threshold of a histogram (the one that maximises the between-class variance).
OtsuSplit otsu_split(const std::array<int, 256>& histogram) {
  double total = 0.0, sum = 0.0;
  for (int v = 0; v < 256; ++v) total += histogram[v], sum += v * static_cast<double>(histogram[v]);
  OtsuSplit best;
  double best_variance = -1.0, below = 0.0, below_sum = 0.0;
  for (int t = 1; t < 256; ++t) {
    below += histogram[t - 1];
    below_sum += (t - 1) * static_cast<double>(histogram[t - 1]);
    const double above = total - below;
    if (below <= 0.0 || above <= 0.0) continue;
    const double lower_mean = below_sum / below, upper_mean = (sum - below_sum) / above;
    const double variance = below * above * (upper_mean - lower_mean) * (upper_mean - lower_mean);
    if (variance > best_variance)
      best_variance = variance, best = {t, above / total, upper_mean - lower_mean};
  }
  return best;
}

}  // namespace

std::optional<ContrastParts> split_by_contrast(const cv::Mat& bgr, const GrownBlob& blob,
                                               const ContrastSplit& split,
                                               std::size_t min_part_pixels) {
  const cv::Vec3b* pixels = bgr.ptr<cv::Vec3b>(0);
  std::array<int, 256> histogram{};
  for (int index : blob.pixels) ++histogram[yellowness(pixels[index])];
  const OtsuSplit otsu = otsu_split(histogram);
  if (otsu.upper_share > split.max_share || otsu.contrast < split.min_contrast) return {};
  cv::Mat1b mask(blob.bbox.size(), 0);
  for (int index : blob.pixels)
    if (yellowness(pixels[index]) >= otsu.threshold)
      mask(index / bgr.cols - blob.bbox.y, index % bgr.cols - blob.bbox.x) = 255;
  cv::Mat1i labels;
  cv::Mat stats, centroids;
  const int count = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 4, CV_32S);
  std::vector<GrownBlob> parts(static_cast<std::size_t>(count));
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x)
      if (const int label = labels(y, x); label > 0)
        parts[static_cast<std::size_t>(label)].pixels.push_back((y + blob.bbox.y) * bgr.cols + x +
                                                                blob.bbox.x);
  ContrastParts result{otsu.threshold, {}};
  for (int label = 1; label < count; ++label) {
    GrownBlob& part = parts[static_cast<std::size_t>(label)];
    if (part.pixels.size() < min_part_pixels) continue;
    part.bbox =
        cv::Rect(stats.at<int>(label, cv::CC_STAT_LEFT) + blob.bbox.x,
                 stats.at<int>(label, cv::CC_STAT_TOP) + blob.bbox.y,
                 stats.at<int>(label, cv::CC_STAT_WIDTH), stats.at<int>(label, cv::CC_STAT_HEIGHT));
    result.parts.push_back(std::move(part));
  }
  return result;
}

}  // namespace ballsight
