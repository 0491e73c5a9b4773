// Calibration from one spin on ring images the simulator draws with their truth
// (sim/omni_ring_image.hpp): thick near lines, several line widths, a tilted camera off the
// image centre, struts, a textured carpet, another mirror. In every direction where a ring's line
// is in view and no strut covers it, the search finds it in at least 90 % of the directions, a
// median error under 1 px (issue 44's target against the team's own detector), and never the
// next ring's line in its place.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "ballsight/camera/mirror_tracer.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/detect/omni_rings.hpp"
#include "ballsight/sim/omni_ring_image.hpp"

namespace ballsight {
namespace {

struct RingFigures {
  double found = 0.0;         // of the directions where the ring is in view, unhidden
  double median_error = 0.0;  // px
  double max_error = 0.0;     // px
};

struct Case {
  std::string name;
  sim::RingImageSpec spec;
};

std::vector<RingFigures> measure(const Case& c, const RingSearch& search,
                                 const sim::RingImage& image) {
  std::vector<RingFigures> figures;
  for (std::size_t k = 0; k < c.spec.distances_m.size(); ++k) {
    std::size_t in_view = 0;
    std::vector<double> errors;
    for (const RingDirection& d : search.directions) {
      const std::optional<double> truth = image.true_radius_px(d.theta_deg, k);
      if (!truth || image.strut_hides(d.theta_deg, *truth)) continue;
      ++in_view;
      if (d.radius_px[k]) errors.push_back(std::abs(*d.radius_px[k] - *truth));
    }
    std::sort(errors.begin(), errors.end());
    RingFigures f;
    f.found = in_view ? static_cast<double>(errors.size()) / static_cast<double>(in_view) : 0.0;
    if (!errors.empty()) {
      f.median_error = errors[errors.size() / 2];
      f.max_error = errors.back();
    }
    figures.push_back(f);
  }
  return figures;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  sim::RingImageSpec base;
  base.rig.width = 480;
  base.rig.height = 480;
  out.push_back({"plain", base});
  sim::RingImageSpec thick = base;
  thick.distances_m = {0.5, 1.0, 1.5, 2.0, 3.0};
  thick.line_widths_m = {0.12};
  out.push_back({"thick near lines", thick});
  sim::RingImageSpec widths = base;
  widths.line_widths_m = {0.12, 0.10, 0.08, 0.05, 0.03};
  out.push_back({"several widths", widths});
  sim::RingImageSpec tilted = base;
  tilted.rig.tilt_deg = 2.0;
  tilted.rig.tilt_azimuth_deg = 30.0;
  tilted.rig.center_offset_px = Vec2(4.0, -3.0);
  out.push_back({"tilted, off centre", tilted});
  sim::RingImageSpec struts = base;
  struts.strut_deg = {30.0, 150.0, 270.0};
  struts.strut_width_px = 8.0;
  out.push_back({"struts", struts});
  sim::RingImageSpec carpet = base;
  carpet.carpet_texture = 25.0;
  carpet.noise_sigma = 5.0;
  out.push_back({"textured carpet", carpet});
  sim::RingImageSpec sphere = base;
  sphere.rig = with_mirror(base.rig, MirrorKind::kSphere);
  out.push_back({"spherical mirror", sphere});
  sim::RingImageSpec all = thick;
  all.line_widths_m = {0.12, 0.10, 0.08, 0.05, 0.05};
  all.rig.tilt_deg = 2.0;
  all.rig.tilt_azimuth_deg = 200.0;
  all.rig.center_offset_px = Vec2(-5.0, 2.0);
  all.strut_deg = {90.0, 210.0, 330.0};
  all.carpet_texture = 20.0;
  all.seed = 7;
  out.push_back({"all of these", all});
  return out;
}

TEST(OmniRingImages, EveryRingFoundInNineTenthsOfItsDirectionsWithinAPixel) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const sim::RingImage image(c.spec);
    RingSearchOptions options;
    options.distances_m = c.spec.distances_m;
    const RingSearch search = find_omni_rings(image.grey(), image.center(), options);
    const std::vector<RingFigures> figures = measure(c, search, image);
    std::cout << c.name << ":";
    for (std::size_t k = 0; k < figures.size(); ++k) {
      const RingFigures& f = figures[k];
      std::cout << " ring " << k + 1 << " " << std::lround(100.0 * f.found) << " % "
                << f.median_error << " / " << f.max_error << " px;";
      EXPECT_GE(f.found, 0.9) << "ring " << k + 1;
      EXPECT_LE(f.median_error, 1.0) << "ring " << k + 1;
      // Never the next ring's line in its place (the rings lie farther apart than this).
      EXPECT_LT(f.max_error, options.tolerance_px) << "ring " << k + 1;
    }
    std::cout << "\n";
  }
}

// One strut at 0 deg: its span runs across the first and the last direction.
TEST(OmniRingImages, TheStrutsAreReportedAsBlockedSpans) {
  sim::RingImageSpec spec = cases()[4].spec;  // the struts
  spec.strut_deg = {0.0, 120.0, 240.0};
  const sim::RingImage image(spec);
  RingSearchOptions options;
  options.distances_m = spec.distances_m;
  options.directions = 360;
  const RingSearch search = find_omni_rings(image.grey(), image.center(), options);
  ASSERT_EQ(search.blocked.size(), spec.strut_deg.size());
  for (std::size_t i = 0; i < spec.strut_deg.size(); ++i) {
    const BlockedSpan& span = search.blocked[i];
    const double middle =
        span.from_deg + 0.5 * std::fmod(span.to_deg - span.from_deg + 360.0, 360.0);
    EXPECT_NEAR(wrap_deg_180(middle - spec.strut_deg[i]), 0.0, 1.5)
        << span.from_deg << " " << span.to_deg;
  }
}

// A near line 30 cm wide on the floor (27 px in the image) is one ring, and the next distance's
// ring is the next line, not its far edge (a top-hat narrower than the line sees only its edges).
TEST(OmniRingImages, AWideLineIsOneRing) {
  sim::RingImageSpec spec;
  spec.rig.width = 480;
  spec.rig.height = 480;
  spec.distances_m = {0.7, 1.5, 2.0};
  spec.line_widths_m = {0.3, 0.05, 0.05};
  const sim::RingImage image(spec);
  RingSearchOptions options;
  options.distances_m = spec.distances_m;
  const RingSearch search = find_omni_rings(image.grey(), image.center(), options);
  const std::vector<RingFigures> figures = measure({"wide", spec}, search, image);
  for (std::size_t k = 0; k < figures.size(); ++k) {
    EXPECT_GE(figures[k].found, 0.9) << "ring " << k + 1;
    EXPECT_LE(figures[k].median_error, 1.0) << "ring " << k + 1;
  }
}

}  // namespace
}  // namespace ballsight
