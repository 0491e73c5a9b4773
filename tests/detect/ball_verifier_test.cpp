#include "ballsight/detect/ball_verifier.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/detect/onnx_sizes.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

TEST(BallVerifier, AFileThatIsNoModelIsAnErrorNamingIt) {
  test::TempDir dir;
  std::ofstream(dir / "broken.onnx") << "\x08\x07not a model at all";
  try {
    BallVerifier::read(dir / "broken.onnx");
    FAIL() << "a broken model was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.onnx"), std::string::npos) << e.what();
  }
  EXPECT_THROW(BallVerifier::read(dir / "missing.onnx"), InputError);
  EXPECT_THROW(BallVerifier("", "empty"), InputError);
}

// The smallest verifier (scripts/make_mean_colour_verifier.py): the logit is 40 times the mean
// yellowness G + R - 2 B (of BGR / 255) of the patch's middle half less that of the rest, less 3.
const std::filesystem::path kMeanColourModel =
    std::filesystem::path(BALLSIGHT_SOURCE_DIR) / "tests/detect/data/mean_colour_verifier.onnx";

// Models the fuzzer made that crash OpenCV 4.6's importer are refused before it reads them.
TEST(BallVerifier, ATensorNotAsLongAsItsDimsSayIsRefusedBeforeOpenCvReadsIt) {
  const std::filesystem::path corpus =
      std::filesystem::path(BALLSIGHT_SOURCE_DIR) / "fuzz/corpus/ball_verifier_onnx";
  const auto refusal = [](const std::filesystem::path& path) -> std::string {
    try {
      check_onnx_sizes(read_file(path), path.filename().string());
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(refusal(kMeanColourModel), "");
  EXPECT_EQ(refusal(corpus / "raw_data_shorter_than_dims.onnx"),
            "raw_data_shorter_than_dims.onnx: holds a tensor whose raw data is not as long as its "
            "dims say");
  EXPECT_NE(refusal(corpus / "unknown_data_type.onnx").find("unknown data type"),
            std::string::npos);
  EXPECT_NE(refusal(corpus / "external_data.onnx").find("outside the file"), std::string::npos);
  EXPECT_NE(refusal(corpus / "truncated.onnx"), "");
  EXPECT_THROW(BallVerifier::read(corpus / "raw_data_shorter_than_dims.onnx"), InputError);
}

TEST(BallVerifier, RunsAModelOnEachCandidatesPatch) {
  BallVerifier verifier = BallVerifier::read(kMeanColourModel);
  cv::Mat image(120, 160, CV_8UC3, cv::Scalar(128, 128, 128));
  image(cv::Rect(20, 20, 21, 21)).setTo(cv::Scalar(40, 220, 200));
  // The square fills the middle half of the first patch, all of the third; the second is grey.
  const std::vector<BallCandidate> candidates{
      {Vec2(30.0, 30.0), 10.5, 1.0}, {Vec2(120.0, 80.0), 10.0, 1.0}, {Vec2(30.0, 30.0), 2.5, 1.0}};
  const std::vector<double> p = verifier.probabilities(image, candidates);
  ASSERT_EQ(p.size(), 3u);
  // Yellow in the middle: 40 * (220 + 200 - 80) / 255 - 3 = 50.3; even: -3.
  EXPECT_NEAR(p[0], 1.0, 1e-6);
  EXPECT_NEAR(p[1], 1.0 / (1.0 + std::exp(3.0)), 1e-4);
  EXPECT_NEAR(p[2], 1.0 / (1.0 + std::exp(3.0)), 1e-4);
  EXPECT_TRUE(verifier.probabilities(image, {}).empty());
}

// The threshold is the one of the best F1 on the sources: a yellow ball on a grey floor, which
// the verifier finds and a detector of pink balls does not.
TEST(BallVerifier, TheThresholdIsFittedOnTheLabelledSources) {
  BallVerifier verifier = BallVerifier::read(kMeanColourModel);
  cv::Mat image(120, 160, CV_8UC3, cv::Scalar(128, 128, 128));
  cv::circle(image, {30, 30}, 10, cv::Scalar(40, 220, 200), -1, cv::LINE_AA);
  LabelledPhotos photos{"drawn", {"square.png"}, {image}, {{{Vec2(30.0, 30.0), 10.0}}}, {}};
  // The detector looks for pink balls only: it finds nothing.
  PhotoBallOptions options;
  BallColour pink{"pink", {}, {}};
  pink.seed = {300.0, 340.0, 0.0, 0.5, 80.0};
  pink.grow = {290.0, 350.0, 0.0, 0.3, 40.0};
  options.colours = BallColours{{pink}};
  PhotoBallDetector detector(options);
  const std::vector<std::vector<VerifiedPhoto>> seen{verify_photos(detector, verifier, photos)};
  ASSERT_EQ(seen[0].size(), 1u);
  EXPECT_TRUE(seen[0][0].balls.empty());
  EXPECT_FALSE(seen[0][0].candidates.empty());
  const double t = fit_min_probability(std::span<const LabelledPhotos>(&photos, 1), seen);
  const std::vector<PhotoBall> kept = with_verified_candidates(seen[0][0], t);
  const BallMatch match = score_photos(photos, [&](std::size_t) { return kept; });
  EXPECT_EQ(match.matched, 1);
  EXPECT_EQ(match.detected, 1);
  EXPECT_LE(t, 1.0);
}

TEST(BallVerifier, CandidatesAreAddedBestFirstWhereNoBallIs) {
  const std::vector<PhotoBall> balls{{Vec2(50.0, 50.0), 10.0, 0.8}};
  const std::vector<BallCandidate> candidates{{Vec2(55.0, 50.0), 8.0, 9.0},    // on the ball
                                              {Vec2(100.0, 50.0), 6.0, 5.0},   // free
                                              {Vec2(103.0, 50.0), 6.0, 7.0},   // on the next
                                              {Vec2(200.0, 50.0), 6.0, 1.0}};  // unlikely
  const std::vector<double> probability{0.99, 0.95, 0.97, 0.5};
  const std::vector<PhotoBall> out =
      with_verified_candidates({balls, candidates, probability}, 0.9);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].center_px, Vec2(50.0, 50.0));
  EXPECT_EQ(out[1].center_px, Vec2(103.0, 50.0));  // the likelier of the two that overlap
  EXPECT_DOUBLE_EQ(out[1].score, 0.97);
  EXPECT_EQ(with_verified_candidates({balls, candidates, probability}, 1.1).size(), 1u);
  EXPECT_THROW(with_verified_candidates({balls, candidates, {0.5}}, 0.9), InputError);
}

}  // namespace
}  // namespace ballsight
