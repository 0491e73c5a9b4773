#pragma once
// Clusters of touching balls fitted to the pixels of their blobs in every camera at once. Where
// the balls are a pixel or two across, each camera sees a cluster of three or four as one blob,
// and neither its size (a single ball's spreads by ~15%) nor its centroid tells three from four;
// the blobs' outlines in several views do. A hypothesis of k balls on the plane of the balls'
// centres is drawn into each camera's coverage patch (discs of the ball's apparent radius, placed
// by the plane's local affine map at the blob, their union's pixel coverage saturating as the
// detector's does) and its positions are fitted to the observed coverage by Levenberg-Marquardt
// (Ceres); a ball is added or removed where that changes the squared coverage residual by more than
// a per-ball penalty measured on isolated single balls (docs/court-vision.md).

#include <functional>
#include <optional>
#include <vector>

#include "ballsight/camera/field_camera.hpp"
#include "ballsight/core/pixel_detection.hpp"
#include "ballsight/world/field_observation.hpp"
#include "ballsight/world/observation_fusion.hpp"

namespace ballsight {

struct PixelFitOptions {
  bool enabled = true;
  double link_distance_radii = 4.0;  // balls this close (in ball radii), or cut from one blob,
                                     // form a group
  // The coverage model, measured on isolated single balls: a ball covers a disc of its outline's
  // radius times radius_scale plus blur_px, a pixel's share of it ramping over one pixel; the
  // detector's coverage is that share times coverage_gain, at most 1.
  double radius_scale = 0.9;
  double blur_px = 0.15;
  double coverage_gain = 1.4;
  /// A further ball must lower the squared coverage residual (summed over the group's pixels) by
  /// this much, and a ball whose removal raises it less goes.
  double ball_penalty = 1.0;
  double min_separation_radii = 1.75;  // balls closer than this cannot both be real
  double overlap_sigma_m = 0.003;      // stiffness of the no-overlap constraint
  int max_added = 2;                   // balls added to one group at most
  int iterations = 8;                  // Levenberg-Marquardt steps per hypothesis

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// Whether camera `camera`'s pixel shows something in front of the balls' plane (the robot's
/// body) that would hide a ball there: such pixels say nothing about the balls.
using HiddenPixel = std::function<bool(int camera, const Vec2& pixel)>;

/// `balls` (fused from `observations`) after refitting each group whose blobs may hold more or
/// fewer balls than it has (several balls, or a blob split in parts) to the coverage patches of
/// its observations' detections; `detections[c]` are camera c's (nullopt: no frame), indexed by
/// FieldObservation::camera and ::detection. Patch pixels `hidden` (if given) are left out of the
/// fit. Other groups are returned unchanged. The groups are fitted side by side
/// (fit_groups_in_parallel): `hidden` is called from several threads at once.
std::vector<FusedObject> fit_clusters_to_pixels(
    const std::vector<FieldObservation>& observations, const std::vector<FusedObject>& balls,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections, double ball_radius_m,
    const PixelFitOptions& options, const HiddenPixel& hidden = {});

}  // namespace ballsight
