#include "ballsight/detect/ball_colour_learning.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight {

namespace {

struct ColourSample {
  double hue = 0.0;         // degrees
  double saturation = 0.0;  // 0-1
  double value = 0.0;       // 0-255
};

constexpr double kMinSaturation = 0.15;  // greyer pixels carry no hue
constexpr double kMinValue = 20.0;
constexpr double kSameHueDeg = 20.0;    // a click's pixels within this of its median hue
constexpr double kHueGapDeg = 20.0;     // a larger gap between sorted hues starts a new colour
constexpr double kSeedMarginDeg = 6.0;  // seed band: what was seen, this much wider each side
constexpr double kMinSeedWidthDeg = 24.0;
constexpr double kGrowMarginDeg = 12.0;  // growth band: the seed band, this much wider each side

double hue_difference(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

std::vector<ColourSample> samples_around(const cv::Mat& bgr, const Vec2& click, std::size_t index) {
  const int cx = static_cast<int>(std::lround(click.x())),
            cy = static_cast<int>(std::lround(click.y()));
  if (cx < 0 || cy < 0 || cx >= bgr.cols || cy >= bgr.rows) {
    std::ostringstream what;
    what << "(" << cx << ", " << cy << ") lies outside the " << bgr.cols << "x" << bgr.rows
         << " image";
    throw InputError("click " + std::to_string(index + 1) + ": " + what.str());
  }
  std::vector<ColourSample> samples;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const int x = cx + dx, y = cy + dy;
      if (dx * dx + dy * dy > 5 || x < 0 || y < 0 || x >= bgr.cols || y >= bgr.rows) continue;
      const cv::Vec3b& p = bgr.at<cv::Vec3b>(y, x);
      const double hi = std::max({p[0], p[1], p[2]}), lo = std::min({p[0], p[1], p[2]});
      if (hi < kMinValue || hi - lo < kMinSaturation * hi) continue;
      samples.push_back({hue_deg(p), (hi - lo) / hi, hi});
    }
  if (samples.empty()) return samples;
  // The click's own hue: the sample nearest to all others (a circular median).
  double best = 0.0, best_cost = -1.0;
  for (const ColourSample& a : samples) {
    double cost = 0.0;
    for (const ColourSample& b : samples) cost += hue_difference(a.hue, b.hue);
    if (best_cost < 0.0 || cost < best_cost) best = a.hue, best_cost = cost;
  }
  std::erase_if(
      samples, [best](const ColourSample& s) { return hue_difference(s.hue, best) > kSameHueDeg; });
  return samples;
}

// Groups of samples whose sorted hues have no gap larger than kHueGapDeg (circularly).
std::vector<std::vector<ColourSample>> hue_groups(std::vector<ColourSample> samples) {
  std::sort(samples.begin(), samples.end(),
            [](const ColourSample& a, const ColourSample& b) { return a.hue < b.hue; });
  // Start after the largest gap, so that a group through 0 degrees stays whole.
  std::size_t start = 0;
  double largest = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double next = i + 1 < samples.size() ? samples[i + 1].hue : samples[0].hue + 360.0;
    if (next - samples[i].hue > largest)
      largest = next - samples[i].hue, start = (i + 1) % samples.size();
  }
  std::rotate(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(start), samples.end());
  std::vector<std::vector<ColourSample>> groups(1);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (i > 0 && std::fmod(samples[i].hue - samples[i - 1].hue + 360.0, 360.0) > kHueGapDeg)
      groups.emplace_back();
    groups.back().push_back(samples[i]);
  }
  return groups;
}

double wrap_deg(double deg) {
  return std::fmod(std::fmod(deg, 360.0) + 360.0, 360.0);
}

BallColour colour_of(const std::vector<ColourSample>& group, std::size_t index) {
  // The group is sorted along the hue circle from its first to its last sample.
  const double first = group.front().hue;
  const double span = std::fmod(group.back().hue - first + 360.0, 360.0);
  const double margin = std::max(kSeedMarginDeg, 0.5 * (kMinSeedWidthDeg - span));
  std::vector<double> saturation, value;
  for (const ColourSample& s : group) saturation.push_back(s.saturation), value.push_back(s.value);
  std::sort(saturation.begin(), saturation.end());
  std::sort(value.begin(), value.end());
  const double low_saturation = saturation[saturation.size() / 10];
  const double low_value = value[value.size() / 10];
  BallColour colour;
  std::ostringstream name;
  name << "learned " << index + 1 << " (hue " << std::lround(wrap_deg(first + 0.5 * span))
       << " deg)";
  colour.name = name.str();
  colour.seed = HueBand{wrap_deg(first - margin), wrap_deg(first + span + margin), 0.0,
                        0.8 * low_saturation, 0.6 * low_value};
  colour.grow = HueBand{wrap_deg(first - margin - kGrowMarginDeg),
                        wrap_deg(first + span + margin + kGrowMarginDeg), 0.0,
                        std::max(0.1, 0.5 * low_saturation), 0.3 * low_value};
  return colour;
}

}  // namespace

BallColours learn_ball_colours(const cv::Mat& bgr, const std::vector<Vec2>& clicks) {
  require(!bgr.empty() && bgr.type() == CV_8UC3, "colour learning", "expected an 8-bit BGR image");
  require(!clicks.empty(), "colour learning", "needs at least one clicked ball pixel");
  std::vector<ColourSample> samples;
  for (std::size_t i = 0; i < clicks.size(); ++i) {
    const std::vector<ColourSample> around = samples_around(bgr, clicks[i], i);
    require(!around.empty(), "click " + std::to_string(i + 1),
            "no coloured pixel around it (grey, black or white): click on the ball's colour");
    samples.insert(samples.end(), around.begin(), around.end());
  }
  BallColours colours;
  for (const std::vector<ColourSample>& group : hue_groups(samples))
    colours.colours.push_back(colour_of(group, colours.colours.size()));
  require(colours.colours.size() <= 8, "colour learning",
          "the clicks hold " + std::to_string(colours.colours.size()) +
              " distinct hues, more than the 8 a model may have: click on balls only");
  colours.validate("learned colours");
  return colours;
}

}  // namespace ballsight
