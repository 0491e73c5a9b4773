#include "ballsight/detect/ball_candidates.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"
#include "ballsight/detect/ball_labels.hpp"
#include "ballsight/detect/ball_patches.hpp"

namespace ballsight {
namespace {

const cv::Scalar kCourt(150, 120, 95);  // blue-grey, BGR
const cv::Scalar kYellow(45, 235, 215);

// Balls of radius 3, 8 and 20 px on a court (drawn with 8x sub-pixel precision).
cv::Mat three_balls() {
  cv::Mat image(240, 320, CV_8UC3, kCourt);
  for (const auto& [x, y, r] :
       {std::tuple{40.5, 50.25, 3.0}, std::tuple{120.0, 60.0, 8.0}, std::tuple{220.0, 150.0, 20.0}})
    cv::circle(image, cv::Point(static_cast<int>(x * 8), static_cast<int>(y * 8)),
               static_cast<int>(r * 8), kYellow, -1, cv::LINE_AA, 3);
  return image;
}

TEST(BallCandidates, FindsEachBallWithItsCentreAndRadius) {
  const std::vector<BallCandidate> found = find_ball_candidates(three_balls());
  for (const LabelledBall& ball :
       {LabelledBall{Vec2(40.5, 50.25), 3.0}, LabelledBall{Vec2(120.0, 60.0), 8.0},
        LabelledBall{Vec2(220.0, 150.0), 20.0}}) {
    const auto best = std::min_element(
        found.begin(), found.end(), [&](const BallCandidate& a, const BallCandidate& b) {
          return (a.center_px - ball.center_px).norm() < (b.center_px - ball.center_px).norm();
        });
    ASSERT_NE(best, found.end());
    EXPECT_LT((best->center_px - ball.center_px).norm(), 0.1 * ball.radius_px + 0.3)
        << "ball of radius " << ball.radius_px;
    EXPECT_NEAR(best->radius_px, ball.radius_px, 0.2 * ball.radius_px);
  }
  // The strongest three are the balls, strongest first.
  ASSERT_GE(found.size(), 3u);
  for (std::size_t i = 1; i < found.size(); ++i)
    EXPECT_GE(found[i - 1].response, found[i].response);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_GT(found[i].response, 50.0);
}

TEST(BallCandidates, AnEvenImageHasNoneAndTheCountIsBounded) {
  EXPECT_TRUE(find_ball_candidates(cv::Mat(100, 100, CV_8UC3, kCourt)).empty());
  EXPECT_TRUE(find_ball_candidates(cv::Mat(1, 1, CV_8UC3, kYellow)).empty());
  BallCandidateOptions one;
  one.max_candidates = 1;
  const std::vector<BallCandidate> found = find_ball_candidates(three_balls(), one);
  ASSERT_EQ(found.size(), 1u);
  // The one kept is the strongest of them all.
  const std::vector<BallCandidate> all = find_ball_candidates(three_balls());
  EXPECT_GT(all.size(), 1u);
  EXPECT_EQ(found[0].center_px, all[0].center_px);
  EXPECT_EQ(found[0].response, all[0].response);
}

TEST(BallCandidates, BadInputIsRefusedNamingIt) {
  BallCandidateOptions bad;
  bad.min_radius_px = 0.5;
  EXPECT_THROW(find_ball_candidates(three_balls(), bad), InputError);
  bad = {};
  bad.max_radius_share = 0.0;
  EXPECT_THROW(bad.validate(), InputError);
  EXPECT_THROW(find_ball_candidates(cv::Mat(10, 10, CV_8UC1, cv::Scalar(0))), InputError);
}

TEST(BallPatches, APatchHoldsTheBallInItsMiddleHalf) {
  const cv::Mat image = three_balls();
  const cv::Mat patch = ball_patch(image, {Vec2(120.0, 60.0), 8.0, 1.0});
  ASSERT_EQ(patch.size(), cv::Size(kBallPatchSize, kBallPatchSize));
  ASSERT_EQ(patch.type(), CV_8UC3);
  const auto is = [](const cv::Vec3b& p, const cv::Scalar& c) {
    return std::abs(p[0] - c[0]) + std::abs(p[1] - c[1]) + std::abs(p[2] - c[2]) < 12;
  };
  EXPECT_TRUE(is(patch.at<cv::Vec3b>(16, 16), kYellow));
  EXPECT_TRUE(is(patch.at<cv::Vec3b>(16, 16 + 6), kYellow));  // within the radius (8 px)
  EXPECT_TRUE(is(patch.at<cv::Vec3b>(16, 16 + 10), kCourt));  // beyond it
  EXPECT_TRUE(is(patch.at<cv::Vec3b>(0, 0), kCourt));
  // A small ball is scaled up, one cut by the border padded with its edge.
  EXPECT_TRUE(is(ball_patch(image, {Vec2(40.5, 50.25), 3.0, 1.0}).at<cv::Vec3b>(16, 16), kYellow));
  const cv::Mat corner = ball_patch(image, {Vec2(0.0, 0.0), 30.0, 1.0});
  EXPECT_EQ(corner.size(), cv::Size(kBallPatchSize, kBallPatchSize));
  EXPECT_TRUE(is(corner.at<cv::Vec3b>(0, 0), kCourt));
}

TEST(BallPatches, CandidatesAreTaggedByTheLabels) {
  const std::vector<LabelledBall> labels{{Vec2(100.0, 100.0), 10.0}};
  const std::vector<LabelledBall> ignored{{Vec2(300.0, 100.0), 10.0}};
  const std::vector<BallCandidate> candidates{{Vec2(104.0, 100.0), 12.0, 1.0},
                                              {Vec2(100.0, 103.0), 30.0, 1.0},
                                              {Vec2(150.0, 100.0), 10.0, 1.0},
                                              {Vec2(302.0, 100.0), 10.0, 1.0}};
  EXPECT_EQ(candidate_truth(candidates, labels, ignored),
            (std::vector<CandidateTruth>{CandidateTruth::ball, CandidateTruth::unknown,
                                         CandidateTruth::not_ball, CandidateTruth::unknown}));
}

}  // namespace
}  // namespace ballsight
