// SingleShootingExponent against its closed form on uniform rods, and the pieces it suggests.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cosserat/rod/cross_section.hpp"
#include "cosserat/rod/material.hpp"
#include "cosserat/strong/shooting_exponent.hpp"

namespace cosserat {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The peer rod: steel, r = 1 mm, L = 0.5 m. λL = L (c0² ρA / EI)^{1/4}, c0 = 1.5/dt,
// written out from the material and radius (not from the section code): 8.66 at dt = 2 ms and
// 24.5 at 0.25 ms, the values docs/dynamics.md quotes (λL ≈ 9 and ≈ 24).
TEST(ShootingExponent, UniformCircleMatchesTheClosedForm) {
  const double E = 200e9, rho = 8000, r = 1e-3, L = 0.5;
  const RodModel rod = RodModel::Uniform(L, CrossSection::Circle(r),
                                         Material::FromShearModulus(E, 80e9, rho));
  for (double dt : {2e-3, 5e-4, 2.5e-4}) {
    const double c0 = 1.5 / dt;
    const double rho_a = rho * kPi * r * r, ei = E * kPi * r * r * r * r / 4;
    const double exact = L * std::pow(c0 * c0 * rho_a / ei, 0.25);
    // A uniform integrand: the midpoint rule is exact up to round-off.
    EXPECT_NEAR(SingleShootingExponent(rod, dt), exact, 1e-12 * exact) << "dt = " << dt;
  }
  EXPECT_NEAR(SingleShootingExponent(rod, 2e-3), 8.660, 5e-4);
  EXPECT_NEAR(SingleShootingExponent(rod, 2.5e-4), 24.49, 5e-3);
}

// A flat strip bends most easily about its thin axis: the exponent uses the smaller EI.
TEST(ShootingExponent, UsesTheSofterBendingAxis) {
  const double E = 200e9, rho = 8000, w = 0.01, t = 0.001, L = 0.3, dt = 1e-3;
  const RodModel rod = RodModel::Uniform(L, CrossSection::Rectangle(w, t),
                                         Material::FromShearModulus(E, 80e9, rho));
  const double ei_min = E * w * t * t * t / 12, c0 = 1.5 / dt;
  const double exact = L * std::pow(c0 * c0 * rho * w * t / ei_min, 0.25);
  EXPECT_NEAR(SingleShootingExponent(rod, dt), exact, 1e-12 * exact);
}

// Under a uniform tension T the shot grows like e^{μL}, μ² = (T + √(T² + 4 EI c0² ρA)) / (2 EI):
// λ without tension, √(T/EI) in statics (dt = ∞), and more than either with both. Compression
// counts as none (it does not make the shot grow faster).
TEST(ShootingExponent, TensionRaisesItToTheTautBeamsRoot) {
  const double E = 200e9, rho = 8000, r = 1e-3, L = 1.0, T = 98.1;
  const RodModel rod = RodModel::Uniform(L, CrossSection::Circle(r),
                                         Material::FromShearModulus(E, 80e9, rho));
  const double rho_a = rho * kPi * r * r, ei = E * kPi * r * r * r * r / 4;
  RodState taut;
  taut.Resize(5);
  for (int i = 0; i < 5; ++i) {
    taut.s[i] = 0.25 * i;
    taut.wrench_B[i] << 0, 0, 0, 0, 0, T;
  }
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_NEAR(SingleShootingExponent(rod, inf, {}, taut), std::sqrt(T / ei) * L, 1e-12 * 25);
  const double dt = 5e-3, c0 = 1.5 / dt;
  const double mu = std::sqrt((T + std::sqrt(T * T + 4 * ei * c0 * c0 * rho_a)) / (2 * ei));
  EXPECT_NEAR(SingleShootingExponent(rod, dt, {}, taut), mu * L, 1e-12 * 25);
  for (Vec6& w : taut.wrench_B) w(5) = -T;
  EXPECT_NEAR(SingleShootingExponent(rod, dt, {}, taut), SingleShootingExponent(rod, dt),
              1e-12 * 25);
}

TEST(ShootingExponent, SuggestsPiecesOfAboutFive) {
  EXPECT_EQ(SuggestedShootingSegments(0.5), 1);
  EXPECT_EQ(SuggestedShootingSegments(8.66), 2);
  EXPECT_EQ(SuggestedShootingSegments(17.3), 4);
  EXPECT_EQ(SuggestedShootingSegments(24.5), 5);
}

}  // namespace
}  // namespace cosserat
