// `ballsight detect balls`, `detect fit`, `detect patches` and `colours learn` as a user runs
// them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace ballsight::test {
namespace {

// Two touching optic-yellow balls and a pink one on a blue-grey court.
std::string write_photo(const TempDir& dir) {
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(150, 120, 95));
  cv::circle(image, {100, 120}, 25, cv::Scalar(45, 245, 220), -1, cv::LINE_AA);
  cv::circle(image, {150, 120}, 25, cv::Scalar(45, 245, 220), -1, cv::LINE_AA);
  cv::circle(image, {250, 80}, 20, cv::Scalar(180, 80, 255), -1, cv::LINE_AA);
  const std::string path = (dir / "photo.png").string();
  cv::imwrite(path, image);
  return path;
}

// A data folder of one labelled source, court-a: the photo with its two yellow balls labelled
// (the pink one is not); returns the source's folder.
std::filesystem::path write_labelled_source(const TempDir& dir) {
  const std::filesystem::path source = dir / "real" / "tennis" / "court-a";
  std::filesystem::create_directories(source / "images");
  std::filesystem::rename(write_photo(dir), source / "images" / "photo.png");
  std::ofstream(source / "labels.csv")
      << "image,cx,cy,r\nphoto.png,100,120,25\nphoto.png,150,120,25\n";
  return source;
}

TEST(DetectBallsCli, PrintsTheBallsAsJsonAndDrawsThem) {
  TempDir dir;
  const std::string photo = write_photo(dir);
  const CliResult r = run_cli(
      {"detect", "balls", "--image", photo, "--json", "--plot", (dir / "plot.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json json = nlohmann::json::parse(r.stdout_text);
  ASSERT_EQ(json["balls"].size(), 2u);
  for (const auto& ball : json["balls"]) {
    EXPECT_NEAR(ball["y_px"].get<double>(), 120.0, 1.0);
    EXPECT_NEAR(ball["radius_px"].get<double>(), 25.0, 2.0);
    EXPECT_GT(ball["score"].get<double>(), 0.5);
  }
  EXPECT_EQ(cv::imread((dir / "plot.png").string()).size(), cv::Size(320, 240));
}

TEST(DetectBallsCli, ALearnedColourModelFindsThePinkBall) {
  TempDir dir;
  const std::string photo = write_photo(dir);
  const std::string model = (dir / "pink.json").string();
  const CliResult learn =
      run_cli({"colours", "learn", "--image", photo, "--at", "250,80;245,85", "--out", model});
  ASSERT_EQ(learn.exit_code, 0) << learn.stderr_text;
  EXPECT_NE(learn.stdout_text.find("1 colour from 2 clicks"), std::string::npos)
      << learn.stdout_text;
  const CliResult r = run_cli({"detect", "balls", "--image", photo, "--colours", model, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json json = nlohmann::json::parse(r.stdout_text);
  ASSERT_EQ(json["balls"].size(), 1u);
  EXPECT_NEAR(json["balls"][0]["x_px"].get<double>(), 250.0, 1.0);
}

TEST(DetectBallsCli, BadInputGetsOneLineNamingIt) {
  TempDir dir;
  const std::string photo = write_photo(dir);
  expect_one_line_error(run_cli({"detect", "balls", "--image", (dir / "none.png").string()}),
                        "none.png");
  expect_one_line_error(
      run_cli({"detect", "balls", "--image", photo, "--colours", (dir / "none.json").string()}),
      "none.json");
  expect_one_line_error(run_cli({"detect", "balls", "--image", photo, "--min-radius-px", "0"}),
                        "min_radius_px");
  expect_one_line_error(run_cli({"colours", "learn", "--image", photo, "--at", "10,x", "--out",
                                 (dir / "c.json").string()}),
                        "--at (click 1)");
  expect_one_line_error(run_cli({"colours", "learn", "--image", photo, "--at", "400,10", "--out",
                                 (dir / "c.json").string()}),
                        "click 1");
  EXPECT_FALSE(std::filesystem::exists(dir / "c.json"));
  // A greyscale photo is refused (balls are found by their colour); a 1x1 photo has no ball.
  cv::imwrite((dir / "grey.png").string(), cv::imread(photo, cv::IMREAD_GRAYSCALE));
  expect_one_line_error(run_cli({"detect", "balls", "--image", (dir / "grey.png").string()}),
                        "greyscale");
  cv::imwrite((dir / "one.png").string(), cv::Mat(1, 1, CV_8UC3, cv::Scalar(45, 245, 220)));
  const CliResult one = run_cli({"detect", "balls", "--image", (dir / "one.png").string()});
  EXPECT_EQ(one.exit_code, 0) << one.stderr_text;
  EXPECT_NE(one.stdout_text.find("0 balls"), std::string::npos) << one.stdout_text;
}

// `detect fit` on a data folder of one labelled source (the photo with its two yellow balls and
// one unlabelled pink ball), then `detect balls` with what it wrote.
TEST(DetectBallsCli, FitsSettingsToALabelledSourceAndDetectsWithThem) {
  TempDir dir;
  const std::filesystem::path source = write_labelled_source(dir);
  const std::string settings = (dir / "detector.json").string();
  const CliResult fit =
      run_cli({"detect", "fit", "--data", dir.path().string(), "--rounds", "1", "--out", settings});
  ASSERT_EQ(fit.exit_code, 0) << fit.stderr_text;
  EXPECT_NE(fit.stdout_text.find("fitted on 1 source"), std::string::npos) << fit.stdout_text;
  EXPECT_NE(fit.stdout_text.find("mean F1 1.000"), std::string::npos) << fit.stdout_text;
  const CliResult r =
      run_cli({"detect", "balls", "--image", (source / "images" / "photo.png").string(),
               "--detector", settings, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(nlohmann::json::parse(r.stdout_text)["balls"].size(), 2u);

  expect_one_line_error(run_cli({"detect", "fit", "--data", dir.path().string(), "--leave-out",
                                 "court-b", "--out", (dir / "x.json").string()}),
                        "court-b");
  expect_one_line_error(run_cli({"detect", "fit", "--data", dir.path().string(), "--leave-out",
                                 "court-a", "--out", (dir / "x.json").string()}),
                        "no labelled source");
  EXPECT_FALSE(std::filesystem::exists(dir / "x.json"));
  std::ofstream(dir / "bad.json") << "{\"format\": \"ballsight-photo-ball-detector\"}";
  expect_one_line_error(
      run_cli({"detect", "balls", "--image", (source / "images" / "photo.png").string(),
               "--detector", (dir / "bad.json").string()}),
      "bad.json");
}

// `detect patches` on the same source: a NumPy file of every candidate's patch and a CSV that
// tells the two balls from the rest.
TEST(DetectBallsCli, WritesTheCandidatesPatchesWithTheirTruth) {
  TempDir dir;
  const std::filesystem::path source = write_labelled_source(dir);
  const std::string out = (dir / "patches").string();
  const CliResult r = run_cli(
      {"detect", "patches", "--data", dir.path().string(), "--source", "court-a", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  std::ifstream csv(out + ".csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "source,image,x_px,y_px,radius_px,response,truth");
  int rows = 0;
  int balls = 0;
  while (std::getline(csv, line)) {
    ++rows;
    balls += line.ends_with(",ball");
  }
  EXPECT_EQ(balls, 2);
  // The NumPy header names as many patches as the CSV has rows, and the data follows it.
  std::ifstream npy(out + ".npy", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(npy)), {});
  ASSERT_GT(bytes.size(), 10u);
  EXPECT_EQ(bytes.substr(0, 6), "\x93NUMPY");
  const std::size_t header =
      10 + static_cast<unsigned char>(bytes[8]) + 256 * static_cast<unsigned char>(bytes[9]);
  EXPECT_EQ(header % 64, 0u);
  EXPECT_NE(bytes.find("'shape': (" + std::to_string(rows) + ", 32, 32, 3)"), std::string::npos);
  EXPECT_EQ(bytes.size(), header + static_cast<std::size_t>(rows) * 32 * 32 * 3);

  expect_one_line_error(run_cli({"detect", "patches", "--data", dir.path().string(), "--source",
                                 "court-b", "--out", (dir / "x").string()}),
                        "court-b");
  expect_one_line_error(run_cli({"detect", "patches", "--out", (dir / "x").string()}),
                        "--sim-scenes");
  EXPECT_FALSE(std::filesystem::exists(dir / "x.npy"));
}

}  // namespace
}  // namespace ballsight::test
