#include "ballsight/detect/blob_evidence.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <string>

#include "ballsight/detect/court_detector.hpp"
#include "ballsight/detect/hue_classes.hpp"

namespace ballsight {
namespace {

// Gaussian noise of 2 grey levels, the same every run.
void add_noise(cv::Mat& image) {
  cv::Mat noise(image.size(), CV_16SC3);
  cv::RNG rng(7);
  rng.fill(noise, cv::RNG::NORMAL, 0, 2);
  cv::add(image, noise, image, cv::noArray(), CV_8UC3);
}

// The court cameras' objects as their detector sees them: the tennis ball, and the back marker
// (blue, hue about 224 deg), each with its growth band and evidence weights.
const CourtObjectColours kColours;
const std::vector<CourtObjectSpec> kObjects = court_objects(kColours);
const CourtObjectSpec& kBall = kObjects[0];
const CourtObjectSpec& kBackMarker = kObjects[2];
const cv::Vec3b kMarker = kColours.back_marker;
const cv::Vec3f kMarkerEvidence = kBackMarker.evidence_bgr;

// A blue court (hue about 197 deg, within the marker's growth band) with a marker on it, a
// marker on the run-off beside it, and a scrap of blue larger than a marker; light noise.
cv::Mat blue_court() {
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(47, 62, 39));  // dark green run-off
  cv::rectangle(image, {40, 30}, {200, 200}, cv::Scalar(80, 67, 35), cv::FILLED);
  cv::circle(image, {120, 110}, 6, cv::Scalar(kMarker), cv::FILLED, cv::LINE_AA);
  cv::circle(image, {260, 60}, 6, cv::Scalar(kMarker), cv::FILLED, cv::LINE_AA);
  cv::ellipse(image, {260, 170}, {30, 12}, 20.0, 0.0, 360.0, cv::Scalar(kMarker), cv::FILLED);
  add_noise(image);
  return image;
}

std::vector<GrownBlob> marker_blobs(const cv::Mat& image) {
  const ColorClassTable table = hue_class_table({{1, kBackMarker.grow_colour}});
  BlobGrowthBuffers buffers;
  buffers.reset(image.rows * image.cols);
  std::vector<GrownBlob> blobs;
  GrownBlob blob;
  for (int seed = 0; seed < image.rows * image.cols; ++seed)
    if (grow_blob(image, table, 1, seed, buffers, blob) && blob.pixels.size() >= 20)
      blobs.push_back(blob);  // not the few mixed pixels where the run-off meets the court
  return blobs;
}

// The limit only ever leaves out a blob whose full measurement holds more than `max_peaks`
// times its peak; below it, the measurement is the full one.
TEST(BlobEvidence, LeavesOutOnlyBlobsOfMorePeaksThanTheLimit) {
  const cv::Mat image = blue_court();
  const std::vector<GrownBlob> blobs = marker_blobs(image);
  ASSERT_EQ(blobs.size(), 3u);  // the court (the marker on it merged), the marker, the scrap
  int left_out = 0, measured = 0;
  for (const GrownBlob& blob : blobs) {
    const std::optional<BlobEvidence> full = measure_blob_evidence(image, blob, kMarkerEvidence, 6);
    ASSERT_TRUE(full);
    ASSERT_GT(full->peak, 0.0);
    const double peaks = full->mass / full->peak;
    for (const double max_peaks : {0.5 * peaks, 0.9 * peaks, 2.0 * peaks, 10.0 * peaks, 1e3, 1e4}) {
      SCOPED_TRACE("blob of " + std::to_string(blob.pixels.size()) + " px, " +
                   std::to_string(peaks) + " peaks, limit " + std::to_string(max_peaks));
      const auto limited = measure_blob_evidence(image, blob, kMarkerEvidence, 6, max_peaks);
      if (!limited) {
        ++left_out;
        EXPECT_GT(peaks, max_peaks);
        continue;
      }
      ++measured;
      EXPECT_EQ(limited->mass, full->mass);
      EXPECT_EQ(limited->peak, full->peak);
      EXPECT_EQ(limited->centroid, full->centroid);
      EXPECT_EQ(limited->pixels.size(), full->pixels.size());
    }
  }
  // Both happen: the court is left out under a limit of a few markers, a marker is measured.
  EXPECT_GT(left_out, 0);
  EXPECT_GT(measured, 0);
  const GrownBlob& court = *std::max_element(
      blobs.begin(), blobs.end(),
      [](const GrownBlob& a, const GrownBlob& b) { return a.pixels.size() < b.pixels.size(); });
  EXPECT_FALSE(measure_blob_evidence(image, court, kMarkerEvidence, 6, 8.0 * 100.0));
}

// A yellow ball's evidence on a light wooden floor, whose chroma leans towards the ball's (hue
// about 32 deg): taken across the floor's chroma, the floor holds none (its evidence along the
// ball's own direction is 55 grey levels). A blue marker on a blue court keeps its own weights
// (less than half of its direction lies across the court's): the court is its background.
TEST(BlobEvidence, TakesTheEvidenceAcrossAFloorOfTheObjectsSide) {
  const ColorClassTable grows = hue_class_table({{1, kBall.grow_colour}});
  const ColorClassTable marker_grows = hue_class_table({{1, kBackMarker.grow_colour}});
  struct Case {
    const char* name;
    cv::Scalar floor, object;
    cv::Vec3f evidence;
    const ColorClassTable* table;
    double min_background, max_background;
    bool alone;  // the object's blob is its own (not grown into the floor)
  };
  const Case cases[] = {{"ball on wood",
                         {100, 150, 195},
                         cv::Scalar(kColours.ball),
                         kBall.evidence_bgr,
                         &grows,
                         0.0,
                         1.0,
                         true},
                        {"marker on a blue court",
                         {80, 67, 35},
                         cv::Scalar(kMarker),
                         kMarkerEvidence,
                         &marker_grows,
                         20.0,
                         40.0,
                         false}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    cv::Mat image(120, 160, CV_8UC3, c.floor);
    cv::circle(image, {80, 60}, 8, c.object, cv::FILLED, cv::LINE_AA);
    add_noise(image);
    BlobGrowthBuffers buffers;
    buffers.reset(image.rows * image.cols);
    GrownBlob blob;
    ASSERT_TRUE(grow_blob(image, *c.table, 1, 60 * image.cols + 80, buffers, blob));
    const auto evidence = measure_blob_evidence(image, blob, c.evidence, 6);
    ASSERT_TRUE(evidence);
    EXPECT_GE(evidence->background, c.min_background);
    EXPECT_LE(evidence->background, c.max_background);
    if (!c.alone) continue;
    EXPECT_NEAR(evidence->centroid.x(), 80.0, 0.1);
    EXPECT_NEAR(evidence->centroid.y(), 60.0, 0.1);
  }
}

}  // namespace
}  // namespace ballsight
