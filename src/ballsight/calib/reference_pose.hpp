#pragma once
// A fixed camera's pose from reference points at known field coordinates (the reference balls of
// the tennis-ball-collecting-robot report, sections 7.3-7.4: the user writes only their
// coordinates; the vision system finds them in the image). Which blob is which reference is not
// known: every triple of the most reliable candidate blobs is tried against every ordered triple
// of references with P3P (cv::solveP3P), each pose is scored by how many references it projects
// onto a candidate, and the best is refined by solvePnPRansac (more than four matches) or
// solvePnP, then Levenberg-Marquardt, re-matching until the matches settle.
//
// A symmetric layout (the twelve line intersections of a tennis court look the same from
// opposite corners) fits equally well from several places: a rough position hint for the camera
// ("pole at the north-east corner, about 5 m high") tells them apart.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ballsight/camera/pinhole.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct ReferencePoint {
  std::string name;
  Vec3 p_in_field = Vec3::Zero();
};

struct ReferencePoseOptions {
  int hypothesis_candidates = 8;  // the first candidates (most reliable) tried in P3P triples
  double match_px = 4.0;          // a projected reference matches a candidate this close
  double ransac_px = 2.0;         // inlier threshold of solvePnPRansac
  double hint_tolerance_m = 5.0;  // the camera stands at most this far from its position hint
  double ambiguity_m = 1.0;       // equally good poses this far apart are ambiguous
  int min_references = 4;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct ReferenceMatch {
  std::size_t reference = 0;  // index into the references
  std::size_t candidate = 0;  // index into the candidates
  double residual_px = 0.0;   // under the final pose
};

/// What a user said about single references (the court calibration page): a reference placed by
/// hand is at that pixel whatever the candidates say; an absent one is matched to nothing (it is
/// hidden, or a blob of another thing was taken for it).
struct ReferenceCorrections {
  std::vector<std::pair<std::size_t, Vec2>> placed;  // reference index, pixel
  std::vector<std::size_t> absent;                   // reference indices

  /// Throws InputError when an index is not below `references` or a reference is named twice.
  void validate(std::size_t references) const;
  bool empty() const { return placed.empty() && absent.empty(); }
};

struct ReferencePose {
  Rigid3 camera_from_field;
  std::vector<ReferenceMatch> matches;  // sorted by reference
  /// The pixel each match was seen at (the candidate's, or where the reference was placed),
  /// parallel to `matches`.
  std::vector<Vec2> matched_px;
  double rms_px = 0.0;
  double max_px = 0.0;
  std::vector<std::size_t> unmatched;  // references not matched, in order
};

/// The camera's pose from `candidates_px` (blob centroids, most reliable first, may include
/// blobs that are no reference) and the references. Throws InputError naming the references
/// found and missing when fewer than options.min_references match one pose, or when two poses
/// far apart fit equally well and no hint decides. Placed references count as matched candidates
/// of their own (always kept, whatever RANSAC says of them).
ReferencePose estimate_reference_pose(const PinholeCamera& camera,
                                      const std::vector<ReferencePoint>& references,
                                      const std::vector<Vec2>& candidates_px,
                                      const std::optional<Vec3>& position_hint_in_field,
                                      const ReferencePoseOptions& options = {},
                                      const ReferenceCorrections& corrections = {});

}  // namespace ballsight
