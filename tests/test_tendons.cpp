// Tendon-driven rods (Rucker & Webster's model as a tendon-augmented constitutive law) against
// the truth: the exact circular arc of a straight tendon, the small-tension twist of a helical
// tendon, and global equilibrium, which tendon tension (an internal load) cannot change.
#include <gtest/gtest.h>

#include <cmath>

#include "cosserat/strong/static_shooting.hpp"

namespace cosserat {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A 0.25 m rod of radius 1 mm with tendons through disks: steel backbone, or, for the arc test,
// with shear and extension made 1e6 times stiffer (the "stiff in shear and extension").
struct TendonRod {
  double L = 0.25, r = 0.001;
  Material material = Material::FromShearModulus(200e9, 80e9, 8000);
  CrossSection section = CrossSection::Circle(r);
  double EI() const { return material.youngs_modulus * section.I1; }
  double GJ() const { return material.shear_modulus * section.torsion_constant; }
  RodModel Model(std::vector<Tendon> tendons, double axial_shear_factor = 1.0) const {
    CrossSection s = section;
    s.area *= axial_shear_factor;
    RodModel m = RodModel::Uniform(L, s, material);
    m.tendons = std::move(tendons);
    return m;
  }
};

Actuation Tensions(std::initializer_list<double> tau) {
  Actuation a;
  int i = 0;
  for (double t : tau) a.tendon_tension[i++] = t;
  return a;
}

TEST(Tendons, StraightTendonBendsTheRodIntoTheArcOfCurvatureTauROverEI) {
  TendonRod rod;
  const double offset = 0.005;  // 5 mm from the axis, along body x
  const RodModel model = rod.Model({{"t0", TendonRoute::Parallel(Vec2(offset, 0))}}, 1e6);
  // A quarter circle: κ L = π/2.
  const double tau = 0.5 * kPi * rod.EI() / (rod.L * offset);
  StaticShootingSolver solver(model, 41, {}, Tensions({tau}));
  const auto summary = solver.Solve(lie::SE3{}, StaticLoads{});
  ASSERT_TRUE(summary.converged()) << ToString(summary.status);
  const double kappa = tau * offset / rod.EI();
  // With Γ = (1 − τ/EA) e3 the centreline is a circle of radius (1 − τ/EA)/κ about (ρ, 0, 0),
  // bent towards the tendon (+x). τ/EA ≈ 1e-9 here.
  const double EA = rod.material.youngs_modulus * rod.section.area * 1e6;
  const double radius = (1 - tau / EA) / kappa;
  const Vec3 centre(radius, 0, 0);
  for (int i = 0; i < solver.state().size(); ++i) {
    // Acceptance 0.1 %. The arc is exact in the model; RK4 at h = L/40 integrates it with a
    // local error ~(κh)^5/120 per step (κh = π/80): ~1e-9 over the rod, so 1e-7 is ample.
    EXPECT_NEAR((solver.state().position_W[i] - centre).norm() / radius, 1.0, 1e-7) << i;
    // The strain is uniform and exact up to the solver tolerance (1e-10 of EI/L).
    EXPECT_NEAR(solver.state().strain[i](1) / kappa, 1.0, 1e-9) << i;
  }
  EXPECT_GT(solver.state().tip_position_W().x(), 0.5 * radius);  // towards the tendon
}

// The twist of the tip about its own axis, from the torsion along the rod (rad).
double TipTwist(const RodState& state) {
  double twist = 0;
  for (int i = 0; i + 1 < state.size(); ++i)
    twist += 0.5 * (state.s[i + 1] - state.s[i]) * (state.strain[i](2) + state.strain[i + 1](2));
  return twist;
}

TEST(Tendons, HelicalTendonTwistsAgainstItsHandednessAndMoreWithTension) {
  // Rucker & Webster: a helical tendon's tangent has a hoop part r' besides e3, so its pull on
  // the guides is a torque −τ r × r'/|q| = −τ ρ² w e3/|q| (w = 2π/pitch): the rod twists opposite
  // to the helix, by θ ≈ −τ ρ² w L /(GJ sqrt(1 + ρ² w²)) for small τ, growing monotonically.
  TendonRod rod;
  const double rho = 0.005, pitch = rod.L / 2;  // two full turns: the bending parts cancel
  const double w = 2 * kPi / pitch;
  for (double sign : {1.0, -1.0}) {
    const RodModel model = rod.Model({{"helix", TendonRoute::Helical(rho, sign * pitch, 0.0)}});
    StaticShootingSolver solver(model, 81);
    double last = 0;
    for (double tau : {0.05, 0.5, 2.0, 5.0}) {
      solver.SetActuation(Tensions({tau}));
      const auto summary = solver.Solve(lie::SE3{}, StaticLoads{});
      ASSERT_TRUE(summary.converged()) << tau;
      const double twist = TipTwist(solver.state());
      EXPECT_LT(sign * twist, 0.0) << "tau " << tau;                // against the helix
      EXPECT_GT(std::abs(twist), std::abs(last)) << "tau " << tau;  // grows with tension
      last = twist;
      if (tau == 0.05) {
        const double linear =
            -sign * tau * rho * rho * w * rod.L / (rod.GJ() * std::sqrt(1 + rho * rho * w * w));
        // Small tension: the linear prediction to O(τ) relative (τ ρ/EI·L ≈ 2e-3 here) plus the
        // trapezoid rule on the node torsion (h = L/80).
        EXPECT_NEAR(twist / linear, 1.0, 1e-2);
      }
    }
  }
}

TEST(Tendons, BaseReactionBalancesTheExternalLoadsWhateverTheTension) {
  TendonRod rod;
  const RodModel model =
      rod.Model({{"a", TendonRoute::Parallel(Vec2(0.004, 0))},
                 {"b", TendonRoute::Converging(Vec2(0, 0.004), Vec2(0, 0.002))}});
  StaticLoads loads;
  loads.gravity_W = Vec3(0, -9.81, 0);
  loads.tip_force = Vec3(0.2, 0, -0.1);
  StaticShootingSolver solver(model, 41);
  const double mass = 8000 * rod.section.area * rod.L;
  const Vec3 external = mass * loads.gravity_W + loads.tip_force;
  for (double tau : {0.0, 1.0, 5.0, 20.0}) {
    solver.SetActuation(Tensions({tau, 0.5 * tau}));
    ASSERT_TRUE(solver.Solve(lie::SE3{}, loads).converged()) << tau;
    const Vec6 reaction = solver.state().BaseReaction_W();
    // The support's force cancels gravity and the tip load; tension is internal. 1e-9 relative:
    // the solver tolerance (1e-10 of EI/L²) and the RK4 error of the body-frame force balance.
    EXPECT_LT((reaction.tail<3>() + external).norm(), 1e-9 * external.norm()) << tau;
  }
}

}  // namespace
}  // namespace cosserat
