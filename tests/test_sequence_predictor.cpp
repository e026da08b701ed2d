// SequencePredictor: polynomial extrapolation of the shooting unknowns from step to step.
// Truths: the degree-p formula is exact on polynomials of degree ≤ p; on a sampled sinusoid
// x_k = sin(θ k) its error is exactly the amplitude times |e^{iθ} − 1|^{p+1} = (2 sin(θ/2))^{p+1}
// (the (p+1)-th forward difference), so the best degree is known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>

#include "cosserat/strong/sequence_predictor.hpp"

namespace cosserat {
namespace {

Vec6 Term(double t) {
  Vec6 x;
  x << 1 + 2 * t - t * t + 0.5 * t * t * t, std::sin(t), std::cos(t), 3.0, -t, t * t;
  return x;
}

TEST(SequencePredictor, ExactOnCubicsOnceFiveTermsAreKnown) {
  // Cubic components: degrees ≥ 3 predict them to round-off; the sin/cos components are not
  // cubic, so compare only the polynomial ones (0, 3, 4, 5).
  const double h = 0.1;
  SequencePredictor p;
  p.Reset(Term(0));
  for (int k = 1; k <= 7; ++k) p.Push(Term(k * h), h);
  const Vec6 predicted = p.Predict(h), truth = Term(8 * h);
  for (int i : {0, 3, 4, 5}) EXPECT_NEAR(predicted(i), truth(i), 1e-12) << i;
  EXPECT_GE(p.degree(), 3);
}

TEST(SequencePredictor, SinusoidErrorMatchesTheForwardDifferenceFormula) {
  // θ = 0.3 (between ω dt of the peer problem's first and second bending modes, 0.07 and 0.44):
  // the degree-10 error θ^11 ≈ 2e-6 stays far above the round-off of its weighted sum (weights
  // summing to 2047 in magnitude: ~5e-13), so the formula is what is measured.
  const double theta = 0.3;
  SequencePredictor p;
  auto term = [](double phase) { return Vec6::Constant(std::sin(phase)); };
  p.Reset(term(0));
  for (int k = 1; k < 40; ++k) p.Push(term(k * theta), 2e-3);
  // All degrees up to kMaxDegree are exact to (2 sin(θ/2))^{p+1} ≈ θ^{p+1}; the highest wins here.
  EXPECT_EQ(p.degree(), SequencePredictor::kMaxDegree);
  const double bound = std::pow(2 * std::sin(theta / 2), SequencePredictor::kMaxDegree + 1);
  const double error = (p.Predict(2e-3) - term(40 * theta)).cwiseAbs().maxCoeff();
  EXPECT_LE(error, bound * (1 + 1e-6) + 1e-12);  // round-off of the sum: ~2047 × 1e-16 × 2
  EXPECT_GT(error, 0.1 * bound);                 // it is the formula's error, not luck
}

TEST(SequencePredictor, AlternatingSequencePicksTheLowestDegreeAllowed) {
  // x_k = (−1)^k: degree p errs by 2^{p+1}, so the lowest degree allowed is best.
  for (int min_degree : {0, 2}) {
    SequencePredictor p(min_degree);
    p.Reset(Vec6::Ones());
    for (int k = 1; k < 12; ++k) p.Push(Vec6::Constant(k % 2 ? -1.0 : 1.0), 1.0);
    EXPECT_EQ(p.degree(), min_degree);
    // 11 is odd, so the latest term is −1 and the truth +1: the error is 2^{p+1}.
    EXPECT_DOUBLE_EQ((p.Predict(1.0) - Vec6::Ones()).cwiseAbs().maxCoeff(),
                     std::pow(2.0, min_degree + 1));
  }
}

TEST(SequencePredictor, AnotherSpacingKeepsOnlyTheLatestTwoTerms) {
  SequencePredictor p;
  p.Reset(Vec6::Zero());
  for (int k = 1; k <= 6; ++k) p.Push(Vec6::Constant(k), 1.0);  // linear, spacing 1
  EXPECT_EQ(p.size(), 7);
  EXPECT_NEAR(p.Predict(1.0)(0), 7.0, 1e-12);
  // At another spacing the prediction is the latest term; after a push at spacing 0.5 only the
  // two terms 0.5 apart remain, and a linear extrapolation from them needs one more.
  EXPECT_EQ(p.Predict(0.5), p.latest());
  p.Push(Vec6::Constant(6.5), 0.5);
  EXPECT_EQ(p.size(), 2);
  p.Push(Vec6::Constant(7.0), 0.5);
  EXPECT_NEAR(p.Predict(0.5)(0), 7.5, 1e-12);
}

TEST(SequencePredictor, WeightedScoresPickTheDegreeForTheComponentsThatCount) {
  // Component 0 alternates, (−1)^k: degree p errs by 2^{p+1} there, so the lowest degree wins.
  // Component 1 is a slow sinusoid: the highest degree wins there. Unweighted, the alternating
  // component dominates the score; weighted by diag(0, 1, 0, …) (the stepper passes its
  // Jacobian: what counts is the residual an error gives), only the sinusoid counts.
  const double theta = 0.3;
  auto term = [&](int k) {
    Vec6 x = Vec6::Zero();
    x(0) = k % 2 ? -1.0 : 1.0;
    x(1) = std::sin(theta * k);
    return x;
  };
  Mat6 weight = Mat6::Zero();
  weight(1, 1) = 1.0;
  SequencePredictor plain(2), weighted(2);
  plain.Reset(term(0));
  weighted.Reset(term(0));
  for (int k = 1; k < 40; ++k) {
    plain.Push(term(k), 1.0);
    weighted.Push(term(k), 1.0, &weight);
  }
  EXPECT_EQ(plain.degree(), 2);
  EXPECT_EQ(weighted.degree(), SequencePredictor::kMaxDegree);
}

TEST(SequencePredictor, RecurrenceHoldsFastDampedModesThatNoDegreeCan) {
  // The peer release's start-up (docs/performance.md, "The start-up after a release"): a slow swing plus the discrete
  // modes 3 and 4 of BDF2 at dt = 2 ms, ζ = 0.895 e^{0.952i} and 0.702 e^{1.372i}, on which a
  // degree-p extrapolation errs by |1 − 1/ζ|^{p+1} ≈ 0.98^{p+1} and 1.57^{p+1} times the
  // amplitude. Six components with different phases and amplitudes, the same roots.
  const std::complex<double> z3 = std::polar(0.8952, 0.952), z4 = std::polar(0.7017, 1.372);
  auto term = [&](int k) {
    Vec6 x;
    for (int c = 0; c < 6; ++c) {
      const std::complex<double> a3 = std::polar(1.0 + c, 0.7 * c),
                                 a4 = std::polar(2.0 - 0.3 * c, -0.4 * c);
      x(c) = 0.5 * std::cos(0.07 * k + c) + (a3 * std::pow(z3, k)).real() +
             (a4 * std::pow(z4, k)).real();
    }
    return x;
  };
  SequencePredictor poly(2), rec(2, true);
  poly.Reset(term(0));
  rec.Reset(term(0));
  const int n = 30;
  for (int k = 1; k < n; ++k) {
    poly.Push(term(k), 2e-3);
    rec.Push(term(k), 2e-3);
  }
  EXPECT_TRUE(rec.uses_recurrence());
  const double poly_error = (poly.Predict(2e-3) - term(n)).norm();
  const double rec_error = (rec.Predict(2e-3) - term(n)).norm();
  std::printf("next-term error: degrees %.2e (degree %d), recurrence %.2e\n", poly_error,
              poly.degree(), rec_error);
  // Measured: degrees 0.22 (mode 3 at k = 30 is still 0.895^30 ≈ 0.036 of its amplitude),
  // recurrence 4e-10 — its 10 lags hold both modes and the slow swing (a recurrence of order 6
  // on the second differences) to the fit's round-off and ridge.
  EXPECT_GT(poly_error, 1e-2);
  EXPECT_LT(rec_error, 1e-3 * poly_error);
}

}  // namespace
}  // namespace cosserat
