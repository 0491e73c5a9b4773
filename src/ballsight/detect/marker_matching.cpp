#include "ballsight/detect/marker_matching.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"

namespace ballsight {

namespace {

struct BearingRay {
  double bearing_deg = 0.0;
  std::vector<int> layout;      // layout indices, nearest first
  std::vector<int> detections;  // detection indices, smallest radius first
};

double angle_between_deg(double a, double b) {
  return std::abs(wrap_deg_180(a - b));
}

template <typename T>
const T& at(const std::vector<T>& v, int i) {
  return v[static_cast<size_t>(i)];
}

std::vector<BearingRay> rays_of_layout(const std::vector<Vec2>& layout) {
  std::vector<BearingRay> rays;
  for (int i = 0; i < static_cast<int>(layout.size()); ++i) {
    const double bearing = polar_from_cartesian(at(layout, i)).theta_deg;
    auto ray = std::find_if(rays.begin(), rays.end(), [&](const BearingRay& r) {
      return angle_between_deg(r.bearing_deg, bearing) < 0.5;
    });
    if (ray == rays.end()) ray = rays.insert(rays.end(), BearingRay{bearing, {}, {}});
    ray->layout.push_back(i);
  }
  for (BearingRay& ray : rays) {
    std::sort(ray.layout.begin(), ray.layout.end(),
              [&](int a, int b) { return at(layout, a).norm() < at(layout, b).norm(); });
  }
  return rays;
}

// The innermost ring of markers (one per ray, all at the same ground distance) images as a circle
// around the true image centre: a least-squares circle fit through the detections nearest the
// nominal centre corrects a centre offset of several pixels before grouping by angle. Falls back
// to the nominal centre when the fit is not trustworthy.
Vec2 refined_center(const std::vector<Vec2>& pixels, size_t ray_count, const Vec2& nominal) {
  if (ray_count < 8 || pixels.size() < ray_count) return nominal;
  std::vector<Vec2> sorted = pixels;
  std::nth_element(
      sorted.begin(), sorted.begin() + static_cast<long>(ray_count), sorted.end(),
      [&](const Vec2& a, const Vec2& b) { return (a - nominal).norm() < (b - nominal).norm(); });
  // Kasa fit: x^2 + y^2 + D x + E y + F = 0.
  Eigen::MatrixXd a(static_cast<long>(ray_count), 3);
  Eigen::VectorXd b(static_cast<long>(ray_count));
  for (size_t i = 0; i < ray_count; ++i) {
    a.row(static_cast<long>(i)) << sorted[i].x(), sorted[i].y(), 1.0;
    b(static_cast<long>(i)) = -sorted[i].squaredNorm();
  }
  const Eigen::Vector3d x = a.colPivHouseholderQr().solve(b);
  const Vec2 center(-x(0) / 2.0, -x(1) / 2.0);
  return (center.allFinite() && (center - nominal).norm() < 20.0) ? center : nominal;
}

// How far a detection may sit from the expected radius of marker k: below half the gap to the
// neighbouring markers' radii, so no detection can take its neighbour's place.
double radius_tolerance(const std::vector<double>& expected, size_t k,
                        const MarkerMatchOptions& options) {
  double tolerance = options.radius_tolerance_px;
  if (k > 0) tolerance = std::min(tolerance, 0.4 * (expected[k] - expected[k - 1]));
  if (k + 1 < expected.size())
    tolerance = std::min(tolerance, 0.4 * (expected[k + 1] - expected[k]));
  return tolerance;
}

// Rays with exactly one detection per marker whose radii agree with their neighbours' (the
// median of the nearest such rays): a missing marker plus a clutter blob also gives the right
// count, but its radii are shifted against the neighbours.
std::vector<const BearingRay*> consistent_complete_rays(const std::vector<BearingRay>& rays,
                                                        const std::vector<Polar>& polar,
                                                        const MarkerMatchOptions& options) {
  std::vector<const BearingRay*> candidates;
  for (const BearingRay& ray : rays)
    if (ray.detections.size() == ray.layout.size()) candidates.push_back(&ray);
  std::vector<const BearingRay*> complete;
  for (const BearingRay* ray : candidates) {
    std::vector<const BearingRay*> neighbours;
    for (const BearingRay* other : candidates)
      if (other != ray && other->layout.size() == ray->layout.size()) neighbours.push_back(other);
    std::sort(neighbours.begin(), neighbours.end(), [&](const BearingRay* a, const BearingRay* b) {
      return angle_between_deg(a->bearing_deg, ray->bearing_deg) <
             angle_between_deg(b->bearing_deg, ray->bearing_deg);
    });
    neighbours.resize(std::min<size_t>(neighbours.size(), 4));
    if (neighbours.size() < 2) {
      complete.push_back(ray);  // nothing to compare with
      continue;
    }
    std::vector<double> expected;
    for (size_t k = 0; k < ray->layout.size(); ++k) {
      std::vector<double> radii;
      for (const BearingRay* n : neighbours) radii.push_back(at(polar, n->detections[k]).radius);
      std::sort(radii.begin(), radii.end());
      expected.push_back(0.5 * (radii[(radii.size() - 1) / 2] + radii[radii.size() / 2]));
    }
    bool consistent = true;
    for (size_t k = 0; k < ray->layout.size(); ++k) {
      consistent &= std::abs(at(polar, ray->detections[k]).radius - expected[k]) <=
                    radius_tolerance(expected, k, options);
    }
    if (consistent) complete.push_back(ray);
  }
  return complete;
}

}  // namespace

std::vector<MarkerMatch> match_markers_to_layout(const std::vector<Vec2>& marker_pixels,
                                                 const std::vector<Vec2>& layout_in_robot,
                                                 const MarkerMatchOptions& options) {
  std::vector<BearingRay> rays = rays_of_layout(layout_in_robot);
  const Vec2 center = refined_center(marker_pixels, rays.size(), options.image_center);
  std::vector<Polar> polar;
  for (const Vec2& p : marker_pixels) polar.push_back(image_polar_from_pixel(p, center));

  // Each detection joins the ray nearest in bearing, if near enough.
  for (int d = 0; d < static_cast<int>(polar.size()); ++d) {
    const double bearing = robot_bearing_deg_from_image_theta_deg(at(polar, d).theta_deg);
    BearingRay* best = nullptr;
    for (BearingRay& ray : rays) {
      if (angle_between_deg(ray.bearing_deg, bearing) <= options.angle_tolerance_deg &&
          (!best || angle_between_deg(ray.bearing_deg, bearing) <
                        angle_between_deg(best->bearing_deg, bearing)))
        best = &ray;
    }
    if (best) best->detections.push_back(d);
  }

  for (BearingRay& ray : rays) {
    std::sort(ray.detections.begin(), ray.detections.end(),
              [&](int a, int b) { return at(polar, a).radius < at(polar, b).radius; });
  }
  const std::vector<const BearingRay*> complete = consistent_complete_rays(rays, polar, options);
  std::vector<MarkerMatch> matches;
  // Complete rays: assign in order of radius.
  for (const BearingRay* ray : complete) {
    for (size_t k = 0; k < ray->layout.size(); ++k)
      matches.push_back({ray->layout[k], at(marker_pixels, ray->detections[k])});
  }
  // Incomplete rays: each layout marker takes the unused detection nearest the radius the
  // nearest complete ray shows at the same position (a tilt bends the profile by direction, so a
  // neighbour predicts better than a global profile), within a tolerance below half the gap to
  // the neighbouring markers.
  for (const BearingRay& ray : rays) {
    if (std::find(complete.begin(), complete.end(), &ray) != complete.end()) continue;
    const BearingRay* reference = nullptr;
    for (const BearingRay* c : complete) {
      if (c->layout.size() != ray.layout.size()) continue;
      if (!reference || angle_between_deg(c->bearing_deg, ray.bearing_deg) <
                            angle_between_deg(reference->bearing_deg, ray.bearing_deg))
        reference = c;
    }
    if (!reference) continue;
    std::vector<double> expected;
    for (int d : reference->detections) expected.push_back(at(polar, d).radius);
    std::vector<bool> used(ray.detections.size(), false);
    for (size_t k = 0; k < ray.layout.size(); ++k) {
      double tolerance = radius_tolerance(expected, k, options);
      int best = -1;
      for (size_t j = 0; j < ray.detections.size(); ++j) {
        const double error = std::abs(at(polar, ray.detections[j]).radius - expected[k]);
        if (!used[j] && error <= tolerance) best = static_cast<int>(j), tolerance = error;
      }
      if (best < 0) continue;
      used[static_cast<size_t>(best)] = true;
      matches.push_back({ray.layout[k], at(marker_pixels, at(ray.detections, best))});
    }
  }
  std::sort(matches.begin(), matches.end(), [](const MarkerMatch& a, const MarkerMatch& b) {
    return a.layout_index < b.layout_index;
  });
  return matches;
}

}  // namespace ballsight
