#include "ballsight/calib/reference_pose.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>

#include "ballsight/core/error.hpp"
#include "ballsight/core/text_format.hpp"

namespace ballsight {

void ReferencePoseOptions::validate() const {
  require(hypothesis_candidates >= 3, "hypothesis_candidates", "must be at least 3");
  require(std::isfinite(match_px) && match_px > 0.0, "match_px", "must be positive");
  require(std::isfinite(ransac_px) && ransac_px > 0.0, "ransac_px", "must be positive");
  require(std::isfinite(hint_tolerance_m) && hint_tolerance_m > 0.0, "hint_tolerance_m",
          "must be positive");
  require(std::isfinite(ambiguity_m) && ambiguity_m > 0.0, "ambiguity_m", "must be positive");
  require(min_references >= 4, "min_references", "must be at least 4");
}

void ReferenceCorrections::validate(std::size_t references) const {
  std::vector<bool> named(references, false);
  const auto name = [&](std::size_t r, const char* where) {
    require(r < references, where,
            "reference " + std::to_string(r) + " of " + std::to_string(references));
    require(!named[r], where, "reference " + std::to_string(r) + " is named twice");
    named[r] = true;
  };
  for (const auto& [r, pixel] : placed) {
    name(r, "placed");
    require(pixel.allFinite(), "placed", "pixel of reference " + std::to_string(r));
  }
  for (std::size_t r : absent) name(r, "absent");
}

namespace {

struct Hypothesis {
  Rigid3 camera_from_field;
  Vec3 center = Vec3::Zero();
  std::vector<ReferenceMatch> matches;
  double squared_error = 0.0;
  double hint_distance_m = 0.0;
};

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

// The candidates with the placed references appended (candidate index `blobs + k` is the k-th
// placed pixel), and per reference its placed candidate, or kNone, or kAbsent.
struct CandidateSet {
  static constexpr std::size_t kAbsent = kNone - 1;

  CandidateSet(const std::vector<Vec2>& blobs, std::size_t references,
               const ReferenceCorrections& corrections)
      : pixels(blobs), blob_count(blobs.size()), fixed(references, kNone) {
    for (const auto& [r, pixel] : corrections.placed) {
      fixed[r] = pixels.size();
      pixels.push_back(pixel);
    }
    for (std::size_t r : corrections.absent) fixed[r] = kAbsent;
  }

  bool placed(std::size_t reference) const { return fixed[reference] < pixels.size(); }
  bool free(std::size_t reference) const { return fixed[reference] == kNone; }
  /// The reference a candidate was placed for, or kNone for a blob.
  std::size_t placed_reference(std::size_t candidate) const {
    if (candidate < blob_count) return kNone;
    return static_cast<std::size_t>(std::find(fixed.begin(), fixed.end(), candidate) -
                                    fixed.begin());
  }

  std::vector<Vec2> pixels;
  std::size_t blob_count;
  std::vector<std::size_t> fixed;
};

// Matches references to candidates under a pose: a placed reference to its pixel, any other (not
// absent) to its nearest blob within the gate, each blob to one reference at most (closest pairs
// first).
class Matcher {
 public:
  Matcher(const PinholeCamera& camera, const std::vector<ReferencePoint>& references,
          const CandidateSet& candidates, double gate_px)
      : camera_(camera), references_(references), candidates_(candidates), gate_px_(gate_px) {}

  std::vector<ReferenceMatch> match(const Rigid3& camera_from_field) const {
    const std::vector<Vec2>& pixels = candidates_.pixels;
    std::vector<ReferenceMatch> proposals, matches;
    for (std::size_t r = 0; r < references_.size(); ++r) {
      const std::optional<Vec2> pixel = project(camera_from_field, r);
      if (!pixel) continue;
      if (candidates_.placed(r)) {
        const std::size_t c = candidates_.fixed[r];
        matches.push_back({r, c, (pixels[c] - *pixel).norm()});
        continue;
      }
      if (!candidates_.free(r)) continue;
      ReferenceMatch best{r, kNone, gate_px_};
      for (std::size_t c = 0; c < candidates_.blob_count; ++c) {
        const double d = (pixels[c] - *pixel).norm();
        if (d <= best.residual_px) best = {r, c, d};
      }
      if (best.candidate != kNone) proposals.push_back(best);
    }
    std::sort(proposals.begin(), proposals.end(),
              [](const ReferenceMatch& a, const ReferenceMatch& b) {
                return a.residual_px < b.residual_px;
              });
    std::vector<bool> taken(pixels.size(), false);
    for (const ReferenceMatch& m : proposals) {
      if (taken[m.candidate]) continue;
      taken[m.candidate] = true;
      matches.push_back(m);
    }
    std::sort(matches.begin(), matches.end(), [](const ReferenceMatch& a, const ReferenceMatch& b) {
      return a.reference < b.reference;
    });
    return matches;
  }

  std::optional<Vec2> project(const Rigid3& camera_from_field, std::size_t reference) const {
    return camera_.project(camera_from_field * references_[reference].p_in_field);
  }

 private:
  const PinholeCamera& camera_;
  const std::vector<ReferencePoint>& references_;
  const CandidateSet& candidates_;
  double gate_px_;
};

double cross2(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double squared_error(const std::vector<ReferenceMatch>& matches) {
  double sum = 0.0;
  for (const ReferenceMatch& m : matches) sum += m.residual_px * m.residual_px;
  return sum;
}

// Better: more matches; among poses with four or more, the smaller error; among exact
// three-point fits (error zero), the one nearer the hint.
bool better(const Hypothesis& a, const Hypothesis& b) {
  if (a.matches.size() != b.matches.size()) return a.matches.size() > b.matches.size();
  if (a.matches.size() >= 4 && a.squared_error != b.squared_error) {
    return a.squared_error < b.squared_error;
  }
  return a.hint_distance_m < b.hint_distance_m;
}

class HypothesisSearch {
 public:
  HypothesisSearch(const PinholeCamera& camera, const std::vector<ReferencePoint>& references,
                   const CandidateSet& candidates, const std::optional<Vec3>& hint,
                   const ReferencePoseOptions& options)
      : references_(references),
        candidates_(candidates),
        hint_(hint),
        options_(options),
        matcher_(camera, references, candidates, options.match_px) {
    // The placed pixels first (the user's word), then the blobs, most reliable first.
    std::vector<std::size_t> order;
    for (std::size_t c = candidates.blob_count; c < candidates.pixels.size(); ++c)
      order.push_back(c);
    for (std::size_t c = 0; c < candidates.blob_count; ++c) order.push_back(c);
    for (std::size_t c : order) {
      if (normalised_.size() >= static_cast<std::size_t>(options.hypothesis_candidates)) break;
      if (const std::optional<Vec3> ray = camera.unproject(candidates.pixels[c])) {
        normalised_.push_back(ray->head<2>() / ray->z());
        normalised_reference_.push_back(candidates.placed_reference(c));
      }
    }
    // References on one horizontal plane: a camera above it sees every triangle of them with
    // its orientation flipped (image y points down), which rules out half of the assignments.
    plane_z_ = references.front().p_in_field.z();
    for (const ReferencePoint& r : references) {
      if (std::abs(r.p_in_field.z() - plane_z_) > 1e-9) coplanar_ = false;
    }
  }

  // Every P3P pose of every candidate triple and ordered reference triple.
  std::vector<Hypothesis> run() const {
    std::vector<Hypothesis> kept;
    const std::size_t n = normalised_.size(), m = references_.size();
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        for (std::size_t k = j + 1; k < n; ++k) {
          const double image_turn =
              cross2(normalised_[j] - normalised_[i], normalised_[k] - normalised_[i]);
          for (std::size_t a = 0; a < m; ++a) {
            for (std::size_t b = 0; b < m; ++b) {
              for (std::size_t c = 0; c < m; ++c) {
                if (a == b || a == c || b == c) continue;
                if (!assignable(i, a) || !assignable(j, b) || !assignable(k, c)) continue;
                if (!plausible(a, b, c, image_turn)) continue;
                solve({normalised_[i], normalised_[j], normalised_[k]}, {a, b, c}, kept);
              }
            }
          }
        }
      }
    }
    return kept;
  }

 private:
  // Whether the `n`-th normalised candidate may be reference `r`: a placed pixel only its own,
  // a blob only a reference neither placed nor absent.
  bool assignable(std::size_t n, std::size_t r) const {
    const std::size_t placed_for = normalised_reference_[n];
    return placed_for == kNone ? candidates_.free(r) : placed_for == r;
  }

  bool plausible(std::size_t a, std::size_t b, std::size_t c, double image_turn) const {
    if (!coplanar_) return true;
    const Vec2 pa = references_[a].p_in_field.head<2>();
    const double field_turn =
        cross2(references_[b].p_in_field.head<2>() - pa, references_[c].p_in_field.head<2>() - pa);
    return field_turn * image_turn < 0.0;  // also rejects collinear references
  }

  void solve(const std::array<Vec2, 3>& image, const std::array<std::size_t, 3>& refs,
             std::vector<Hypothesis>& kept) const {
    std::vector<cv::Point3d> object;
    std::vector<cv::Point2d> points;
    for (std::size_t q = 0; q < 3; ++q) {
      const Vec3& p = references_[refs[q]].p_in_field;
      object.emplace_back(p.x(), p.y(), p.z());
      points.emplace_back(image[q].x(), image[q].y());
    }
    std::vector<cv::Mat> rvecs, tvecs;
    const int solutions = cv::solveP3P(object, points, cv::Mat::eye(3, 3, CV_64F), cv::Mat(), rvecs,
                                       tvecs, cv::SOLVEPNP_AP3P);
    for (int s = 0; s < solutions; ++s) {
      Hypothesis h;
      h.camera_from_field = Rigid3::from_rvec_tvec(
          Vec3(rvecs[s].at<double>(0), rvecs[s].at<double>(1), rvecs[s].at<double>(2)),
          Vec3(tvecs[s].at<double>(0), tvecs[s].at<double>(1), tvecs[s].at<double>(2)));
      h.center = h.camera_from_field.inverse().translation;
      if (coplanar_ && h.center.z() <= plane_z_) continue;
      if (hint_) {
        h.hint_distance_m = (h.center - *hint_).norm();
        if (h.hint_distance_m > options_.hint_tolerance_m) continue;
      }
      h.matches = matcher_.match(h.camera_from_field);
      if (h.matches.size() < 3) continue;
      h.squared_error = squared_error(h.matches);
      kept.push_back(std::move(h));
    }
  }

  const std::vector<ReferencePoint>& references_;
  const CandidateSet& candidates_;
  std::optional<Vec3> hint_;
  ReferencePoseOptions options_;
  Matcher matcher_;
  std::vector<Vec2> normalised_;                   // undistorted candidates, z = 1
  std::vector<std::size_t> normalised_reference_;  // the reference each was placed for, or kNone
  double plane_z_ = 0.0;
  bool coplanar_ = true;
};

std::string names(const std::vector<ReferencePoint>& references,
                  const std::vector<std::size_t>& indices) {
  std::string out;
  for (std::size_t i : indices) out += (out.empty() ? "" : ", ") + references[i].name;
  return out.empty() ? "none" : out;
}

std::vector<std::size_t> unmatched(std::size_t count, const std::vector<ReferenceMatch>& matches) {
  std::vector<bool> found(count, false);
  for (const ReferenceMatch& m : matches) found[m.reference] = true;
  std::vector<std::size_t> out;
  for (std::size_t r = 0; r < count; ++r) {
    if (!found[r]) out.push_back(r);
  }
  return out;
}

[[noreturn]] void too_few(const std::vector<ReferencePoint>& references,
                          const std::vector<ReferenceMatch>& matches,
                          const ReferencePoseOptions& options, bool hinted) {
  std::vector<std::size_t> found;
  for (const ReferenceMatch& m : matches) found.push_back(m.reference);
  throw InputError("reference balls: found " + std::to_string(found.size()) + " of " +
                   std::to_string(references.size()) + " (" + names(references, found) +
                   "), at least " + std::to_string(options.min_references) +
                   " needed; missing: " + names(references, unmatched(references.size(), matches)) +
                   (hinted ? " (poses farther than " + fixed(options.hint_tolerance_m, 1) +
                                 " m from the camera's position hint were not considered)"
                           : ""));
}

cv::Mat cv_vec(const Vec3& v) {
  return (cv::Mat_<double>(3, 1) << v.x(), v.y(), v.z());
}

Rigid3 rigid_from_cv(const cv::Mat& rvec, const cv::Mat& tvec) {
  return Rigid3::from_rvec_tvec(Vec3(rvec.at<double>(0), rvec.at<double>(1), rvec.at<double>(2)),
                                Vec3(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2)));
}

}  // namespace

ReferencePose estimate_reference_pose(const PinholeCamera& camera,
                                      const std::vector<ReferencePoint>& references,
                                      const std::vector<Vec2>& candidates_px,
                                      const std::optional<Vec3>& position_hint_in_field,
                                      const ReferencePoseOptions& options,
                                      const ReferenceCorrections& corrections) {
  options.validate();
  corrections.validate(references.size());
  require(references.size() >= static_cast<std::size_t>(options.min_references), "reference balls",
          "need at least " + std::to_string(options.min_references) + ", got " +
              std::to_string(references.size()));
  const CandidateSet candidates(candidates_px, references.size(), corrections);
  const HypothesisSearch search(camera, references, candidates, position_hint_in_field, options);
  const std::vector<Hypothesis> hypotheses = search.run();
  if (hypotheses.empty()) too_few(references, {}, options, position_hint_in_field.has_value());
  const Hypothesis& best = *std::min_element(hypotheses.begin(), hypotheses.end(), better);
  if (best.matches.size() < static_cast<std::size_t>(options.min_references)) {
    too_few(references, best.matches, options, position_hint_in_field.has_value());
  }
  for (const Hypothesis& h : hypotheses) {
    // As many matches, about as good a fit, somewhere else: the layout alone cannot decide.
    if (h.matches.size() == best.matches.size() &&
        h.squared_error <= 4.0 * best.squared_error + 1e-9 &&
        (h.center - best.center).norm() > options.ambiguity_m) {
      throw InputError("reference balls: " + std::to_string(best.matches.size()) +
                       " match equally well with the camera near (" + fixed(best.center.x(), 1) +
                       ", " + fixed(best.center.y(), 1) + ") and near (" + fixed(h.center.x(), 1) +
                       ", " + fixed(h.center.y(), 1) +
                       ") m: give the camera's rough position (position_hint_m)");
    }
  }

  // Refine: RANSAC over the matches (more than four), Levenberg-Marquardt on the inliers, then
  // match again under the better pose until the matches settle.
  const Matcher matcher(camera, references, candidates, options.match_px);
  const std::vector<Vec2>& pixels = candidates.pixels;
  const cv::Mat k(camera.camera_matrix());
  const cv::Mat distortion = camera.distortion_coefficients();
  Rigid3 pose = best.camera_from_field;
  std::vector<ReferenceMatch> matches = best.matches;
  for (int round = 0; round < 5; ++round) {
    std::vector<cv::Point3d> object;
    std::vector<cv::Point2d> image;
    for (const ReferenceMatch& m : matches) {
      const Vec3& p = references[m.reference].p_in_field;
      object.emplace_back(p.x(), p.y(), p.z());
      image.emplace_back(pixels[m.candidate].x(), pixels[m.candidate].y());
    }
    cv::Mat rvec = cv_vec(pose.rvec()), tvec = cv_vec(pose.translation);
    if (matches.size() > 4) {
      std::vector<int> inliers;
      if (!cv::solvePnPRansac(object, image, k, distortion, rvec, tvec, true, 200,
                              static_cast<float>(options.ransac_px), 0.999, inliers,
                              cv::SOLVEPNP_ITERATIVE))
        inliers.clear();  // no consensus: only the balls placed by hand count
      for (std::size_t i = 0; i < matches.size(); ++i) {  // placed by hand: kept
        if (candidates.placed(matches[i].reference) &&
            std::find(inliers.begin(), inliers.end(), static_cast<int>(i)) == inliers.end()) {
          inliers.push_back(static_cast<int>(i));
        }
      }
      if (inliers.size() < static_cast<std::size_t>(options.min_references)) {
        too_few(references, {}, options, position_hint_in_field.has_value());
      }
      std::vector<cv::Point3d> object_in;
      std::vector<cv::Point2d> image_in;
      for (int i : inliers) {
        object_in.push_back(object[static_cast<std::size_t>(i)]);
        image_in.push_back(image[static_cast<std::size_t>(i)]);
      }
      object.swap(object_in);
      image.swap(image_in);
    } else if (!cv::solvePnP(object, image, k, distortion, rvec, tvec, true,
                             cv::SOLVEPNP_ITERATIVE)) {
      throw InputError("reference balls: no camera pose fits the " +
                       std::to_string(matches.size()) + " matched (solvePnP found none)");
    }
    cv::solvePnPRefineLM(object, image, k, distortion, rvec, tvec);
    pose = rigid_from_cv(rvec, tvec);
    std::vector<ReferenceMatch> again = matcher.match(pose);
    const bool settled =
        again.size() == matches.size() &&
        std::equal(again.begin(), again.end(), matches.begin(),
                   [](const ReferenceMatch& a, const ReferenceMatch& b) {
                     return a.reference == b.reference && a.candidate == b.candidate;
                   });
    matches = std::move(again);
    if (settled) break;
  }
  if (matches.size() < static_cast<std::size_t>(options.min_references)) {
    too_few(references, matches, options, position_hint_in_field.has_value());
  }

  ReferencePose result;
  result.camera_from_field = pose;
  result.matches = matches;
  for (const ReferenceMatch& m : matches) result.matched_px.push_back(pixels[m.candidate]);
  for (const ReferenceMatch& m : matches) result.max_px = std::max(result.max_px, m.residual_px);
  result.rms_px = std::sqrt(squared_error(matches) / static_cast<double>(matches.size()));
  result.unmatched = unmatched(references.size(), matches);
  return result;
}

}  // namespace ballsight
