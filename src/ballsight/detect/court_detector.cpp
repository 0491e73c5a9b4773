#include "ballsight/detect/court_detector.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/detect/blob_evidence.hpp"
#include "ballsight/detect/blob_split.hpp"

namespace ballsight {

void CourtObjectSpec::validate(const char* name) const {
  const std::string where = name;
  require(radius_m > 0.0 && std::isfinite(radius_m), where + ".radius_m", "must be positive");
  require(center_height_m >= 0.0 && std::isfinite(center_height_m), where + ".center_height_m",
          "must be non-negative");
  seed_colour.validate((where + ".seed_colour").c_str());
  if (shade_seed_colour) shade_seed_colour->validate((where + ".shade_seed_colour").c_str());
  grow_colour.validate((where + ".grow_colour").c_str());
  require(std::abs(evidence_bgr[0] + evidence_bgr[1] + evidence_bgr[2]) < 1e-4f,
          where + ".evidence_bgr", "weights must sum to 0 (grey gives no evidence)");
  require(max_split >= 1 && max_split <= 16, where + ".max_split", "must be within [1, 16]");
}

namespace {

// A ball in a building's hard shadow (a tenth to a third of the sunlit brightness) keeps its hue
// and its saturation, not its chroma: 27-32 against the seed band's 35 on the simulator, where
// the report's HSV box found some of them and ballsight did not.
constexpr double kShadeMinChroma = 20.0;
constexpr double kShadeMinSaturation = 0.45;

CourtObjectSpec object_of_colour(ObjectClass object, const cv::Vec3b& bgr, double radius_m,
                                 double center_height_m) {
  CourtObjectSpec spec;
  spec.object = object;
  spec.radius_m = radius_m;
  spec.center_height_m = center_height_m;
  const double hue = hue_deg(bgr);
  const auto band = [hue](double half_width_deg, double min_chroma, double min_saturation) {
    return HueBand{std::fmod(hue - half_width_deg + 360.0, 360.0),
                   std::fmod(hue + half_width_deg, 360.0), min_chroma, min_saturation};
  };
  spec.seed_colour = band(20.0, 35.0, 0.0);
  spec.shade_seed_colour = band(20.0, kShadeMinChroma, kShadeMinSaturation);
  spec.grow_colour = band(32.0, 15.0, 0.0);
  const cv::Vec3f colour(bgr[0], bgr[1], bgr[2]);
  const float mean = (colour[0] + colour[1] + colour[2]) / 3.0f;
  const cv::Vec3f chroma = colour - cv::Vec3f::all(mean);
  require(cv::norm(chroma) >= 10.0, std::string(object_class_name(object)) + " colour",
          "is too grey to be told apart by its hue");
  spec.evidence_bgr = chroma / static_cast<float>(cv::norm(chroma));
  spec.max_split = object == ObjectClass::ball ? 6 : 1;
  return spec;
}

}  // namespace

std::vector<CourtObjectSpec> court_objects(const CourtObjectColours& colours, double ball_radius_m,
                                           double marker_radius_m, double marker_height_m) {
  return {object_of_colour(ObjectClass::ball, colours.ball, ball_radius_m, ball_radius_m),
          object_of_colour(ObjectClass::robot_front_marker, colours.front_marker, marker_radius_m,
                           marker_height_m),
          object_of_colour(ObjectClass::robot_back_marker, colours.back_marker, marker_radius_m,
                           marker_height_m)};
}

void CourtDetectorOptions::validate() const {
  require(!objects.empty() && objects.size() <= 4, "court detector objects",
          "need 1 to 4 object specs");
  for (size_t i = 0; i < objects.size(); ++i)
    objects[i].validate(("court detector objects[" + std::to_string(i) + "]").c_str());
  require(area.valid(), "court detector area", "must have a positive size");
  require(min_radius_px > 0.0, "court detector min_radius_px", "must be positive");
  require(seed_step_per_radius > 0.0, "court detector seed_step_per_radius", "must be positive");
  require(max_seed_step_px >= 1, "court detector max_seed_step_px", "must be at least 1");
  require(size_cell_px >= 1 && size_cell_px <= 256, "court detector size_cell_px",
          "must be within [1, 256]");
  require(max_objects_in_blob >= 1.0, "court detector max_objects_in_blob", "must be at least 1");
  require(split_rounding >= 0.0 && split_rounding < 1.0, "court detector split_rounding",
          "must be within [0, 1)");
  require(saturation > 0.0 && saturation <= 1.0, "court detector saturation",
          "must be within (0, 1]");
  require(min_thickness >= 0.0 && min_thickness < 1.0, "court detector min_thickness",
          "must be within [0, 1)");
}

namespace {

ColorClassMask seed_bit(size_t spec) {
  return static_cast<ColorClassMask>(1u << (2 * spec));
}
ColorClassMask grow_bits(size_t spec) {
  return static_cast<ColorClassMask>(3u << (2 * spec));
}

ColorClassTable court_table(const std::vector<CourtObjectSpec>& objects) {
  std::vector<HueClassRule> rules;
  for (size_t i = 0; i < objects.size(); ++i) {
    rules.push_back({seed_bit(i), objects[i].seed_colour});
    if (objects[i].shade_seed_colour) rules.push_back({seed_bit(i), *objects[i].shade_seed_colour});
    rules.push_back(
        {static_cast<ColorClassMask>(grow_bits(i) & ~seed_bit(i)), objects[i].grow_colour});
  }
  return hue_class_table(rules);
}

// Mean over a lit sphere's disc of its brightness relative to the brightest pixel: sun from above
// at 35-70 deg with 40-50% ambient light (measured on the simulator's balls: 0.6-0.9).
constexpr double kShadedFill = 0.75;
// Apparent growth of a small disc by pixel footprint and optics (fits the simulator's balls of
// 0.8-3 px radius).
constexpr double kBlurPx = 0.15;
// A blob is split when it is this elongated.
constexpr double kSplitElongation = 1.8;

}  // namespace

CourtDetector::CourtDetector(const FieldCamera& camera, const CourtDetectorOptions& options)
    : options_(options),
      size_(camera.camera.width(), camera.camera.height()),
      table_((options.validate(), court_table(options.objects))) {
  for (const CourtObjectSpec& spec : options_.objects)
    sizes_.emplace_back(camera, spec.radius_m, spec.center_height_m, options_.area,
                        options_.size_cell_px);
  // Seed grid: in every cell where some object can be seen, a step of about the smallest
  // object's apparent radius, aligned to the image so neighbouring cells share grid lines.
  const cv::Size grid = sizes_.front().grid_size();
  const int cell = options_.size_cell_px;
  for (int cy = 0; cy < grid.height; ++cy) {
    for (int cx = 0; cx < grid.width; ++cx) {
      double smallest = 0.0;
      for (const ApparentSizeMap& map : sizes_) {
        const double r = map.radius_px_at_cell(cx, cy);
        if (r >= options_.min_radius_px && (smallest == 0.0 || r < smallest)) smallest = r;
      }
      if (smallest == 0.0) continue;
      const int step = std::clamp(static_cast<int>(options_.seed_step_per_radius * smallest), 1,
                                  options_.max_seed_step_px);
      const int y_end = std::min((cy + 1) * cell, size_.height);
      const int x_end = std::min((cx + 1) * cell, size_.width);
      for (int y = (cy * cell + step - 1) / step * step; y < y_end; y += step)
        for (int x = (cx * cell + step - 1) / step * step; x < x_end; x += step)
          seeds_.push_back(y * size_.width + x);
    }
  }
  std::sort(seeds_.begin(), seeds_.end());
  buffers_.reset(size_.area());
}

std::vector<PixelDetection> CourtDetector::detect(const cv::Mat& bgr) {
  require(bgr.type() == CV_8UC3, "court detector", "expected an 8-bit BGR image");
  require(bgr.size() == size_, "court detector",
          "image is " + std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows) +
              " but the camera's calibration is for " + std::to_string(size_.width) + "x" +
              std::to_string(size_.height));
  const cv::Mat image = bgr.isContinuous() ? bgr : bgr.clone();
  const auto* pixels = image.ptr<cv::Vec3b>(0);
  // A warm lamp's cast: the frame's colours are classified as they would be under white light.
  const ColorClassTable& table = table_.update(image);
  std::vector<PixelDetection> out;
  int blob_count = 0;
  for (int seed : seeds_) {
    const ColorClassMask classes = table.classify(pixels[seed]);
    if (!classes) continue;
    for (size_t i = 0; i < options_.objects.size(); ++i) {
      if (!(classes & seed_bit(i))) continue;
      if (!grow_blob(image, table, grow_bits(i), seed, buffers_, blob_)) break;
      touched_.insert(touched_.end(), blob_.pixels.begin(), blob_.pixels.end());
      measure(image, blob_, i, blob_count++, out);
      break;
    }
  }
  for (int index : touched_) buffers_.visited[static_cast<size_t>(index)] = 0;
  touched_.clear();
  return out;
}

namespace {

// The coverage of `pixels` (weights saturating at `level`) over their box grown by 2 pixels.
CoveragePatch coverage_patch(const std::vector<EvidencePixel>& pixels, float level, int blob) {
  CoveragePatch patch;
  patch.blob = blob;
  if (pixels.empty()) return patch;
  constexpr int kMargin = 2;
  float x0 = pixels.front().x, y0 = pixels.front().y, x1 = x0, y1 = y0;
  for (const EvidencePixel& p : pixels) {
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  }
  patch.x = static_cast<int>(x0) - kMargin;
  patch.y = static_cast<int>(y0) - kMargin;
  patch.width = static_cast<int>(x1 - x0) + 1 + 2 * kMargin;
  patch.height = static_cast<int>(y1 - y0) + 1 + 2 * kMargin;
  patch.coverage.assign(static_cast<size_t>(patch.width * patch.height), 0.0f);
  for (const EvidencePixel& p : pixels)
    patch.coverage[static_cast<size_t>((static_cast<int>(p.y) - patch.y) * patch.width +
                                       static_cast<int>(p.x) - patch.x)] =
        std::min(p.weight, level) / level;
  return patch;
}

}  // namespace

void CourtDetector::measure(const cv::Mat& bgr, const GrownBlob& blob, size_t spec_index,
                            int blob_index, std::vector<PixelDetection>& out) const {
  const CourtObjectSpec& spec = options_.objects[spec_index];
  const Vec2 box_center(blob.bbox.x + 0.5 * (blob.bbox.width - 1),
                        blob.bbox.y + 0.5 * (blob.bbox.height - 1));
  const double expected_r = sizes_[spec_index].radius_px(box_center);
  if (expected_r <= 0.0) return;  // outside the field area
  // Size and shape against one object of the expected size: a disc of radius r, blurred by the
  // pixel and the optics (as if about kBlurPx larger), holds about kShadedFill * pi (r + blur)^2
  // times the peak evidence and has a variance of (r + blur)^2 / 4 + 1/12 along every axis.
  const double blurred_r = expected_r + kBlurPx;
  const double single_mass = kShadedFill * std::numbers::pi * blurred_r * blurred_r;
  const double disc_variance = blurred_r * blurred_r / 4.0 + 1.0 / 12.0;
  const int margin = 2 + static_cast<int>(std::ceil(0.5 * expected_r));
  // A blob of more objects than max_objects_in_blob whatever its peak (a court of a marker's
  // colour) is left unmeasured.
  const std::optional<BlobEvidence> measured = measure_blob_evidence(
      bgr, blob, spec.evidence_bgr, margin, options_.max_objects_in_blob * single_mass);
  if (!measured) return;
  const BlobEvidence& evidence = *measured;
  if (evidence.mass <= 0.0 || evidence.peak < 3.0 * evidence.noise_sigma) return;
  const double objects_by_mass = evidence.mass / (evidence.peak * single_mass);
  if (objects_by_mass > options_.max_objects_in_blob) return;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> shape(evidence.covariance);
  const double elongation = std::max(0.0, shape.eigenvalues()(1)) / disc_variance;
  const double thinness = std::max(0.0, shape.eigenvalues()(0)) / disc_variance;
  if (expected_r >= 2.0 && std::sqrt(thinness) < options_.min_thickness)
    return;  // a line or an edge, not a sphere
  // The most covered pixel has the object's own colour: the yellowish rim of an orange reference
  // ball, whose core is orange, is not a tennis ball.
  if (!spec.is_own_colour(evidence.peak_bgr)) return;
  // Touching objects: more evidence than one, or stretched (two discs in a row: ~5x the variance
  // along the row for large discs, ~2-3x for discs of a pixel). Thresholds measured on the
  // simulator's clusters (docs/court-eval.md).
  int count = 1;
  const int by_mass = static_cast<int>(std::floor(objects_by_mass + options_.split_rounding));
  if (by_mass >= 2 || elongation >= kSplitElongation)
    count = std::max(by_mass, elongation >= kSplitElongation ? 2 : 1);
  count = std::clamp(count, 1, spec.max_split);

  // Centres from the coverage, not the brightness: weights saturate at a share of the peak, so
  // the sunlit top of a ball does not pull its centre up.
  std::vector<EvidencePixel> coverage = evidence.pixels;
  const auto level = static_cast<float>(options_.saturation * evidence.peak);
  for (EvidencePixel& p : coverage) p.weight = std::min(p.weight, level);
  std::vector<BlobPart> parts;
  if (count == 1) {
    parts.emplace_back();
    parts.back().pixels = coverage;
    weighted_moments(coverage, parts.back().mass, parts.back().centroid, parts.back().covariance);
  } else {
    parts = split_blob(coverage, count);
  }
  const CoveragePatch patch = coverage_patch(coverage, level, blob_index);
  for (const BlobPart& part : parts) {
    PixelDetection d;
    d.patch = patch;
    d.object = spec.object;
    d.center_px = part.centroid;
    d.area_px = part.mass / level;
    d.radius_px = std::sqrt(d.area_px / std::numbers::pi);
    d.split_count = static_cast<int>(parts.size());
    d.blob_objects = objects_by_mass;
    // Expected error of the centre: pixel noise through the weighted centroid, shading of the
    // sphere, the cut between split parts, and what is missing when the object is partly hidden.
    double spread = 0.0;
    for (const EvidencePixel& p : part.pixels)
      spread += (Vec2(p.x, p.y) - part.centroid).squaredNorm();
    const double noise_var =
        evidence.noise_sigma * evidence.noise_sigma * spread / (2.0 * part.mass * part.mass);
    const double fill = d.area_px / (std::numbers::pi * blurred_r * blurred_r);
    const double missing = std::max(0.0, 0.8 - fill);
    double variance = noise_var + std::pow(0.05 * expected_r, 2) +
                      std::pow(missing * expected_r, 2) + 0.02 * 0.02;
    if (parts.size() > 1) variance += std::pow(0.1 * expected_r, 2);
    if (evidence.touches_border) variance += expected_r * expected_r;
    d.center_sigma_px = std::sqrt(variance);
    out.push_back(d);
  }
}

}  // namespace ballsight
