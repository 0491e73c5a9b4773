#include "ballsight/calib/lut_inspect.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ballsight/camera/ground_map_io.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/statistics.hpp"

namespace ballsight {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr int kIrisImageSize = 640;  // a square around the centre holding the 320 px radius

}  // namespace

LutFormat lut_format_from_string(std::string_view name) {
  if (name == "auto") return LutFormat::automatic;
  if (name == "ballsight") return LutFormat::ballsight;
  if (name == "iris-px2cm") return LutFormat::iris_px2cm;
  throw InputError("--format: unknown table format '" + std::string(name) +
                   "' (expected auto, ballsight or iris-px2cm)");
}

std::string_view to_string(LutFormat format) {
  switch (format) {
    case LutFormat::ballsight:
      return "ballsight";
    case LutFormat::iris_px2cm:
      return "iris-px2cm";
    case LutFormat::automatic:
      break;
  }
  return "auto";
}

int RadialTable::bin_at(double radius_px) const {
  return static_cast<int>(std::lround(radius_px * bins_per_px));
}

std::span<const float> RadialTable::ray(int theta_deg) const {
  return std::span<const float>(distance_cm)
      .subspan(static_cast<std::size_t>(theta_deg) * bins, bins);
}

InspectedLut inspected_from_iris(const IrisLut& px2cm, std::string source) {
  require(px2cm.kind() == IrisLutKind::px2cm, source, "inspection needs a px2cm table");
  InspectedLut lut{std::move(source), LutFormat::iris_px2cm, {}, {}, {}};
  lut.rays.bins_per_px = IrisLut::kPx2cmBinsPerPx;
  lut.rays.bins = px2cm.bins();
  lut.rays.distance_cm.assign(px2cm.values().begin(), px2cm.values().end());
  lut.image_center_px = Vec2(0.5 * (kIrisImageSize - 1), 0.5 * (kIrisImageSize - 1));
  lut.distance_image_cm.create(kIrisImageSize, kIrisImageSize);
  for (int y = 0; y < kIrisImageSize; ++y) {
    for (int x = 0; x < kIrisImageSize; ++x) {
      const Polar polar = image_polar_from_pixel(Vec2(x, y), lut.image_center_px);
      const std::optional<int> d = iris_distance_cm(px2cm, polar.theta_deg, polar.radius);
      lut.distance_image_cm(y, x) = d && *d > 0 ? static_cast<float>(*d) : kNaN;
    }
  }
  return lut;
}

InspectedLut inspected_from_ground_map(const GroundMap& map, std::string source) {
  const GroundMapInfo& info = map.info();
  InspectedLut lut{std::move(source), LutFormat::ballsight, {}, {}, info.image_center_px};
  lut.rays.bins_per_px = 10.0;
  lut.rays.bins = static_cast<int>(std::ceil((info.max_radius_px + 1.0) * lut.rays.bins_per_px));
  lut.rays.distance_cm.assign(static_cast<std::size_t>(RadialTable::kDirections) * lut.rays.bins,
                              kNaN);
  for (int theta = 0; theta < RadialTable::kDirections; ++theta) {
    for (int bin = 0; bin < lut.rays.bins; ++bin) {
      const std::optional<Vec2> p_cm = map.robot_point_cm(
          pixel_from_image_polar({double(theta), lut.rays.radius_px(bin)}, info.image_center_px));
      if (p_cm) {
        lut.rays.distance_cm[static_cast<std::size_t>(theta) * lut.rays.bins + bin] =
            static_cast<float>(p_cm->norm());
      }
    }
  }
  lut.distance_image_cm.create(map.height(), map.width());
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      const GroundCell c = map.at(x, y);
      lut.distance_image_cm(y, x) = c.valid() ? std::hypot(c.x_cm, c.y_cm) : kNaN;
    }
  }
  return lut;
}

InspectedLut read_lut_for_inspection(const std::filesystem::path& path, LutFormat format) {
  if (format == LutFormat::automatic) {
    const std::string bytes = read_file(path);
    const std::size_t iris_bytes = 2u * IrisLut::kDirections * IrisLut::kPx2cmBins;
    require(!bytes.empty(), path.string(), "empty file (expected a lookup table)");
    if (has_ground_map_magic(bytes)) {
      format = LutFormat::ballsight;
    } else if (bytes.size() == iris_bytes) {
      format = LutFormat::iris_px2cm;
    } else {
      throw InputError(path.string() + ": unknown table format (no ballsight header and not " +
                       std::to_string(iris_bytes) + " bytes like an iris px2cm table, got " +
                       std::to_string(bytes.size()) + "); pass --format");
    }
  }
  if (format == LutFormat::ballsight) {
    return inspected_from_ground_map(load_ground_map(path), path.string());
  }
  return inspected_from_iris(read_iris_lut(path, IrisLutKind::px2cm), path.string());
}

void LutInspectOptions::validate() const {
  const std::string where = "lut inspect";
  require(std::isfinite(drop_tolerance_cm) && drop_tolerance_cm >= 0.0, where,
          "drop_tolerance_cm must be >= 0");
  require(std::isfinite(max_plausible_cm) && max_plausible_cm > 0.0, where,
          "max_plausible_cm must be > 0");
  require(std::isfinite(confirm_run_px) && confirm_run_px > 0.0, where,
          "confirm_run_px must be > 0");
  for (const double r : spread_radii_px) {
    require(std::isfinite(r) && r >= 0.0, where, "spread_radii_px must be >= 0");
  }
}

namespace {

bool is_plausible(float v, const LutInspectOptions& options) {
  return std::isfinite(v) && v > 0.0f && v <= options.max_plausible_cm;
}

struct RayScan {
  RayFindings findings;
  int first_bin = -1;
  int last_bin = -1;
};

// Along one ray: the first run of `run` plausible non-decreasing bins marks where the table was
// written (below it, the paper's generator left memory uninitialised); then holes and the first
// drop of more than the tolerance below the running maximum.
RayScan scan_ray(const RadialTable& rays, int theta_deg, int run,
                 const LutInspectOptions& options) {
  const std::span<const float> ray = rays.ray(theta_deg);
  const auto plausible = [&](float v) { return is_plausible(v, options); };
  RayScan scan;
  const int n = static_cast<int>(ray.size());
  for (int i = 0, length = 0; i < n; ++i) {
    if (plausible(ray[i]) && length > 0 && ray[i] >= ray[i - 1]) {
      ++length;
    } else {
      length = plausible(ray[i]) ? 1 : 0;  // a decrease starts a new run
    }
    if (length >= run) {
      scan.first_bin = i - run + 1;
      break;
    }
  }
  if (scan.first_bin < 0) return scan;
  for (int i = n - 1; i >= scan.first_bin; --i) {
    if (plausible(ray[i])) {
      scan.last_bin = i;
      break;
    }
  }
  RayFindings& f = scan.findings;
  f.first_written_px = rays.radius_px(scan.first_bin);
  f.last_written_px = rays.radius_px(scan.last_bin);
  float running_max = ray[scan.first_bin];
  for (int i = scan.first_bin; i <= scan.last_bin; ++i) {
    if (!plausible(ray[i])) {
      ++f.holes;
      continue;
    }
    if (!f.drop_px && ray[i] < running_max - options.drop_tolerance_cm)
      f.drop_px = rays.radius_px(i);
    running_max = std::max(running_max, ray[i]);
  }
  return scan;
}

}  // namespace

LutInspection inspect_lut(const InspectedLut& lut, const LutInspectOptions& options) {
  options.validate();
  const RadialTable& rays = lut.rays;
  LutInspection out;
  out.source = lut.source;
  out.format = std::string(to_string(lut.format));
  out.radius_step_px = 1.0 / rays.bins_per_px;
  out.bins = rays.bins;
  out.drop_tolerance_cm = options.drop_tolerance_cm;
  const int run = std::max(2, rays.bin_at(options.confirm_run_px));
  std::vector<RayScan> scans;
  std::vector<double> firsts;
  for (int theta = 0; theta < RadialTable::kDirections; ++theta) {
    scans.push_back(scan_ray(rays, theta, run, options));
    const RayScan& scan = scans.back();
    const RayFindings& f = scan.findings;
    out.rays.push_back(f);
    if (!f.first_written_px) continue;
    ++out.written_directions;
    firsts.push_back(*f.first_written_px);
    out.last_written_min_px =
        std::min(out.last_written_min_px.value_or(*f.last_written_px), *f.last_written_px);
    out.last_written_max_px =
        std::max(out.last_written_max_px.value_or(*f.last_written_px), *f.last_written_px);
    const double until = f.drop_px.value_or(*f.last_written_px);
    if (!out.monotonic_until_px || until < *out.monotonic_until_px) {
      out.monotonic_until_px = until;
      out.monotonic_until_theta_deg = theta;
    }
    out.non_monotonic_directions += f.drop_px ? 1 : 0;
    out.holes += f.holes;
    out.directions_with_holes += f.holes > 0 ? 1 : 0;
    out.written_bins += scan.last_bin - scan.first_bin + 1;
  }
  if (!firsts.empty()) {
    out.first_written_min_px = *std::min_element(firsts.begin(), firsts.end());
    out.first_written_max_px = *std::max_element(firsts.begin(), firsts.end());
    out.first_written_median_px = median(firsts);
  }
  for (const double r : options.spread_radii_px) {
    const int bin = rays.bin_at(r);
    if (bin >= rays.bins) continue;
    RadiusSpread spread{r, 0, 0.0, 0.0};
    for (int theta = 0; theta < RadialTable::kDirections; ++theta) {
      const RayScan& scan = scans[static_cast<std::size_t>(theta)];
      const float v = rays.ray(theta)[static_cast<std::size_t>(bin)];
      if (bin < scan.first_bin || bin > scan.last_bin || !is_plausible(v, options)) continue;
      spread.min_cm = spread.directions == 0 ? v : std::min<double>(spread.min_cm, v);
      spread.max_cm = spread.directions == 0 ? v : std::max<double>(spread.max_cm, v);
      ++spread.directions;
    }
    if (spread.directions > 0) out.spread.push_back(spread);
  }
  return out;
}

}  // namespace ballsight
