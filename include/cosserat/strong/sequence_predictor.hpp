#pragma once
/// \file
/// Predicts the next term of an evenly spaced sequence of 6-vectors (the shooting unknowns of
/// successive time steps) by polynomial extrapolation, choosing the degree that predicted the
/// recent terms best. A good predictor is worth more than anything else in the shooting stepper:
/// the tip residual amplifies an error in the base unknowns by the shot's gain e^{λL}, so the
/// Newton iteration count depends on it directly. Fixed size: no heap allocation.

#include <array>

#include "cosserat/lie/types.hpp"

namespace cosserat {

class SequencePredictor {
 public:
  // Degree 10 on the peer problem (issue 3): the first residual of a step falls from 3e-6
  // (degree ≤ 6) to ~3e-8, near the floor set by the converged terms' own errors (the weights
  // of degree p sum to 2^{p+1} − 1 in magnitude, 2047 here); degrees 11–12 gained nothing.
  static constexpr int kMaxDegree = 10;

  /// Degrees below min_degree are never chosen once enough terms are known for it. The stepper
  /// uses 2: in the fast transient right after a release, the running scores are too noisy to
  /// trust a constant or linear guess (one such pick left Newton outside its basin on a tip-mass
  /// test at dt = 1 ms, where the quadratic always converged).
  explicit SequencePredictor(int min_degree = 0);

  /// Forgets everything; `x` becomes the only term.
  void Reset(const Vec6& x);
  /// Appends the term that follows the latest one at distance `spacing` (a time step, s). A
  /// spacing other than the previous one drops all but the latest two terms, since the
  /// extrapolation weights assume even spacing. With `weight`, the degrees are scored by the
  /// norm of weight × (prediction − x) instead of the plain norm: the stepper passes its
  /// Jacobian, so that the score is the first residual each degree would have given.
  void Push(const Vec6& x, double spacing, const Mat6* weight = nullptr);
  /// The next term at distance `spacing` after the latest one: the extrapolation of the current
  /// degree, or the latest term itself when the spacing differs or too few terms are known.
  Vec6 Predict(double spacing) const;

  const Vec6& latest() const { return terms_[0]; }
  int size() const { return count_; }
  /// Degree used by Predict(): the one from min_degree up whose recent predictions erred least
  /// (a running mean of the squared errors, halving the weight of each older one).
  int degree() const { return degree_; }

 private:
  /// Extrapolation of degree p from terms_[first], terms_[first + 1], … (newest first):
  /// Σ_{j=0}^{p} (−1)^j C(p+1, j+1) terms_[first + j], exact for polynomials of degree p.
  Vec6 Extrapolate(int p, int first) const;

  std::array<Vec6, kMaxDegree + 2> terms_{};  ///< newest first
  int count_ = 0;
  double spacing_ = 0.0;
  int min_degree_ = 0;
  int degree_ = 0;
  std::array<double, kMaxDegree + 1> score_{};  ///< running mean square error per degree; −1: none
};

}  // namespace cosserat
