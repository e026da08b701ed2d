#pragma once
/// \file
/// Predicts the next term of an evenly spaced sequence of 6-vectors (the shooting unknowns of
/// successive time steps) by polynomial extrapolation, choosing the degree that predicted the
/// recent terms best. A good predictor is worth more than anything else in the shooting stepper:
/// the tip residual amplifies an error in the base unknowns by the shot's gain e^{λL}, so the
/// Newton iteration count depends on it directly. Fixed size: no heap allocation.

#include <Eigen/Core>
#include <array>

#include "cosserat/lie/types.hpp"

namespace cosserat {

class SequencePredictor {
 public:
  // Degree 10 on the peer release (bench/peer_rod.hpp): the first residual of a step falls from
  // 3e-6 (degree ≤ 6) to ~3e-8, near the floor set by the converged terms' own errors (the weights
  // of degree p sum to 2^{p+1} − 1 in magnitude, 2047 here); degrees 11–12 gained nothing.
  static constexpr int kMaxDegree = 10;

  /// Degrees below min_degree are never chosen once enough terms are known for it. The stepper
  /// uses 2: in the fast transient right after a release, the running scores are too noisy to
  /// trust a constant or linear guess (one such pick left Newton outside its basin on a tip-mass
  /// test at dt = 1 ms, where the quadratic always converged).
  explicit SequencePredictor(int min_degree = 0, bool recurrence = false);

  /// The recurrence candidate (constructor flag `recurrence`): a linear recurrence of
  /// kRecurrenceLags terms on the second differences of the sequence, d_k = x_k − 2x_{k−1} +
  /// x_{k−2}, d_{k+1} ≈ Σ_i a_i d_{k−i}, with scalar a_i shared by the six components and fitted
  /// by least squares (each component weighted by its column norm of the first weight passed,
  /// older equations forgotten by kRecurrenceMemory per term). It is scored like the degrees and
  /// used when it has predicted best recently. It needs kRecurrenceLags + 3 terms. Why: the
  /// sudden release of the peer problem excites the rod's third to fifth bending modes,
  /// which BDF2 at dt = 2 ms turns by 1–1.6 rad per step and damps by 0.9–0.5 per step; no
  /// polynomial can extrapolate them (the degree-p error on such a mode is |1 − 1/ζ|^{p+1} ≥ 1
  /// times its amplitude), while a short recurrence holds them exactly. Off by default.
  static constexpr int kRecurrenceLags = 10;
  static constexpr double kRecurrenceMemory = 0.8;
  /// The recurrence is solved and scored only while the best degree's score exceeds this (in
  /// the units of the weighted squared error: with the stepper's Jacobian, first residuals of
  /// 1e-5, where Newton needs 3 shots; on the peer problem the degrees do better after ~1 s).
  /// Solved at every step, it cost ~1 µs per step (a tenth of a peer-problem step, measured);
  /// its normal equations are kept up to date all the same.
  static constexpr double kRecurrenceFrom = 1e-10;

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
  /// Predict() uses the recurrence candidate rather than the degree().
  bool uses_recurrence() const { return use_recurrence_; }

 private:
  /// Extrapolation of degree p from terms_[first], terms_[first + 1], … (newest first):
  /// Σ_{j=0}^{p} (−1)^j C(p+1, j+1) terms_[first + j], exact for polynomials of degree p.
  Vec6 Extrapolate(int p, int first) const;

  /// Newest first; the recurrence's prediction needs kRecurrenceLags + 2 of them.
  std::array<Vec6, (kMaxDegree > kRecurrenceLags ? kMaxDegree : kRecurrenceLags) + 2> terms_{};
  int count_ = 0;
  double spacing_ = 0.0;
  int min_degree_ = 0;
  int degree_ = 0;
  std::array<double, kMaxDegree + 1> score_{};  ///< running mean square error per degree; −1: none

  // The recurrence candidate.
  void ResetRecurrence();
  /// Scores the recurrence's prediction of x (the latest term, already pushed), updates the fit
  /// and predicts the next term; chooses it over the degrees when its score beats `best`.
  void PushRecurrence(const Vec6& x, const Mat6* weight, double best);
  static constexpr int kLags = kRecurrenceLags;
  using MatL = Eigen::Matrix<double, kLags, kLags>;
  using VecL = Eigen::Matrix<double, kLags, 1>;
  bool recurrence_ = false;
  bool use_recurrence_ = false;
  int differences_ = 0;                     ///< second differences known (≤ kLags + 1)
  std::array<Vec6, kLags + 1> weighted_{};  ///< fit_scale_ ⊙ d_k, newest first
  /// The fit's weights: the column norms of the weight at the fit's first term, then fixed (the
  /// normal equations are accumulated, so every equation must be weighted alike).
  Vec6 fit_scale_ = Vec6::Ones();
  MatL gram_ = MatL::Zero();       ///< normal equations of the fit, forgetting
  MatL lags_gram_ = MatL::Zero();  ///< Gram matrix of the newest equation's lags
  bool lags_gram_valid_ = false;
  VecL rhs_ = VecL::Zero();
  bool recurrence_ready_ = false;              ///< recurrence_prediction_ is valid
  Vec6 recurrence_prediction_ = Vec6::Zero();  ///< of the next term, at spacing_
  double recurrence_score_ = -1.0;
};

}  // namespace cosserat
