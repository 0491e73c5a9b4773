// Pixel -> robot-local ground point conversions of the omnidirectional camera: the paper's
// lookup table read exactly as its robots do, the paper's polynomial (Algorithm 1), ballsight's
// GroundMap (one read per pixel, and bilinear for sub-pixel queries). Items processed =
// conversions; the pixels are random inside the tables' valid range and precomputed outside the
// timed loop.
//
// Each benchmark is one function: fetch the shared tables, then run_conversions() with a lambda
// converting one pixel.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include "ballsight/calib/polynomial_model.hpp"
#include "ballsight/calib/simulated_calibration.hpp"
#include "ballsight/camera/ground_map.hpp"
#include "ballsight/camera/iris_lut.hpp"
#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/camera/rig_ground_map.hpp"
#include "ballsight/core/conventions.hpp"

namespace ballsight {
namespace {

constexpr int kPixels = 1 << 16;
constexpr unsigned kSeed = 20240611;

struct IntPixel {
  int x, y;
};

// Tables of the true mapping of a rig with the paper's misalignments (2 deg tilt, 5 px offset),
// and the random query pixels.
struct ConversionSetup {
  GroundMap map;
  IrisLut paper_lut;
  std::vector<Vec2> subpixels;
  std::vector<IntPixel> pixels;
};

OmniRigParams misaligned_rig() {
  OmniRigParams params;
  params.tilt_deg = 2.0;
  params.tilt_azimuth_deg = 30.0;
  params.center_offset_px = {3.0, 4.0};
  return params;
}

ConversionSetup make_setup() {
  const OmniRig rig(misaligned_rig());
  GroundMapInfo info;
  info.min_radius_px = 30.0;
  info.max_radius_px = 200.0;
  info.method = "omni-rig-truth";
  GroundMap map = ground_map_from_rig(rig, info);
  IrisLut paper_lut = iris_px2cm_from_ground_map(map);
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> theta(0.0, 360.0);
  std::uniform_real_distribution<double> radius(info.min_radius_px + 1.0, info.max_radius_px - 1.0);
  std::vector<Vec2> subpixels;
  std::vector<IntPixel> pixels;
  for (int i = 0; i < kPixels; ++i) {
    const Vec2 p = pixel_from_image_polar({theta(rng), radius(rng)}, info.image_center_px);
    subpixels.push_back(p);
    pixels.push_back({static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y()))});
  }
  return {std::move(map), std::move(paper_lut), std::move(subpixels), std::move(pixels)};
}

// Built once for the whole program: Google Benchmark calls each benchmark several times.
const ConversionSetup& setup() {
  static const ConversionSetup instance = make_setup();
  return instance;
}

/// Times `convert` over every pixel of `pixels` per iteration.
template <typename Pixel, typename Convert>
void run_conversions(benchmark::State& state, std::span<const Pixel> pixels, Convert convert) {
  for (auto _ : state) {
    for (const Pixel& p : pixels) benchmark::DoNotOptimize(convert(p));
  }
  const auto conversions = state.iterations() * static_cast<std::int64_t>(pixels.size());
  state.SetItemsProcessed(conversions);
  state.counters["time_per_conversion"] = benchmark::Counter(
      static_cast<double>(conversions), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Algorithms 4-6 of the omnivision paper as the IRIS robots run them (shared/data/README.md):
// atan2 + sqrt, lut[(int)angle * 3200 + (int)(dist * 10)], then cos/sin at angle - 90 deg.
struct RobotPoint {
  double x_cm, y_cm;
};
RobotPoint paper_robot_convert(const std::int16_t* lut, double cx, double cy, const Vec2& pixel) {
  constexpr double kRad2Deg = 180.0 / std::numbers::pi, kDeg2Rad = std::numbers::pi / 180.0;
  const double dx = pixel.x() - cx;
  const double dy = cy - pixel.y();
  double angle = std::atan2(dy, dx) * kRad2Deg;
  if (angle < 0.0) angle += 360.0;
  const double dist = std::sqrt(dx * dx + dy * dy);
  const double r = lut[static_cast<int>(angle) * 3200 + static_cast<int>(dist * 10.0)];
  const double field_theta = (angle - 90.0) * kDeg2Rad;  // robot heading 0
  return {r * std::cos(field_theta), r * std::sin(field_theta)};
}

void BM_ConvertPaperLut(benchmark::State& state) {
  const ConversionSetup& s = setup();
  const std::int16_t* lut = s.paper_lut.values().data();
  const Vec2 c = s.map.info().image_center_px;
  // Not timed: the verbatim robot code agrees with the library's reading of the same table.
  for (const Vec2& p : std::span(s.subpixels).first(1000)) {
    const RobotPoint robot = paper_robot_convert(lut, c.x(), c.y(), p);
    const std::optional<Vec2> library = iris_robot_point_cm(s.paper_lut, p, c);
    if (!library || std::abs(library->x() - robot.x_cm) > 1e-6 ||
        std::abs(library->y() - robot.y_cm) > 1e-6) {
      std::cerr << "paper robot code and iris_robot_point_cm disagree\n";
      std::abort();
    }
  }
  run_conversions(state, std::span<const Vec2>(s.subpixels),
                  [&](const Vec2& p) { return paper_robot_convert(lut, c.x(), c.y(), p); });
}
BENCHMARK(BM_ConvertPaperLut);

void BM_ConvertBallsightLut(benchmark::State& state) {
  const ConversionSetup& s = setup();
  run_conversions(state, std::span<const IntPixel>(s.pixels),
                  [&](const IntPixel& p) { return s.map.at(p.x, p.y); });
}
BENCHMARK(BM_ConvertBallsightLut);

void BM_ConvertBallsightLutBilinear(benchmark::State& state) {
  const ConversionSetup& s = setup();
  run_conversions(state, std::span<const Vec2>(s.subpixels),
                  [&](const Vec2& p) { return s.map.robot_point_cm(p); });
}
BENCHMARK(BM_ConvertBallsightLutBilinear);

// The paper's polynomial (degree 6) fitted to a simulated marker calibration of the same rig.
const PolynomialGroundModel& paper_polynomial() {
  static const PolynomialGroundModel model = fit_polynomial_model(
      simulate_calibration(OmniRig(misaligned_rig()), SimulatedCalibrationOptions{}).samples, {});
  return model;
}

// Algorithm 1 as written: atan2, sqrt, the polynomial, then cos/sin of the bearing.
RobotPoint polynomial_convert_with_trig(const PolynomialGroundModel& model, const Vec2& pixel) {
  constexpr double kDeg2Rad = std::numbers::pi / 180.0;
  const Vec2 c = model.domain().image.center_px;
  const double dx = pixel.x() - c.x();
  const double dy = c.y() - pixel.y();
  const double theta = std::atan2(dy, dx);
  const double d = model.polynomial()(std::sqrt(dx * dx + dy * dy));
  const double bearing = theta - 90.0 * kDeg2Rad;
  return {d * std::cos(bearing), d * std::sin(bearing)};
}

// The baseline as the paper's robots run it (Algorithm 1).
void BM_ConvertPolynomial(benchmark::State& state) {
  const PolynomialGroundModel& model = paper_polynomial();
  run_conversions(state, std::span<const Vec2>(setup().subpixels),
                  [&](const Vec2& p) { return polynomial_convert_with_trig(model, p); });
}
BENCHMARK(BM_ConvertPolynomial);

// PolynomialGroundModel::convert: the same without trigonometry (cos/sin of the bearing are
// (dy, -dx) / r), a faster baseline than the paper's, measured beside it.
void BM_ConvertPolynomialNoTrig(benchmark::State& state) {
  const PolynomialGroundModel& model = paper_polynomial();
  run_conversions(state, std::span<const Vec2>(setup().subpixels),
                  [&](const Vec2& p) { return model.convert(p); });
}
BENCHMARK(BM_ConvertPolynomialNoTrig);

}  // namespace
}  // namespace ballsight

BENCHMARK_MAIN();
