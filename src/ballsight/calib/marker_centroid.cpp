#include "ballsight/calib/marker_centroid.hpp"

#include <cmath>
#include <numbers>

namespace ballsight {

std::optional<Vec2> disc_centroid_offset_px(const CatadioptricFloorParams& params,
                                            const Vec2& center_cm, double radius_cm) {
  CatadioptricFloorParams ideal = params;
  ideal.distortion = Vec3::Zero();
  const auto p = ideal.to_array();
  const auto project = [&](const Vec2& floor_cm) -> std::optional<Vec2> {
    const double floor[2] = {floor_cm.x(), floor_cm.y()};
    double pixel[2];
    if (!pixel_from_floor_point(p.data(), floor, pixel)) return std::nullopt;
    return Vec2(pixel[0], pixel[1]);
  };
  const std::optional<Vec2> center_px = project(center_cm);
  if (!center_px) return std::nullopt;
  // The outline as a fine polygon; its area centroid by the shoelace formula, relative to the
  // centre's pixel for precision.
  constexpr int kVertices = 96;
  std::vector<Vec2> outline;
  for (int i = 0; i < kVertices; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kVertices;
    const std::optional<Vec2> q = project(center_cm + radius_cm * Vec2(std::cos(a), std::sin(a)));
    if (!q) return std::nullopt;
    outline.push_back(*q - *center_px);
  }
  double twice_area = 0.0;
  Vec2 weighted = Vec2::Zero();
  for (int i = 0; i < kVertices; ++i) {
    const Vec2& a = outline[static_cast<std::size_t>(i)];
    const Vec2& b = outline[static_cast<std::size_t>((i + 1) % kVertices)];
    const double cross = a.x() * b.y() - b.x() * a.y();
    twice_area += cross;
    weighted += cross * (a + b);
  }
  if (std::abs(twice_area) < 1e-12) return std::nullopt;
  return weighted / (3.0 * twice_area);
}

std::vector<MarkerObservation> disc_centres(std::span<const FoundDisc> discs,
                                            const CatadioptricFloorParams& params) {
  std::vector<MarkerObservation> markers;
  markers.reserve(discs.size());
  for (const FoundDisc& disc : discs) {
    const std::optional<Vec2> offset =
        disc_centroid_offset_px(params, 100.0 * disc.p_in_robot, 100.0 * disc.radius_m);
    markers.push_back({disc.centroid_px - offset.value_or(Vec2::Zero()), disc.p_in_robot});
  }
  return markers;
}

std::vector<PolarSample> debiased_disc_samples(std::span<const FoundDisc> discs,
                                               const OmniImage& image, int iterations) {
  std::vector<MarkerObservation> markers;
  for (const FoundDisc& disc : discs) markers.push_back({disc.centroid_px, disc.p_in_robot});
  std::vector<PolarSample> samples = samples_from_markers(markers, image.center_px);
  for (int i = 0; i < iterations; ++i) {
    const BallsightGroundModel model = fit_ballsight_model(samples, image);
    samples = samples_from_markers(disc_centres(discs, model.params()), image.center_px);
  }
  return samples;
}

}  // namespace ballsight
