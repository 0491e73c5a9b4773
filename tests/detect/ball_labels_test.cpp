// Labelled photo sources (labels.csv and images/) and how detections are scored against labels.
#include "ballsight/detect/ball_labels.hpp"

#include <gtest/gtest.h>

#include <array>
#include <opencv2/imgcodecs.hpp>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

namespace fs = std::filesystem;

// A source folder with two 40x30 images and `csv` as its labels.csv.
fs::path write_source(const test::TempDir& dir, const std::string& csv) {
  const fs::path folder = dir / "court-a";
  fs::create_directories(folder / "images");
  for (const char* name : {"b.png", "a.jpg"})
    cv::imwrite((folder / "images" / name).string(), cv::Mat3b(30, 40, cv::Vec3b(0, 80, 0)));
  write_file_atomic(folder / "labels.csv", csv);
  return folder;
}

TEST(BallLabels, ReadsASourceAndItsImagesWithoutBalls) {
  const test::TempDir dir;
  const fs::path folder = write_source(dir, "image,cx,cy,r\nb.png,10,12.5,4\nb.png,30,5,2.5\n");
  const LabelledSource source = read_labelled_source(folder);
  EXPECT_EQ(source.name, "court-a");
  ASSERT_EQ(source.images.size(), 2u);
  EXPECT_EQ(source.images[0].file, "a.jpg");
  EXPECT_TRUE(source.images[0].balls.empty());
  ASSERT_EQ(source.images[1].balls.size(), 2u);
  EXPECT_EQ(source.images[1].balls[0].center_px, Vec2(10, 12.5));
  EXPECT_EQ(source.images[1].balls[1].radius_px, 2.5);
  const std::vector<LabelledSource> all = read_labelled_sources(dir.path());
  ASSERT_EQ(all.size(), 1u);
  EXPECT_TRUE(read_labelled_sources(dir / "absent").empty());
}

TEST(BallLabels, AMalformedRowIsAnErrorNamingFileAndLine) {
  const test::TempDir dir;
  const auto message = [&](const std::string& csv) {
    try {
      read_labelled_source(write_source(dir, csv));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("image,cx,cy,r\nb.png,10,12\n").find("labels.csv:2"), std::string::npos);
  EXPECT_NE(message("image,cx,cy,r\nb.png,1,2,3\nb.png,x,2,3\n").find("labels.csv:3"),
            std::string::npos);
  EXPECT_NE(message("image,cx,cy,r\nc.png,1,2,3\n").find("c.png"), std::string::npos);
  EXPECT_NE(message("image,cx,cy,r\nb.png,1,2,0\n").find("radius"), std::string::npos);
  EXPECT_NE(message("file,x,y\n").find("header"), std::string::npos);
}

TEST(BallLabels, ADetectionFindsALabelWithinItsRadiusOnceBestScoreFirst) {
  const std::array<LabelledBall, 2> labels{LabelledBall{Vec2(20, 20), 5.0},
                                           LabelledBall{Vec2(60, 20), 3.0}};
  // Best first: the first takes the label at (20, 20); the second is a duplicate of it; the third
  // lies 3.5 px from the small label, beyond its radius.
  const std::array<PhotoBall, 3> balls{PhotoBall{Vec2(22, 20), 5.0, 0.9},
                                       PhotoBall{Vec2(20, 21), 5.0, 0.8},
                                       PhotoBall{Vec2(60, 23.5), 3.0, 0.7}};
  const BallMatch match = match_balls_to_labels(labels, balls, {100, 100});
  EXPECT_EQ(match.labelled, 2);
  EXPECT_EQ(match.detected, 3);
  EXPECT_EQ(match.matched, 1);
  EXPECT_EQ(match.label_matched, (std::vector<bool>{true, false}));
  ASSERT_EQ(match.center_error_px.size(), 1u);
  EXPECT_DOUBLE_EQ(match.center_error_px[0], 2.0);
  EXPECT_DOUBLE_EQ(match.center_error_radii[0], 0.4);
  EXPECT_DOUBLE_EQ(recall(match), 0.5);
  EXPECT_DOUBLE_EQ(precision(match), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(f1_score(match), 0.4);
  const nlohmann::json json = ball_match_json(match);
  EXPECT_DOUBLE_EQ(json["median_center_error_radii"].get<double>(), 0.4);
}

TEST(BallLabels, ABallCutByTheBorderIsComparedByItsVisiblePart) {
  // A ball of radius 20 centred 10 px left of the image: its label boxes the visible part, pixel
  // edges x 0..10 (centre 4.5) and y 40..80 (centre 59.5).
  const LabelledBall label = label_of_box(cv::Rect2d(0, 40, 10, 40));
  EXPECT_EQ(label.center_px, Vec2(4.5, 59.5));
  EXPECT_DOUBLE_EQ(label.radius_px, 12.5);
  const std::array<PhotoBall, 1> whole{PhotoBall{Vec2(-10.5, 59.5), 20.0, 1.0}};
  const BallMatch match = match_balls_to_labels(std::span(&label, 1), whole, {200, 100});
  EXPECT_EQ(match.matched, 1);
  EXPECT_NEAR(match.center_error_px[0], 0.0, 1e-9);
}

// A detection on an ignored object (a simulated frame's reference ball, say) is neither right nor
// wrong, unless it lies on a label too.
TEST(BallLabels, ADetectionOnAnIgnoredObjectIsLeftOut) {
  const std::array<LabelledBall, 1> labels{LabelledBall{Vec2(20, 20), 5.0}};
  const std::array<LabelledBall, 2> ignored{LabelledBall{Vec2(60, 20), 4.0},
                                            LabelledBall{Vec2(24, 20), 3.0}};
  const std::array<PhotoBall, 4> balls{
      PhotoBall{Vec2(61, 21), 4.0, 0.9},    // on an ignored object: left out
      PhotoBall{Vec2(65.5, 20), 4.0, 0.8},  // within its radius and the 2 px margin: left out
      PhotoBall{Vec2(23, 20), 5.0, 0.7},    // on the label and an ignored object: kept
      PhotoBall{Vec2(90, 20), 4.0, 0.6}};   // on nothing: kept (a false detection)
  const std::vector<PhotoBall> kept = without_ignored(balls, labels, ignored);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].center_px, Vec2(23, 20));
  EXPECT_EQ(kept[1].center_px, Vec2(90, 20));
}

TEST(BallLabels, RecallByRadiusCountsEachLabelInItsRange) {
  BallMatch total;
  const std::array<LabelledBall, 3> labels{LabelledBall{Vec2(10, 10), 2.0},
                                           LabelledBall{Vec2(50, 10), 8.0},
                                           LabelledBall{Vec2(100, 10), 30.0}};
  const std::array<PhotoBall, 1> one{PhotoBall{Vec2(50, 11), 8.0, 1.0}};
  add_match(total, match_balls_to_labels(labels, one, {400, 400}));
  const std::array<double, 3> edges{1.0, 5.0, 20.0};
  const std::vector<RadiusRecall> ranges = recall_by_radius(total, edges);
  ASSERT_EQ(ranges.size(), 3u);
  EXPECT_EQ(ranges[0].labelled, 1);
  EXPECT_EQ(ranges[0].matched, 0);
  EXPECT_EQ(ranges[1].matched, 1);
  EXPECT_EQ(ranges[2].labelled, 1);
  EXPECT_EQ(recall_by_radius_json(ranges)[2]["radius_px"][1], nullptr);
  const std::array<double, 2> unordered{5.0, 5.0};
  EXPECT_THROW(recall_by_radius(total, unordered), InputError);
}

}  // namespace
}  // namespace ballsight
