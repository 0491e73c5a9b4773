#include "ballsight/detect/color_classes.hpp"

#include <cassert>
#include <opencv2/imgproc.hpp>
#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight {

void YuvRange::validate(const char* name) const {
  static constexpr const char* kChannel[] = {"Y", "U", "V"};
  for (size_t c = 0; c < 3; ++c) {
    require(min[c] >= 0 && max[c] <= 255, name,
            std::string(kChannel[c]) + " bounds must be within [0, 255]");
    require(min[c] <= max[c], name, std::string(kChannel[c]) + " minimum exceeds maximum");
  }
}

bool YuvRange::contains(const cv::Vec3b& yuv) const {
  for (int c = 0; c < 3; ++c) {
    if (yuv[c] < min[static_cast<size_t>(c)] || yuv[c] > max[static_cast<size_t>(c)]) return false;
  }
  return true;
}

namespace {

constexpr int kCells = 1 << ColorClassTable::kBits;

// The centre colour of every quantisation cell, one image row per (b, g) and one column per r,
// so that row * kCells + column is the cell's table index.
cv::Mat cell_centres_bgr() {
  constexpr int kHalf = 1 << (ColorClassTable::kShift - 1);
  cv::Mat bgr(kCells * kCells, kCells, CV_8UC3);
  for (int b = 0; b < kCells; ++b)
    for (int g = 0; g < kCells; ++g)
      for (int r = 0; r < kCells; ++r)
        bgr.at<cv::Vec3b>(b * kCells + g, r) =
            cv::Vec3b(static_cast<uchar>((b << ColorClassTable::kShift) + kHalf),
                      static_cast<uchar>((g << ColorClassTable::kShift) + kHalf),
                      static_cast<uchar>((r << ColorClassTable::kShift) + kHalf));
  return bgr;
}

}  // namespace

ColorClassTable::ColorClassTable(const std::vector<ColorClassRule>& rules)
    : table_(std::size_t{1} << (3 * kBits), 0) {
  for (const ColorClassRule& rule : rules) rule.range.validate("colour class");
  // Classify the centre of every quantisation cell with OpenCV's own YUV conversion, so the
  // table agrees with segment_yuv_inrange except within half a cell of a range boundary.
  cv::Mat yuv;
  cv::cvtColor(cell_centres_bgr(), yuv, cv::COLOR_BGR2YUV);
  for (int row = 0; row < yuv.rows; ++row) {
    for (int r = 0; r < kCells; ++r) {
      const cv::Vec3b& c = yuv.at<cv::Vec3b>(row, r);
      ColorClassMask m = 0;
      for (const ColorClassRule& rule : rules)
        if (rule.range.contains(c)) m |= rule.mask;
      table_[(static_cast<std::size_t>(row) << kBits) | static_cast<std::size_t>(r)] = m;
    }
  }
}

ColorClassTable ColorClassTable::from_classifier(
    const std::function<ColorClassMask(const cv::Vec3b& bgr)>& classify) {
  ColorClassTable table(std::vector<ColorClassRule>{});
  const cv::Mat bgr = cell_centres_bgr();
  for (int row = 0; row < bgr.rows; ++row)
    for (int r = 0; r < kCells; ++r)
      table.table_[(static_cast<std::size_t>(row) << kBits) | static_cast<std::size_t>(r)] =
          classify(bgr.at<cv::Vec3b>(row, r));
  return table;
}

ColorClassTable ColorClassTable::remapped(const ChannelCellMap& map) const {
  ColorClassTable out = *this;
  for (int b = 0; b < kCellsPerChannel; ++b)
    for (int g = 0; g < kCellsPerChannel; ++g)
      for (int r = 0; r < kCellsPerChannel; ++r)
        out.table_[cell(b, g, r)] =
            table_[cell(map[0][static_cast<std::size_t>(b)], map[1][static_cast<std::size_t>(g)],
                        map[2][static_cast<std::size_t>(r)])];
  return out;
}

void classify_rows(const cv::Mat& bgr, const ColorClassTable& table, cv::Range rows,
                   cv::Mat1b& classes) {
  assert(bgr.type() == CV_8UC3 && classes.size() == bgr.size());
  for (int y = rows.start; y < rows.end; ++y) {
    const cv::Vec3b* in = bgr.ptr<cv::Vec3b>(y);
    ColorClassMask* out = classes.ptr<ColorClassMask>(y);
    for (int x = 0; x < bgr.cols; ++x) out[x] = table.classify(in[x]);
  }
}

cv::Mat1b segment(const cv::Mat& bgr, const ColorClassTable& table, ColorClassMask mask) {
  require(bgr.type() == CV_8UC3, "segment", "expected an 8-bit BGR image");
  cv::Mat1b classes(bgr.size());
  classify_rows(bgr, table, cv::Range(0, bgr.rows), classes);
  cv::Mat1b out;
  cv::compare(classes & mask, 0, out, cv::CMP_NE);
  return out;
}

cv::Mat1b segment_yuv_inrange(const cv::Mat& bgr, const YuvRange& range) {
  require(bgr.type() == CV_8UC3, "segment", "expected an 8-bit BGR image");
  cv::Mat yuv;
  cv::cvtColor(bgr, yuv, cv::COLOR_BGR2YUV);
  cv::Mat1b out;
  cv::inRange(yuv, cv::Scalar(range.min[0], range.min[1], range.min[2]),
              cv::Scalar(range.max[0], range.max[1], range.max[2]), out);
  return out;
}

}  // namespace ballsight
