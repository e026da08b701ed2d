// Buckling on the quaternion-FD model against the truth: Euler's load of the cantilever, the
// SE(3) shooting analysis of the same rod, and the second-order convergence of the discrete
// model's critical load.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "cosserat/analysis/quatfd_buckling.hpp"
#include "cosserat/rod/section_profile.hpp"
#include "../src/analysis/banded_inertia.hpp"
#include "support/analytic/euler_buckling.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

// The slender steel column of test_buckling.cpp (r/L = 1/200): the Cosserat model's critical load
// lies 2.8e-5 below Euler's (shear and extension), the same for both formulations.
const testing::SteelRod kColumn{1.0, 0.005};
RodModel SteelColumn() { return kColumn.model(); }
double EulerCantilever() { return truth::EulerLoadClampedFree(kColumn.EI(), kColumn.length); }

QuatFdBucklingSummary QuatFdCritical(int segments) {
  quatfd::QuatFdOptions mo;
  mo.segments = segments;
  QuatFdBucklingOptions options;
  options.lambda_max = 1.5 * EulerCantilever();
  options.scan_steps = 15;  // steps of 0.1 P_E; the refinement (Illinois) does the rest
  QuatFdBuckling b(SteelColumn(), lie::SE3{}, LoadPath::TipForce(Vec3(0, 0, -1)), mo, options);
  return b.FindCriticalLoad();
}

// Acceptance: the Euler load at 40 segments within 0.5 %, and the SE(3) shooting analysis's
// critical load (RK4 on 41 nodes: 1e-7 from its converged value, so the exact Cosserat load for
// this comparison) within 1e-3: the quaternion-FD scheme is second order, and for the first
// cantilever mode (wavenumber π/2L) its error is of the order (πΔs/2L)²/12 ≈ 1.3e-4 at
// Δs = L/40.
TEST(QuatFdBuckling, CantileverEulerLoadAt40Segments) {
  const double P = EulerCantilever();
  const QuatFdBucklingSummary q = QuatFdCritical(40);
  ASSERT_TRUE(q.found()) << ToString(q.status);
  BucklingOptions so;
  so.lambda_max = 1.5 * P;
  BucklingAnalysis se3(SteelColumn(), 41, ColumnEnds::kClampedFree, lie::SE3{},
                       LoadPath::TipForce(Vec3(0, 0, -1)), so);
  const BucklingSummary s = se3.FindCriticalLoad();
  ASSERT_TRUE(s.found());
  std::printf("quatfd N = 40: P_cr/P_Euler - 1 = %+.3e, against SE(3) %+.3e (%d solves, %.0f ms)\n",
              q.critical_load / P - 1, q.critical_load / s.critical_load - 1, q.solves,
              1e3 * q.wall_time_s);
  EXPECT_NEAR(q.critical_load / P, 1.0, 5e-3);
  EXPECT_NEAR(q.critical_load / s.critical_load, 1.0, 1e-3);
  // A circle buckles in two planes at once: two eigenvalues cross zero together.
  EXPECT_EQ(q.multiplicity, 2);
  EXPECT_EQ(q.mode_s_max, 0.0);  // Euler's cantilever mode bends most at the clamp
}

// The error against the SE(3) load falls as Δs²: order fitted over 10, 20, 40 segments.
TEST(QuatFdBuckling, CriticalLoadConvergesAtSecondOrder) {
  BucklingOptions so;
  so.lambda_max = 1.5 * EulerCantilever();
  BucklingAnalysis se3(SteelColumn(), 41, ColumnEnds::kClampedFree, lie::SE3{},
                       LoadPath::TipForce(Vec3(0, 0, -1)), so);
  const double reference = se3.FindCriticalLoad().critical_load;
  std::vector<double> errors;
  for (int n : {10, 20, 40}) {
    const QuatFdBucklingSummary q = QuatFdCritical(n);
    ASSERT_TRUE(q.found()) << n;
    errors.push_back(std::abs(q.critical_load / reference - 1));
    std::printf("quatfd N = %2d: |P_cr / P_cr(SE(3)) - 1| = %.3e\n", n, errors.back());
  }
  for (int k = 0; k < 2; ++k) {
    const double order = std::log2(errors[k] / errors[k + 1]);
    EXPECT_GT(order, 1.7) << k;
    EXPECT_LT(order, 2.3) << k;
  }
}

// The stiffness is the Hessian of a potential: symmetric to the difference error, and positive
// definite at zero load.
TEST(QuatFdBuckling, StiffnessIsSymmetricAndPositiveUnloaded) {
  quatfd::QuatFdOptions mo;
  mo.segments = 12;
  QuatFdBucklingOptions options;
  options.lambda_max = 1.0;
  LoadPath path = LoadPath::TipForce(Vec3(0.3, 0, -1));
  path.fixed.gravity_W = Vec3(0, -9.81, 0);
  QuatFdBuckling b(SteelColumn(), lie::SE3{}, path, mo, options);
  Eigen::VectorXd q = b.q();
  EXPECT_GT(b.StiffnessEigenvalues(0.0, q)(0), 0.0);
  // A bent equilibrium under a sideways load and gravity, solved on a model of the same rod.
  quatfd::QuatFdModel twin(SteelColumn(), lie::SE3{}, mo);
  ASSERT_TRUE(quatfd::SolveStatics(&twin, path.LoadsAt(100.0), q).converged());
  const Eigen::VectorXd e = b.StiffnessEigenvalues(100.0, q);
  EXPECT_LT(b.last_asymmetry(), 1e-5) << "relative |H - H^T|";
  EXPECT_GT(e(0), 0.0);
  // The stiffness from the exact banded ∂f/∂q against central differences of the forces: the
  // difference error is O(h²) ≈ 1e-10 of an entry (h = 1e-5), round-off ε |G|/h ≈ 1e-11
  // (measured 4.5e-12).
  const Eigen::MatrixXd Ha = b.Stiffness(100.0, q, false), Hf = b.Stiffness(100.0, q, true);
  const double diff = (Ha - Hf).cwiseAbs().maxCoeff() / Ha.cwiseAbs().maxCoeff();
  std::printf("stiffness: analytic vs central differences %.2e (relative to the largest entry)\n",
              diff);
  EXPECT_LT(diff, 1e-8);
}

// The count of unstable directions by the inertia of the banded stiffness (an LDLᵀ factorisation
// of H + 1e-6 I in the coordinates ordered along the rod, Sylvester's law) against the count of
// its eigenvalues below −1e-6, the same matrix's spectrum: the straight column pressed by 0.5 to
// 60 cantilever Euler loads (2 more unstable directions past each), and a bent equilibrium.
// The banded count on its own (the test below cannot tell it from its eigenvalue fallback): the
// second-difference matrix tridiag(−1, 2 − σ, −1) of size m has the eigenvalues
// 2 − σ − 2 cos(kπ/(m + 1)), so a known number below zero. Its rows and columns shuffled, the
// count in the order that makes it tridiagonal again is that number, and never −1 (σ keeps every
// eigenvalue 1e-3 or more from zero, far above the pivot floor).
TEST(QuatFdBuckling, TheBandedInertiaCountsAShuffledSecondDifference) {
  const int m = 60;
  std::vector<int> shuffled(m);
  for (int i = 0; i < m; ++i) shuffled[i] = (7 * i + 3) % m;  // 7 is prime to 60: a permutation
  for (const double sigma : {0.0, 0.5, 1.7, 3.1}) {
    std::vector<Eigen::Triplet<double>> entries;  // S(p(i), p(j)) = T(i, j)
    for (int i = 0; i < m; ++i) {
      entries.emplace_back(shuffled[i], shuffled[i], 2.0 - sigma);
      if (i + 1 < m) {
        entries.emplace_back(shuffled[i], shuffled[i + 1], -1.0);
        entries.emplace_back(shuffled[i + 1], shuffled[i], -1.0);
      }
    }
    Eigen::SparseMatrix<double> S(m, m);
    S.setFromTriplets(entries.begin(), entries.end());
    int expected = 0;
    for (int k = 1; k <= m; ++k) expected += 2.0 - sigma - 2.0 * std::cos(k * M_PI / (m + 1)) < 0;
    const detail::SymmetricBand band = detail::BandInOrder(S, shuffled);
    EXPECT_EQ(band.half_bandwidth(), 1) << sigma;  // tridiagonal again in that order
    EXPECT_EQ(detail::CountEigenvaluesBelow(band, 0.0), expected) << sigma;
  }
}

TEST(QuatFdBuckling, TheInertiaCountsTheNegativeEigenvaluesOfTheSpectrum) {
  quatfd::QuatFdOptions mo;
  mo.segments = 40;
  QuatFdBucklingOptions options;
  options.lambda_max = 1.0;
  const LoadPath axial = LoadPath::TipForce(Vec3(0, 0, -1));
  QuatFdBuckling b(SteelColumn(), lie::SE3{}, axial, mo, options);
  quatfd::QuatFdModel twin(SteelColumn(), lie::SE3{}, mo);
  int largest = 0;
  for (const double ratio : {0.5, 1.5, 7.0, 20.0, 60.0}) {
    const double lambda = ratio * EulerCantilever();
    Eigen::VectorXd q = b.q();  // straight, then shortened by the load: still straight
    ASSERT_TRUE(quatfd::SolveStatics(&twin, axial.LoadsAt(lambda), q).converged());
    const Eigen::VectorXd e = b.StiffnessEigenvalues(lambda, q);
    const int spectrum = static_cast<int>((e.array() < -1e-6).count());
    EXPECT_EQ(b.StiffnessEigenvaluesBelow(lambda, q, 1e-6), spectrum) << ratio;
    largest = std::max(largest, spectrum);
  }
  EXPECT_GE(largest, 8);  // the count was exercised, not only zeros
  LoadPath side = LoadPath::TipForce(Vec3(0.3, 0, -1));
  side.fixed.gravity_W = Vec3(0, -9.81, 0);
  QuatFdBuckling bent(SteelColumn(), lie::SE3{}, side, mo, options);
  Eigen::VectorXd qb = bent.q();
  ASSERT_TRUE(quatfd::SolveStatics(&twin, side.LoadsAt(100.0), qb).converged());
  const Eigen::VectorXd e = bent.StiffnessEigenvalues(100.0, qb);
  EXPECT_EQ(bent.StiffnessEigenvaluesBelow(100.0, qb, 1e-6),
            static_cast<int>((e.array() < -1e-6).count()));
}

// A soft band (α = 0.1 on [0.6, 0.7] L, band ends on vertices) localises the buckle on the
// quaternion-FD model as on the SE(3) one: the same critical load to 2e-3 (second order with a
// stiffness jump on a vertex; measured +6.2e-5) and the mode bending most in the band (0.625 L:
// the first vertex inside it; the vertex at 0.6 L straddles the jump).
TEST(QuatFdBuckling, SoftBandAgreesWithShooting) {
  RodModel model = SteelColumn();
  model.section = std::make_shared<BandedSection>(
      std::make_shared<UniformSection>(kColumn.section(), kColumn.material),
      std::vector<BandedSection::Band>{{0.6, 0.7, 0.1}});
  const double P = EulerCantilever();
  BucklingOptions so;
  so.lambda_max = 1.5 * P;
  BucklingAnalysis se3(model, 41, ColumnEnds::kClampedFree, lie::SE3{},
                       LoadPath::TipForce(Vec3(0, 0, -1)), so);
  const BucklingSummary s = se3.FindCriticalLoad();
  ASSERT_TRUE(s.found());
  quatfd::QuatFdOptions mo;
  mo.segments = 40;
  QuatFdBucklingOptions options;
  options.lambda_max = 1.5 * P;
  options.scan_steps = 15;
  QuatFdBuckling b(model, lie::SE3{}, LoadPath::TipForce(Vec3(0, 0, -1)), mo, options);
  const QuatFdBucklingSummary q = b.FindCriticalLoad();
  ASSERT_TRUE(q.found());
  std::printf("band: quatfd P_cr / SE(3) - 1 = %+.3e, mode s_max %.3f (SE(3) %.3f) m\n",
              q.critical_load / s.critical_load - 1, q.mode_s_max, s.mode.s_max_curvature);
  EXPECT_NEAR(q.critical_load / s.critical_load, 1.0, 2e-3);
  EXPECT_GE(q.mode_s_max, 0.6);
  EXPECT_LE(q.mode_s_max, 0.7);
}

// A standing column under its own weight (Greenhill 1881): it buckles at q L³/EI = 7.8373
// (q = ρ A g, the first root of J_{−1/3}(2/3 sqrt(q L³/EI)) = 0), a distributed load path on both
// formulations. Both within 0.5 % of Greenhill (the shear and extension difference is O((r/L)²)
// as for the tip load; the quatfd discretisation, with lumped vertex weights, is O(Δs²)), and
// within 1e-3 of each other. Measured: quatfd −3.6e-4, SE(3) −3.6e-5 (7.8373 is good to 1e-5).
TEST(QuatFdBuckling, SelfWeightBucklingIsGreenhills) {
  const double EI = kColumn.EI(), rhoA = kColumn.rhoA();
  const double g_cr = truth::GreenhillSelfWeightLoad() * EI / rhoA;  // m/s², L = 1
  LoadPath path;
  path.per_unit.gravity_W = Vec3(0, 0, -1);  // λ: the gravity, m/s²
  quatfd::QuatFdOptions mo;
  mo.segments = 40;
  QuatFdBucklingOptions options;
  options.lambda_max = 1.5 * g_cr;
  options.scan_steps = 15;
  const QuatFdBucklingSummary q =
      QuatFdBuckling(SteelColumn(), lie::SE3{}, path, mo, options).FindCriticalLoad();
  ASSERT_TRUE(q.found());
  BucklingOptions so;
  so.lambda_max = 1.5 * g_cr;
  const BucklingSummary s =
      BucklingAnalysis(SteelColumn(), 41, ColumnEnds::kClampedFree, lie::SE3{}, path, so)
          .FindCriticalLoad();
  ASSERT_TRUE(s.found());
  std::printf("self-weight: quatfd g_cr/Greenhill - 1 = %+.3e, SE(3) %+.3e\n",
              q.critical_load / g_cr - 1, s.critical_load / g_cr - 1);
  EXPECT_NEAR(q.critical_load / g_cr, 1.0, 5e-3);
  EXPECT_NEAR(s.critical_load / g_cr, 1.0, 5e-3);
  EXPECT_NEAR(q.critical_load / s.critical_load, 1.0, 1e-3);
}

// A cantilever the file's own loads press past Euler's load (a fixed 5 P_E; the next load is
// 9 P_E): its stiffness at λ = 0 already has the two negative eigenvalues of the first,
// double root, and the search once reported "found" at 0 on top of it. Under half of P_E fixed
// the search finds the other half (to the 5e-3 of CantileverEulerLoadAt40Segments).
TEST(QuatFdBuckling, APreloadPastEulersLoadIsReportedNotAHigherLoad) {
  const double P = EulerCantilever();
  auto search = [&](double preload) {
    quatfd::QuatFdOptions mo;
    mo.segments = 40;
    QuatFdBucklingOptions options;
    options.lambda_max = 1.5 * P;
    options.scan_steps = 15;
    LoadPath path = LoadPath::TipForce(Vec3(0, 0, -1));
    path.fixed.tip_force = Vec3(0, 0, -preload);
    QuatFdBuckling b(SteelColumn(), lie::SE3{}, path, mo, options);
    return b.FindCriticalLoad();
  };
  const QuatFdBucklingSummary past = search(5 * P);
  ASSERT_EQ(past.status, BucklingStatus::kPreloadPastCritical) << ToString(past.status);
  EXPECT_EQ(past.preload_unstable_directions, 2);
  const QuatFdBucklingSummary below = search(0.5 * P);
  ASSERT_TRUE(below.found()) << ToString(below.status);
  EXPECT_NEAR((0.5 * P + below.critical_load) / P, 1.0, 5e-3);
}

TEST(QuatFdBuckling, BadInputNamesTheField) {
  quatfd::QuatFdOptions mo;
  mo.segments = 8;
  auto message = [&](const quatfd::QuatFdOptions& m, const LoadPath& path,
                     const QuatFdBucklingOptions& o) -> std::string {
    try {
      QuatFdBuckling b(SteelColumn(), lie::SE3{}, path, m, o);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  const LoadPath dead = LoadPath::TipForce(Vec3(0, 0, -1));
  quatfd::QuatFdOptions pinned = mo;
  pinned.base_end = quatfd::EndCondition::kPinned;
  EXPECT_NE(message(pinned, dead, {}).find("base_end"), std::string::npos);
  EXPECT_NE(message(mo, LoadPath::TipForce(Vec3(0, 0, -1), LoadFrame::kBody), {})
                .find("tip_force_frame"),
            std::string::npos);
  LoadPath tension;
  tension.tension_per_unit[0] = 1;
  EXPECT_NE(message(mo, tension, {}).find("load path"), std::string::npos);
  QuatFdBucklingOptions bad;
  bad.lambda_max = -1;
  EXPECT_NE(message(mo, dead, bad).find("lambda_max"), std::string::npos);
}

}  // namespace
}  // namespace cosserat
