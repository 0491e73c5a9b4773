#include "ballsight/camera/iris_lut.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/little_endian.hpp"

namespace ballsight {

std::string_view to_string(IrisLutKind kind) {
  return kind == IrisLutKind::px2cm ? "px2cm" : "cm2px";
}

IrisLut::IrisLut(IrisLutKind kind)
    : kind_(kind), values_(static_cast<std::size_t>(kDirections) * bins_for(kind), 0) {}

IrisLut::IrisLut(IrisLutKind kind, std::vector<std::int16_t> values)
    : kind_(kind), values_(std::move(values)) {
  const std::size_t expected = static_cast<std::size_t>(kDirections) * bins_for(kind);
  require(
      values_.size() == expected, std::string("iris ") + std::string(to_string(kind)) + " table",
      "expected " + std::to_string(expected) + " entries, got " + std::to_string(values_.size()));
}

std::size_t IrisLut::index(int theta_deg, int bin) const {
  assert(theta_deg >= 0 && theta_deg < kDirections && bin >= 0 && bin < bins());
  return static_cast<std::size_t>(theta_deg) * bins() + bin;
}

std::span<const std::int16_t> IrisLut::direction(int theta_deg) const {
  return std::span<const std::int16_t>(values_).subspan(index(theta_deg, 0), bins());
}

std::int16_t& IrisLut::at(int theta_deg, int bin) {
  return values_[index(theta_deg, bin)];
}

std::int16_t IrisLut::at(int theta_deg, int bin) const {
  return values_[index(theta_deg, bin)];
}

IrisLut read_iris_lut(const std::filesystem::path& path, IrisLutKind kind) {
  return parse_iris_lut(read_file(path), path.string(), kind);
}

IrisLut parse_iris_lut(std::string_view file, const std::string& where, IrisLutKind kind) {
  const std::size_t entries =
      static_cast<std::size_t>(IrisLut::kDirections) * IrisLut::bins_for(kind);
  const std::string expected = std::to_string(2 * entries) + " bytes";
  const std::string layout = "an iris " + std::string(to_string(kind)) + " table is 360 x " +
                             std::to_string(IrisLut::bins_for(kind)) + " int16";
  require(!file.empty(), where, "empty file (" + layout + ")");
  const std::string got = ", got " + std::to_string(file.size()) + " (" + layout + ")";
  require(file.size() >= 2 * entries, where, "truncated: expected " + expected + got);
  require(file.size() == 2 * entries, where, "expected " + expected + got);
  std::vector<std::int16_t> values(entries);
  LittleEndianReader in(file);
  for (std::int16_t& v : values) v = in.i16();
  return IrisLut(kind, std::move(values));
}

std::string iris_lut_bytes(const IrisLut& lut) {
  std::string file;
  file.reserve(2 * lut.values().size());
  LittleEndianWriter out(file);
  for (const std::int16_t v : lut.values()) out.i16(v);
  return file;
}

void write_iris_lut(const std::filesystem::path& path, const IrisLut& lut) {
  write_file_atomic(path, iris_lut_bytes(lut));
}

namespace {

// The robots' index: (int)theta * bins + (int)(x * scale), range-checked.
std::optional<std::int16_t> robot_read(const IrisLut& lut, double theta_deg, double x,
                                       double scale) {
  if (!(theta_deg >= 0.0 && theta_deg < IrisLut::kDirections)) return std::nullopt;
  const double bin = x * scale;
  if (!(bin >= 0.0 && bin < lut.bins())) return std::nullopt;
  return lut.at(static_cast<int>(theta_deg), static_cast<int>(bin));
}

}  // namespace

std::optional<int> iris_distance_cm(const IrisLut& px2cm, double theta_deg, double radius_px) {
  assert(px2cm.kind() == IrisLutKind::px2cm);
  return robot_read(px2cm, theta_deg, radius_px, IrisLut::kPx2cmBinsPerPx);
}

std::optional<double> iris_radius_px(const IrisLut& cm2px, double theta_deg, double distance_cm) {
  assert(cm2px.kind() == IrisLutKind::cm2px);
  const std::optional<std::int16_t> v = robot_read(cm2px, theta_deg, distance_cm, 1.0);
  if (!v) return std::nullopt;
  return *v / IrisLut::kCm2pxValuePerPx;
}

std::optional<Vec2> iris_robot_point_cm(const IrisLut& px2cm, const Vec2& pixel,
                                        const Vec2& image_center_px) {
  const Polar polar = image_polar_from_pixel(pixel, image_center_px);  // Algorithm 4
  const std::optional<int> d_cm = iris_distance_cm(px2cm, polar.theta_deg, polar.radius);
  if (!d_cm || *d_cm <= 0) return std::nullopt;
  return robot_point_from_bearing(robot_bearing_deg_from_image_theta_deg(polar.theta_deg),
                                  *d_cm);  // Algorithm 6 with the robot at the origin
}

IrisLut build_iris_px2cm(const RadialDistanceCm& distance_cm) {
  IrisLut lut(IrisLutKind::px2cm);
  for (int theta = 0; theta < IrisLut::kDirections; ++theta) {
    for (int bin = 0; bin < lut.bins(); ++bin) {
      const std::optional<double> d =
          distance_cm(theta + 0.5, (bin + 0.5) / IrisLut::kPx2cmBinsPerPx);
      if (!d || !std::isfinite(*d)) continue;
      lut.at(theta, bin) = static_cast<std::int16_t>(
          std::clamp(std::round(*d), 0.0, double{std::numeric_limits<std::int16_t>::max()}));
    }
  }
  return lut;
}

GroundMap ground_map_from_iris_px2cm(const IrisLut& px2cm, const GroundMapInfo& info) {
  require(px2cm.kind() == IrisLutKind::px2cm, "iris import", "needs a px2cm table");
  return build_ground_map(
      [&](const Vec2& pixel) { return iris_robot_point_cm(px2cm, pixel, info.image_center_px); },
      info);
}

IrisLut iris_px2cm_from_ground_map(const GroundMap& map) {
  const Vec2 center = map.info().image_center_px;
  return build_iris_px2cm([&](double theta_deg, double radius_px) -> std::optional<double> {
    const std::optional<Vec2> p_cm =
        map.robot_point_cm(pixel_from_image_polar({theta_deg, radius_px}, center));
    if (!p_cm) return std::nullopt;
    return p_cm->norm();
  });
}

}  // namespace ballsight
