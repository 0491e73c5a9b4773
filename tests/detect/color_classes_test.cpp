#include "ballsight/detect/color_classes.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "ballsight/core/error.hpp"
#include "ballsight/detect/blob_growth.hpp"

namespace ballsight {
namespace {

constexpr unsigned kClassesSeed = 99;
const YuvRange kOrange{{40, 60, 150}, {230, 125, 230}};

TEST(ColorClassTable, AgreesWithCvtColorAndInRangeAwayFromBoundaries) {
  SCOPED_TRACE("seed " + std::to_string(kClassesSeed));
  const ColorClassTable table({{1, kOrange}});
  std::mt19937 rng(kClassesSeed);
  std::uniform_int_distribution<int> byte(0, 255);
  cv::Mat bgr(200, 200, CV_8UC3);
  for (int i = 0; i < bgr.rows * bgr.cols; ++i)
    bgr.at<cv::Vec3b>(i) = cv::Vec3b(static_cast<uchar>(byte(rng)), static_cast<uchar>(byte(rng)),
                                     static_cast<uchar>(byte(rng)));
  const cv::Mat1b fast = segment(bgr, table, 1);
  const cv::Mat1b paper = segment_yuv_inrange(bgr, kOrange);
  cv::Mat yuv;
  cv::cvtColor(bgr, yuv, cv::COLOR_BGR2YUV);
  int disagreements = 0, interior_disagreements = 0;
  for (int i = 0; i < bgr.rows * bgr.cols; ++i) {
    if (fast(i) == paper(i)) continue;
    ++disagreements;
    // A 6-bit cell is 4 levels wide per channel, up to ~4 levels in YUV: only colours that close
    // to a boundary may disagree.
    const cv::Vec3b c = yuv.at<cv::Vec3b>(i);
    bool near_boundary = false;
    for (int ch = 0; ch < 3; ++ch) {
      near_boundary |= std::abs(c[ch] - kOrange.min[static_cast<size_t>(ch)]) <= 5 ||
                       std::abs(c[ch] - kOrange.max[static_cast<size_t>(ch)]) <= 5;
    }
    interior_disagreements += !near_boundary;
  }
  EXPECT_EQ(interior_disagreements, 0);
  EXPECT_LT(disagreements, bgr.rows * bgr.cols / 50);
  EXPECT_GT(cv::countNonZero(paper), 100);  // the test colours do hit the class
}

TEST(ColorClassTable, ClassesAreBits) {
  const YuvRange everything;
  const ColorClassTable table({{1, kOrange}, {4, everything}});
  EXPECT_EQ(table.classify(cv::Vec3b(0, 0, 0)), 4);
  cv::Mat yuv(1, 1, CV_8UC3, cv::Scalar(120, 90, 190)), bgr;
  cv::cvtColor(yuv, bgr, cv::COLOR_YUV2BGR);
  EXPECT_EQ(table.classify(bgr.at<cv::Vec3b>(0)), 5);
}

TEST(ColorClassTable, RejectsInvalidRanges) {
  EXPECT_THROW(ColorClassTable({{1, YuvRange{{0, 0, 0}, {300, 255, 255}}}}), InputError);
  EXPECT_THROW(ColorClassTable({{1, YuvRange{{10, 0, 0}, {5, 255, 255}}}}), InputError);
  EXPECT_THROW(segment(cv::Mat1b(4, 4), ColorClassTable({}), 1), InputError);
}

TEST(ColorClassTable, GrowingOnTheClassImageIsGrowingThroughTheTable) {
  // Blocks of random colours, so that regions of a class are of many shapes and sizes.
  std::mt19937 rng(kClassesSeed);
  std::uniform_int_distribution<int> byte(0, 255);
  cv::Mat small(24, 32, CV_8UC3), bgr;
  for (int i = 0; i < small.rows * small.cols; ++i)
    small.at<cv::Vec3b>(i) = cv::Vec3b(static_cast<uchar>(byte(rng)), static_cast<uchar>(byte(rng)),
                                       static_cast<uchar>(byte(rng)));
  cv::resize(small, bgr, {}, 5, 5, cv::INTER_NEAREST);
  const ColorClassTable table({{1, kOrange}, {2, YuvRange{{0, 0, 0}, {255, 128, 255}}}});
  cv::Mat1b classes(bgr.size());
  classify_rows(bgr, table, cv::Range(0, bgr.rows / 2), classes);
  classify_rows(bgr, table, cv::Range(bgr.rows / 2, bgr.rows), classes);
  int mismatched = 0;
  for (int i = 0; i < static_cast<int>(bgr.total()); ++i)
    mismatched += classes(i) != table.classify(bgr.at<cv::Vec3b>(i));
  EXPECT_EQ(mismatched, 0);
  BlobGrowthBuffers through_table, through_classes;
  through_table.reset(static_cast<int>(bgr.total()));
  through_classes.reset(static_cast<int>(bgr.total()));
  GrownBlob a, b;
  int blobs = 0;
  for (int seed = 0; seed < static_cast<int>(bgr.total()); ++seed) {
    for (const ColorClassMask mask : {ColorClassMask{1}, ColorClassMask{3}}) {
      const bool grown = grow_blob(bgr, table, mask, seed, through_table, a);
      ASSERT_EQ(grow_blob(classes, mask, seed, through_classes, b), grown) << "seed " << seed;
      if (!grown) continue;
      ++blobs;
      EXPECT_EQ(a.pixels, b.pixels);
      EXPECT_EQ(a.bbox, b.bbox);
    }
  }
  EXPECT_GT(blobs, 20);
}

}  // namespace
}  // namespace ballsight
