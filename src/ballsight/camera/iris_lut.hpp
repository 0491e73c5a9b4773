#pragma once
// The omnivision paper team's raw lookup tables (IRIS robots; format in shared/data/README.md):
// headerless little-endian int16 arrays of 360 directions (1 deg bins of the image angle) x
// radial bins, laid out as Eq. 7-8 of the paper (index = theta * r_max + r).
//   px2cm: 360 x 3200, bin floor(radius_px * 10), value ground distance in cm.
//   cm2px: 360 x 1200, bin floor(distance_cm), value pixel radius x 10.
// An entry <= 0 was never written by the generator.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ballsight/camera/ground_map.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

enum class IrisLutKind { px2cm, cm2px };

std::string_view to_string(IrisLutKind kind);

class IrisLut {
 public:
  static constexpr int kDirections = 360;
  static constexpr int kPx2cmBins = 3200;  // 0.1 px bins, radius 0 .. 319.9 px
  static constexpr int kCm2pxBins = 1200;  // 1 cm bins, distance 0 .. 1199 cm
  static constexpr double kPx2cmBinsPerPx = 10.0;
  static constexpr double kCm2pxValuePerPx = 10.0;

  /// All entries zero (unwritten).
  explicit IrisLut(IrisLutKind kind);
  /// Throws InputError when `values` is not directions x bins long.
  IrisLut(IrisLutKind kind, std::vector<std::int16_t> values);

  static int bins_for(IrisLutKind kind) {
    return kind == IrisLutKind::px2cm ? kPx2cmBins : kCm2pxBins;
  }

  IrisLutKind kind() const { return kind_; }
  int bins() const { return bins_for(kind_); }
  std::span<const std::int16_t> values() const { return values_; }
  /// The bins of one direction, theta_deg in [0, 360).
  std::span<const std::int16_t> direction(int theta_deg) const;
  std::int16_t& at(int theta_deg, int bin);
  std::int16_t at(int theta_deg, int bin) const;

 private:
  std::size_t index(int theta_deg, int bin) const;
  IrisLutKind kind_;
  std::vector<std::int16_t> values_;
};

/// Reads a raw table; throws InputError naming the file when it is missing or not exactly
/// 360 x bins int16 long.
IrisLut read_iris_lut(const std::filesystem::path& path, IrisLutKind kind);
/// The same from the file's bytes, `where` naming them in errors.
IrisLut parse_iris_lut(std::string_view bytes, const std::string& where, IrisLutKind kind);
/// The raw little-endian table's bytes.
std::string iris_lut_bytes(const IrisLut& lut);
/// Writes the raw little-endian table atomically.
void write_iris_lut(const std::filesystem::path& path, const IrisLut& lut);

/// Algorithm 5 of the omnivision paper as the robots read it:
/// lut[(int)theta_deg * 3200 + (int)(radius_px * 10)], the raw value in cm; nullopt outside the
/// table (theta not in [0, 360) or radius not in [0, 320)), which the robots do not check.
std::optional<int> iris_distance_cm(const IrisLut& px2cm, double theta_deg, double radius_px);
/// The inverse table: lut[(int)theta_deg * 1200 + (int)distance_cm] / 10, in px.
std::optional<double> iris_radius_px(const IrisLut& cm2px, double theta_deg, double distance_cm);

/// Algorithms 4-6 of the omnivision paper with the robot at the origin: the pixel's image polar
/// coordinates around `image_center_px`, the px2cm read, and the point at that distance along
/// bearing theta - 90 deg, in robot-local cm; nullopt outside the table or on an unwritten entry.
std::optional<Vec2> iris_robot_point_cm(const IrisLut& px2cm, const Vec2& pixel,
                                        const Vec2& image_center_px);

/// Ground distance along a ray: (image theta in deg, pixel radius) -> cm; nullopt where unknown.
using RadialDistanceCm = std::function<std::optional<double>(double theta_deg, double radius_px)>;

/// Eq. 7-8 of the omnivision paper: a 360 x 3200 px2cm table from any radial mapping. Each bin
/// holds the rounded distance at its centre (theta + 0.5 deg, (bin + 0.5) / 10 px), so the
/// robots' floor() read errs by at most half a bin; unknown distances are written as 0.
IrisLut build_iris_px2cm(const RadialDistanceCm& distance_cm);

/// A ballsight table that converts as the robots do with `px2cm` (iris_robot_point_cm at every
/// pixel) over the image, centre and valid range of `info`.
GroundMap ground_map_from_iris_px2cm(const IrisLut& px2cm, const GroundMapInfo& info);
/// The px2cm table of a ballsight table: the distance of its (interpolated) ground point at each
/// bin centre around the table's image centre. The bearing is implied by the layout (image angle
/// - 90 deg), so a table's deviation from radial bearings is lost.
IrisLut iris_px2cm_from_ground_map(const GroundMap& map);

}  // namespace ballsight
