#include "ballsight/camera/unified_model.hpp"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ballsight/core/geometry.hpp"

namespace ballsight {
namespace {

class UnifiedModelXi : public ::testing::TestWithParam<double> {};

// Directions over the whole sphere, by polar angle from the axis and azimuth.
std::vector<Vec3> sphere_directions() {
  std::vector<Vec3> out;
  for (double polar = 0.0; polar < std::numbers::pi; polar += 0.05)
    for (double azimuth = 0.0; azimuth < 2.0 * std::numbers::pi; azimuth += 0.3)
      out.emplace_back(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                       std::cos(polar));
  return out;
}

// Project then lift: the unit ray of the point, wherever the model has a unique projection; and
// where it has none, the point lies behind the shifted pinhole or beyond the fold.
TEST_P(UnifiedModelXi, ProjectThenLiftIsThePointsRay) {
  const UnifiedModel<double> model{GetParam()};
  int projected = 0;
  for (const Vec3& s : sphere_directions()) {
    const Vec3 p = 2.7 * s;
    Vec2 m;
    if (!model.project(p.data(), m.data())) {
      EXPECT_TRUE(s.z() + model.xi <= 1e-9 || (model.xi > 1.0 && s.z() <= -1.0 / model.xi + 1e-12))
          << "refused a point it images: " << s.transpose();
      continue;
    }
    ++projected;
    Vec3 ray;
    ASSERT_TRUE(model.lift(m.x(), m.y(), ray.data())) << s.transpose();
    EXPECT_NEAR((ray - s).norm(), 0.0, 1e-9) << s.transpose();
  }
  EXPECT_GT(projected, 500);
}

// Past the border of the model's image (1 + (1 - xi^2) |m|^2 <= 0, only for xi > 1) no point
// lifts; just inside it one does.
TEST_P(UnifiedModelXi, LiftIsValidUpToTheBorderOfTheImage) {
  const UnifiedModel<double> model{GetParam()};
  Vec3 ray;
  if (model.xi <= 1.0) {
    EXPECT_TRUE(model.lift(1e3, -1e3, ray.data()));  // no border: every point lifts
    return;
  }
  const double border = 1.0 / std::sqrt(model.xi * model.xi - 1.0);
  EXPECT_TRUE(model.lift(0.999 * border, 0.0, ray.data()));
  EXPECT_FALSE(model.lift(1.001 * border, 0.0, ray.data()));
  EXPECT_FALSE(model.lift(0.0, -1.001 * border, ray.data()));
}

// The projection's Jacobian by the point, as Ceres' autodiff takes it through the template,
// against central differences.
TEST_P(UnifiedModelXi, ProjectionJacobianMatchesNumericDifferences) {
  using Jet = ceres::Jet<double, 3>;
  const double xi = GetParam();
  const UnifiedModel<Jet> jet_model{Jet(xi)};
  const UnifiedModel<double> model{xi};
  for (const Vec3& p : {Vec3(0.3, -0.2, 1.0), Vec3(1.5, 0.4, 0.2), Vec3(-0.7, 0.9, 0.1)}) {
    const Jet x[3] = {Jet(p.x(), 0), Jet(p.y(), 1), Jet(p.z(), 2)};
    Jet m[2];
    ASSERT_TRUE(jet_model.project(x, m)) << p.transpose();
    for (int axis = 0; axis < 3; ++axis) {
      constexpr double h = 1e-6;
      Vec3 plus = p, minus = p;
      plus(axis) += h;
      minus(axis) -= h;
      Vec2 m_plus, m_minus;
      ASSERT_TRUE(model.project(plus.data(), m_plus.data()));
      ASSERT_TRUE(model.project(minus.data(), m_minus.data()));
      const Vec2 numeric = (m_plus - m_minus) / (2.0 * h);
      EXPECT_NEAR(m[0].v(axis), numeric.x(), 1e-7) << "d mx / d p" << axis;
      EXPECT_NEAR(m[1].v(axis), numeric.y(), 1e-7) << "d my / d p" << axis;
    }
  }
}

// The same by xi, which the omni calibration fits: lift's ray and project's image point.
TEST_P(UnifiedModelXi, JacobianByXiMatchesNumericDifferences) {
  using Jet = ceres::Jet<double, 1>;
  const double xi = GetParam();
  const UnifiedModel<Jet> jet_model{Jet(xi, 0)};
  constexpr double h = 1e-6;
  const UnifiedModel<double> plus{xi + h}, minus{xi - h};
  const Vec3 p(0.4, -0.3, 0.8);
  const Jet point[3] = {Jet(p.x()), Jet(p.y()), Jet(p.z())};
  Jet m[2];
  ASSERT_TRUE(jet_model.project(point, m));
  Vec2 m_plus, m_minus;
  ASSERT_TRUE(plus.project(p.data(), m_plus.data()));
  ASSERT_TRUE(minus.project(p.data(), m_minus.data()));
  const Vec2 numeric_m = (m_plus - m_minus) / (2.0 * h);
  EXPECT_NEAR(m[0].v(0), numeric_m.x(), 1e-7);
  EXPECT_NEAR(m[1].v(0), numeric_m.y(), 1e-7);
  Jet ray[3];
  ASSERT_TRUE(jet_model.lift(Jet(0.5), Jet(-0.2), ray));
  Vec3 ray_plus, ray_minus;
  ASSERT_TRUE(plus.lift(0.5, -0.2, ray_plus.data()));
  ASSERT_TRUE(minus.lift(0.5, -0.2, ray_minus.data()));
  const Vec3 numeric_ray = (ray_plus - ray_minus) / (2.0 * h);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(ray[k].v(0), numeric_ray(k), 1e-7) << "ray " << k;
}

INSTANTIATE_TEST_SUITE_P(Xi, UnifiedModelXi, ::testing::Values(0.0, 0.5, 0.9, 1.0, 1.3));

}  // namespace
}  // namespace ballsight
