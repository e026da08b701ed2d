// The analytic references of support/analytic/ against the published tables they come from, so
// that every test comparing with them compares with the literature: the β_n L roots (computed
// by bisection) against tests/reference/natural_frequencies.json, the elastica closed form
// against tests/reference/elastica_tip_load.json (Bisshopp & Drucker 1945), the clamped–pinned
// and Greenhill loads against Timoshenko & Gere (1961), and the tip-mass root against Blevins
// (1979).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/analytic/beam_vibration.hpp"
#include "support/analytic/elastica.hpp"
#include "support/analytic/euler_buckling.hpp"

namespace cosserat {
namespace {

nlohmann::json LoadReference(const std::string& name) {
  std::ifstream in(std::string(COSSERAT_REFERENCE_DIR) + "/" + name);
  EXPECT_TRUE(in.good()) << "missing reference file " << name;
  return nlohmann::json::parse(in);
}

// The roots are the last bit of a bisection; the file's are printed to 16–17 digits.
TEST(AnalyticReferences, BetaLRootsMatchTheReferenceFile) {
  const nlohmann::json ref = LoadReference("natural_frequencies.json");
  const auto& cantilever = ref["beta_L_clamped_free"];
  const auto& free_free = ref["beta_L_free_free_and_clamped_clamped"];
  ASSERT_EQ(cantilever.size(), 6u);
  ASSERT_EQ(free_free.size(), 6u);
  for (int n = 1; n <= 6; ++n) {
    EXPECT_NEAR(truth::CantileverBetaL(n), cantilever[n - 1].get<double>(), 1e-12) << n;
    EXPECT_NEAR(truth::FreeFreeBetaL(n), free_free[n - 1].get<double>(), 1e-12) << n;
  }
}

// The cantilever's mode shapes satisfy its end conditions: φ = φ' = 0 at the clamp and
// φ'' = φ''' = 0 at the free end (central differences, h = 1e-3: truncation ~ (β h)² relative).
TEST(AnalyticReferences, CantileverModeShapesMeetTheEndConditions) {
  const double h = 1e-3;
  for (int n = 1; n <= 3; ++n) {
    auto phi = [n](double x) { return truth::CantileverModeShape(n, x); };
    const double b = truth::CantileverBetaL(n), scale = std::abs(phi(1.0));
    EXPECT_EQ(phi(0.0), 0.0) << n;
    // φ'(0) by central differences: truncation h² |φ'''(0)|/6 = h² σ β³/3.
    EXPECT_NEAR((phi(h) - phi(-h)) / (2 * h), 0.0, h * h * b * b * b * scale) << n;
    const double d2 = (phi(1 + h) - 2 * phi(1) + phi(1 - h)) / (h * h);
    const double d3 =
        (phi(1 + 2 * h) - 2 * phi(1 + h) + 2 * phi(1 - h) - phi(1 - 2 * h)) / (2 * h * h * h);
    EXPECT_NEAR(d2, 0.0, 1e-4 * b * b * scale) << n;
    EXPECT_NEAR(d3, 0.0, 1e-4 * b * b * b * scale) << n;
  }
}

// Blevins (1979), table 8-1: λ₁ for a tip mass equal to the beam's mass, to the digits printed.
// No mass: the bare root.
TEST(AnalyticReferences, TipMassRoot) {
  EXPECT_NEAR(truth::CantileverTipMassBetaL(1.0), truth::kTipMassEqualBetaLPrinted, 1e-4);
  EXPECT_NEAR(truth::CantileverTipMassBetaL(1e-12), truth::CantileverBetaL(1), 1e-9);
}

// Unloaded, the compressed cantilever's frequency is the bare one. At P = P_cr/2 it lies between
// Galef's ω₀ sqrt(1 − P/P_cr) (below, by about 2 %) and Rayleigh's quotient with the unloaded
// mode φ, ω² ≤ (E I ∫φ''² − P ∫φ'²)/(ρA ∫φ²) = ω₀² (1 − P ∫φ'²/(β⁴ ∫φ²)) on L = 1 (above: the
// quotient is an upper bound; trapezoid rule, central differences for φ').
TEST(AnalyticReferences, CompressedCantileverFrequency) {
  const double EI = 2.0, rhoA = 0.3, L = 1.0;
  const double b = truth::CantileverBetaL(1);
  const double w0 = truth::EulerBernoulliOmega(b, EI, rhoA, L);
  EXPECT_NEAR(truth::CompressedCantileverOmega(EI, rhoA, 1e-12 * EI, L, w0) / w0, 1.0, 1e-9);
  const double P = 0.5 * truth::EulerLoadClampedFree(EI, L);
  const double ratio = truth::CompressedCantileverOmega(EI, rhoA, P, L, w0) / w0;
  const int n = 2000;
  const double h = 1.0 / n;
  double phi2 = 0, dphi2 = 0;
  for (int i = 0; i <= n; ++i) {
    const double x = i * h, w = (i == 0 || i == n ? 0.5 : 1.0) * h;
    const double p = truth::CantileverModeShape(1, x);
    const double dp =
        (truth::CantileverModeShape(1, x + 1e-6) - truth::CantileverModeShape(1, x - 1e-6)) / 2e-6;
    phi2 += w * p * p;
    dphi2 += w * dp * dp;
  }
  const double rayleigh = std::sqrt(1 - P / EI * dphi2 / (b * b * b * b * phi2));
  EXPECT_GT(ratio, 1.01 * std::sqrt(0.5));
  EXPECT_LT(ratio, rayleigh);
}

// Timoshenko & Gere (1961): clamped–pinned βL (and P_cr L²/EI, the reference file's value),
// Greenhill's standing column q L³/EI, to the digits printed.
TEST(AnalyticReferences, BucklingRoots) {
  EXPECT_NEAR(truth::ClampedPinnedBetaL(), truth::kClampedPinnedBetaLPrinted, 1e-4);
  EXPECT_NEAR(std::tan(truth::ClampedPinnedBetaL()), truth::ClampedPinnedBetaL(), 1e-9);
  EXPECT_NEAR(truth::EulerLoadClampedPinned(1, 1), truth::kClampedPinnedLoadPrinted, 0.005);
  EXPECT_NEAR(truth::GreenhillSelfWeightLoad(), truth::kGreenhillLoadPrinted, 1e-4);
  EXPECT_NEAR(truth::EulerLoadClampedFree(1, 1, 2) / truth::EulerLoadClampedFree(1, 1), 9.0, 1e-12);
}

// The closed form reproduces every row of the table (its values are printed to 10 digits).
TEST(AnalyticReferences, TipLoadElasticaMatchesTheReferenceFile) {
  const nlohmann::json ref = LoadReference("elastica_tip_load.json");
  ASSERT_GE(ref["rows"].size(), 6u);
  for (const auto& row : ref["rows"]) {
    const double alpha = row["alpha"];
    EXPECT_NEAR(truth::TipLoadElasticaDeflection(alpha), row["deflection_over_L"].get<double>(),
                1e-8)
        << alpha;
  }
}

}  // namespace
}  // namespace cosserat
