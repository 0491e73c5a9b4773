// Fitting the photo detector's settings to labelled photos, and saving them.
#include "ballsight/detect/photo_ball_fit.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

// Photos of dim yellow balls (value 95, saturation 0.53: no seed of the shade colour) on a green
// court, three to a photo.
LabelledPhotos dim_balls() {
  LabelledPhotos photos{"dim", {}, {}, {}, {}};
  for (int k = 0; k < 3; ++k) {
    cv::Mat3b image(120, 160, cv::Vec3b(40, 110, 30));
    std::vector<LabelledBall> labels;
    for (int b = 0; b < 3; ++b) {
      const cv::Point center(30 + 45 * b, 40 + 20 * k);
      const int radius = 6 + 2 * b;
      cv::circle(image, center, radius, {45, 95, 90}, cv::FILLED, cv::LINE_AA);
      labels.push_back({Vec2(center.x, center.y), static_cast<double>(radius)});
    }
    photos.files.push_back("photo" + std::to_string(k) + ".png");
    photos.images.push_back(image);
    photos.labels.push_back(labels);
  }
  return photos;
}

TEST(PhotoBallFit, FindsSettingsThatSeeWhatTheStartMissed) {
  PhotoBallFitOptions options;
  options.start.colours.colours[0].seed.min_value = 130.0;  // above the balls' value
  const std::vector<LabelledPhotos> sources{dim_balls()};
  PhotoBallDetector start(options.start);
  EXPECT_EQ(score_photos(start, sources[0]).matched, 0);
  const PhotoBallFit fit = fit_photo_ball_detector(sources, options);
  EXPECT_DOUBLE_EQ(fit.mean_f1, 1.0);
  EXPECT_LE(fit.options.colours.colours[0].seed.min_value, 95.0);
  EXPECT_EQ(fit.fitted_on, std::vector<std::string>{"dim"});
  EXPECT_GT(fit.evaluations, 1);
  // Deterministic.
  const PhotoBallFit again = fit_photo_ball_detector(sources, options);
  EXPECT_EQ(photo_ball_fit_json(again), photo_ball_fit_json(fit));
}

TEST(PhotoBallFit, SettingsRoundTripThroughAFileAndBadOnesAreErrors) {
  const test::TempDir dir;
  PhotoBallFit fit;
  fit.options.circles.min_score = 0.45;
  fit.fitted_on = {"a", "b"};
  const auto path = dir / "detector.json";
  write_file_atomic(path, photo_ball_fit_json(fit).dump());
  const PhotoBallOptions read = read_photo_ball_options(path.string());
  EXPECT_DOUBLE_EQ(read.circles.min_score, 0.45);
  EXPECT_EQ(ball_colours_json(read.colours), ball_colours_json(fit.options.colours));

  nlohmann::json bad = photo_ball_fit_json(fit);
  bad["min_score"] = 1.5;
  try {
    photo_ball_options_from_json(bad, "detector.json");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "detector.json: min_score: must be within [0, 1]");
  }
  bad = photo_ball_fit_json(fit);
  bad["format"] = "ballsight-ball-colours";
  EXPECT_THROW(photo_ball_options_from_json(bad, "f"), InputError);
  write_file_atomic(path, "{\"format\": ");
  try {
    read_photo_ball_options(path.string());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_THROW(fit_photo_ball_detector({}, {}), InputError);
}

// The build holds the committed shipped settings (a fit's output that names its command; that
// the command gives these numbers is not rerun here: a minute on the real photos).
TEST(PhotoBallFit, TheBuildHoldsTheCommittedShippedSettings) {
  const std::string path =
      std::string(BALLSIGHT_SOURCE_DIR) + "/src/ballsight/detect/shipped_photo_ball_detector.json";
  const PhotoBallOptions committed = read_photo_ball_options(path);
  const PhotoBallOptions shipped = shipped_photo_ball_options();
  EXPECT_EQ(ball_colours_json(shipped.colours), ball_colours_json(committed.colours));
  EXPECT_EQ(shipped.circles.min_score, committed.circles.min_score);
  EXPECT_EQ(shipped.split.min_contrast, committed.split.min_contrast);
  EXPECT_EQ(shipped.split.max_share, committed.split.max_share);
  const nlohmann::json file = nlohmann::json::parse(read_file(path));
  EXPECT_TRUE(file["command"].get<std::string>().starts_with("ballsight detect fit "));
  EXPECT_EQ(file["fitted_on"].size(), 4u);  // the three real sources and the simulator
}

}  // namespace
}  // namespace ballsight
