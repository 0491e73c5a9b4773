#include "ballsight/detect/photo_balls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "ballsight/core/error.hpp"
#include "ballsight/detect/hue_classes.hpp"

namespace ballsight {

void PhotoBallOptions::validate() const {
  colours.validate("ball colours");
  require(circles.min_radius_px >= 1.0, "min_radius_px", "must be at least 1 pixel");
  require(circles.max_radius_px >= circles.min_radius_px, "max_radius_px",
          "must be at least min_radius_px");
  require(circles.min_score >= 0.0 && circles.min_score <= 1.0, "min_score",
          "must be within [0, 1]");
  require(bands >= 0, "bands", "must be 0 (one per thread) or more");
  require(split.min_contrast >= 0.0, "split.min_contrast", "must be 0 or more");
  require(split.max_share > 0.0 && split.max_share <= 1.0, "split.max_share",
          "must be within (0, 1]");
}

namespace {

// A ball is mostly its own colour: at least this share of its inner disc is of a seed colour
// (the growth colours are for its rim, its shade and its pale top).
constexpr double kMinSeedShare = 0.3;
constexpr double kMinBoxFill = 0.15;
// A tiny ball's blob is its disc and rim. A blob with one circle of at most kMaxLoneRadiusPx
// that is longer, at any angle, than the circle's diameter and kMaxLoneOverhangPx (2 px a side:
// the antialiased rim, and the JPEG's chroma at half resolution) is a flat scrap of a ball's
// colour, a wrapper or a leaf, not a ball (on the real photos: a yellow scrap on the court, 9-11
// px long, whose brightest part fits a circle of 2.3-2.8 px).
constexpr double kMaxLoneRadiusPx = 4.0;
constexpr double kMaxLoneOverhangPx = 4.0;
constexpr double kMinBlobSeedShare = 0.15;
// Ring pixels of the ball's own hue family (within this of its mean hue, saturation >= 0.2):
// foliage, a wall or a court of the ball's colour, not a ball standing out.
constexpr double kAlikeHueDeg = 40.0;
constexpr double kAlikeSaturation = 0.2;
// A ball's felt is smooth at a photo's scale: its disc shades slowly, broken only by the thin
// seam and a shadow's edge, while a patch of leaves or weeds of its colour is all edges and gaps.
// Roughness: the mean absolute difference between a disc pixel's brightness and the mean of its
// four neighbours, over the disc's mean brightness. Noise of sigma s grey levels in the
// brightness (the mean of B, G and R) adds about 0.9 s over the brightness (0.04 for s = 5 on a
// ball of 120). On the real court photos (docs/RESULTS.md), looked at when this bound was set:
// the balls 0.01-0.12, the weeds behind the fence that passed every other test 0.23-0.40.
constexpr double kMaxRoughness = 0.2;

// The floor: a blob of a ball's colours that is no ball. A court, a wooden floor or a wall of a
// growth colour (or of the seed colour of one of the model's balls: a red court is stage orange)
// grows into one blob that swallows the balls on it; so does a floor whose colours a warm lamp
// has pushed into a growth band. A blob is floor when it covers kFloorMinShare of the image or
// more, is smooth (kFloorMaxRoughness: the simulator's floors 0.008-0.012, the real photos'
// foliage, which is no floor, 0.07-0.31), and is either rejected before its circles are sought
// or covered by its balls for less than kFloorMaxExplained. Its colours (floor_colours.hpp) are
// then no ball colour in this image, and the image is searched again (up to kMaxFloorPasses
// times). Once a floor was found, a smaller smooth blob (kLaterFloorMinShare) is floor too: the
// same floor in a shadow or under another lamp, whose colours the first pass did not reach (on a
// wooden floor, the strips in the net's shadow that swallow the balls lying there).
constexpr double kFloorMinShare = 0.02;
constexpr double kFloorMaxRoughness = 0.05;
constexpr double kFloorMaxExplained = 0.5;
constexpr double kLaterFloorMinShare = 0.005;
constexpr int kMaxFloorPasses = 3;

// By default a band per thread, each of at least this many rows (a band costs a pass over its
// record of grown pixels, and a blob across k bands is grown k times).
constexpr int kMinBandRows = 64;
// A blob that is not of balls alone is split by contrast (ContrastSplit) when it could hold
// kMinSplitBalls of the smallest balls and is smooth (kMaxSplitRoughness, as kMaxSurfaceRoughness
// below: a court, not foliage, whose sunlit specks would become balls).
constexpr double kMinSplitBalls = 4.0;
// A part of a split smaller than a disc of this radius is left: specks (sunlit leaves in a field
// of foliage) that, each a blob of its own, would excuse each other in the isolation test.
constexpr double kMinSplitRadiusPx = 3.0;
constexpr double kMaxSplitRoughness = 0.1;

constexpr ColorClassMask kAnySeed = kBallSeedClass | kFarBallSeedClass;

bool is_seed(ColorClassMask classes) {
  return (classes & kAnySeed) != 0;
}

// The seed classes of a ball of `radius_px`: a far colour's only for a far ball.
ColorClassMask seed_classes(double radius_px) {
  return radius_px <= kFarBallMaxRadiusPx ? kAnySeed : kBallSeedClass;
}

struct Appearance {
  double seed_share = 0.0;  // seed-colour pixels in the disc of 0.8 r
  double ring_alike = 0.0;  // ring pixels (r + max(1, 0.2 r) to r + max(3, 0.8 r)) of its hue
  double roughness = 0.0;   // of the disc of min(0.8 r, r - 1) (kMaxRoughness)
  double hue_deg = 0.0;     // the mean hue of its seed pixels (weighed by saturation)
};

double brightness(const cv::Vec3b& p) {
  return (p[0] + p[1] + p[2]) / 3.0;
}

// |brightness - mean of the four neighbours| at (x, y), which lies at least a pixel inside.
double laplacian_residual(const cv::Mat& bgr, int x, int y) {
  const auto* row = bgr.ptr<cv::Vec3b>(y);
  const double around = brightness(row[x - 1]) + brightness(row[x + 1]) +
                        brightness(bgr.ptr<cv::Vec3b>(y - 1)[x]) +
                        brightness(bgr.ptr<cv::Vec3b>(y + 1)[x]);
  return std::abs(brightness(row[x]) - 0.25 * around);
}

// The roughness of a blob (as a ball's, kMaxRoughness) over about kRoughnessSamples of its
// pixels that lie a pixel inside the image.
double blob_roughness(const cv::Mat& bgr, const std::vector<int>& pixels) {
  constexpr std::size_t kRoughnessSamples = 4096;
  const std::size_t step = std::max<std::size_t>(1, pixels.size() / kRoughnessSamples);
  double light = 0.0, residual = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < pixels.size(); k += step) {
    const int x = pixels[k] % bgr.cols, y = pixels[k] / bgr.cols;
    if (x < 1 || y < 1 || x + 1 >= bgr.cols || y + 1 >= bgr.rows) continue;
    light += brightness(bgr.ptr<cv::Vec3b>(y)[x]);
    residual += laplacian_residual(bgr, x, y);
    ++count;
  }
  return count > 0 && light > 0.0 ? residual / light : 0.0;
}

// Whether `p` is of the hue family of a ball of hue `ball_hue_deg` (kAlikeHueDeg).
bool of_hue_family(const cv::Vec3b& p, double ball_hue_deg) {
  return std::abs(std::remainder(hue_deg(p) - ball_hue_deg, 360.0)) <= kAlikeHueDeg;
}

// `classes` are the image's pixels' classes (the floor's colours taken out, a warm cast
// corrected), `model` is the colour model's own table: a ring pixel of a ball colour the photo's
// classes do not hold is floor (or floor and lines under a warm lamp), which a ball stands out
// from whatever its hue.
Appearance appearance(const cv::Mat& bgr, const cv::Mat1b& classes, const ColorClassTable& model,
                      const BlobCircle& circle, int min_yellowness) {
  const double r = circle.radius_px;
  const double inner = 0.8 * r, ring_in = r + std::max(1.0, 0.2 * r),
               ring_out = r + std::max(3.0, 0.8 * r);
  // Roughness only where the four neighbours lie on the ball too (a small ball's rim is an edge).
  const double smooth = std::min(inner, r - 1.0);
  const int step = std::max(1, static_cast<int>(r / 12.0));
  const Vec2& c = circle.center_px;
  const ColorClassMask seeds_of_this_size = seed_classes(r);
  const int x0 = std::max(0, static_cast<int>(std::floor(c.x() - ring_out)));
  const int y0 = std::max(0, static_cast<int>(std::floor(c.y() - ring_out)));
  const int x1 = std::min(bgr.cols - 1, static_cast<int>(std::ceil(c.x() + ring_out)));
  const int y1 = std::min(bgr.rows - 1, static_cast<int>(std::ceil(c.y() + ring_out)));
  int disc = 0, seeds = 0, inside = 0;
  double light = 0.0, residual = 0.0;
  Vec2 hue_sum = Vec2::Zero();
  std::vector<std::pair<cv::Vec3b, ColorClassMask>> ring;
  for (int y = y0; y <= y1; y += step) {
    const auto* row = bgr.ptr<cv::Vec3b>(y);
    const auto* row_classes = classes.ptr<ColorClassMask>(y);
    for (int x = x0; x <= x1; x += step) {
      const double d = (Vec2(x, y) - c).norm();
      if (d <= inner) {
        ++disc;
        light += brightness(row[x]);
        if (d <= smooth && x > 0 && y > 0 && x + 1 < bgr.cols && y + 1 < bgr.rows) {
          ++inside;
          residual += laplacian_residual(bgr, x, y);
        }
        if ((row_classes[x] & seeds_of_this_size) != 0) {
          ++seeds;
          const double h = hue_deg(row[x]) * std::numbers::pi / 180.0;
          hue_sum += saturation(row[x]) * Vec2(std::cos(h), std::sin(h));
        }
      } else if (d >= ring_in && d <= ring_out) {
        ring.emplace_back(row[x], row_classes[x]);
      }
    }
  }
  Appearance look;
  if (disc == 0 || seeds == 0) return look;
  look.seed_share = static_cast<double>(seeds) / disc;
  if (inside > 0 && light > 0.0) look.roughness = residual / inside / (light / disc);
  const double mean_hue = std::atan2(hue_sum.y(), hue_sum.x()) * 180.0 / std::numbers::pi;
  look.hue_deg = mean_hue;
  int alike = 0;
  for (const auto& [p, photo_classes] : ring) {
    const bool floor =
        (model.classify(p) & kBallGrowClass) != 0 && (photo_classes & kBallGrowClass) == 0;
    alike += saturation(p) >= kAlikeSaturation && of_hue_family(p, mean_hue) && !floor &&
             yellowness(p) >= min_yellowness;
  }
  look.ring_alike =
      ring.empty() ? 0.0 : static_cast<double>(alike) / static_cast<double>(ring.size());
  return look;
}

// A small ball (a few pixels: its shape says little) stands apart from everything of a ball
// colour: weeds, leaves and foliage come in fields of specks. Its wide ring
// (r + max(3, 0.3 r) to r + max(12, 0.6 r)) holds almost no pixel of a ball colour of the
// ball's own hue family (kAlikeHueDeg: orange specks are no field of yellow leaves; a seed or a
// growth colour) apart from other balls:
// those found in other blobs (balls lie in groups; two small balls a few radii apart each hold
// the other in their rings), those kept already (best score first) and those of its own clump.
// The circles a blob that is no clump is split into (a painted line, a leaf) do not excuse each
// other. Growth-colour pixels count only as specks, when they are rough (kMaxSurfaceRoughness,
// as a ball's roughness): a smooth surface of the ball's hue family (a wooden floor, a court
// under a warm lamp whose noise crosses into a growth band) is where the ball lies, not a field
// of leaves. Measured (docs/RESULTS.md): the simulator's floors 0.02-0.08, the weeds and leaf
// litter around the real photos' small false candidates 0.13-0.36.
constexpr double kSmallRadiusPx = 8.0;
constexpr double kMaxWideShare = 0.02;
constexpr double kMaxSurfaceRoughness = 0.1;
constexpr double kOtherBallMarginPx = 2.0;

// The inner and outer radius of a ball's wide ring.
std::pair<double, double> wide_ring(double r) {
  return {r + std::max(3.0, 0.3 * r), r + std::max(12.0, 0.6 * r)};
}

// Whether a small ball stands apart (see above): its wide ring, less the balls `others`.
bool stands_apart(const cv::Mat& bgr, const cv::Mat1b& classes, const PhotoBall& ball,
                  double hue_deg_of_ball, int min_yellowness,
                  const std::vector<PhotoBall>& others) {
  const auto [ring_in, ring_out] = wide_ring(ball.radius_px);
  const Vec2& c = ball.center_px;
  int count = 0, seeds = 0, alike = 0;
  double alike_light = 0.0, alike_residual = 0.0;  // of the growth pixels a pixel inside
  for (int y = std::max(0, static_cast<int>(std::floor(c.y() - ring_out)));
       y <= std::min(bgr.rows - 1, static_cast<int>(std::ceil(c.y() + ring_out))); ++y) {
    const auto* row = bgr.ptr<cv::Vec3b>(y);
    const auto* row_classes = classes.ptr<ColorClassMask>(y);
    for (int x = std::max(0, static_cast<int>(std::floor(c.x() - ring_out)));
         x <= std::min(bgr.cols - 1, static_cast<int>(std::ceil(c.x() + ring_out))); ++x) {
      const Vec2 q(x, y);
      const double d = (q - c).norm();
      if (d < ring_in || d > ring_out) continue;
      const bool in_other = std::any_of(others.begin(), others.end(), [&q](const PhotoBall& o) {
        return (q - o.center_px).norm() <= o.radius_px + kOtherBallMarginPx;
      });
      if (in_other) continue;
      ++count;
      // Most ring pixels are of no ball colour: their hue is not asked.
      if ((row_classes[x] & (kAnySeed | kBallGrowClass)) == 0 ||
          !of_hue_family(row[x], hue_deg_of_ball) || yellowness(row[x]) < min_yellowness)
        continue;
      if (is_seed(row_classes[x])) {
        ++seeds;
      } else if ((row_classes[x] & kBallGrowClass) != 0) {
        ++alike;
        if (x > 0 && y > 0 && x + 1 < bgr.cols && y + 1 < bgr.rows) {
          alike_light += brightness(row[x]);
          alike_residual += laplacian_residual(bgr, x, y);
        }
      }
    }
  }
  const bool specks = alike_light > 0.0 && alike_residual / alike_light > kMaxSurfaceRoughness;
  return seeds + (specks ? alike : 0) <= kMaxWideShare * count;
}

// A blob's length in pixels at whatever angle it lies: the largest distance between two of its
// pixels' centres, plus one (a row of n pixels is n long). For a blob larger than a few tiny
// balls, the longer side of its box (a lower bound, and long enough).
double blob_length(const GrownBlob& blob, int cols) {
  const int box = std::max(blob.bbox.width, blob.bbox.height);
  if (box > 4 * kMaxLoneRadiusPx) return box;
  int farthest = 0;  // squared
  for (std::size_t i = 0; i < blob.pixels.size(); ++i)
    for (std::size_t j = i + 1; j < blob.pixels.size(); ++j) {
      const int dx = blob.pixels[i] % cols - blob.pixels[j] % cols;
      const int dy = blob.pixels[i] / cols - blob.pixels[j] / cols;
      farthest = std::max(farthest, dx * dx + dy * dy);
    }
  return std::sqrt(farthest) + 1.0;
}

}  // namespace

PhotoBallDetector::PhotoBallDetector(const PhotoBallOptions& options)
    : options_(options), table_((options.validate(), ball_colour_table(options.colours))) {}

std::vector<PhotoBall> PhotoBallDetector::keep_isolated(const cv::Mat& bgr,
                                                        const std::vector<Found>& found) const {
  std::vector<bool> kept(found.size(), false);
  std::vector<PhotoBall> balls, others;
  for (std::size_t k = 0; k < found.size(); ++k) {
    const Found& f = found[k];
    if (f.ball.radius_px <= kSmallRadiusPx) {
      const double reach_px = wide_ring(f.ball.radius_px).second;
      others.clear();
      for (std::size_t j = 0; j < found.size(); ++j) {
        const PhotoBall& o = found[j].ball;
        if (j != k && (kept[j] || found[j].blob != f.blob || f.clump) &&
            (o.center_px - f.ball.center_px).norm() <= reach_px + o.radius_px + kOtherBallMarginPx)
          others.push_back(o);
      }
      if (!stands_apart(bgr, classes_, f.ball, f.hue_deg, f.min_yellowness, others)) continue;
    }
    kept[k] = true;
    balls.push_back(f.ball);
  }
  return balls;
}

std::vector<PhotoBall> PhotoBallDetector::detect(const cv::Mat& bgr) {
  require(!bgr.empty() && bgr.type() == CV_8UC3, "ball detector", "expected an 8-bit BGR image");
  const cv::Mat image = bgr.isContinuous() ? bgr : bgr.clone();
  floor_excluded_ = false;
  // A warm lamp's cast: this photo's colours are classified as they would be under white light.
  table_.update(image);
  search(image);
  for (int pass = 0; pass < kMaxFloorPasses && exclude_floor_colours(image); ++pass) search(image);
  std::vector<Found> found;
  int blobs = 0;  // of the bands before
  for (const Band& band : bands_) {
    for (Found f : band.found) {
      f.blob += blobs;
      found.push_back(f);
    }
    blobs += band.blobs;
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const Found& a, const Found& b) { return a.ball.score > b.ball.score; });
  return keep_isolated(image, found);
}

void PhotoBallDetector::search(const cv::Mat& bgr) {
  const int count = std::clamp(
      options_.bands > 0 ? options_.bands : std::min(cv::getNumThreads(), bgr.rows / kMinBandRows),
      1, bgr.rows);
  bands_.resize(static_cast<std::size_t>(count));
  const auto band_rows = [&](int b) {
    return cv::Range(b * bgr.rows / count, (b + 1) * bgr.rows / count);
  };
  // Every band grows over the whole image: all rows are classified before any band is searched.
  classes_.create(bgr.size());
  cv::parallel_for_(cv::Range(0, count), [&](const cv::Range& range) {
    for (int b = range.start; b < range.end; ++b)
      classify_rows(bgr, active(), band_rows(b), classes_);
  });
  cv::parallel_for_(cv::Range(0, count), [&](const cv::Range& range) {
    for (int b = range.start; b < range.end; ++b)
      scan_band(bgr, band_rows(b), bands_[static_cast<std::size_t>(b)]);
  });
}

bool PhotoBallDetector::exclude_floor_colours(const cv::Mat& bgr) {
  std::vector<const std::vector<int>*> parts;
  for (const Band& band : bands_)
    if (!band.floor.empty()) parts.push_back(&band.floor);
  if (parts.empty()) return false;
  const std::vector<std::size_t> cells = floor_colours_.cells(bgr, parts);
  if (cells.empty()) return false;
  if (!floor_excluded_) floor_table_ = base();
  for (const std::size_t cell : cells)
    floor_table_->remove_classes(cell, kAnySeed | kBallGrowClass);
  floor_excluded_ = true;
  return true;
}

void PhotoBallDetector::scan_band(const cv::Mat& bgr, cv::Range rows, Band& band) const {
  // Blobs grow beyond the band, so the band marks what it grew over the whole image.
  band.buffers.reset(static_cast<int>(bgr.total()));
  band.found.clear();
  band.floor.clear();
  band.blobs = 0;
  const int begin = rows.start * bgr.cols, end = rows.end * bgr.cols;
  const ColorClassMask* classes = classes_.ptr<ColorClassMask>(0);
  constexpr std::uint64_t kSeedBytes = 0x0101010101010101ULL * kAnySeed;
  for (int seed = begin; seed < end; ++seed) {
    // Most pixels are of no seed colour: eight at a time.
    std::uint64_t eight = 0;
    while (seed + 8 <= end && (std::memcpy(&eight, classes + seed, 8), !(eight & kSeedBytes)))
      seed += 8;
    if (seed == end) break;
    if (!is_seed(classes[seed]) || band.buffers.visited[static_cast<std::size_t>(seed)]) continue;
    grow_blob(classes_, kBallGrowClass, seed, band.buffers, band.blob);
    // A blob with a seed pixel above the band is an earlier band's.
    if (band.blob.bbox.y < rows.start &&
        std::any_of(band.blob.pixels.begin(), band.blob.pixels.end(),
                    [&](int index) { return index < begin && is_seed(classes[index]); }))
      continue;
    find_circles(bgr, band);
  }
}

void PhotoBallDetector::find_circles(const cv::Mat& bgr, Band& band) const {
  const double min_r = options_.circles.min_radius_px, max_r = options_.circles.max_radius_px;
  // A ball's blob holds at least a third of its disc; a blob larger than a few of the largest
  // balls is ground, foliage or a wall.
  // A blob of balls fills a good part of its box (one ball 0.79, three in a diagonal row 0.26);
  // foliage and leaf litter do not.
  const double area = static_cast<double>(band.blob.pixels.size());
  // Not a blob of balls alone: floor, when large and smooth; and the balls on it apart by their
  // contrast.
  const auto not_balls = [&] {
    if (area >= (floor_excluded_ ? kLaterFloorMinShare : kFloorMinShare) *
                    static_cast<double>(bgr.total()) &&
        blob_roughness(bgr, band.blob.pixels) <= kFloorMaxRoughness)
      band.floor.insert(band.floor.end(), band.blob.pixels.begin(), band.blob.pixels.end());
    find_balls_by_contrast(bgr, band);
  };
  if (area < std::numbers::pi * min_r * min_r / 3.0) return;
  if (area > 6.0 * std::numbers::pi * max_r * max_r || area < kMinBoxFill * band.blob.bbox.area())
    return not_balls();
  // Most of a ball is of a seed colour (kMinSeedShare of its disc); a blob grown mostly through
  // the looser growth colours is shade, foliage or a wall.
  if (seed_share(band.blob) < kMinBlobSeedShare) return not_balls();
  if (fit_blob(bgr, band.blob, 0, band) < kFloorMaxExplained * area) not_balls();
}

double PhotoBallDetector::seed_share(const GrownBlob& blob) const {
  std::size_t seeds = 0;
  const ColorClassMask* classes = classes_.ptr<ColorClassMask>(0);
  for (int index : blob.pixels) seeds += is_seed(classes[index]);
  return static_cast<double>(seeds) / static_cast<double>(blob.pixels.size());
}

double PhotoBallDetector::fit_blob(const cv::Mat& bgr, const GrownBlob& grown, int min_yellowness,
                                   Band& band) const {
  constexpr int kMargin = 3;
  const cv::Rect region =
      cv::Rect(grown.bbox.x - kMargin, grown.bbox.y - kMargin, grown.bbox.width + 2 * kMargin,
               grown.bbox.height + 2 * kMargin) &
      cv::Rect(0, 0, bgr.cols, bgr.rows);
  // The blob with a one-pixel frame, so that the flood from the frame reaches every outside
  // pixel; what it does not reach is a hole.
  band.patch.create(region.height + 2, region.width + 2);
  band.patch.setTo(0);
  for (int index : grown.pixels)
    band.patch(index / bgr.cols - region.y + 1, index % bgr.cols - region.x + 1) = 255;
  cv::floodFill(band.patch, cv::Point(0, 0), 128);
  BlobMask blob;
  cv::compare(band.patch(cv::Rect(1, 1, region.width, region.height)), 128, blob.mask, cv::CMP_NE);
  blob.origin = Vec2(region.x, region.y);
  blob.image_size = bgr.size();
  BlobCircleOptions geometry = options_.circles;
  geometry.min_score = 0.0;
  std::vector<BlobCircle> balls;
  std::vector<double> hues;
  for (BlobCircle circle : circles_in_blob(blob, geometry)) {
    const Appearance look = appearance(bgr, classes_, table_.model(), circle, min_yellowness);
    if (look.seed_share < kMinSeedShare || look.roughness > kMaxRoughness) continue;
    circle.score *= 1.0 - look.ring_alike;
    if (circle.score < options_.circles.min_score) continue;
    balls.push_back(circle);
    hues.push_back(look.hue_deg);
  }
  double explained = 0.0;
  for (const BlobCircle& ball : balls)
    explained += std::numbers::pi * ball.radius_px * ball.radius_px;
  if (balls.empty()) return explained;
  if (balls.size() == 1 && balls[0].radius_px <= kMaxLoneRadiusPx &&
      blob_length(grown, bgr.cols) > 2.0 * balls[0].radius_px + kMaxLoneOverhangPx)
    return explained;  // a flat scrap, not a ball
  // Whether the blob's balls are a clump is judged by them alone, not by the circles dropped.
  const bool clump = is_clump(blob, balls);
  for (std::size_t k = 0; k < balls.size(); ++k)
    band.found.push_back({{balls[k].center_px, balls[k].radius_px, balls[k].score},
                          hues[k],
                          min_yellowness,
                          band.blobs,
                          clump});
  ++band.blobs;
  return explained;
}

void PhotoBallDetector::find_balls_by_contrast(const cv::Mat& bgr, Band& band) const {
  const GrownBlob& blob = band.blob;
  const double min_r = options_.circles.min_radius_px;
  if (static_cast<double>(blob.pixels.size()) < kMinSplitBalls * std::numbers::pi * min_r * min_r ||
      blob_roughness(bgr, blob.pixels) > kMaxSplitRoughness)
    return;
  const auto split =
      split_by_contrast(bgr, blob, options_.split,
                        static_cast<std::size_t>(
                            std::ceil(std::numbers::pi * kMinSplitRadiusPx * kMinSplitRadiusPx)));
  if (!split) return;
  const std::size_t before = band.found.size();
  for (const GrownBlob& part : split->parts)
    if (seed_share(part) >= kMinBlobSeedShare) fit_blob(bgr, part, split->threshold, band);
  // A ball the whole blob already gave is not given twice.
  const auto given = band.found.begin() + static_cast<std::ptrdiff_t>(before);
  band.found.erase(
      std::remove_if(given, band.found.end(),
                     [&](const Found& f) {
                       return std::any_of(band.found.begin(), given, [&](const Found& o) {
                         return (o.ball.center_px - f.ball.center_px).norm() <= o.ball.radius_px;
                       });
                     }),
      band.found.end());
}

}  // namespace ballsight
