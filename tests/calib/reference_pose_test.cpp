#include "ballsight/calib/reference_pose.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"

namespace ballsight {
namespace {

std::vector<ReferencePoint> court_references() {
  const std::vector<Vec3> points = sim::reference_ball_positions({});
  std::vector<ReferencePoint> references;
  for (std::size_t i = 0; i < points.size(); ++i) {
    references.push_back({"ref" + std::to_string(i), points[i]});
  }
  return references;
}

/// Pixels of the references a camera sees within `max_distance_m`, with Gaussian noise, in a
/// shuffled order, followed by `false_blobs` random blobs; `truth[i]` is candidate i's reference
/// (or -1).
struct Candidates {
  std::vector<Vec2> pixels;
  std::vector<int> truth;
};

Candidates observe(const sim::CourtCamera& camera, const std::vector<ReferencePoint>& references,
                   double max_distance_m, double noise_px, int false_blobs, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_px);
  Candidates out;
  std::vector<std::size_t> order(references.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), rng);
  for (std::size_t r : order) {
    const Vec3& p = references[r].p_in_field;
    if ((camera.center_in_field() - p).norm() > max_distance_m) continue;
    const auto pixel = camera.camera.project(camera.camera_from_field * p);
    if (!pixel || !camera.camera.in_image(*pixel)) continue;
    out.pixels.push_back(*pixel + Vec2(noise(rng), noise(rng)));
    out.truth.push_back(static_cast<int>(r));
  }
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int f = 0; f < false_blobs; ++f) {
    out.pixels.emplace_back(u(rng) * camera.camera.width(), u(rng) * camera.camera.height());
    out.truth.push_back(-1);
  }
  return out;
}

double rotation_error_deg(const Rigid3& a, const Rigid3& b) {
  return deg_from_rad(Eigen::AngleAxisd(a.rotation.transpose() * b.rotation).angle());
}

TEST(ReferencePose, FindsEveryCornerCameraFromItsNearReferencesAndAHint) {
  const std::vector<ReferencePoint> references = court_references();
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    const sim::CourtRig rig = sim::make_court_rig({}, {}, seed);
    for (std::size_t c = 0; c < rig.cameras.size(); ++c) {
      SCOPED_TRACE("rig seed " + std::to_string(seed) + " camera " + std::to_string(c));
      const sim::CourtCamera& camera = rig.cameras[c];
      const Candidates candidates = observe(camera, references, 19.5, 0.15, 3, seed * 10 + c);
      // The hint: the pole's corner at a typical height, up to a couple of metres off.
      const Vec3 center = camera.center_in_field();
      const Vec3 hint(std::copysign(18.25, center.x()), std::copysign(9.25, center.y()), 5.0);
      const ReferencePose pose =
          estimate_reference_pose(camera.camera, references, candidates.pixels, hint);
      EXPECT_LT((pose.camera_from_field.inverse().translation - center).norm(), 0.10);
      EXPECT_LT(rotation_error_deg(pose.camera_from_field, camera.camera_from_field), 0.1);
      EXPECT_LT(pose.rms_px, 0.4);
      for (const ReferenceMatch& m : pose.matches) {
        EXPECT_EQ(candidates.truth[m.candidate], static_cast<int>(m.reference));
      }
      EXPECT_GE(pose.matches.size(), 5u);
      EXPECT_EQ(pose.matches.size() + pose.unmatched.size(), references.size());
    }
  }
}

TEST(ReferencePose, WithoutAHintTheSymmetricCourtIsAmbiguous) {
  const std::vector<ReferencePoint> references = court_references();
  const sim::CourtCamera camera = sim::make_court_rig({}, {}, 4).cameras[0];
  const Candidates candidates = observe(camera, references, 19.5, 0.1, 0, 4);
  try {
    estimate_reference_pose(camera.camera, references, candidates.pixels, std::nullopt);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("position_hint_m"), std::string::npos) << e.what();
  }
  // An asymmetric layout needs no hint: drop the references of the far half but one.
  std::vector<ReferencePoint> asymmetric;
  for (const ReferencePoint& r : references) {
    if (r.p_in_field.x() >= 0.0 || r.name == "ref3") asymmetric.push_back(r);
  }
  const Candidates seen = observe(camera, asymmetric, 19.5, 0.1, 0, 5);
  const ReferencePose pose =
      estimate_reference_pose(camera.camera, asymmetric, seen.pixels, std::nullopt);
  EXPECT_LT((pose.camera_from_field.inverse().translation - camera.center_in_field()).norm(), 0.1);
}

TEST(ReferencePose, FewerThanFourFoundNamesTheMissingOnes) {
  const std::vector<ReferencePoint> references = court_references();
  const sim::CourtCamera camera = sim::make_court_rig({}, {}, 5).cameras[1];
  Candidates candidates = observe(camera, references, 19.5, 0.1, 0, 6);
  ASSERT_GE(candidates.pixels.size(), 4u);
  candidates.pixels.resize(3);
  candidates.truth.resize(3);
  const Vec3 hint(18.25, -9.25, 5.0);
  try {
    estimate_reference_pose(camera.camera, references, candidates.pixels, hint);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("found 3 of 12"), std::string::npos) << what;
    EXPECT_NE(what.find("at least 4 needed; missing: "), std::string::npos) << what;
    // The three it saw are named as found, the others as missing.
    const std::string missing = what.substr(what.find("missing: "));
    for (int t : candidates.truth) {
      EXPECT_EQ(missing.find("ref" + std::to_string(t) + ","), std::string::npos) << what;
    }
  }
  EXPECT_THROW(estimate_reference_pose(camera.camera, references, {}, hint), InputError);
}

// The court calibration page's corrections: with only three references seen as blobs the pose
// cannot be found; a fourth placed by hand where the user saw it makes it, and the placed one is
// kept as a match with its pixel. A reference marked absent is matched to nothing, even when a
// blob lies where it projects.
TEST(ReferencePose, PlacedAndAbsentReferencesAreTheUsersWord) {
  const std::vector<ReferencePoint> references = court_references();
  const sim::CourtCamera camera = sim::make_court_rig({}, {}, 5).cameras[1];
  Candidates seen = observe(camera, references, 19.5, 0.1, 0, 6);
  ASSERT_GE(seen.pixels.size(), 5u);
  const Vec3 hint(18.25, -9.25, 5.0);
  std::vector<Vec2> three(seen.pixels.begin(), seen.pixels.begin() + 3);
  EXPECT_THROW(estimate_reference_pose(camera.camera, references, three, hint), InputError);

  ReferenceCorrections corrections;
  const auto fourth = static_cast<std::size_t>(seen.truth[3]);
  corrections.placed.push_back({fourth, seen.pixels[3]});
  const ReferencePose pose =
      estimate_reference_pose(camera.camera, references, three, hint, {}, corrections);
  EXPECT_LT((pose.camera_from_field.inverse().translation - camera.center_in_field()).norm(), 0.2);
  ASSERT_EQ(pose.matches.size(), 4u);
  ASSERT_EQ(pose.matched_px.size(), 4u);
  const auto placed = std::find_if(pose.matches.begin(), pose.matches.end(),
                                   [&](const ReferenceMatch& m) { return m.reference == fourth; });
  ASSERT_NE(placed, pose.matches.end());
  EXPECT_EQ(pose.matched_px[static_cast<std::size_t>(placed - pose.matches.begin())],
            seen.pixels[3]);

  // Every reference seen, and the first marked absent: it is not matched, the rest are.
  ReferenceCorrections absent;
  absent.absent.push_back(static_cast<std::size_t>(seen.truth[0]));
  const ReferencePose without =
      estimate_reference_pose(camera.camera, references, seen.pixels, hint, {}, absent);
  EXPECT_EQ(without.matches.size(), seen.pixels.size() - 1);
  for (const ReferenceMatch& m : without.matches) EXPECT_NE(m.reference, absent.absent[0]);

  ReferenceCorrections twice;
  twice.placed.push_back({0, Vec2(1, 1)});
  twice.absent.push_back(0);
  EXPECT_THROW(estimate_reference_pose(camera.camera, references, seen.pixels, hint, {}, twice),
               InputError);
}

}  // namespace
}  // namespace ballsight
