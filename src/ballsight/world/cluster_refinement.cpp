#include "ballsight/world/cluster_refinement.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>

#include "ballsight/core/error.hpp"

namespace ballsight {

void ClusterOptions::validate() const {
  require(link_distance_radii > 0.0, "cluster link_distance_radii", "must be positive");
  require(merged_sigma_radii >= 0.0, "cluster merged_sigma_radii", "must be non-negative");
  require(min_chi2_gain > 0.0 && min_chi2_keep > 0.0, "cluster",
          "min_chi2_gain and min_chi2_keep must be positive");
  require(min_separation_radii >= 0.0, "cluster min_separation_radii", "must be non-negative");
  require(max_added >= 0 && max_added <= 8, "cluster max_added", "must be within [0, 8]");
  require(iterations >= 1, "cluster iterations", "must be at least 1");
  require(assign_gate_chi2 > 0.0, "cluster assign_gate_chi2", "must be positive");
}

namespace {

constexpr double kOverlapSigmaM = 0.003;  // stiffness of the no-overlap constraint

// Area of the union of discs of one radius in units of one disc's area: their count when no two
// overlap, else by counting the points of a grid of a fifth of the radius inside (within 3%), row
// by row through the discs' chords.
double union_of_discs(const std::vector<Vec2>& centers, double radius) {
  bool apart = true;
  for (size_t i = 0; i < centers.size() && apart; ++i)
    for (size_t j = i + 1; j < centers.size() && apart; ++j)
      apart = (centers[i] - centers[j]).squaredNorm() >= 4.0 * radius * radius;
  if (apart) return static_cast<double>(centers.size());
  Vec2 lo = centers.front(), hi = centers.front();
  for (const Vec2& c : centers) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
  lo -= Vec2::Constant(radius);
  hi += Vec2::Constant(radius);
  const double step = radius / 5.0;
  const double x0 = lo.x() + 0.5 * step;
  const double columns = std::ceil((hi.x() - x0) / step);
  std::vector<std::pair<double, double>> chords;  // grid columns from, to (inclusive)
  int inside = 0;
  for (double y = lo.y() + 0.5 * step; y < hi.y(); y += step) {
    chords.clear();
    for (const Vec2& c : centers) {
      const double h2 = radius * radius - (y - c.y()) * (y - c.y());
      if (h2 < 0.0) continue;
      const double h = std::sqrt(h2);
      const double from = std::max(0.0, std::ceil((c.x() - h - x0) / step));
      const double to = std::min(columns - 1.0, std::floor((c.x() + h - x0) / step));
      if (from <= to) chords.emplace_back(from, to);
    }
    std::sort(chords.begin(), chords.end());
    double counted_to = -1.0;
    for (const auto& [from, to] : chords) {
      if (to > counted_to) inside += static_cast<int>(to - std::max(from, counted_to + 1.0) + 1.0);
      counted_to = std::max(counted_to, to);
    }
  }
  return inside * step * step / (std::numbers::pi * radius * radius);
}

// One hypothesis: ball positions and, per observation, the balls it covers.
struct Fit {
  std::vector<Vec2> balls;
  std::vector<std::vector<int>> covered;  // per observation of the group
  Eigen::MatrixXd information;            // 2N x 2N, of the last solve
  double chi2 = std::numeric_limits<double>::max();
};

class GroupFitter {
 public:
  GroupFitter(const std::vector<FieldObservation>& all, std::vector<int> members,
              double ball_radius_m, const ClusterOptions& options)
      : all_(all), members_(std::move(members)), radius_(ball_radius_m), options_(options) {
    for (int o : members_) {
      const FieldObservation& obs = all_[static_cast<size_t>(o)];
      information_.push_back(obs.covariance_m2.inverse());
      pixel_per_plane_.push_back(obs.plane_per_pixel.inverse());
      const Eigen::JacobiSVD<Eigen::Matrix2d> svd(obs.plane_per_pixel);
      ball_radius_px_.push_back(radius_ / svd.singularValues()(1));
      if (std::find(cameras_.begin(), cameras_.end(), all_[static_cast<size_t>(o)].camera) ==
          cameras_.end())
        cameras_.push_back(all_[static_cast<size_t>(o)].camera);
    }
  }

  Fit fit(const std::vector<Vec2>& start) const {
    Fit f;
    f.balls = start;
    for (int it = 0; it < options_.iterations; ++it) {
      f.covered = assign(f.balls);
      solve(start, f);
    }
    f.covered = assign(f.balls);
    f.chi2 = chi2(f);
    return f;
  }

  // Cameras whose observations cover ball i.
  int camera_count(const Fit& f, int ball) const {
    std::vector<int> seen;
    for (size_t o = 0; o < members_.size(); ++o) {
      const auto& cov = f.covered[o];
      if (std::find(cov.begin(), cov.end(), ball) == cov.end()) continue;
      const int camera = observation(o).camera;
      if (std::find(seen.begin(), seen.end(), camera) == seen.end()) seen.push_back(camera);
    }
    return static_cast<int>(seen.size());
  }

 private:
  const FieldObservation& observation(size_t o) const {
    return all_[static_cast<size_t>(members_[o])];
  }

  // For an observation no ball took: a part of a split blob may be half of a ball split in two,
  // up to about half a radius off its centre.
  double unexplained_d2(size_t o, const Vec2& x) const {
    if (observation(o).split_count < 2) return d2(o, x);
    const double half = 0.5 * radius_;
    const Vec2 r = observation(o).position_m - x;
    return r.dot(
        (observation(o).covariance_m2 + half * half * Eigen::Matrix2d::Identity()).inverse() * r);
  }

  double d2(size_t o, const Vec2& x) const {
    const Vec2 r = observation(o).position_m - x;
    return r.dot(information_[o] * r);
  }

  // Image distance (pixels) in observation o's camera between two plane points.
  double image_distance(size_t o, const Vec2& a, const Vec2& b) const {
    return (pixel_per_plane_[o] * (a - b)).norm();
  }
  // A ball's image radius near observation o: the radius over the plane's metres per pixel
  // across the line of sight (the smaller singular value; along it the plane is stretched).
  double ball_radius_px(size_t o) const { return ball_radius_px_[o]; }
  // Two balls farther apart in the image than two ball images and a pixel cannot make one blob.
  bool apart_in_image(size_t o, const Vec2& a, const Vec2& b) const {
    return image_distance(o, a, b) > 2.0 * ball_radius_px(o) + 1.0;
  }
  // Ball x may be (part of) what observation o saw: within its error gate, or inside its blob.
  bool may_cover(size_t o, const Vec2& x) const {
    return d2(o, x) <= options_.assign_gate_chi2 ||
           image_distance(o, observation(o).position_m, x) <=
               std::max(observation(o).radius_px, ball_radius_px(o)) + 0.5;
  }

  // In every camera each ball goes to the nearest observation (in the image) that may cover it
  // (none: that camera did not see it); an observation covers several balls only if they could
  // make one blob there, else it keeps the nearest of them.
  std::vector<std::vector<int>> assign(const std::vector<Vec2>& balls) const {
    std::vector<std::vector<int>> covered(members_.size());
    for (size_t i = 0; i < balls.size(); ++i) {
      for (int camera : cameras_) {
        size_t best = members_.size();
        double best_px = 0.0;
        for (size_t o = 0; o < members_.size(); ++o) {
          if (observation(o).camera != camera || !may_cover(o, balls[i])) continue;
          const double px = image_distance(o, observation(o).position_m, balls[i]);
          if (best == members_.size() || px < best_px) best = o, best_px = px;
        }
        if (best < members_.size()) covered[best].push_back(static_cast<int>(i));
      }
    }
    for (size_t o = 0; o < members_.size(); ++o) {
      auto& cov = covered[o];
      if (cov.size() < 2) continue;
      std::sort(cov.begin(), cov.end(), [&](int a, int b) {
        return d2(o, balls[static_cast<size_t>(a)]) < d2(o, balls[static_cast<size_t>(b)]);
      });
      const Vec2 nearest = balls[static_cast<size_t>(cov.front())];
      std::erase_if(cov, [&](int i) {
        return i != cov.front() && apart_in_image(o, nearest, balls[static_cast<size_t>(i)]);
      });
    }
    return covered;
  }

  Eigen::Matrix2d weight(size_t o, size_t covering) const {
    const double extra = options_.merged_sigma_radii * radius_;
    const Eigen::Matrix2d cov = observation(o).covariance_m2 + static_cast<double>(covering - 1) *
                                                                   extra * extra *
                                                                   Eigen::Matrix2d::Identity();
    return cov.inverse();
  }

  // Weighted least squares: observation o measures the mean of the balls it covers. A weak prior
  // (10 cm) on the starting positions keeps balls that are never seen apart where they started.
  void solve(const std::vector<Vec2>& start, Fit& f) const {
    const auto n = static_cast<Eigen::Index>(f.balls.size());
    Eigen::MatrixXd h = Eigen::MatrixXd::Identity(2 * n, 2 * n) / (0.1 * 0.1);
    Eigen::VectorXd b(2 * n);
    for (Eigen::Index i = 0; i < n; ++i)
      b.segment<2>(2 * i) = start[static_cast<size_t>(i)] / (0.1 * 0.1);
    for (size_t o = 0; o < members_.size(); ++o) {
      const auto& cov = f.covered[o];
      if (cov.empty()) continue;
      const double k = static_cast<double>(cov.size());
      const Eigen::Matrix2d w = weight(o, cov.size());
      for (int i : cov) {
        b.segment<2>(2 * i) += w * observation(o).position_m / k;
        for (int j : cov) h.block<2, 2>(2 * i, 2 * j) += w / (k * k);
      }
    }
    // Balls cannot overlap: a pair closer than two radii is pushed apart to touching (a stiff
    // linearised constraint on their distance, active only where violated).
    const double touching = 2.0 * radius_;
    for (Eigen::Index i = 0; i < n; ++i) {
      for (Eigen::Index j = i + 1; j < n; ++j) {
        const Vec2 d = f.balls[static_cast<size_t>(i)] - f.balls[static_cast<size_t>(j)];
        if (d.norm() >= touching) continue;
        const Vec2 u = d.norm() > 1e-9 ? Vec2(d.normalized()) : Vec2::UnitX();
        const Eigen::Matrix2d w = u * u.transpose() / (kOverlapSigmaM * kOverlapSigmaM);
        h.block<2, 2>(2 * i, 2 * i) += w;
        h.block<2, 2>(2 * j, 2 * j) += w;
        h.block<2, 2>(2 * i, 2 * j) -= w;
        h.block<2, 2>(2 * j, 2 * i) -= w;
        b.segment<2>(2 * i) += w * u * touching;
        b.segment<2>(2 * j) -= w * u * touching;
      }
    }
    // h is the prior's diagonal plus positive semi-definite terms: positive definite, solvable
    // unless an observation was not finite.
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(h);
    const Eigen::VectorXd x = ldlt.solve(b);
    require(ldlt.info() == Eigen::Success && x.allFinite(), "cluster refinement",
            "the balls' normal equations have no finite solution");
    for (Eigen::Index i = 0; i < n; ++i) f.balls[static_cast<size_t>(i)] = x.segment<2>(2 * i);
    f.information = std::move(h);
  }

  double chi2(const Fit& f) const {
    double sum = size_chi2(f.balls);
    for (size_t o = 0; o < members_.size(); ++o) {
      const auto& cov = f.covered[o];
      if (cov.empty()) {  // unexplained: as far as its nearest ball, at most the gate
        double best = options_.assign_gate_chi2;
        for (const Vec2& x : f.balls) best = std::min(best, unexplained_d2(o, x));
        sum += best;
        continue;
      }
      Vec2 mean = Vec2::Zero();
      for (int i : cov) mean += f.balls[static_cast<size_t>(i)];
      const Vec2 r = observation(o).position_m - mean / static_cast<double>(cov.size());
      sum += r.dot(weight(o, cov.size()) * r);
    }
    return sum;
  }

  // How many balls the balls' images amount to in each camera (the area of the union of their
  // discs, in discs: nearer balls hide farther ones) against what each camera measured (the
  // observations' shares of their blobs), as a chi-square. The images are placed by the plane's
  // local affine map at one of the camera's observations.
  double size_chi2(const std::vector<Vec2>& balls) const {
    double sum = 0.0;
    for (int camera : cameras_) {
      double measured = 0.0;
      size_t reference = members_.size();
      for (size_t o = 0; o < members_.size(); ++o) {
        if (observation(o).camera != camera) continue;
        measured += observation(o).objects;
        if (reference == members_.size()) reference = o;
      }
      const Eigen::Matrix2d& pixel_per_plane = pixel_per_plane_[reference];
      const double disc = ball_radius_px(reference) + options_.blur_px;
      std::vector<Vec2> centers;
      for (const Vec2& x : balls) {
        const Vec2 q = pixel_per_plane * (x - observation(reference).position_m);
        if (q.norm() < 6.0 * disc + 6.0) centers.push_back(q);  // this blob's balls only
      }
      const double predicted = union_of_discs(centers, disc);
      const double sigma = options_.size_sigma_floor + options_.size_sigma_share * predicted;
      sum += (measured - predicted) * (measured - predicted) / (sigma * sigma);
    }
    return sum;
  }

  const std::vector<FieldObservation>& all_;
  std::vector<int> members_;
  std::vector<Eigen::Matrix2d> information_;
  std::vector<Eigen::Matrix2d> pixel_per_plane_;  // inverse of each observation's plane_per_pixel
  std::vector<double> ball_radius_px_;            // a ball's image radius at each observation
  std::vector<int> cameras_;
  double radius_;
  const ClusterOptions& options_;
};

// The best fit with one more ball: each ball in turn split in two, touching, in four directions.
Fit fit_with_one_more(const GroupFitter& fitter, const Fit& current, double radius_m) {
  Fit best;
  for (size_t i = 0; i < current.balls.size(); ++i) {
    for (int k = 0; k < 4; ++k) {
      const double angle = k * std::numbers::pi / 4.0;
      const Vec2 offset = radius_m * Vec2(std::cos(angle), std::sin(angle));
      std::vector<Vec2> start = current.balls;
      start[i] -= offset;
      start.push_back(current.balls[i] + offset);
      Fit f = fitter.fit(start);
      if (f.chi2 < best.chi2) best = std::move(f);
    }
  }
  return best;
}

// The best fit with one ball less.
Fit fit_with_one_less(const GroupFitter& fitter, const Fit& current) {
  Fit best;
  for (size_t i = 0; i < current.balls.size(); ++i) {
    std::vector<Vec2> start = current.balls;
    start.erase(start.begin() + static_cast<std::ptrdiff_t>(i));
    Fit f = fitter.fit(start);
    if (f.chi2 < best.chi2) best = std::move(f);
  }
  return best;
}

// One group of nearby balls refitted (as they were where nothing needs fitting).
std::vector<FusedObject> refine_group(const std::vector<FieldObservation>& observations,
                                      const std::vector<FusedObject>& fused,
                                      const std::vector<int>& group, double ball_radius_m,
                                      const ClusterOptions& options) {
  std::vector<int> members;
  std::vector<Vec2> start;
  for (int g : group) {
    const FusedObject& object = fused[static_cast<size_t>(g)];
    members.insert(members.end(), object.observations.begin(), object.observations.end());
    start.push_back(object.position_m);
  }
  if (group.size() == 1 && members.size() < 3) {
    return {fused[static_cast<size_t>(group.front())]};
  }
  const GroupFitter fitter(observations, members, ball_radius_m, options);
  Fit best = fitter.fit(start);
  if (group.size() == 1 && best.chi2 < options.min_chi2_gain) {  // a lone ball that fits
    return {fused[static_cast<size_t>(group.front())]};
  }
  // Fewer balls where the observations do not need them (a ball's observations fused apart).
  while (best.balls.size() > 1) {
    Fit fewer = fit_with_one_less(fitter, best);
    if (fewer.chi2 - best.chi2 >= options.min_chi2_keep) break;
    best = std::move(fewer);
  }
  const int wanted = static_cast<int>(start.size()) + options.max_added;
  // A further ball lowers the chi-square by at most all of it.
  while (static_cast<int>(best.balls.size()) < wanted && best.chi2 >= options.min_chi2_gain) {
    Fit more = fit_with_one_more(fitter, best, ball_radius_m);
    if (best.chi2 - more.chi2 < options.min_chi2_gain) break;
    if (min_separation(more.balls) < options.min_separation_radii * ball_radius_m) break;
    if (fitter.camera_count(more, static_cast<int>(more.balls.size()) - 1) < 2) break;
    best = std::move(more);
  }
  const Eigen::MatrixXd covariance = best.information.inverse();
  std::vector<FusedObject> out;
  for (size_t i = 0; i < best.balls.size(); ++i) {
    FusedObject object;
    object.position_m = best.balls[i];
    object.covariance_m2 =
        covariance.block<2, 2>(2 * static_cast<Eigen::Index>(i), 2 * static_cast<Eigen::Index>(i));
    for (size_t o = 0; o < members.size(); ++o) {
      const auto& cov = best.covered[o];
      if (std::find(cov.begin(), cov.end(), static_cast<int>(i)) == cov.end()) continue;
      object.observations.push_back(members[o]);
      const int camera = observations[static_cast<size_t>(members[o])].camera;
      if (std::find(object.cameras.begin(), object.cameras.end(), camera) == object.cameras.end())
        object.cameras.push_back(camera);
    }
    std::sort(object.observations.begin(), object.observations.end());
    std::sort(object.cameras.begin(), object.cameras.end());
    out.push_back(std::move(object));
  }
  return out;
}

}  // namespace

double min_separation(const std::vector<Vec2>& balls) {
  double best = std::numeric_limits<double>::max();
  for (size_t i = 0; i < balls.size(); ++i)
    for (size_t j = i + 1; j < balls.size(); ++j)
      best = std::min(best, (balls[i] - balls[j]).norm());
  return best;
}

std::vector<std::vector<int>> linked_groups(size_t count,
                                            const std::function<bool(size_t, size_t)>& linked) {
  std::vector<int> parent(count);
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int i) {
    while (parent[static_cast<size_t>(i)] != i) i = parent[static_cast<size_t>(i)];
    return i;
  };
  for (size_t i = 0; i < count; ++i)
    for (size_t j = i + 1; j < count; ++j)
      if (linked(i, j))
        parent[static_cast<size_t>(root(static_cast<int>(j)))] = root(static_cast<int>(i));
  std::vector<std::vector<int>> groups(count);
  for (size_t i = 0; i < count; ++i)
    groups[static_cast<size_t>(root(static_cast<int>(i)))].push_back(static_cast<int>(i));
  std::erase_if(groups, [](const std::vector<int>& g) { return g.empty(); });
  return groups;
}

std::vector<std::vector<int>> ball_groups(const std::vector<FusedObject>& fused, double link_m) {
  return linked_groups(fused.size(), [&](size_t i, size_t j) {
    return (fused[i].position_m - fused[j].position_m).norm() < link_m;
  });
}

std::vector<FusedObject> fit_groups_in_parallel(
    const std::vector<std::vector<int>>& groups,
    const std::function<std::vector<FusedObject>(const std::vector<int>& group)>& fit) {
  std::vector<std::vector<FusedObject>> fitted(groups.size());
  tbb::parallel_for(std::size_t{0}, groups.size(),
                    [&](std::size_t g) { fitted[g] = fit(groups[g]); });
  std::vector<FusedObject> out;
  for (std::vector<FusedObject>& objects : fitted)
    out.insert(out.end(), std::make_move_iterator(objects.begin()),
               std::make_move_iterator(objects.end()));
  return out;
}

std::vector<FusedObject> refine_clusters(const std::vector<FieldObservation>& observations,
                                         const std::vector<FusedObject>& fused,
                                         double ball_radius_m, const ClusterOptions& options) {
  options.validate();
  return fit_groups_in_parallel(ball_groups(fused, options.link_distance_radii * ball_radius_m),
                                [&](const std::vector<int>& group) {
                                  return refine_group(observations, fused, group, ball_radius_m,
                                                      options);
                                });
}

}  // namespace ballsight
