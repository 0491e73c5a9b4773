// The ball colour model: its file (round trip, errors naming file and field) and learning it
// from a few clicks.
#include "ballsight/detect/ball_colours.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/detect/ball_colour_learning.hpp"
#include "ballsight/detect/photo_balls.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BallColours, FileRoundTrips) {
  test::TempDir dir;
  const BallColours colours = default_ball_colours();
  write_ball_colours((dir / "c.json").string(), colours);
  const BallColours back = read_ball_colours((dir / "c.json").string());
  ASSERT_EQ(back.colours.size(), colours.colours.size());
  for (std::size_t i = 0; i < colours.colours.size(); ++i) {
    EXPECT_EQ(back.colours[i].name, colours.colours[i].name);
    EXPECT_EQ(back.colours[i].seed.hue_min_deg, colours.colours[i].seed.hue_min_deg);
    EXPECT_EQ(back.colours[i].grow.min_saturation, colours.colours[i].grow.min_saturation);
    EXPECT_EQ(back.colours[i].seed.min_value, colours.colours[i].seed.min_value);
    EXPECT_EQ(back.colours[i].far, colours.colours[i].far);
  }
  EXPECT_TRUE(back.colours.back().far);  // the far orange
}

TEST(BallColours, ErrorsNameTheFileAndTheField) {
  test::TempDir dir;
  const std::string path = (dir / "c.json").string();
  EXPECT_NE(error_of([&] { read_ball_colours(path); }).find(path), std::string::npos);
  write_file_atomic(path, "{not json");
  EXPECT_NE(error_of([&] { read_ball_colours(path); }).find("not valid JSON"), std::string::npos);
  nlohmann::json json = ball_colours_json(default_ball_colours());
  json["colours"][1]["seed"]["min_saturation"] = 1.5;
  write_file_atomic(path, json.dump());
  EXPECT_NE(error_of([&] { read_ball_colours(path); }).find(path + ".colours[1].seed"),
            std::string::npos);
  json = ball_colours_json(default_ball_colours());
  json["colours"][0]["seed"]["hue_deg"] = {20, 120};  // wider than its growth band
  write_file_atomic(path, json.dump());
  EXPECT_NE(error_of([&] { read_ball_colours(path); }).find("within the grow band"),
            std::string::npos);
  json = ball_colours_json(default_ball_colours());
  json["colours"][0]["far"] = "yes";
  write_file_atomic(path, json.dump());
  EXPECT_NE(error_of([&] { read_ball_colours(path); }).find(path + ".colours[0].far"),
            std::string::npos);
  json["format"] = "something else";
  write_file_atomic(path, json.dump());
  EXPECT_NE(error_of([&] { read_ball_colours(path); }).find(".format"), std::string::npos);
}

// A purple ball (no default colour) and an orange-and-yellow one on grey.
cv::Mat two_balls() {
  cv::Mat image(200, 300, CV_8UC3, cv::Scalar(128, 128, 128));
  cv::circle(image, {80, 100}, 30, cv::Scalar(200, 40, 150), -1);
  cv::circle(image, {220, 100}, 30, cv::Scalar(30, 140, 250), -1);
  cv::ellipse(image, {220, 100}, {30, 30}, 0, -90, 90, cv::Scalar(40, 240, 210), -1);
  return image;
}

TEST(BallColours, LearnedFromClicksFindsWhatWasClicked) {
  const cv::Mat image = two_balls();
  PhotoBallDetector default_detector;
  EXPECT_EQ(default_detector.detect(image).size(), 1u);  // the purple ball is no tennis ball
  const BallColours learned = learn_ball_colours(image, {{75, 95}, {210, 100}, {235, 100}});
  ASSERT_EQ(learned.colours.size(), 3u);  // purple, orange and yellow
  PhotoBallOptions options;
  options.colours = learned;
  PhotoBallDetector detector(options);
  const std::vector<PhotoBall> balls = detector.detect(image);
  ASSERT_EQ(balls.size(), 2u);
  for (const PhotoBall& b : balls) {
    EXPECT_NEAR(b.radius_px, 30.0, 2.0);
    EXPECT_NEAR(b.center_px.y(), 100.0, 1.0);
  }
}

TEST(BallColours, LearningRefusesClicksOutsideOrOnGrey) {
  const cv::Mat image = two_balls();
  EXPECT_NE(error_of([&] {
              learn_ball_colours(image, {{75, 95}, {400, 10}});
            }).find("click 2"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              learn_ball_colours(image, {{5, 5}});
            }).find("no coloured pixel"),
            std::string::npos);
  EXPECT_THROW(learn_ball_colours(image, {}), InputError);
}

}  // namespace
}  // namespace ballsight
