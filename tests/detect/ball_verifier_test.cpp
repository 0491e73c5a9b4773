#include "ballsight/detect/ball_verifier.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "ballsight/core/error.hpp"
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

TEST(BallVerifier, CandidatesAreAddedBestFirstWhereNoBallIs) {
  const std::vector<PhotoBall> balls{{Vec2(50.0, 50.0), 10.0, 0.8}};
  const std::vector<BallCandidate> candidates{{Vec2(55.0, 50.0), 8.0, 9.0},    // on the ball
                                              {Vec2(100.0, 50.0), 6.0, 5.0},   // free
                                              {Vec2(103.0, 50.0), 6.0, 7.0},   // on the next
                                              {Vec2(200.0, 50.0), 6.0, 1.0}};  // unlikely
  const std::vector<double> probability{0.99, 0.95, 0.97, 0.5};
  const std::vector<PhotoBall> out = with_verified_candidates(balls, candidates, probability, 0.9);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].center_px, Vec2(50.0, 50.0));
  EXPECT_EQ(out[1].center_px, Vec2(103.0, 50.0));  // the likelier of the two that overlap
  EXPECT_DOUBLE_EQ(out[1].score, 0.97);
  EXPECT_EQ(with_verified_candidates(balls, candidates, probability, 1.1).size(), 1u);
  EXPECT_THROW(with_verified_candidates(balls, candidates, std::vector<double>{0.5}, 0.9),
               InputError);
}

}  // namespace
}  // namespace ballsight
