#include "ballsight/detect/color_blobs.hpp"

#include <gtest/gtest.h>

#include <iostream>

#include "ballsight/core/error.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "sim/court_test_support.hpp"

namespace ballsight {
namespace {

struct CentroidStats {
  int found = 0, visible = 0, false_blobs = 0;
  double worst_px = 0.0;
  Vec2 offset_sum = Vec2::Zero();
  double squared_sum = 0.0;
};

// Reference balls (orange, 2 cm) in noisy, shadowed court views: every visible one within 19 m is
// found, centroids close to the analytic silhouette centroid, and nothing else is found.
TEST(ColorBlobs, ReferenceBallsInCourtViews) {
  const auto& court = sim::test_support::shared_court();
  CentroidStats stats;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const sim::CourtScene scene = sim::make_court_scene(court.rig.court, {}, seed);
    const sim::test_support::RenderedScene rendered =
        sim::test_support::render_in_all_cameras(scene, seed);
    for (std::size_t c = 0; c < court.rig.cameras.size(); ++c) {
      SCOPED_TRACE("scene seed " + std::to_string(seed) + " camera " + std::to_string(c));
      const std::vector<ColorBlob> blobs = find_color_blobs(rendered.renders[c].bgr, {});
      std::vector<bool> used(blobs.size(), false);
      for (const sim::SphereTruth& truth : rendered.truth) {
        if (truth.sphere.kind != sim::ObjectKind::reference_ball) continue;
        const sim::SphereViewTruth& view = truth.views[c];
        const double distance =
            (court.rig.cameras[c].center_in_field() - truth.sphere.center_in_field).norm();
        if (!view.visible || distance > 19.0) continue;
        ++stats.visible;
        const Vec2 t = *view.silhouette_centroid_px;
        std::size_t best = blobs.size();
        for (std::size_t b = 0; b < blobs.size(); ++b) {
          if ((blobs[b].centroid_px - t).norm() < 2.0) best = b;
        }
        if (best == blobs.size()) {
          ADD_FAILURE() << "reference ball " << truth.sphere.id << " at " << distance
                        << " m not found";
          continue;
        }
        used[best] = true;
        const Vec2 offset = blobs[best].centroid_px - t;
        ++stats.found;
        stats.worst_px = std::max(stats.worst_px, offset.norm());
        stats.offset_sum += offset;
        stats.squared_sum += offset.squaredNorm();
      }
      for (std::size_t b = 0; b < blobs.size(); ++b) {
        if (used[b]) continue;
        // Unmatched blobs are far reference balls only.
        bool far_reference = false;
        for (const sim::SphereTruth& truth : rendered.truth) {
          if (truth.sphere.kind == sim::ObjectKind::reference_ball &&
              truth.views[c].silhouette_centroid_px &&
              (*truth.views[c].silhouette_centroid_px - blobs[b].centroid_px).norm() < 2.0) {
            far_reference = true;
          }
        }
        if (!far_reference) {
          ++stats.false_blobs;
          ADD_FAILURE() << "blob at " << blobs[b].centroid_px.transpose() << " area "
                        << blobs[b].area_px << " is no reference ball";
        }
      }
    }
  }
  const double rms = std::sqrt(stats.squared_sum / stats.found);
  std::cout << stats.found << " of " << stats.visible << " reference balls found, centroid rms "
            << rms << " px, worst " << stats.worst_px << " px, mean offset "
            << (stats.offset_sum / stats.found).transpose() << " px, " << stats.false_blobs
            << " false blobs\n";
  EXPECT_LT(rms, 0.18);
  EXPECT_LT(stats.worst_px, 0.4);
}

TEST(ColorBlobs, OptionsAreValidated) {
  ColorBlobOptions options;
  options.hue_tolerance_deg = 0.0;
  EXPECT_THROW(options.validate(), InputError);
  options = {};
  options.max_area_px = 0;
  EXPECT_THROW(options.validate(), InputError);
}

}  // namespace
}  // namespace ballsight
