#include "ballsight/detect/colour_cast.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "ballsight/core/error.hpp"
#include "ballsight/detect/hue_classes.hpp"

namespace ballsight {

namespace {

// About kSamples pixels are looked at (at 640x480 every fourth of every fourth row, enough for
// the brightest two percent; at 1920x1080 every 27th of every fourth row, so that a cast is
// read in about 0.1 ms, not 0.6 ms as with every fourth: bench_court_pipeline's one frame).
constexpr int kMinStep = 4;
constexpr double kSamples = 19200.0;
// The brightest share of the samples (by their largest channel), less the clipped and the
// coloured ones, is taken for white, when it is bright enough to be one and holds enough.
constexpr double kBrightestShare = 0.02;
constexpr int kClipped = 250;
constexpr double kMaxSaturation = 0.4;
constexpr int kMinWhite = 64;
constexpr int kMinWhiteSamples = 50;
// A cast is warm when the white's red exceeds its blue by kMinWarmRatio (the simulator's hall
// lamps: 1.12-1.47; daylight whites are bluish, <= 1); beyond kMaxWarmRatio the "white" is a
// coloured surface (sand, light wood), not a lamp's white.
constexpr double kMinWarmRatio = 1.1;
constexpr double kMaxWarmRatio = 1.6;
constexpr double kGainSteps = 64.0;

int largest_channel(const cv::Vec3b& p) {
  return std::max({p[0], p[1], p[2]});
}

}  // namespace

std::optional<cv::Vec3d> warm_cast_gains(const cv::Mat& bgr) {
  require(!bgr.empty() && bgr.type() == CV_8UC3, "colour cast", "expected an 8-bit BGR image");
  // The brightest kBrightestShare of all samples; of those, the ones neither clipped nor
  // coloured are taken for white. (Counting the clipped and coloured samples too keeps a sunny
  // photo, whose brightest share is burnt-out sky and white, from reading its sunlit ground for
  // white: on the real photos, two more false balls otherwise.)
  const auto candidate = [](const cv::Vec3b& p) {
    return largest_channel(p) < kClipped && saturation(p) <= kMaxSaturation;
  };
  // Every kMinStep-th row; in the k-th of them every column_step-th pixel from column k (a
  // skewed lattice: a thin line at any angle crosses sampled pixels).
  const int column_step = std::max(
      kMinStep, static_cast<int>(static_cast<double>(bgr.total()) / (kSamples * kMinStep)));
  const auto for_each_sample = [&](const auto& visit) {
    for (int y = 0, k = 0; y < bgr.rows; y += kMinStep, ++k) {
      const auto* row = bgr.ptr<cv::Vec3b>(y);
      for (int x = k % column_step; x < bgr.cols; x += column_step) visit(row[x]);
    }
  };
  std::array<int, 256> histogram{};
  int samples = 0;
  for_each_sample([&](const cv::Vec3b& p) {
    ++histogram[static_cast<std::size_t>(largest_channel(p))];
    ++samples;
  });
  // The lowest brightness of the brightest kBrightestShare.
  int threshold = 255, above = 0;
  while (threshold > 0 &&
         above + histogram[static_cast<std::size_t>(threshold)] <= kBrightestShare * samples)
    above += histogram[static_cast<std::size_t>(threshold--)];
  if (threshold < kMinWhite) return std::nullopt;  // a dark photo: no white to read a cast off
  cv::Vec3d sum(0.0, 0.0, 0.0);
  int whites = 0;
  for_each_sample([&](const cv::Vec3b& p) {
    if (!candidate(p) || largest_channel(p) < threshold) return;
    sum += cv::Vec3d(p[0], p[1], p[2]);
    ++whites;
  });
  if (whites < kMinWhiteSamples) return std::nullopt;
  const cv::Vec3d white = sum / whites;
  const double warmth = white[2] / white[0];  // > 0: the white is no darker than kMinWhite
  if (warmth < kMinWarmRatio || warmth > kMaxWarmRatio) return std::nullopt;
  // Gains in steps of 1/kGainSteps: a camera's frames under one lamp give the same gains, and
  // the corrected table can be kept from one frame to the next.
  const double grey = (white[0] + white[1] + white[2]) / 3.0;
  const auto gain = [&](double channel) {
    return std::round(grey / channel * kGainSteps) / kGainSteps;
  };
  return cv::Vec3d(gain(white[0]), gain(white[1]), gain(white[2]));
}

ColorClassTable corrected_for_cast(const ColorClassTable& table, const cv::Vec3d& gains) {
  // A cell's centre, corrected, falls in the cell it is classified as.
  constexpr int kHalf = 1 << (ColorClassTable::kShift - 1);
  ColorClassTable::ChannelCellMap map;
  for (std::size_t channel = 0; channel < 3; ++channel)
    for (int cell = 0; cell < ColorClassTable::kCellsPerChannel; ++cell)
      map[channel][static_cast<std::size_t>(cell)] = static_cast<std::uint8_t>(
          cv::saturate_cast<uchar>(((cell << ColorClassTable::kShift) + kHalf) *
                                   gains[static_cast<int>(channel)]) >>
          ColorClassTable::kShift);
  return table.remapped(map);
}

const ColorClassTable& CastCorrectedTable::update(const cv::Mat& bgr) {
  const std::optional<cv::Vec3d> gains = warm_cast_gains(bgr);
  if (gains && (!corrected_ || *gains != gains_)) {
    corrected_ = corrected_for_cast(model_, *gains);
    gains_ = *gains;
  }
  corrected_now_ = gains.has_value();
  return current();
}

}  // namespace ballsight
