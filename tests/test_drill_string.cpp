// The drill string's torsion: a string clamped at the rotary table with a bottom-hole assembly
// (a rigid body of rotary inertia J_BHA) at its lower end twists and is let go; its first
// torsional frequency satisfies (ωL/c) tan(ωL/c) = J_string / J_BHA (SE(3) BDF2 stepper with a
// tip body). Driven by the table at a constant speed against the bit's velocity-weakening
// friction, it sticks and slips as the one-degree-of-freedom torsional pendulum does when the
// string is light beside the BHA. Lying in a horizontal bore, a string's end rests on the bore's
// wall with the reaction beam theory gives for the gap, in both formulations. A kilometre hanging
// in tension runs with the automatic pieces and hangs its whole weight on the table.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <vector>

#include "cosserat/io/problem.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/loads/bit_friction.hpp"
#include "cosserat/quatfd/quatfd_statics.hpp"
#include "cosserat/robots/rotary_table_drive.hpp"
#include "cosserat/run/run.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "support/analytic/torsion.hpp"
#include "support/source_json.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

// A 50 m steel string: the torsion constant of a 5" drill pipe (OD 127 mm, ID 108 mm), its polar
// moment taken for the rotary inertia, and a bending stiffness 1600 times the pipe's, which
// keeps BDF2's bending exponent (c0² ρA/EI)^¼ L near 20 (four shooting pieces) without touching
// the torsion, which does not couple to bending in a straight string. The first period is
// measured between zero crossings of the BHA's twist over four periods, dt = T/200 (BDF2's
// period error (ω dt)²/3 ≈ 3e-4); the spatial error of RK4 on 41 nodes is below 1e-6. Within
// 0.5 % (the acceptance) for J_string/J_BHA = 0.2 and 2.
double MeasuredOverPredicted(double ratio) {
  const double L = 50.0, rho = 7850.0, G = 80e9, E = 200e9;
  const double D = 0.127, d = 0.108;
  const double J = M_PI / 32 * (std::pow(D, 4) - std::pow(d, 4));  // polar moment, m⁴
  const double A = M_PI / 4 * (D * D - d * d);
  const double I = 1600 * J / 2;  // bending, per axis; I_p = 2I stands for the rotary inertia
  Material m = Material::FromShearModulus(E, G, rho);
  // Torsion constant J (stiffness GJ); polar moment 2I = 1600 J. The wave speed uses the polar
  // moment the model's rotary inertia uses.
  const RodModel rod = RodModel::Uniform(L, CrossSection::Explicit(A, I, I, J), m);
  const double Ip = 2 * I;
  const double c = std::sqrt(G * J / (rho * Ip));
  const double J_string = rho * Ip * L;
  const double J_bha = J_string / ratio;
  const double omega = truth::ShaftWithDiscFirstOmega(ratio, c, L);
  Bdf2Options opt;
  opt.dt = 2 * M_PI / omega / 200;
  opt.tip_mass = 1000.0;
  opt.tip_inertia_B = Vec3(J_bha, J_bha, J_bha);
  Bdf2ShootingStepper stepper(rod, 41, opt);
  StepInput in;  // clamped at the origin along +z (the string hangs along it; no gravity)
  in.loads.tip_moment = Vec3(0, 0, 1e-4 * G * J / L);  // a twist of ~1e-4 rad at the BHA
  EXPECT_TRUE(stepper.InitializeAtRest(in).converged());
  in.loads.tip_moment.setZero();
  auto twist = [&] {
    const Mat3& R = stepper.state().rotation_WB.back();
    return std::atan2(R(1, 0), R(0, 0));
  };
  std::vector<double> crossings;
  double prev = twist();
  int pieces = 1;
  for (int i = 0; i < 2000 && crossings.size() < 5; ++i) {
    const StepSummary s = stepper.Step(in);
    EXPECT_TRUE(s.converged()) << "step " << i;
    pieces = std::max(pieces, s.shooting_segments);
    const double now = twist();
    if (prev < 0 && now >= 0) crossings.push_back(stepper.time() - opt.dt * now / (now - prev));
    prev = now;
  }
  EXPECT_EQ(crossings.size(), 5u);
  const double period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  std::printf("J_string/J_BHA = %.2f: measured %.6f rad/s, (wL/c) tan(wL/c) = ratio gives %.6f "
              "rad/s, %d shooting pieces\n",
              ratio, 2 * M_PI / period, omega, pieces);
  return 2 * M_PI / period / omega;
}

TEST(DrillString, TorsionalFrequencyWithABottomHoleAssembly) {
  for (double ratio : {0.2, 2.0}) EXPECT_NEAR(MeasuredOverPredicted(ratio), 1.0, 5e-3);
}

// The SE(3) modes of a cantilever with a body at its tip (a BHA: dynamics.tip_mass and
// tip_inertia): 20 m of 5 in pipe, no gravity, a 275.3 kg body (half the pipe's mass, μ = 0.5)
// with no inertia across the pipe and J_z = 38.3 kg·m² about it (20 times the pipe's polar
// inertia). Bending: the Euler–Bernoulli cantilever with a tip mass, 1 + cos λ cosh λ +
// μ λ (cos λ sinh λ − sin λ cosh λ) = 0, ω = λ² sqrt(EI/ρA L⁴) (Blevins 1979), in both planes;
// shear and the pipe's rotary inertia lower it by about (1 + E/κG)(λ r_g/L)²/2 (Timoshenko), so
// twice that is the tolerance. Torsion: (ωL/c) tan(ωL/c) = J_pipe/J_z (Timoshenko, Young &
// Weaver 1974), uncoupled from bending in a straight pipe: 1e-9. Without the body the first
// frequency is 1.74 times higher. The quaternion-FD modes, which would leave it out, refuse it.
TEST(DrillString, ModesTakeTheBodyAtTheTip) {
  const char* text = R"({"format": "cosserat-problem/1", "analysis": "modes",
      "rod": {"length": 20, "nodes": 101,
        "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.054},
        "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 7850}},
      "dynamics": {"tip_mass": 275.3, "tip_inertia": [0, 0, 38.3]}, "modes": {"count": 8}})";
  const io::ParseResult parsed = io::ParseProblem(text);
  ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
  const run::Result r = run::Run(*parsed.problem);
  ASSERT_EQ(r.json["status"], "converged") << r.log;
  const double ro = 0.0635, ri = 0.054, L = 20, rho = 7850, E = 200e9, G = 80e9;
  const double A = M_PI * (ro * ro - ri * ri), I = M_PI / 4 * (std::pow(ro, 4) - std::pow(ri, 4));
  const double mu = 275.3 / (rho * A * L), r_g = std::sqrt(I / A);
  auto equation = [mu](double l) {
    return 1 + std::cos(l) * std::cosh(l) +
           mu * l * (std::cos(l) * std::sinh(l) - std::sin(l) * std::cosh(l));
  };
  const auto& f = r.json["modes"]["frequencies_hz"];
  const auto& kinds = r.json["modes"]["kinds"];
  int n = 0;  // bending modes met, two per λ
  double lo = 0.5;
  for (size_t i = 0; i < f.size() && n < 4; ++i) {
    if (kinds[i] != "bending") continue;
    const double lambda = truth::Bisect(equation, lo, lo + 3.0);
    const double omega = lambda * lambda * std::sqrt(E * I / (rho * A * std::pow(L, 4)));
    const double shear = (1 + E / (0.5 * G)) * std::pow(lambda * r_g / L, 2);
    EXPECT_NEAR(2 * M_PI * f[i].get<double>() / omega, 1.0, shear) << i;
    if (++n % 2 == 0) lo = lambda + 0.1;
  }
  EXPECT_EQ(n, 4);
  const double c = std::sqrt(G / rho), ratio = rho * 2 * I * L / 38.3;
  const double torsion = truth::ShaftWithDiscFirstOmega(ratio, c, L);
  bool found = false;
  for (size_t i = 0; i < f.size(); ++i)
    if (kinds[i] == "torsion" && !found) {
      found = true;
      EXPECT_NEAR(2 * M_PI * f[i].get<double>() / torsion, 1.0, 1e-9);
    }
  EXPECT_TRUE(found) << r.log;
  nlohmann::json doc = nlohmann::json::parse(text);
  doc["formulation"] = "quaternion-fd";
  const io::ParseResult fd = io::ParseProblem(doc.dump());
  ASSERT_TRUE(fd.ok());
  const std::vector<std::string> refused = io::UnsupportedFeatures(*fd.problem);
  ASSERT_EQ(refused.size(), 1u);
  EXPECT_EQ(refused[0].rfind("dynamics.tip_mass: the quaternion-FD modes leave a body", 0), 0u);
}

// A rotary table with a motor's inertia J_m instead of a prescribed speed, its motor idle: the
// string, twisted by a moment at the BHA and let go, swings the table and the BHA against each
// other at the free-free torsional frequency of a shaft with a disc at each end (Timoshenko,
// Young & Weaver 1974): (J_m J_b β²/J_s² − 1) tan β = (J_m + J_b) β/J_s, β = ωL/c, here
// J_m = J_b = 2 J_s. The period from the zero crossings of the BHA's turn less the table's over
// four periods, dt = T/200 (BDF2's period error (ω dt)²/3 ≈ 3e-4); within 0.5 %, as for the
// fixed table. A fixed table would swing 32 % slower (1.043 rad/s).
TEST(DrillString, AMotorDrivenTableAndTheBhaSwingAtTheFreeFreeFrequency) {
  const double L = 50.0, rho = 7850.0, G = 80e9, E = 200e9;
  const double D = 0.127, d = 0.108;
  const double J = M_PI / 32 * (std::pow(D, 4) - std::pow(d, 4));
  const double A = M_PI / 4 * (D * D - d * d), I = 1600 * J / 2;
  const RodModel rod = RodModel::Uniform(L, CrossSection::Explicit(A, I, I, J),
                                         Material::FromShearModulus(E, G, rho));
  const double J_s = rho * 2 * I * L, J_m = 2 * J_s, J_b = 2 * J_s;
  const double c = std::sqrt(G * J / (rho * 2 * I));
  auto f = [&](double b) {
    return (J_m * J_b * b * b / (J_s * J_s) - 1) * std::tan(b) - (J_m + J_b) * b / J_s;
  };
  double lo = 1e-9, hi = 0.5 * M_PI - 1e-9;  // f < 0 near 0, > 0 near π/2
  for (int k = 0; k < 200; ++k) (f(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
  const double omega = 0.5 * (lo + hi) * c / L;
  Bdf2Options opt;
  opt.dt = 2 * M_PI / omega / 200;
  opt.tip_mass = 1000.0;
  opt.tip_inertia_B = Vec3(J_b, J_b, J_b);
  Bdf2ShootingStepper stepper(rod, 41, opt);
  StepInput in;
  in.loads.tip_moment = Vec3(0, 0, 1e-4 * G * J / L);  // a twist of ~1e-4 rad, let go at t = 0
  ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
  in.loads.tip_moment.setZero();
  RotaryTable table;
  table.inertia = J_m;  // the motor idle: no torque
  RotaryTableDrive drive(table, in.base_pose);
  auto relative_turn = [&] {
    const Mat3& R = stepper.state().rotation_WB.back();
    return std::atan2(R(1, 0), R(0, 0)) - drive.angle();
  };
  std::vector<double> crossings;
  double prev = relative_turn();
  for (int i = 0; i < 2000 && crossings.size() < 5; ++i) {
    ASSERT_TRUE(drive.Step(&stepper, &in, opt.dt).converged()) << "step " << i;
    const double now = relative_turn();
    if (prev < 0 && now >= 0) crossings.push_back(stepper.time() - opt.dt * now / (now - prev));
    prev = now;
  }
  ASSERT_EQ(crossings.size(), 5u);
  const double period = (crossings.back() - crossings.front()) / 4;
  std::printf("motor-driven table: %.6f rad/s, the free-free frequency equation %.6f rad/s\n",
              2 * M_PI / period, omega);
  EXPECT_NEAR(2 * M_PI / period / omega, 1.0, 5e-3);
}

// --- Bit friction and stick-slip ----------------------------------------------------------------

// The friction law's derivative against central differences (h = 1e-7 rad/s against the
// regularisation's scale ω_ε = 1e-2: truncation (h/ω_ε)² ≈ 1e-10, round-off 1e-16 T/h ≈ 1e-9 of
// the derivative's scale W R/ω_ε).
TEST(BitFriction, TorqueDerivativeMatchesCentralDifferences) {
  BitFriction bit{5e4, 0.1, 0.8, 0.5, 1.0, 1e-2, 0.0};
  for (double w : {-3.0, -0.5, -0.02, -1e-3, 0.0, 1e-3, 0.02, 0.5, 3.0}) {
    double d;
    bit.Torque(w, &d);
    const double h = 1e-7;
    const double fd = (bit.Torque(w + h) - bit.Torque(w - h)) / (2 * h);
    EXPECT_NEAR(d, fd, 1e-6 * 5e4 * 0.1 / 1e-2) << "spin " << w;
  }
  // Opposes the spin; the static value near rest, the kinetic one fast.
  EXPECT_NEAR(bit.Torque(0.1), -5e3 * (0.5 + 0.3 * std::exp(-0.1)), 5e3 * 1e-2);
  EXPECT_NEAR(bit.Torque(-20.0), 5e3 * 0.5, 5e3 * 1e-6);
}

/// The BHA's spin over time, sampled every dt: from the rod (SE(3) stepper, table turning at
/// `table` rad/s from rest) or from the lumped pendulum J θ̈ = k (Ω t − θ) + T(θ̇) with the
/// string's inertia added as J_string/3 (RK4 at 1e-4 s, well inside its stability bound
/// 2.8 J ω_ε / (W R μ_s) ≈ 3e-3 s).
struct DrillString {
  double L = 100, rho = 7850, G = 80e9, E = 200e9;
  double D = 0.127, d = 0.108;
  double J_bha = 500;  // kg·m²
  // W = 50 kN on a 0.1 m bit, μ 0.8 → 0.5 over ω_s = 1 rad/s, mud damping c = 100 N·m·s: the
  // steady spin is linearly stable above ω_s ln(W R (μ_s − μ_k) / (ω_s c)) ≈ 2.7 rad/s, but a
  // start from rest still falls into stick-slip up to ~4.9 rad/s (the cycle is subcritical).
  BitFriction bit{5e4, 0.1, 0.8, 0.5, 1.0, 1e-2, 100.0};
  double Jp() const { return M_PI / 32 * (std::pow(D, 4) - std::pow(d, 4)); }
  double k() const { return G * Jp() / L; }
  double J_string() const { return rho * Jp() * L; }
};

std::vector<double> RodSpin(const DrillString& s, double table, double duration, double dt) {
  const double A = M_PI / 4 * (s.D * s.D - s.d * s.d);
  const Material m = Material::FromShearModulus(s.E, s.G, s.rho);
  const RodModel rod =
      RodModel::Uniform(s.L, CrossSection::Explicit(A, s.Jp() / 2, s.Jp() / 2, s.Jp()), m);
  Bdf2Options opt;
  opt.dt = dt;
  opt.tip_mass = 100.0;
  opt.tip_inertia_B = Vec3(s.J_bha, s.J_bha, s.J_bha);
  Bdf2ShootingStepper stepper(rod, 41, opt);
  StepInput in;  // hanging along +z from the table, no gravity: torsion alone
  EXPECT_TRUE(stepper.InitializeAtRest(in).converged());
  in.loads.bit = s.bit;
  in.base_twist_B << 0, 0, table, 0, 0, 0;
  std::vector<double> spin;
  const int steps = static_cast<int>(std::round(duration / dt));
  for (int i = 1; i <= steps; ++i) {
    in.base_pose.R = lie::SO3Exp(Vec3(0, 0, table * i * dt));
    const StepSummary r = stepper.Step(in);
    EXPECT_TRUE(r.converged()) << "step " << i;
    if (!r.converged()) break;
    spin.push_back(stepper.state().twist_B.back()(2));
  }
  return spin;
}

std::vector<double> PendulumSpin(const DrillString& s, double table, double duration, double dt) {
  const double J = s.J_bha + s.J_string() / 3, k = s.k(), h = 1e-4;
  const int sub = static_cast<int>(std::round(dt / h));
  double theta = 0, w = 0, t = 0;
  const auto acc = [&](double tt, double th, double ww) {
    return (k * (table * tt - th) + s.bit.Torque(ww)) / J;
  };
  std::vector<double> spin;
  const int steps = static_cast<int>(std::round(duration / dt));
  for (int i = 0; i < steps; ++i) {
    for (int j = 0; j < sub; ++j) {
      const double k1t = w, k1w = acc(t, theta, w);
      const double k2t = w + 0.5 * h * k1w, k2w = acc(t + 0.5 * h, theta + 0.5 * h * k1t, w + 0.5 * h * k1w);
      const double k3t = w + 0.5 * h * k2w, k3w = acc(t + 0.5 * h, theta + 0.5 * h * k2t, w + 0.5 * h * k2w);
      const double k4t = w + h * k3w, k4w = acc(t + h, theta + h * k3t, w + h * k3w);
      theta += h / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
      w += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
      t += h;
    }
    spin.push_back(w);
  }
  return spin;
}

/// The stick-slip cycle of a spin history after `settle` samples: the mean period between
/// upward crossings of the table speed, and the largest spin.
struct Cycle {
  double period = 0, peak = 0;
  int cycles = 0;
};
Cycle Measure(const std::vector<double>& spin, double table, double dt, int settle) {
  std::vector<double> up;
  Cycle c;
  for (size_t i = settle + 1; i < spin.size(); ++i) {
    c.peak = std::max(c.peak, spin[i]);
    if (spin[i - 1] < table && spin[i] >= table)
      up.push_back(dt * (i - 1 + (table - spin[i - 1]) / (spin[i] - spin[i - 1])));
  }
  c.cycles = static_cast<int>(up.size()) - 1;
  if (c.cycles > 0) c.period = (up.back() - up.front()) / c.cycles;
  return c;
}

// J_string / J_BHA = 0.02: the rod and the pendulum stick and slip with the same period and
// peak spin within 5 % (the acceptance). The rod's BDF2 at dt = 5 ms resolves the slip phase
// (ω_n dt ≈ 0.02) to well under that; the lumped inertia J_string/3 is the first term of the
// string's own dynamics, whose rest is O((J_string/J_BHA)²).
TEST(DrillString, StickSlipAsTheTorsionalPendulum) {
  const DrillString s;
  const double table = 1.0, duration = 20.0, dt = 5e-3;
  const Cycle rod = Measure(RodSpin(s, table, duration, dt), table, dt, 1000);
  const Cycle lumped = Measure(PendulumSpin(s, table, duration, dt), table, dt, 1000);
  std::printf("stick-slip at %.2f rad/s: rod period %.4f s, peak %.4f rad/s (%d cycles); "
              "pendulum %.4f s, %.4f rad/s (%d cycles)\n",
              table, rod.period, rod.peak, rod.cycles, lumped.period, lumped.peak, lumped.cycles);
  ASSERT_GE(rod.cycles, 3);
  ASSERT_GE(lumped.cycles, 3);
  EXPECT_NEAR(rod.period, lumped.period, 0.05 * lumped.period);
  EXPECT_NEAR(rod.peak, lumped.peak, 0.05 * lumped.peak);
}

/// Whether the BHA sticks in the settled part of a spin history: its spin falls below a tenth of
/// the table's.
bool Sticks(const std::vector<double>& spin, double table, int settle) {
  for (size_t i = settle; i < spin.size(); ++i)
    if (spin[i] < 0.1 * table) return true;
  return false;
}

// Above a table speed the bit's friction no longer falls fast enough with speed to feed the
// oscillation, and the BHA turns steadily. The pendulum's threshold by bisection (to 1 %), and
// the rod at 10 % either side of it: sticking below, turning steadily above.
TEST(DrillString, StickSlipVanishesAboveATableSpeed) {
  const DrillString s;
  const double duration = 20.0, dt = 5e-3;
  double lo = 1.0, hi = 10.0;  // sticks at lo, not at hi
  ASSERT_TRUE(Sticks(PendulumSpin(s, lo, duration, dt), lo, 2000));
  ASSERT_FALSE(Sticks(PendulumSpin(s, hi, duration, dt), hi, 2000));
  while (hi - lo > 0.01 * lo) {
    const double mid = 0.5 * (lo + hi);
    (Sticks(PendulumSpin(s, mid, duration, dt), mid, 2000) ? lo : hi) = mid;
  }
  const double threshold = 0.5 * (lo + hi);
  const bool below = Sticks(RodSpin(s, 0.9 * threshold, duration, dt), 0.9 * threshold, 2000);
  const bool above = Sticks(RodSpin(s, 1.1 * threshold, duration, dt), 1.1 * threshold, 2000);
  std::printf("stick-slip vanishes above %.3f rad/s (pendulum); the rod sticks at 0.9x: %s, at "
              "1.1x: %s\n",
              threshold, below ? "yes" : "no", above ? "yes" : "no");
  EXPECT_TRUE(below);
  EXPECT_FALSE(above);
}

// --- Contact with the bore ------------------------------------------------------------------

// A horizontal steel string (1 m, r = 5 mm) clamped on the axis of a bore (a cylinder, "inside")
// whose wall lies δ = w0/2 below it, w0 = q L⁴/(8EI) the free sag of its tip under its weight q:
// the tip comes to rest on the wall and nowhere else (the propped cantilever's deflection rises
// to its end: w'(L) > 0 for a prop at w ≤ w0). Beam theory then gives the wall's force on the tip
// from the tip's measured deflection w_L: R = 3 EI (w0 − w_L)/L³, and the clamp carries q L − R.
// The stiff wall (k = 1e8 N/m²) lets the tip in by ~5e-5 m over a patch of a few mm, whose spread
// changes R by O(ℓ/L) ≈ 0.5 %; the geometric nonlinearity is O((w/L)²) ≈ 1e-4. Within 1 %; a wrong
// gap (the outer radius, the side or the axis) moves w_L by millimetres and R by 100 %.
struct BoreRest {
  double R, R_expected, w_tip, gap;
};

BoreRest ExpectedBoreRest(const testing::SteelRod& rod, const RodState& st, double gap) {
  const double q = rod.rhoA() * 9.81, L = rod.length;
  const double w0 = q * std::pow(L, 4) / (8 * rod.EI());
  BoreRest b;
  b.w_tip = -st.tip_position_W().z();
  b.R = q * L - st.BaseReaction_W()(5);  // the wall's share of the weight
  b.R_expected = 3 * rod.EI() * (w0 - b.w_tip) / std::pow(L, 3);
  b.gap = gap;
  return b;
}

struct BoreSetUp {
  testing::SteelRod rod{1.0, 0.005};
  lie::SE3 base;  // on the bore's axis, the tangent along +x
  StaticLoads loads;
  double gap = 0.0;  // m, from the straight rod's underside to the wall
  BoreSetUp() {
    base.R << 0, 0, 1, 0, 1, 0, -1, 0, 0;
    const double q = rod.rhoA() * 9.81;
    gap = 0.5 * q * std::pow(rod.length, 4) / (8 * rod.EI());
    loads.gravity_W = Vec3(0, 0, -9.81);
    loads.contact.count = 1;
    ContactSurface& bore = loads.contact.surface[0];
    bore.shape = ContactSurface::Shape::kCylinder;
    bore.inside = true;
    bore.point_W = Vec3::Zero();
    bore.direction_W = Vec3::UnitX();
    bore.radius = rod.r + gap;
    bore.stiffness = 1e8;
  }
};

void ExpectRestsOnTheWall(const BoreRest& b, const char* formulation) {
  std::printf("%s: tip %.4e m down (gap %.4e m), wall force %.5f N, beam theory %.5f N\n",
              formulation, b.w_tip, b.gap, b.R, b.R_expected);
  EXPECT_GT(b.w_tip, b.gap);         // on the wall
  EXPECT_LT(b.w_tip, 1.05 * b.gap);  // in by less than the stiff wall allows
  EXPECT_NEAR(b.R, b.R_expected, 0.01 * b.R_expected);
}

// A kilometre of 5" drill pipe (OD 127 mm, ID 108 mm) hanging from a rotary table turning at
// 1 rad/s, a 100 kg bottom-hole assembly grinding on the rock. Its weight, 2.7e5 N at the top,
// makes the shot's exponent sqrt(T/EI) L ≈ 470: some 94 automatic pieces. Capped at 32 they
// failed 6.6 s in; with default settings the run now converges, and the table holds the string
// and the assembly's whole weight (the bit friction and the spin act about the axis, and the run
// starts hanging at rest), to the solve tolerance.
TEST(DrillString, AKilometreStringHangingInTensionRunsWithDefaultPieces) {
  const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
    "analysis": "dynamics",
    "rod": {"length": 1000, "nodes": 601,
      "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.054},
      "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 7850}},
    "base": {"position": [0, 0, 0], "rotation": [[1, 0, 0], [0, -1, 0], [0, 0, -1]]},
    "loads": {"gravity": [0, 0, -9.81],
      "bit_friction": {"weight_on_bit": 5e4, "radius": 0.1, "static_coefficient": 0.8,
        "kinetic_coefficient": 0.5, "stribeck_velocity": 1.0, "regularisation": 0.01,
        "viscous": 100}},
    "dynamics": {"dt": 0.05, "duration": 10, "output_interval": 0.5, "tip_mass": 100,
      "tip_inertia": [500, 500, 500], "base_spin": 1.0}})");
  ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
  const run::Result r = run::Run(*parsed.problem);
  ASSERT_TRUE(r.converged) << r.log;
  EXPECT_GT(r.json["shooting_segments"].get<int>(), 32);
  const double area = M_PI * (0.0635 * 0.0635 - 0.054 * 0.054);
  const double weight = (7850 * area * 1000 + 100) * 9.81;  // N
  EXPECT_NEAR(r.json["base_wrench"]["force"][2].get<double>() / weight, 1.0, 1e-8) << r.log;
}

// A 100 m pipe lying on the low side of a bore inclined 60° from the vertical (wall stiffness
// 1e6 N/m per m), on the SE(3) path with default settings, in statics and in dynamics (where it
// starts at rest on the wall and stays there): the clamp carries the weight's component along
// the bore, w L cos 60°, the soft-string hook load, since a frictionless wall pushes across the
// axis only. To 1e-6 of it on 201 nodes: the dynamics' start balances it to 1e-13, and the
// statics in pieces converge to it at about h^3.5 (4.9e-6, 5.1e-7, 3.6e-8 on 51, 101 and 201
// nodes: RK4's error in s; their tolerance does not move it). The
// statics' load steps stop at 0 of the load (each Newton step from the straight pipe sags it
// through the wall), and the rest solve stalls at 1.4e-10 against 1e-10 unless the tolerance
// counts the round-off the wall's stiffness makes of the positions.
TEST(DrillString, APipeLyingInAnInclinedBoreCarriesTheSoftStringHookLoad) {
  const double c = std::cos(M_PI / 3), s = std::sin(M_PI / 3);
  for (const char* analysis : {"statics", "dynamics"}) {
    std::ostringstream text;
    text << std::setprecision(17) << R"({"format": "cosserat-problem/1", "analysis": ")"
         << analysis << R"(",
      "rod": {"length": 100, "nodes": 201,
        "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.0543},
        "material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3, "density": 7850}},
      "base": {"position": [0, 0, 0], "rotation": [[)" << c << ", 0, " << s
         << "], [0, -1, 0], [" << s << ", 0, " << -c << R"(]]},
      "environment": {"contact": [{"shape": "cylinder", "point": [0, 0, 0], "axis": [)" << s
         << ", 0, " << -c << R"(], "radius": 0.108, "side": "inside", "stiffness": 1e6}]},
      "loads": {"gravity": [0, 0, -9.81]},
      "dynamics": {"dt": 0.01, "duration": 0.2, "output_interval": 0.1}})";
    const io::ParseResult parsed = io::ParseProblem(text.str());
    ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
    const run::Result r = run::Run(*parsed.problem);
    ASSERT_TRUE(r.converged) << analysis << ": " << r.log;
    const auto& f = r.json["base_wrench"]["force"];
    const double along = -(f[0].get<double>() * s - f[2].get<double>() * c);  // up the bore, N
    const double w = 7850 * M_PI * (0.0635 * 0.0635 - 0.0543 * 0.0543) * 9.81;  // N/m
    EXPECT_NEAR(along / (w * 100 * c), 1.0, 1e-6) << analysis << ": " << r.log;
  }
}

/// One step of a 100 m string of 5 in pipe hanging from a table spun at 1 rad/s (no fluid), with
/// `weight` N on a 0.1 m bit (μ_s 0.8, μ_k 0.5) and `up` N of tip force up the hole (−z), run as
/// the command runs it: its log is what these tests read.
run::Result OneStepOfAHangingString(double weight, double up) {
  std::ostringstream text;
  text << std::setprecision(17) << R"({"format": "cosserat-problem/1", "analysis": "dynamics",
    "rod": {"length": 100, "nodes": 51,
      "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.0543},
      "material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3, "density": 7850}},
    "base": {"rotation": [[1, 0, 0], [0, -1, 0], [0, 0, -1]]},
    "loads": {"gravity": [0, 0, -9.81], "tip_force": [0, 0, )" << up << R"(],
      "bit_friction": {"weight_on_bit": )" << weight << R"(, "radius": 0.1,
                       "static_coefficient": 0.8, "kinetic_coefficient": 0.5}},
    "dynamics": {"dt": 0.01, "duration": 0.01, "base_spin": 1.0}})";
  const io::ParseResult parsed = io::ParseProblem(text.str());
  EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
  return parsed.ok() ? run::Run(*parsed.problem) : run::Result{};
}

// The weight on bit sets the bit's friction only; the log says so unless the tip force pushes
// the bit up the hole with about that much. A 100 m string hanging from a table (26 kN of
// weight, no fluid) with 5 kN on bit: pushed up by 5 kN, no note; the same force pulling the bit
// down, off the rock, and none at all, the note, which gives the force as it is (it read "0 N up
// the hole" for a pull down it).
TEST(DrillString, TheWeightOnBitNoteFollowsTheTipForcesDirection) {
  for (const double up : {5e3, -5e3, 0.0}) {  // N along −z, up the hole
    const run::Result r = OneStepOfAHangingString(5e3, up);
    EXPECT_EQ(r.log.find("weight_on_bit (5e+03 N) sets the bit's friction torque only") !=
                  std::string::npos,
              up <= 0.0)
        << up << "\n" << r.log;
    if (up < 0.0)
      EXPECT_NE(r.log.find("tip_force (5e+03 N down the hole here, pulling the bit off the rock)"),
                std::string::npos)
          << r.log;
    if (up == 0.0) EXPECT_NE(r.log.find("tip_force (0 N up the hole here)"), std::string::npos);
  }
}

// Pushed up past its buckling load, a hanging string's straight equilibrium is unstable, and a
// run from it keeps it straight: the log warns. The string's free lower end buckles at
// P = 1.0188 (EI w²)^⅓ (Airy's equation of the hanging column; the string, 100 m, is over six
// times its bending length (EI/w)^⅓, so its length does not count): 4.47 kN here. At 0.8 P no
// warning, at 1.25 P one.
TEST(DrillString, ARunFromAStringPushedPastBucklingIsWarned) {
  const double ro = 0.0635, ri = 0.0543;
  const double EI = 207e9 * M_PI / 4 * (std::pow(ro, 4) - std::pow(ri, 4));
  const double w = 7850 * 9.81 * M_PI * (ro * ro - ri * ri);  // N/m
  const double critical = 1.0188 * std::cbrt(EI * w * w);
  for (const double factor : {0.8, 1.25}) {
    const run::Result r = OneStepOfAHangingString(1.0, factor * critical);
    ASSERT_EQ(r.json["status"], "converged") << r.log;
    EXPECT_EQ(r.log.find("warning: the run starts from an unstable equilibrium") !=
                  std::string::npos,
              factor > 1.0)
        << factor << "\n" << r.log;
  }
}

// With a base_spin, the trajectory carries the string's torque on the table. The stick-slip
// example without its bit friction: the table turning at ω from t = 0 winds the string (k = GJ/L)
// against the BHA, a torsional pendulum of J_eff = J_BHA + J_string/3, so the torque is
// −ω sqrt(k J_eff) sin(Ω t), Ω = sqrt(k/J_eff): its peak (2.21 kN·m) a quarter period in. The
// sudden start also sends a torsional wave down the string, of torque ω J sqrt(G ρ) (its
// impedance: 0.31 kN·m), which the peak may carry: that is the tolerance. Given as 0, base_spin
// still reports the table (at rest) and the tip's spin.
TEST(DrillString, ASpinningTableReportsTheStringsTorqueOnIt) {
  nlohmann::json doc = testing::SourceJson("examples/drill_string_stick_slip.json");
  doc["loads"].erase("bit_friction");
  doc["dynamics"]["duration"] = 1.5;
  doc["dynamics"]["output_interval"] = doc["dynamics"]["dt"];
  const io::ParseResult parsed = io::ParseProblem(doc.dump());
  ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
  const run::Result r = run::Run(*parsed.problem);
  ASSERT_TRUE(r.converged) << r.log;
  const double ro = 0.0635, ri = 0.054, J = M_PI / 2 * (std::pow(ro, 4) - std::pow(ri, 4));
  const double G = 80e9, rho = 7850, L = 100, omega = 1.0;
  const double k = G * J / L, j_eff = 500 + rho * J * L / 3;
  const auto& t = r.json["trajectory"]["t"];
  const auto& torque = r.json["trajectory"]["table_torque"];
  const auto& speed = r.json["trajectory"]["table_speed"];
  ASSERT_EQ(torque.size(), t.size());
  size_t peak = 0;
  for (size_t i = 0; i < torque.size(); ++i) {
    EXPECT_EQ(speed[i].get<double>(), omega);
    if (torque[i].get<double>() < torque[peak].get<double>()) peak = i;
  }
  EXPECT_NEAR(-torque[peak].get<double>(), omega * std::sqrt(k * j_eff),
              omega * J * std::sqrt(G * rho));
  EXPECT_NEAR(t[peak].get<double>(), M_PI / 2 * std::sqrt(j_eff / k), 0.05);
  doc["dynamics"]["base_spin"] = 0.0;
  doc["dynamics"]["duration"] = 0.01;
  const run::Result still = run::Run(*io::ParseProblem(doc.dump()).problem);
  EXPECT_TRUE(still.json["trajectory"].contains("tip_spin"));
  EXPECT_TRUE(still.json["trajectory"].contains("table_torque"));
}

// A weight on bit in the wrong units (5e9 N on a 0.1 m bit) would twist a 100 m string of 5 in
// pipe (GJ = 9.5e5 N·m²) through μ_s W R L/GJ = 4.2e4 rad at once: the log says so, whatever
// the run makes of it; 5e3 N (42 rad, a few turns wound up before the bit slips) is not
// questioned.
TEST(DrillString, AWeightOnBitInTheWrongUnitsIsWarned) {
  for (const double weight : {5e9, 5e3}) {  // N
    const run::Result r = OneStepOfAHangingString(weight, 0.0);
    EXPECT_EQ(r.log.find("would twist the string through") != std::string::npos, weight > 1e6)
        << weight << "\n" << r.log;
  }
}

TEST(DrillString, AStringInABoreRestsItsEndOnTheWall) {
  const BoreSetUp set;
  StaticMultipleShootingSolver solver(set.rod.model(), 201);
  ASSERT_TRUE(solver.Solve(set.base, set.loads).converged());
  ExpectRestsOnTheWall(ExpectedBoreRest(set.rod, solver.state(), set.gap), "SE(3)");
}

TEST(DrillString, AQuaternionFdStringInABoreRestsItsEndOnTheWall) {
  const BoreSetUp set;
  quatfd::QuatFdOptions options;
  options.segments = 200;
  quatfd::QuatFdModel model(set.rod.model(), set.base, options);
  Eigen::VectorXd q(model.size()), v(model.size());
  model.set_loads(set.loads);
  model.RestState(q, v);
  ASSERT_TRUE(quatfd::SolveStatics(&model, set.loads, q).converged());
  RodState st;
  model.ToRodState(q, Eigen::VectorXd::Zero(model.size()), &st);
  ExpectRestsOnTheWall(ExpectedBoreRest(set.rod, st, set.gap), "quaternion FD");
}

// The motor-driven table of examples/drill_string_motor.json (J = 2000 kg·m², T0 = 5200 N·m,
// ω0 = 2 rad/s), its first 5 s: the trajectory's table speed and the string's torque on the
// table satisfy the table's equation J ω̇ = T0 (1 − ω/ω0) + m₃(0), integrated over the frames
// (every 50 ms, by the trapezoid rule) to 1e-3 of the largest term over the time (measured
// 4e-4 at 1 s: the rule's error on the stick-slip's torque steps). A torque of the wrong sign or
// frame, or a speed a frame off, breaks it by the whole term.
TEST(DrillString, TheMotorDrivenTablesSpeedAndTorqueKeepItsEquationOfMotion) {
  nlohmann::json problem = testing::SourceJson("examples/drill_string_motor.json");
  problem["dynamics"]["duration"] = 5.0;
  const io::ParseResult parsed = io::ParseProblem(problem.dump());
  ASSERT_TRUE(parsed.ok());
  const run::Result r = run::Run(*parsed.problem);
  ASSERT_TRUE(r.converged) << r.log;
  const auto& tr = r.json["trajectory"];
  const std::vector<double> t = tr["t"], w = tr["table_speed"], T = tr["table_torque"];
  ASSERT_EQ(w.size(), t.size());
  ASSERT_EQ(T.size(), t.size());
  const double J = 2000, T0 = 5200, w0 = 2.0;
  double integral = 0.0, largest = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double rhs = T0 * (1 - w[k] / w0) + T[k];
    largest = std::max(largest, std::abs(rhs));
    if (k > 0) integral += 0.5 * (t[k] - t[k - 1]) * (rhs + T0 * (1 - w[k - 1] / w0) + T[k - 1]);
    if (k % 20 == 0 && k > 0)
      EXPECT_NEAR(J * (w[k] - w[0]), integral, 1e-3 * largest * t[k]) << "t = " << t[k];
  }
}

// The weight on bit that buckles a string hanging in mud from a clamp, its bit pinned on the
// bottom, by an independent model: an inextensible Euler–Bernoulli beam in Hermite cubic
// elements (h = 0.5 m, against a bending length (EI/w)^⅓ of 17 m near the bit) whose tension is
// its buoyed weight below, w (L − s), less P. Its geometric stiffness ∫ T N'ᵀ N' ds is exact by
// 3-point Gauss on the linear T. The load is where K_b + K_g(P) first has a negative eigenvalue,
// counted by the signs of an LDLᵀ factorisation's pivots (Sylvester) and bisected.
double HangingStringCriticalLoad(double L, double EI, double w) {
  const int elements = static_cast<int>(std::lround(2 * L)), dofs = 2 * (elements + 1);
  const double h = L / elements;
  auto matrix = [&](double P) {
    std::vector<Eigen::Triplet<double>> t;
    for (int e = 0; e < elements; ++e) {
      Eigen::Matrix4d k;  // bending: EI ∫ N''ᵀ N'' ds
      k << 12, 6 * h, -12, 6 * h, 6 * h, 4 * h * h, -6 * h, 2 * h * h, -12, -6 * h, 12, -6 * h,
          6 * h, 2 * h * h, -6 * h, 4 * h * h;
      k *= EI / (h * h * h);
      const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, wg[3] = {5 / 9., 8 / 9., 5 / 9.};
      for (int q = 0; q < 3; ++q) {
        const double x = 0.5 * (1 + g[q]);  // in the element, 0..1
        const double s = (e + x) * h;
        Eigen::Vector4d dN;  // d/ds of the Hermite functions
        dN << (-6 * x + 6 * x * x) / h, 1 - 4 * x + 3 * x * x, (6 * x - 6 * x * x) / h,
            -2 * x + 3 * x * x;
        k += 0.5 * h * wg[q] * (w * (L - s) - P) * dN * dN.transpose();
      }
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) t.emplace_back(2 * e + a, 2 * e + b, k(a, b));
    }
    Eigen::SparseMatrix<double> K(dofs, dofs);
    K.setFromTriplets(t.begin(), t.end());
    // Clamped at the top (s = 0: deflection and slope), pinned at the bit (its deflection): kept
    // are the rows and columns 2 … dofs − 3 and dofs − 1.
    std::vector<int> keep;
    for (int i = 2; i < dofs; ++i)
      if (i != dofs - 2) keep.push_back(i);
    Eigen::SparseMatrix<double> R(static_cast<int>(keep.size()), dofs);
    for (size_t i = 0; i < keep.size(); ++i) R.insert(static_cast<int>(i), keep[i]) = 1.0;
    return Eigen::SparseMatrix<double>(R * K * R.transpose());
  };
  auto negative = [&](double P) {
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(matrix(P));
    return (ldlt.vectorD().array() < 0).count();
  };
  double lo = 0.0, hi = 1.0;
  while (negative(hi) == 0) hi *= 2;
  for (int i = 0; i < 50; ++i) (negative(0.5 * (lo + hi)) == 0 ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

// 300 m of 5" pipe (OD 127 mm, ID 108 mm) hanging in 1.2 SG mud, mud inside too, written in a
// y-up world: clamped at the table, its bit pinned on the bottom and pushed up. Its weight puts
// it in a tension whose exponent ∫ sqrt(T/EI) ds is 47, where the Jacobi fields of one shot are
// rounding: the search goes by multiple shooting, and its critical load is the same on 301, 601
// and 1201 nodes and within 1e-4 of the beam's (shear and stretch move it by P/κGA ~ 5e-5;
// measured 2.2e-5). Hanging alone the string is not past critical: in tension everywhere, no
// direction lowers its energy, and the search, on every grid, finds the load on top of it.
TEST(DrillString, AHangingStringBucklesUnderTheBeamsWeightOnBitOnEveryGrid) {
  const double A = M_PI * (0.0635 * 0.0635 - 0.054 * 0.054);
  const double EI = 200e9 * M_PI / 4 * (std::pow(0.0635, 4) - std::pow(0.054, 4));
  const double reference = HangingStringCriticalLoad(300.0, EI, (7850 - 1200) * A * 9.81);
  for (const int nodes : {301, 601, 1201}) {
    const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
        "analysis": "buckling", "boundary": "clamped-pinned",
        "rod": {"length": 300, "nodes": )" + std::to_string(nodes) + R"(,
          "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.054,
                      "contents_density": 1200},
          "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 7850}},
        "base": {"rotation": [[1, 0, 0], [0, 0, -1], [0, 1, 0]]},
        "loads": {"gravity": [0, -9.81, 0]}, "environment": {"fluid": {"density": 1200}},
        "buckling": {"load": "tip_force", "direction": [0, 1, 0], "max": 30000}})");
    ASSERT_TRUE(parsed.ok());
    const run::Result r = run::Run(*parsed.problem);
    ASSERT_EQ(r.json["buckling"]["status"], "found") << nodes << ": " << r.log;
    EXPECT_NEAR(r.json["buckling"]["critical_load"].get<double>() / reference, 1.0, 1e-4)
        << nodes << ": " << r.log;
  }
}

}  // namespace
}  // namespace cosserat
