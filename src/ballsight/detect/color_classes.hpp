#pragma once
// Colour segmentation in YUV as the omnivision paper (Section IV), through a colour-class table:
// every BGR colour, quantised to 6 bits per channel, maps to a bit set of colour classes, so
// classifying a pixel is one table read instead of a colour conversion and six comparisons.

#include <array>
#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

namespace ballsight {

/// An axis-aligned box in OpenCV's 8-bit YUV (cv::COLOR_BGR2YUV), bounds inclusive.
struct YuvRange {
  std::array<int, 3> min{0, 0, 0};
  std::array<int, 3> max{255, 255, 255};

  /// Throws InputError naming `name` when a bound is outside [0, 255] or min > max.
  void validate(const char* name = "yuv range") const;
  bool contains(const cv::Vec3b& yuv) const;
};

/// Colour classes are bits so that one table entry can belong to several classes.
using ColorClassMask = std::uint8_t;

struct ColorClassRule {
  ColorClassMask mask = 0;
  YuvRange range;
};

class ColorClassTable {
 public:
  static constexpr int kBits = 6;  // 64^3 entries = 256 KiB: stays in L2
  static constexpr int kShift = 8 - kBits;

  explicit ColorClassTable(const std::vector<ColorClassRule>& rules);
  /// Any rule on BGR colours (hue bands, chroma, ...), evaluated at the centre of every cell.
  static ColorClassTable from_classifier(
      const std::function<ColorClassMask(const cv::Vec3b& bgr)>& classify);

  ColorClassMask classify(const cv::Vec3b& bgr) const { return table_[index(bgr)]; }
  /// Takes the classes `classes` away from the cell of index `cell` (see index()).
  void remove_classes(std::size_t cell, ColorClassMask classes) {
    table_[cell] = static_cast<ColorClassMask>(table_[cell] & ~classes);
  }
  static constexpr std::size_t kTableSize = std::size_t{1} << (3 * kBits);
  static constexpr int kCellsPerChannel = 1 << kBits;
  /// The cell of quantised channels (each in [0, kCellsPerChannel)), and back.
  static std::size_t cell(int b, int g, int r) {
    return (static_cast<std::size_t>(b) << (2 * kBits)) | (static_cast<std::size_t>(g) << kBits) |
           static_cast<std::size_t>(r);
  }
  static cv::Vec3i cell_channels(std::size_t cell) {
    const auto mask = static_cast<std::size_t>(kCellsPerChannel - 1);
    return {static_cast<int>(cell >> (2 * kBits)), static_cast<int>((cell >> kBits) & mask),
            static_cast<int>(cell & mask)};
  }
  /// Per channel (B, G, R), the cell each cell of that channel is read from (remapped()).
  using ChannelCellMap = std::array<std::array<std::uint8_t, kCellsPerChannel>, 3>;
  /// The table whose cell (b, g, r) holds this table's classes of cell (map[0][b], map[1][g],
  /// map[2][r]): a change of colour channel by channel (a gain per channel) in one pass.
  ColorClassTable remapped(const ChannelCellMap& map) const;
  static std::size_t index(const cv::Vec3b& bgr) { return index(bgr[0], bgr[1], bgr[2]); }
  static std::size_t index(std::uint8_t b, std::uint8_t g, std::uint8_t r) {
    return cell(b >> kShift, g >> kShift, r >> kShift);
  }

 private:
  std::vector<ColorClassMask> table_;
};

/// The classes of the pixels of rows [rows.start, rows.end) of an 8-bit BGR image, into the same
/// rows of `classes` (of the image's size): a class image read instead of the table where a
/// detector looks at most pixels, some several times.
void classify_rows(const cv::Mat& bgr, const ColorClassTable& table, cv::Range rows,
                   cv::Mat1b& classes);

/// 255 where a BGR pixel belongs to any class in `mask`, 0 elsewhere (whole image).
cv::Mat1b segment(const cv::Mat& bgr, const ColorClassTable& table, ColorClassMask mask);

/// The paper's way, kept as the baseline: cvtColor to YUV, then inRange.
cv::Mat1b segment_yuv_inrange(const cv::Mat& bgr, const YuvRange& range);

}  // namespace ballsight
