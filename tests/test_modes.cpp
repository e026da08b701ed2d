// Natural frequencies and modes against the truth: Euler–Bernoulli cantilever frequencies
// (../shared/reference/natural_frequencies.json), the exact Euler–Bernoulli frequency of a
// cantilever under an axial compressive dead load, torsional and axial fundamentals, exact modal
// damping ratios for stiffness-proportional damping, and the two formulations (quaternion FD
// and SE(3) frequency-domain shooting) against each other about a sagging cantilever.

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "cosserat/analysis/column.hpp"
#include "cosserat/analysis/frequency_shooting.hpp"
#include "cosserat/analysis/modes.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "support/analytic/beam_vibration.hpp"
#include "support/analytic/euler_buckling.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

using truth::kPi;

struct SteelRod : testing::SteelRod {
  SteelRod() : testing::SteelRod{0.5, 0.001} {}  // r/L = 1/500
  /// Euler–Bernoulli cantilever frequency n (0-based), Hz.
  double EulerBernoulliHz(int n) const {
    return truth::EulerBernoulliOmega(truth::CantileverBetaL(n + 1), EI(), rhoA(), length) /
           (2 * kPi);
  }
};

ModalResult QuatFdModes(const RodModel& rod, const lie::SE3& base, const StaticLoads& loads,
                        int segments, int count, bool shapes = true) {
  quatfd::QuatFdOptions opt;
  opt.segments = segments;
  quatfd::QuatFdModel model(rod, base, opt);
  ModalOptions mo;
  mo.count = count;
  mo.shapes = shapes;
  return ComputeModes(&model, loads, mo);
}

ModalResult ShootingModes(const RodModel& rod, const lie::SE3& base, const StaticLoads& loads,
                          int nodes, int count, double omega_min = 0, double omega_max = 0) {
  ShootingModalOptions so;
  so.modal.count = count;
  so.omega_min = omega_min;
  so.omega_max = omega_max;
  return ComputeModesShooting(rod, nodes, base, loads, so);
}

TEST(Modes, StraightCantileverMatchesEulerBernoulliBothFormulations) {
  // Budget for 0.5 %: at r/L = 1/500, shear and rotary inertia lower mode n by ~(β_n r)² ≈
  // 5e-4 (0.05 %) for mode 4 (measured 0.027 %); the quatfd second-order grid error is ≈ (β_n h)²/3
  // (measured at N = 40 in test_quatfd_verification: 0.08 % / 0.4 % for modes 1 / 2), 0.40 % for
  // mode 4 at N = 100; the shooting is RK4 in s (error ~(β h)⁴, < 1e-4 %). Each frequency appears
  // twice (circle).
  SteelRod rod;
  const ModalResult fd = QuatFdModes(rod.model(), lie::SE3(), {}, 100, 8);
  const ModalResult sh = ShootingModes(rod.model(), lie::SE3(), {}, 101, 8);
  ASSERT_TRUE(fd.converged()) << ToString(fd.status);
  ASSERT_TRUE(sh.converged()) << ToString(sh.status);
  EXPECT_TRUE(fd.symmetric);
  ASSERT_EQ(fd.modes.size(), 8u);
  ASSERT_EQ(sh.modes.size(), 8u);
  for (int k = 0; k < 8; ++k) {
    const double eb = rod.EulerBernoulliHz(k / 2);
    std::printf("  mode %d: EB %.4f Hz, quatfd %.5f, shooting %.7f (ratios)\n", k, eb,
                fd.modes[k].frequency_hz / eb, sh.modes[k].frequency_hz / eb);
    EXPECT_NEAR(fd.modes[k].frequency_hz / eb, 1.0, 0.005) << "quatfd mode " << k;
    EXPECT_NEAR(sh.modes[k].frequency_hz / eb, 1.0, 0.005) << "shooting mode " << k;
    // The shooting has no grid error to speak of (RK4, < 1e-7): what is left is the physics
    // Euler–Bernoulli leaves out. Shear and rotary inertia lower mode n by c (β_n r)² with
    // c = (1 + E/κG)/4 ≈ 0.9 for a simply supported beam; assert 0 < 1 − f/f_EB < (β_n r)².
    const double br = truth::CantileverBetaL(k / 2 + 1) * rod.r / rod.length;
    EXPECT_GT(1 - sh.modes[k].frequency_hz / eb, 0.0) << "shooting mode " << k;
    EXPECT_LT(1 - sh.modes[k].frequency_hz / eb, br * br) << "shooting mode " << k;
    EXPECT_NEAR(fd.modes[k].frequency_hz / sh.modes[k].frequency_hz, 1.0, 0.005);
    EXPECT_EQ(fd.modes[k].kind, ModeKind::kBending);
    EXPECT_EQ(sh.modes[k].kind, ModeKind::kBending);
  }
  // The shapes: first bending mode, tip displacement normalised to +L (largest entry), zero at
  // the clamp, and the Euler–Bernoulli shape at midspan, φ(L/2)/φ(L).
  const double mid_over_tip = truth::CantileverModeShape(1, 0.5) / truth::CantileverModeShape(1, 1);
  for (const ModalResult* r : {&fd, &sh}) {
    const Mode& m = r->modes[0];
    ASSERT_EQ(m.displacement_W.size(), 101u);
    EXPECT_LT(m.displacement_W.front().norm(), 1e-12);
    const double tip = m.displacement_W.back().norm(), mid = m.displacement_W[50].norm();
    EXPECT_NEAR(mid / tip, mid_over_tip, 2e-3);
  }
}

// Columns (the tip guided along the axis): pinned–pinned against the simply supported Timoshenko
// beam, whose closed form has the section's own shear stiffness and rotary inertia, so only
// RK4's grid error is left, of fourth order (mode 3: 3.2e-6 on 81 nodes, 2.0e-7 on 161,
// measured; 1e-5 asserted, and the order within 0.3 of 4);
// clamped–clamped and clamped–pinned against Euler–Bernoulli (Rao 2007), which shear and
// rotary inertia lie below by under (β_n r)² (as the cantilever's above). Each frequency
// twice (a circle). Pressed by half its Euler load, the pinned–pinned column's first frequency
// falls by sqrt(1 − P/P_E) (the mode stays sin(πs/L); shear shifts the ratio by ~(πr/L)² =
// 4e-5: 1e-4 asserted).
TEST(Modes, ColumnsVibrateAsTheirBeamTheorySays) {
  SteelRod rod;
  const RodModel model = rod.model();
  const SectionProperties p = model.section->At(0.0, Actuation{});
  auto modes = [&](ColumnEnds ends, const StaticLoads& loads, int nodes = 81) {
    ShootingModalOptions so;
    so.modal.count = 6;
    const ModalResult r = ComputeModesShooting(model, nodes, lie::SE3(), loads, so, {}, ends);
    EXPECT_TRUE(r.converged()) << ToString(r.status);
    EXPECT_EQ(r.modes.size(), 6u);
    return r;
  };
  auto timoshenko = [&](int n) {
    return truth::SimplySupportedTimoshenkoOmega(n, rod.EI(), p.stiffness(3, 3), rod.rhoA(),
                                                 p.mass(0, 0), rod.length);
  };
  const ModalResult pp = modes(ColumnEnds::kPinnedPinned, {});
  for (int k = 0; k < 6 && k < static_cast<int>(pp.modes.size()); ++k)
    EXPECT_NEAR(pp.modes[k].omega / timoshenko(k / 2 + 1), 1.0, 1e-5) << "pinned-pinned " << k;
  const ModalResult fine = modes(ColumnEnds::kPinnedPinned, {}, 161);
  ASSERT_GE(fine.modes.size(), 5u);
  const double order = std::log2((pp.modes[4].omega / timoshenko(3) - 1) /
                                 (fine.modes[4].omega / timoshenko(3) - 1));
  EXPECT_NEAR(order, 4.0, 0.3);
  const struct {
    ColumnEnds ends;
    double (*beta_L)(int);
  } eb[] = {{ColumnEnds::kClampedClamped, truth::FreeFreeBetaL},
            {ColumnEnds::kClampedPinned, truth::ClampedPinnedVibrationBetaL}};
  for (const auto& c : eb) {
    const ModalResult r = modes(c.ends, {});
    for (int k = 0; k < 6 && k < static_cast<int>(r.modes.size()); ++k) {
      const double beta_L = c.beta_L(k / 2 + 1);
      const double w = truth::EulerBernoulliOmega(beta_L, rod.EI(), rod.rhoA(), rod.length);
      const double br = beta_L * rod.r / rod.length;
      EXPECT_GT(1 - r.modes[k].omega / w, 0.0) << ToString(c.ends) << " mode " << k;
      EXPECT_LT(1 - r.modes[k].omega / w, br * br) << ToString(c.ends) << " mode " << k;
    }
  }
  StaticLoads pressed;
  pressed.tip_force = Vec3(0, 0, -0.5 * kPi * kPi * rod.EI() / (rod.length * rod.length));
  const ModalResult half = modes(ColumnEnds::kPinnedPinned, pressed);
  ASSERT_FALSE(half.modes.empty());
  EXPECT_NEAR(half.modes[0].omega / pp.modes[0].omega, std::sqrt(0.5), 1e-4);
}

// A taut wire (steel, 1 m, r = 1 mm, pinned–pinned, pulled by 100 N: L sqrt(T/EI) = 25) is the
// tensioned beam, f_n = n/(2ℓ) sqrt(T/m) sqrt(1 + (nπ)² EI/(T ℓ²)) with ℓ and m of the stretched
// wire, each n twice (a circle). One shot amplifies round-off by e^{∫ μ ds}, 25 here at ω → 0
// (frequency_shot_limit.hpp): near 28 a pair's two roots blur into one minimum, and a lost
// partner would let the next pair's 185.8 Hz take its place in the list. Every frequency listed
// must be its pair's, pairs
// whole: within 1e-4 (shear and rotary inertia shift the bending part, at most 1/4 of ω² here,
// by (nπr/ℓ)² < 1.6e-4), and fewer than asked only with status too_few_modes and the limit
// below the first pair not listed.
TEST(Modes, ATautWiresPairsAreListedWholeOrNotAtAll) {
  const double L = 0.99984087, T = 100.0;
  testing::SteelRod rod{L, 0.001};
  rod.material.shear_modulus = 80e9;
  StaticLoads pulled;
  pulled.tip_force = Vec3(0, 0, T);
  ShootingModalOptions so;
  so.modal.count = 8;
  const ModalResult r =
      ComputeModesShooting(rod.model(), 41, lie::SE3(), pulled, so, {}, ColumnEnds::kPinnedPinned);
  const double stretched = L * (1 + T / rod.EA()), m = rod.rhoA() * L / stretched;
  auto beam_hz = [&](int n) {
    const double k = n * kPi / stretched;
    return std::sqrt((T * k * k + rod.EI() * k * k * k * k) / m) / (2 * kPi);
  };
  ASSERT_GE(r.modes.size(), 6u) << ToString(r.status);
  EXPECT_EQ(r.modes.size() % 2, 0u);
  for (size_t i = 0; i < r.modes.size(); ++i)
    EXPECT_NEAR(r.modes[i].frequency_hz / beam_hz(static_cast<int>(i) / 2 + 1), 1.0, 1e-4) << i;
  if (r.modes.size() < 8) {
    EXPECT_EQ(r.status, ModalStatus::kTooFewModes);
    EXPECT_LT(r.shot_limit_hz, beam_hz(static_cast<int>(r.modes.size()) / 2 + 1));
    EXPECT_GT(r.shot_limit_hz, r.modes.back().frequency_hz);
  }
}

TEST(Modes, SecondOrderConvergenceOfQuatFdFrequencies) {
  // The quatfd error in the 4th bending frequency against the (RK4-exact) shooting value, at N
  // and 2N segments: the observed order lies within ±0.3 of 2.
  SteelRod rod;
  const double ref = ShootingModes(rod.model(), lie::SE3(), {}, 101, 8).modes[6].frequency_hz;
  const double e25 = QuatFdModes(rod.model(), lie::SE3(), {}, 25, 8, false).modes[6].frequency_hz;
  const double e50 = QuatFdModes(rod.model(), lie::SE3(), {}, 50, 8, false).modes[6].frequency_hz;
  const double order = std::log2(std::abs(e25 - ref) / std::abs(e50 - ref));
  std::printf("  mode 4 rel. error: N=25 %.3g, N=50 %.3g, order %.3f\n", (e25 - ref) / ref,
              (e50 - ref) / ref, order);
  EXPECT_NEAR(order, 2.0, 0.3);
}

TEST(Modes, CompressedCantileverMatchesExactEulerBernoulli) {
  // Axial dead load P = Pcr/2 (Pcr = π² EI / 4L²) along −z at the tip of the straight rod. The
  // truth is the root of the exact Euler–Bernoulli frequency equation (≈ 2 % above Galef's
  // ω² = ω₀² (1 − P/Pcr)). Budget: shooting 1e-4 (r/L = 1/500 shear/rotary shifts ~1e-5);
  // quatfd 0.1 % (its grid error for mode 1 at N = 100 is ≈ (β₁ h)²/3 ≈ 0.01 %).
  SteelRod rod;
  const double Pcr = truth::EulerLoadClampedFree(rod.EI(), rod.length);
  StaticLoads loads;
  loads.tip_force = Vec3(0, 0, -0.5 * Pcr);
  const double w0 =
      truth::EulerBernoulliOmega(truth::CantileverBetaL(1), rod.EI(), rod.rhoA(), rod.length);
  const double exact =
      truth::CompressedCantileverOmega(rod.EI(), rod.rhoA(), 0.5 * Pcr, rod.length, w0);
  const ModalResult fd = QuatFdModes(rod.model(), lie::SE3(), loads, 100, 2, false);
  const ModalResult sh = ShootingModes(rod.model(), lie::SE3(), loads, 101, 2);
  ASSERT_TRUE(fd.converged()) << ToString(fd.status);
  ASSERT_TRUE(sh.converged()) << ToString(sh.status);
  std::printf("  P = Pcr/2: exact/ω0 %.5f (Galef %.5f), quatfd %.6f, shooting %.6f (ratios)\n",
              exact / w0, std::sqrt(0.5), fd.modes[0].omega / exact, sh.modes[0].omega / exact);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(sh.modes[k].omega / exact, 1.0, 1e-4) << k;
    EXPECT_NEAR(fd.modes[k].omega / exact, 1.0, 1e-3) << k;
  }
}

TEST(Modes, FormulationsAgreeOnSaggingCantilever) {
  // A horizontal cantilever (tangent along world +x) bent by its weight to a tip drop of about
  // a quarter of its length (w L³ / EI = 2), plus a small out-of-plane tip force so nothing is
  // symmetric: the in-plane and out-of-plane modes split and couple with torsion. The two
  // formulations, each with its own statics, agree on the first six frequencies within 0.5 %
  // (quatfd grid error ≤ 0.4 % as in the straight test, shooting ≪), and on the shapes (MAC
  // > 0.99, limited by the quatfd grid error in the shape).
  SteelRod rod;
  rod.r = 0.005;  // r/L = 1/100
  lie::SE3 base;
  base.R << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // body z → world +x
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -2.0 * rod.EI() / (rod.rhoA() * std::pow(rod.length, 3)));
  loads.tip_force = Vec3(0, 0.1 * rod.EI() / (rod.length * rod.length), 0);
  const ModalResult fd = QuatFdModes(rod.model(), base, loads, 100, 6);
  const ModalResult sh = ShootingModes(rod.model(), base, loads, 101, 6);
  ASSERT_TRUE(fd.converged()) << ToString(fd.status);
  ASSERT_TRUE(sh.converged()) << ToString(sh.status);
  ASSERT_EQ(sh.modes.size(), 6u);
  for (int k = 0; k < 6; ++k) {
    const Mode &a = fd.modes[k], &b = sh.modes[k];
    double ab = 0, aa = 0, bb = 0;
    for (size_t n = 0; n < a.displacement_W.size(); ++n) {
      ab += a.displacement_W[n].dot(b.displacement_W[n]);
      aa += a.displacement_W[n].squaredNorm();
      bb += b.displacement_W[n].squaredNorm();
    }
    const double mac = ab * ab / (aa * bb);
    std::printf("  sagging mode %d (%s): quatfd %.5f Hz, shooting %.5f Hz, ratio %.5f, MAC %.6f\n",
                k, ToString(b.kind), a.frequency_hz, b.frequency_hz,
                a.frequency_hz / b.frequency_hz, mac);
    EXPECT_NEAR(a.frequency_hz / b.frequency_hz, 1.0, 0.005) << k;
    EXPECT_GT(mac, 0.99) << k;
  }
  // The sag really splits the pairs of the straight rod.
  EXPECT_GT(sh.modes[1].frequency_hz / sh.modes[0].frequency_hz, 1.01);
}

TEST(Modes, EachPlaneOfASaggingWireIsItsOwnMode) {
  // The 0.5 m wire, horizontal under its own weight (w L³/EI = 0.025): the weight splits each
  // bending pair of the straight rod by ~5e-5 of its frequency (in and out of the plane of the
  // sag). A scan that took the pair's two small singular values at one frequency reported one
  // mode twice (the same shape, MAC 1) and dropped its partner. Every pair must be two modes:
  // distinct frequencies, shapes orthogonal in displacement (MAC < 0.01: one in the vertical
  // plane, one across it), each within 0.5 % of Euler–Bernoulli (shear and rotary inertia are
  // ≤ 0.1 % at mode 6 for r/L = 1/500; the sag's tension ~1e-4).
  SteelRod rod;
  lie::SE3 base;
  base.R << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // body z → world +x
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  const ModalResult sh = ShootingModes(rod.model(), base, loads, 101, 12);
  ASSERT_TRUE(sh.converged()) << ToString(sh.status);
  ASSERT_EQ(sh.modes.size(), 12u);
  for (int pair = 0; pair < 6; ++pair) {
    const Mode &a = sh.modes[2 * pair], &b = sh.modes[2 * pair + 1];
    double ab = 0, aa = 0, bb = 0;
    for (size_t n = 0; n < a.displacement_W.size(); ++n) {
      ab += a.displacement_W[n].dot(b.displacement_W[n]);
      aa += a.displacement_W[n].squaredNorm();
      bb += b.displacement_W[n].squaredNorm();
    }
    std::printf("  pair %d: %.6f and %.6f Hz (Euler-Bernoulli %.6f), MAC %.2e\n", pair,
                a.frequency_hz, b.frequency_hz, rod.EulerBernoulliHz(pair), ab * ab / (aa * bb));
    EXPECT_GT(b.frequency_hz / a.frequency_hz - 1, 1e-6) << pair;
    EXPECT_LT(ab * ab / (aa * bb), 0.01) << pair;
    for (const Mode* m : {&a, &b})
      EXPECT_NEAR(m->frequency_hz / rod.EulerBernoulliHz(pair), 1.0, 5e-3) << pair;
  }
}

TEST(Modes, ThinHangingWiresKeepTheirLowestModesOnQuatFd) {
  // A steel wire 1 m long hanging from a clamp. Its shear and rotation modes sit at
  // ω² ≈ κGA/ρI, ~1e15 times its first: the dense eigen-solve resolved ω² only to ε ω²_max, and
  // the two planes of the round wire came out 0.61002 and 0.61559 Hz (r = 0.05 mm), the
  // cable-like section I = 1e-18 m⁴ gave negative frequencies, both "converged". Against the
  // other formulation (shooting resolves the low modes directly) at r = 0.05 mm: within 1e-3
  // (the quatfd grid's O(h²) error at 100 segments is ~2e-4), the planes equal to 1e-9. The
  // cable against the hanging chain, ω_n = (j₀,ₙ/2) √(g/L) (j₀,₁ = 2.404826, j₀,₂ = 5.520078):
  // its bending stiffness (boundary layer √(EI/T) ≈ 1.4 mm) and the grid: within 1e-3.
  lie::SE3 base;
  base.R << 1, 0, 0, 0, -1, 0, 0, 0, -1;  // hanging: body z → world −z
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  testing::SteelRod wire{1.0, 5e-5};
  const ModalResult fd = QuatFdModes(wire.model(), base, loads, 100, 4, false);
  const ModalResult sh = ShootingModes(wire.model(), base, loads, 101, 4);
  ASSERT_TRUE(fd.converged()) << ToString(fd.status);
  ASSERT_TRUE(sh.converged()) << ToString(sh.status);
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(fd.modes[k].frequency_hz / sh.modes[k].frequency_hz, 1.0, 1e-3) << k;
  for (int pair = 0; pair < 2; ++pair)
    EXPECT_NEAR(fd.modes[2 * pair + 1].frequency_hz / fd.modes[2 * pair].frequency_hz, 1.0, 1e-9);

  // The wire's area (r = 0.636 mm) with I1 = I2 = 1e-18 m⁴: a cable, EI = 2e-7 N·m².
  const RodModel cable =
      RodModel::Uniform(1.0, CrossSection::Explicit(1.27e-6, 1e-18, 1e-18, 2e-18),
                        Material::FromShearModulus(200e9, 80e9, 8000));
  const ModalResult chain = QuatFdModes(cable, base, loads, 100, 4, false);
  ASSERT_TRUE(chain.converged()) << ToString(chain.status);
  const double j0[] = {2.404826, 5.520078};
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(chain.modes[k].frequency_hz / (j0[k / 2] / 2 * std::sqrt(9.81) / (2 * kPi)), 1.0,
                1e-3)
        << k;
}

TEST(Modes, ThinHangingWiresKeepTheirLowestDampedModesOnQuatFd) {
  // The 0.1 mm wire above with Kelvin–Voigt damping D = τ K (τ = 1e-5 s): the damped modes came
  // from the lossy direct spectrum (0.6299 and 0.6310 Hz about an undamped 0.6307, one above it,
  // the planes' ζ 30 % apart). Light damping lowers a frequency by a factor √(1 − ζ²), here
  // within 1e-8 of 1, and the two planes of a round wire are one pair: frequencies within 1e-8,
  // ζ within 1 % (the truncated modal basis of the inverse spectrum).
  lie::SE3 base;
  base.R << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  const double r = 5e-5, E = 200e9, G = 80e9, tau = 1e-5;
  Material m = Material::FromShearModulus(E, G, 8000);
  const CrossSection circle = CrossSection::Circle(r);
  m.damping.bending = tau * E * circle.I1;
  m.damping.torsion = tau * G * circle.torsion_constant;
  m.damping.shear = tau * G * circle.area;
  m.damping.extension = tau * E * circle.area;
  const ModalResult fd =
      QuatFdModes(RodModel::Uniform(1.0, circle, m), base, loads, 100, 4, false);
  ASSERT_TRUE(fd.converged()) << ToString(fd.status);
  ASSERT_EQ(fd.damped.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(fd.damped[k].damped_frequency_hz / fd.modes[k].frequency_hz, 1.0, 1e-8) << k;
    EXPECT_GT(fd.damped[k].damping_ratio, 0.0) << k;
  }
  for (int pair = 0; pair < 2; ++pair) {
    const DampedMode &a = fd.damped[2 * pair], &b = fd.damped[2 * pair + 1];
    EXPECT_NEAR(b.damped_frequency_hz / a.damped_frequency_hz, 1.0, 1e-8) << pair;
    EXPECT_NEAR(b.damping_ratio / a.damping_ratio, 1.0, 1e-2) << pair;
  }
}

TEST(Modes, FormulationsAgreeOnAStableRodUnderATipMoment) {
  // A cantilever bent by a dead tip moment ML/EI = 3 (a little short of a full circle's 2π). The
  // quaternion-FD spectrum of its whole (non-symmetric) linearisation is real and positive:
  // stable. Shooting used to call it unstable from the symmetric part of a stiffness a dead
  // moment makes non-symmetric. Both converged, the first four within 0.5 % (the quatfd grid).
  SteelRod rod;
  rod.r = 0.005;
  StaticLoads loads;
  loads.tip_moment = Vec3(0, 3.0 * rod.EI() / rod.length, 0);
  const ModalResult fd = QuatFdModes(rod.model(), lie::SE3(), loads, 100, 4, false);
  const ModalResult sh = ShootingModes(rod.model(), lie::SE3(), loads, 101, 4);
  ASSERT_TRUE(fd.converged()) << ToString(fd.status);
  ASSERT_TRUE(sh.converged()) << ToString(sh.status);
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(fd.modes[k].frequency_hz / sh.modes[k].frequency_hz, 1.0, 5e-3) << k;
}

TEST(Modes, QuatFdFindsBecksFlutterAndOnlyIt) {
  // Beck's column: a cantilever under a follower tip force P loses stability by flutter, its
  // first two modes merging into a complex pair, at P L²/EI = 20.05 (Beck 1952). At 19 the
  // spectrum below the modes returned is real (converged); at 21 the pair is gone (unstable).
  // Complex pairs among the grid's highest modes do not count (see the tip-moment test). The
  // 1 mm rod's spectrum spans more than double precision resolves directly: it read "unstable"
  // at 5 and 19 with its lowest modes lost. At 5 its first frequency is shooting's within the
  // grid's 0.5 %. So is a 0.1 mm wire's, whose follower force's asymmetry is 1e-7 of its
  // stiffness's shear scale κGA: a symmetry test that forgave such asymmetry read it 20 % low
  // at 5, unstable by divergence at 19, and divergence for flutter at 21.
  for (const double radius : {0.005, 0.001, 0.0001}) {
    SteelRod rod;
    rod.r = radius;
    StaticLoads loads;
    loads.tip_force_frame = LoadFrame::kBody;
    for (const double lambda : {5.0, 19.0}) {
      loads.tip_force = Vec3(0, 0, -lambda * rod.EI() / (rod.length * rod.length));
      const ModalResult fd = QuatFdModes(rod.model(), lie::SE3(), loads, 40, 4, false);
      ASSERT_TRUE(fd.converged()) << radius << " at " << lambda << ": " << ToString(fd.status);
      if (lambda == 5.0) {
        const ModalResult sh = ShootingModes(rod.model(), lie::SE3(), loads, 41, 1);
        ASSERT_TRUE(sh.converged()) << ToString(sh.status);
        EXPECT_NEAR(fd.modes[0].frequency_hz / sh.modes[0].frequency_hz, 1.0, 5e-3) << radius;
      }
    }
    loads.tip_force = Vec3(0, 0, -21.0 * rod.EI() / (rod.length * rod.length));
    const ModalResult past = QuatFdModes(rod.model(), lie::SE3(), loads, 40, 4, false);
    EXPECT_EQ(past.status, ModalStatus::kUnstable) << radius;
    EXPECT_EQ(past.instability.rfind("flutter", 0), 0u) << past.instability;  // says which
  }
}

TEST(Modes, ShootingSeesBecksFlutterAndNoFalseFrequency) {
  // Frequency shooting finds real frequencies only. Past Beck's 20.05 EI/L² the first two
  // merge into a complex pair; det B then dips near their real part without vanishing, and that
  // dip was listed as a single "frequency" (8.70 Hz at 21, where the quaternion-FD pair is at
  // 8.86 Hz) in a "converged" run. Below flutter (19.9) every root of this isotropic rod is a
  // pair, one per bending plane; past it (20.2, 21) the run is unstable and says flutter.
  SteelRod rod;
  rod.r = 0.002;
  StaticLoads loads;
  loads.tip_force_frame = LoadFrame::kBody;
  for (const double lambda : {19.9, 20.2, 21.0}) {
    loads.tip_force = Vec3(0, 0, -lambda * rod.EI() / (rod.length * rod.length));
    const ModalResult r = ShootingModes(rod.model(), lie::SE3(), loads, 81, 4);
    if (lambda < 20.05) {
      ASSERT_TRUE(r.converged()) << lambda << ": " << ToString(r.status);
      ASSERT_EQ(r.modes.size(), 4u);
      for (int k = 0; k < 4; k += 2)  // pairs to the scan's refinement, 1e-10 ω
        EXPECT_NEAR(r.modes[k].omega / r.modes[k + 1].omega, 1.0, 1e-9) << lambda << " " << k;
    } else {
      EXPECT_EQ(r.status, ModalStatus::kUnstable) << lambda << ": " << ToString(r.status);
      EXPECT_EQ(r.instability.rfind("flutter", 0), 0u) << r.instability;
    }
  }
}

TEST(Modes, ShootingKeepsBothBendingPlanesUnderASmallLateralLoad) {
  // A 0.01 N lateral tip force (P L²/EI = 0.016), dead or following, splits each bending pair
  // by ~1e-6 of ω: closer than the scan separates roots, and one of each pair was lost, so four
  // modes asked listed the first four pairs' halves. Both planes are listed now: pairs equal
  // within 1e-5, the second pair at Euler–Bernoulli's ratio (4.6941/1.8751)² within 1e-3 (the
  // rod's shear and the load's stiffening are ~1e-5).
  SteelRod rod;  // 0.5 m, r = 1 mm
  for (const LoadFrame frame : {LoadFrame::kWorld, LoadFrame::kBody}) {
    StaticLoads loads;
    loads.tip_force_frame = frame;
    loads.tip_force = Vec3(0.01, 0, 0);
    const ModalResult r = ShootingModes(rod.model(), lie::SE3(), loads, 41, 4);
    ASSERT_TRUE(r.converged()) << ToString(r.status);
    ASSERT_EQ(r.modes.size(), 4u);
    EXPECT_NEAR(r.modes[1].omega / r.modes[0].omega, 1.0, 1e-5);
    EXPECT_NEAR(r.modes[3].omega / r.modes[2].omega, 1.0, 1e-5);
    EXPECT_NEAR(r.modes[2].omega / r.modes[0].omega, std::pow(4.6941 / 1.8751, 2), 1e-3);
  }
}

TEST(Modes, ShootingListsEachPlaneOnceWhenThePairsAreSplitBy3e5) {
  // A 2 × 2.00006 mm steel rectangle: each bending pair split by 3e-5 (h ratio), more than the
  // 1e-5 within which a cluster's extra small singular values are listed as roots. Each
  // neighbour also makes a singular value small at the other's ω, and counting those listed
  // both halves twice (113.365 113.365 113.368 113.368, the fourth pair pushed out); each plane
  // once now: pairs split by 3e-5 (to 5e-6, the scan's refinement) and the fourth pair at
  // Euler–Bernoulli's (10.9955/1.8751)² of the first (1e-3: shear and the grid).
  const Material m = Material::FromShearModulus(200e9, 80e9, 8000);
  const RodModel rod = RodModel::Uniform(0.5, CrossSection::Rectangle(0.002, 0.00200006), m);
  const ModalResult r = ShootingModes(rod, lie::SE3(), {}, 41, 8);
  ASSERT_TRUE(r.converged()) << ToString(r.status);
  ASSERT_EQ(r.modes.size(), 8u);
  for (int k = 0; k < 8; k += 2)
    EXPECT_NEAR(r.modes[k + 1].omega / r.modes[k].omega - 1, 3e-5, 5e-6) << k;
  EXPECT_NEAR(r.modes[6].omega / r.modes[0].omega, std::pow(10.9955 / 1.8751, 2), 1e-3 * 34.4);
}

TEST(Modes, ShootingCallsNoRoundOffDipFlutter) {
  // High up the scan one shot amplifies round-off by e^{λL}: a 0.5 m, 1 mm steel cantilever
  // under a 0.01 N lateral follower force asked for 25 frequencies shows a dip of det B near
  // 1421 Hz (λL ≈ 27) that no merged pair makes, and the run read "unstable: flutter". Dips
  // count only where one shot resolves det B (λL ≤ 15; Beck's pair meets at λL ≈ 3.3).
  SteelRod rod;  // 0.5 m, r = 1 mm
  StaticLoads loads;
  loads.tip_force_frame = LoadFrame::kBody;
  loads.tip_force = Vec3(0.01, 0, 0);
  const ModalResult r = ShootingModes(rod.model(), lie::SE3(), loads, 41, 25);
  ASSERT_EQ(r.statics_status, SolveStatus::kConverged);  // the scan ran, about the equilibrium
  EXPECT_NE(r.status, ModalStatus::kUnstable) << r.instability;
}

TEST(Modes, QuatFdFindsAStandingWirePastItsSelfWeightBucklingUnstable) {
  // A 1 mm steel wire standing up from a clamp buckles under its own weight at
  // L³ = 7.837 EI/(ρ A g) (Greenhill), 1.71 m. At 1.5 m it stands (converged); at 2 m its first
  // ω² is negative, −(2π 0.27 Hz)², against ω²_max ~1e17: the direct spectrum called that
  // round-off and the run "converged"; the factorisation of the stiffness sees it.
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  for (const double length : {1.5, 2.0}) {
    const RodModel wire = testing::SteelRod{length, 0.001}.model();
    const ModalResult fd = QuatFdModes(wire, lie::SE3(), loads, 40, 4, false);
    EXPECT_EQ(fd.status, length < 1.71 ? ModalStatus::kConverged : ModalStatus::kUnstable)
        << length << ": " << ToString(fd.status);
    // The reason names the divergence and its ω² (the first frequency, −0.27 Hz, squared).
    if (length > 1.71)
      EXPECT_NE(fd.instability.find("divergence: the stiffness is indefinite, ω² = -2.9"),
                std::string::npos)
          << fd.instability;
  }
}

// An equilibrium near its critical load has a small ω² of a real sign, not round-off: a 1 m
// steel column of radius 5 mm pressed by 0.997 and 1.003 times its Euler load π²EI/4L² is stable
// and unstable (its ω² about ±6 rad²/s² on 40 segments, whose grid lowers the critical load by
// 0.085 (k h)², 2e-4), and so is one at 1.001 (ω² about −2.5), which a window of 1e3 ε ‖M⁻¹K‖₁
// called neutral; none is taken for a neutral mode, whose round-off lies below
// ε max |(M⁻¹K)_ii| (3e-4 rad²/s² on this rod's 1.5e12).
TEST(Modes, AColumnJustPastItsCriticalLoadIsUnstableNotNeutral) {
  const testing::SteelRod steel{1.0, 0.005};
  const RodModel rod = steel.model();
  const double critical = truth::EulerLoadClampedFree(steel.EI(), 1.0);
  for (const double factor : {0.997, 1.001, 1.003}) {
    StaticLoads loads;
    loads.tip_force = Vec3(0, 0, -factor * critical);
    const ModalResult fd = QuatFdModes(rod, lie::SE3(), loads, 40, 4, false);
    EXPECT_EQ(fd.status, factor < 1 ? ModalStatus::kConverged : ModalStatus::kUnstable)
        << factor << ": " << ToString(fd.status);
    ASSERT_EQ(fd.modes.size(), 4u);
    for (const Mode& m : fd.modes) EXPECT_FALSE(m.neutral) << factor << " " << m.frequency_hz;
    EXPECT_EQ(fd.modes[0].frequency_hz < 0, factor > 1) << fd.modes[0].frequency_hz;
  }
}

// A cantilever pressed along its axis by 1.29 Pcr has two unstable directions (the two bending
// planes), each growing as e^{σ t}. Both formulations list them first, as the negative
// frequencies −σ/2π (SE(3) by frequency shooting at ω² = −σ², where it once listed only the
// stable pairs behind them, so that mode 1 was 31 Hz there and −3.2 Hz on the quaternion-FD
// path), then the stable pair. Their continua are the same: on 100 segments the quaternion-FD
// grid error is ~0.2 (k h)², 0.04 % for the stable pair, less for the slower growth; 0.2 %.
TEST(Modes, BothFormulationsListTheGrowthOfAnUnstableEquilibriumFirst) {
  SteelRod rod;
  StaticLoads loads;
  loads.tip_force = Vec3(0, 0, -1.29 * truth::EulerLoadClampedFree(rod.EI(), rod.length));
  const ModalResult fd = QuatFdModes(rod.model(), lie::SE3(), loads, 100, 4, false);
  const ModalResult sh = ShootingModes(rod.model(), lie::SE3(), loads, 101, 4);
  ASSERT_EQ(fd.status, ModalStatus::kUnstable) << ToString(fd.status);
  ASSERT_EQ(sh.status, ModalStatus::kUnstable) << ToString(sh.status);
  ASSERT_EQ(fd.modes.size(), 4u);
  ASSERT_EQ(sh.modes.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    std::printf("  mode %d: quatfd %.6f Hz, shooting %.6f Hz\n", k + 1, fd.modes[k].frequency_hz,
                sh.modes[k].frequency_hz);
    EXPECT_EQ(sh.modes[k].frequency_hz < 0, k < 2) << k;
    EXPECT_NEAR(sh.modes[k].frequency_hz / fd.modes[k].frequency_hz, 1.0, 2e-3) << k;
    EXPECT_EQ(sh.modes[k].kind, ModeKind::kBending) << k;
  }
}

// The lowest modes by subspace iteration on the banded factorisation (ModalOptions::sparse_above
// 0) against the dense spectrum of the same reduced matrices. A 5 mm rod sagging under a lateral
// tip force: the same ω² to 1e-9 and, its pairs split, the same shapes (MAC 1 − 1e-9). A 0.1 mm
// wire hanging from its clamp in water (3×3 vertex blocks of added mass) and a cable
// (I = 1e-18 m⁴), whose ω² span 1e15 or more: there neither path resolves the lowest ω² beyond
// about 1e-7 (against a long-double solve of the same matrix, the cable's first: dense 4e-8 off,
// banded 1.2e-7), so 1e-6, far below the grid's own 1e-4. A standing wire past its buckling
// length is not definite: the banded path declines it and the dense one finds it unstable.
TEST(Modes, TheBandedSpectrumIsTheDenseOne) {
  struct Case {
    RodModel rod;
    lie::SE3 base;
    StaticLoads loads;
    bool compare_shapes;
    double tolerance;  // on ω², relative
  };
  std::vector<Case> cases;
  {
    SteelRod rod;
    rod.r = 0.005;
    Case c{rod.model(), {}, {}, true, 1e-9};
    c.base.R << 0, 0, 1, 0, 1, 0, -1, 0, 0;
    c.loads.gravity_W = Vec3(0, 0, -2.0 * rod.EI() / (rod.rhoA() * std::pow(rod.length, 3)));
    c.loads.tip_force = Vec3(0, 0.1 * rod.EI() / (rod.length * rod.length), 0);
    cases.push_back(c);
  }
  lie::SE3 hanging;
  hanging.R << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  StaticLoads in_water;
  in_water.gravity_W = Vec3(0, 0, -9.81);
  in_water.fluid.density = 1025.0;
  in_water.fluid.added_mass = 1.0;
  cases.push_back({testing::SteelRod{1.0, 5e-5}.model(), hanging, in_water, false, 1e-6});
  StaticLoads gravity;
  gravity.gravity_W = Vec3(0, 0, -9.81);
  cases.push_back({RodModel::Uniform(1.0, CrossSection::Explicit(1.27e-6, 1e-18, 1e-18, 2e-18),
                                     Material::FromShearModulus(200e9, 80e9, 8000)),
                   hanging, gravity, false, 1e-6});
  for (size_t i = 0; i < cases.size(); ++i) {
    ModalResult out[2];
    for (const int path : {0, 1}) {
      quatfd::QuatFdOptions opt;
      opt.segments = 100;
      quatfd::QuatFdModel model(cases[i].rod, cases[i].base, opt);
      ModalOptions mo;
      mo.count = 6;
      mo.sparse_above = path == 0 ? 0 : std::numeric_limits<int>::max();
      out[path] = ComputeModes(&model, cases[i].loads, mo);
      ASSERT_TRUE(out[path].converged()) << i << " " << ToString(out[path].status);
    }
    EXPECT_TRUE(out[0].sparse) << i;
    EXPECT_FALSE(out[1].sparse) << i;
    for (int k = 0; k < 6; ++k) {
      const Mode &a = out[0].modes[k], &b = out[1].modes[k];
      EXPECT_NEAR(a.omega * a.omega / (b.omega * b.omega), 1.0, cases[i].tolerance)
          << i << " mode " << k << ": " << a.omega << " vs " << b.omega << " rad/s";
      if (!cases[i].compare_shapes) continue;
      double ab = 0, aa = 0, bb = 0;
      for (size_t n = 0; n < a.displacement_W.size(); ++n) {
        ab += a.displacement_W[n].dot(b.displacement_W[n]);
        aa += a.displacement_W[n].squaredNorm();
        bb += b.displacement_W[n].squaredNorm();
      }
      EXPECT_GT(ab * ab / (aa * bb), 1.0 - 1e-9) << i << " mode " << k;
    }
  }
  // Not definite: declined, and the dense spectrum judges it.
  lie::SE3 standing;
  StaticLoads down;
  down.gravity_W = Vec3(0, 0, -9.81);
  quatfd::QuatFdOptions opt;
  opt.segments = 100;
  quatfd::QuatFdModel model(testing::SteelRod{2.0, 5e-4}.model(), standing, opt);
  ModalOptions mo;
  mo.sparse_above = 0;
  const ModalResult r = ComputeModes(&model, down, mo);
  EXPECT_FALSE(r.sparse);
  EXPECT_EQ(r.status, ModalStatus::kUnstable) << ToString(r.status);
}

TEST(Modes, TorsionalAndAxialFundamentals) {
  // L = 1 m, r = 1 cm steel: the first torsional and axial modes are ω = (π / 2L) sqrt(G/ρ) and
  // (π / 2L) sqrt(E/ρ) (a circle has J = I_p). Both are second-order accurate in quatfd, error
  // ≈ (π/2N)²/24 ≈ 6e-5 at N = 40; tolerance 1e-3. The shooting scans ±3 % around each.
  SteelRod rod;
  rod.length = 1.0;
  rod.r = 0.01;
  const double rho = rod.material.density;
  const double wt =
      truth::ClampedFreeWaveOmega(1, std::sqrt(rod.material.shear_modulus / rho), rod.length);
  const double wa =
      truth::ClampedFreeWaveOmega(1, std::sqrt(rod.material.youngs_modulus / rho), rod.length);
  const ModalResult fd = QuatFdModes(rod.model(), lie::SE3(), {}, 40, 6 * 40);
  ASSERT_TRUE(fd.converged()) << ToString(fd.status);
  auto first = [](const ModalResult& r, ModeKind kind) {
    for (const Mode& m : r.modes)
      if (m.kind == kind) return m.omega;
    return 0.0;
  };
  std::printf("  quatfd: torsion %.6f, axial %.6f (ratios)\n", first(fd, ModeKind::kTorsion) / wt,
              first(fd, ModeKind::kAxial) / wa);
  EXPECT_NEAR(first(fd, ModeKind::kTorsion) / wt, 1.0, 1e-3);
  EXPECT_NEAR(first(fd, ModeKind::kAxial) / wa, 1.0, 1e-3);
  for (const auto& [w, kind] : {std::pair{wt, ModeKind::kTorsion}, {wa, ModeKind::kAxial}}) {
    // A pair of high bending modes lies 0.5 % below the torsional one: ask for three.
    const ModalResult sh = ShootingModes(rod.model(), lie::SE3(), {}, 41, 3, 0.97 * w, 1.03 * w);
    std::printf("  shooting: %s %.7f (ratio)\n", ToString(kind), first(sh, kind) / w);
    EXPECT_NEAR(first(sh, kind) / w, 1.0, 1e-5);
  }
}

/// A 0.5 m soft rod (E 5 MPa, ν 0.5, r 5 mm) with Kelvin–Voigt damping D = τ K in every strain.
RodModel StiffnessProportionallyDampedRod(double tau) {
  Material m = Material::FromPoissonRatio(5e6, 0.5, 1100);
  const CrossSection c = CrossSection::Circle(0.005);
  const double kappa = c.ShearCoefficient(m.PoissonRatio());
  m.damping.bending = tau * m.youngs_modulus * c.I1;
  m.damping.torsion = tau * m.shear_modulus * c.torsion_constant;
  m.damping.shear = tau * kappa * m.shear_modulus * c.area;
  m.damping.extension = tau * m.youngs_modulus * c.area;
  return RodModel::Uniform(0.5, c, m);
}

TEST(Modes, StiffnessProportionalDampingGivesExactModalDamping) {
  // D = τ K in every strain (bending, torsion, shear, stretch): about the unloaded straight rest
  // state C = τ K exactly, so each mode has ζ = τ ω / 2 and ω_n = ω (to round-off).
  const double tau = 2e-4;
  const RodModel rod = StiffnessProportionallyDampedRod(tau);
  const ModalResult r = QuatFdModes(rod, lie::SE3(), {}, 20, 4, false);
  ASSERT_TRUE(r.converged()) << ToString(r.status);
  ASSERT_EQ(r.damped.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    std::printf("  mode %d: ω %.4f, ω_n %.4f, ζ %.6f (τω/2 %.6f)\n", k, r.modes[k].omega,
                r.damped[k].omega_n, r.damped[k].damping_ratio, tau * r.modes[k].omega / 2);
    EXPECT_NEAR(r.damped[k].omega_n / r.modes[k].omega, 1.0, 1e-8);
    EXPECT_NEAR(r.damped[k].damping_ratio / (tau * r.modes[k].omega / 2), 1.0, 1e-6);
  }
}

// The same law damped hard on a steel wire, ζ = τω/2 = 0.7 on the first pair: every higher mode
// is overdamped, and each has a slow root near −1/τ, hundreds of equal real roots the
// eigensolver splits into pairs with Im λ ~ 1e-5 |λ|. Those had taken the first pair's place
// (all four reported overdamped). The first pair must keep ζ = τω/2 and ω_d = ω √(1 − ζ²)
// (1e-6, as above), the second, at ζ = 4.4, be overdamped (NaN).
TEST(Modes, AHeavilyDampedPairIsNotLostAmongOverdampedRoots) {
  // A steel wire (0.5 m, r = 1 mm) on 40 segments, D = τ K in every strain.
  const auto wire = [](double tau) {
    Material m = Material::FromShearModulus(200e9, 80e9, 8000);
    const CrossSection c = CrossSection::Circle(0.001);
    m.damping.bending = tau * m.youngs_modulus * c.I1;
    m.damping.torsion = tau * m.shear_modulus * c.torsion_constant;
    m.damping.shear = tau * c.ShearCoefficient(m.PoissonRatio()) * m.shear_modulus * c.area;
    m.damping.extension = tau * m.youngs_modulus * c.area;
    return RodModel::Uniform(0.5, c, m);
  };
  const ModalResult undamped = QuatFdModes(wire(0.0), lie::SE3(), {}, 40, 4, false);
  ASSERT_TRUE(undamped.converged());
  const double tau = 2 * 0.7 / undamped.modes[0].omega;  // s
  const ModalResult r = QuatFdModes(wire(tau), lie::SE3(), {}, 40, 4, false);
  ASSERT_TRUE(r.converged()) << ToString(r.status);
  ASSERT_EQ(r.damped.size(), 4u);
  for (int k = 0; k < 2; ++k) {  // the round rod's two bending planes
    EXPECT_NEAR(r.damped[k].damping_ratio, 0.7, 1e-6 * 0.7) << k;
    EXPECT_NEAR(r.damped[k].damped_frequency_hz * 2 * M_PI,
                r.modes[k].omega * std::sqrt(1 - 0.49), 1e-6 * r.modes[k].omega)
        << k;
  }
  for (int k = 2; k < 4; ++k) EXPECT_TRUE(std::isnan(r.damped[k].damping_ratio)) << k;
}

// Damping on bending alone (one D for both directions) on a 10 × 10.35 mm rubber bar, whose two
// bending directions differ by 3.5 % in frequency: each bending mode keeps ζ = ω D / (2 EI) of
// its own direction (its energy is bending's to O((h/L)²) = 4e-4; 2 % covers the grid's and
// the damped |λ|'s shifts), the stiffer direction's the smaller, at ζ ≈ 0.25 on the second
// pair.
TEST(Modes, EachBendingDirectionKeepsItsOwnDampingWhenBendingAloneIsDamped) {
  Material m = Material::FromPoissonRatio(5e6, 0.5, 1100);
  const CrossSection c = CrossSection::Rectangle(0.01, 0.01035);
  const double tau = 0.029;  // s: ζ = τ ω / 2 ≈ 0.25 at the second bending pair
  m.damping.bending = tau * m.youngs_modulus * std::sqrt(c.I1 * c.I2);
  const RodModel rod = RodModel::Uniform(0.5, c, m);
  const ModalResult r = QuatFdModes(rod, lie::SE3(), {}, 40, 4, true);
  ASSERT_TRUE(r.converged()) << ToString(r.status);
  ASSERT_EQ(r.damped.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    // The mode's direction: its tip displacement along body x bends about y (I2), along y
    // about x (I1).
    const Vec3 tip = r.modes[k].displacement_W.back();
    const double EI = m.youngs_modulus * (std::abs(tip.x()) > std::abs(tip.y()) ? c.I2 : c.I1);
    const double expected = r.modes[k].omega * m.damping.bending / (2 * EI);
    std::printf("  mode %d: %.4f Hz, ζ %.4f (ω D / 2EI %.4f)\n", k, r.modes[k].frequency_hz,
                r.damped[k].damping_ratio, expected);
    EXPECT_NEAR(r.damped[k].damping_ratio / expected, 1.0, 2e-2) << k;
  }
}

// The same law with a τ that overdamps the higher modes: ζ = τ ω / 2 passes 1 at ω = 2/τ. Each
// mode's damped entry is its own, in the modes' order: ζ = τ ω / 2 where that is below 1, none
// (NaN) above. The list was once the lowest underdamped pairs by |λ|: past the first
// overdamped mode it paired each mode with a higher one's ζ.
TEST(Modes, EachModeKeepsItsOwnDampingAndAnOverdampedOneHasNone) {
  const double tau = 0.04;  // s: ζ = 1 at ω = 50 rad/s, between the third and fourth pairs
  const RodModel rod = StiffnessProportionallyDampedRod(tau);
  const ModalResult r = QuatFdModes(rod, lie::SE3(), {}, 20, 8, false);
  ASSERT_TRUE(r.converged()) << ToString(r.status);
  ASSERT_EQ(r.damped.size(), r.modes.size());
  int underdamped = 0, overdamped = 0;
  for (size_t k = 0; k < r.modes.size(); ++k) {
    const double zeta = tau * r.modes[k].omega / 2;
    std::printf("  mode %zu: ω %.2f, ζ %.4f (τω/2 %.4f)\n", k, r.modes[k].omega,
                r.damped[k].damping_ratio, zeta);
    if (zeta < 0.9) {
      ++underdamped;
      EXPECT_NEAR(r.damped[k].damping_ratio / zeta, 1.0, 1e-6) << k;
    } else if (zeta > 1.1) {
      ++overdamped;
      EXPECT_TRUE(std::isnan(r.damped[k].damping_ratio)) << k;
    }
  }
  EXPECT_GT(underdamped, 0);
  EXPECT_GT(overdamped, 0);
}

// A soft rod curled into a 2 rad arc (L 0.1 m, r 8 mm, E 1 MPa, rest curvature 20 /m) and damped
// in bending only: its out-of-plane modes bend and twist, the twist undamped, so the damping
// mixes the modes and moves |λ| off ω by up to 30 %. A pair leaves the complex plane only
// where two roots meet on the real axis (ζ = 1), so while every mode's ζ stays below 1/2 as D
// grows from 1e-6 N·m²·s (ζ ≤ 0.05, |λ| = ω to O(ζ²)), each mode keeps its pair, and the pair
// moves by little between steps of 1.25 in D (measured: at most 8 % of |λ|; 25 % tolerated).
// Matching pairs to modes by |λ| within 2 % finds none for four of the six at D = 1e-5.
TEST(Modes, EachModeOfACurledRodDampedInBendingKeepsItsPair) {
  Material m = Material::FromPoissonRatio(1e6, 0.5, 1100);
  std::vector<std::complex<double>> previous;
  for (double D = 1e-6; D < 1.01e-5; D *= 1.25) {
    m.damping.bending = D;
    RodModel rod = RodModel::Uniform(0.1, CrossSection::Circle(0.008), m);
    rod.rest_strain = ConstantRestCurvature(Vec3(0, 20, 0));
    const ModalResult r = QuatFdModes(rod, lie::SE3(), {}, 40, 6, false);
    ASSERT_TRUE(r.converged()) << ToString(r.status);
    ASSERT_EQ(r.damped.size(), 6u);
    std::vector<std::complex<double>> now;
    for (int k = 0; k < 6; ++k) {
      const DampedMode& d = r.damped[k];
      ASSERT_TRUE(std::isfinite(d.damping_ratio)) << "mode " << k << " at D " << D;
      EXPECT_LT(d.damping_ratio, 0.5) << k;
      now.push_back(std::polar(d.omega_n, kPi - std::acos(d.damping_ratio)));
      if (D == 1e-6) EXPECT_NEAR(d.omega_n / r.modes[k].omega, 1.0, 1e-2) << k;
      if (!previous.empty())
        EXPECT_LT(std::abs(now[k] - previous[k]), 0.25 * std::abs(previous[k]))
            << "mode " << k << " at D " << D;
    }
    previous = now;
  }
}

TEST(FrequencyShooting, BoundaryMatrixAtZeroIsTheStaticsJacobian) {
  // At ω = 0 the frequency-domain linearisation is the tangent of the statics shot: compare
  // with StaticShootingSolver::ResidualJacobian (matrix coordinates for R instead of rotation
  // vectors: the two discretisations agree to the RK4 error, ~1e-8 here).
  SteelRod rod;
  rod.r = 0.005;
  StaticLoads loads;
  loads.gravity_W = Vec3(-9.81e3, 0, 0);
  loads.tip_force = Vec3(0, 0.5 * rod.EI() / (rod.length * rod.length), 0);
  loads.tip_moment = Vec3(0, 0, 0.3 * rod.EI() / rod.length);
  StaticShootingSolver solver(rod.model(), 41);
  ASSERT_TRUE(solver.Solve(lie::SE3(), loads).converged());
  const FrequencyShooting fs(rod.model(), solver.grid(), lie::SE3(), loads, solver.base_wrench_B());
  const double L = rod.length, EI = rod.EI();
  Vec6 scale;
  scale << EI / L, EI / L, EI / L, EI / (L * L), EI / (L * L), EI / (L * L);
  const Vec6 x = solver.base_wrench_B().cwiseQuotient(scale);
  const Mat6 J = solver.ResidualJacobian(lie::SE3(), loads, x);
  const Mat6 B = fs.BoundaryMatrix(0.0);
  EXPECT_LT((B - J).norm(), 1e-6 * J.norm()) << "B\n" << B << "\nJ\n" << J;
}

// The same for a column (clamped base, pinned tip guided along the axis) bent by gravity across
// it and pressed by a follower force along its tip's tangent: B(0) is ColumnSolver's exact
// Jacobian, whose axial row takes the follower part out of the force that turns with the tip.
TEST(FrequencyShooting, AColumnsBoundaryMatrixAtZeroIsTheColumnsJacobian) {
  SteelRod rod;
  rod.r = 0.005;
  const double L = rod.length, EI = rod.EI();
  StaticLoads loads;
  loads.gravity_W = Vec3(-9.81e3, 0, 0);
  loads.tip_force = Vec3(0, 0, -5.0 * EI / (L * L));  // along the tip's tangent, into the column
  loads.tip_force_frame = LoadFrame::kBody;
  ColumnSolver column(rod.model(), 41, ColumnEnds::kClampedPinned);
  ASSERT_TRUE(column.SolveFromUnloaded(lie::SE3(), loads).converged());
  Mat6 J;
  column.Residual(lie::SE3(), loads, column.unknowns(), &J);
  ShootingEnds ends;
  ends.tip_guided = true;
  const FrequencyShooting fs(rod.model(), column.grid(), lie::SE3(), loads,
                             column.state().wrench_B[0], {}, ends);
  const Mat6 B = fs.BoundaryMatrix(0.0);
  EXPECT_LT((B - J).norm(), 1e-6 * J.norm()) << "B\n" << B << "\nJ\n" << J;
}

}  // namespace
}  // namespace cosserat
