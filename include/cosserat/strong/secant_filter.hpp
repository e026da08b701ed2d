#pragma once
/// \file
/// The Jacobian of the BDF2 shooting residual, tracked across time steps from the secants that
/// Newton measures (bdf2_stepper.cpp, SolveStep).
///
/// Model: a Kalman filter on the rows of J, which change smoothly with the rod's motion: "J
/// changes by D per step, D drifts". Each step starts from J + D; each measured secant (dx, dr),
/// J dx = dr, corrects J and D by the gain of one 12 × 12 covariance P of (row of J, row of D),
/// shared by the six rows. Unlike Broyden's update, which forgets J along every earlier dx as
/// soon as a new dx differs, the filter keeps what earlier secants taught (P shrinks along them)
/// and learns the drift from step to step. With P = identity and no drift it is Broyden's update.
/// The secants are taken as exact (Newton's corrections are ~1e-8, where the shot is linear), so
/// only ratios of the noise levels matter: J is held to its last measurements (kDriftJ ≪
/// kDriftRate) and its rate follows the latest steps. The rate decays by kRateMemory per step (a
/// memory of ~100 steps), so steps without secants (a rod at rest, converged at its first shot)
/// cannot drift J without bound. Peer release (bench/peer_rod.hpp): 2.89 shots per step with
/// Broyden's update, 2.20 with the filter; the same to ±0.003 with kDriftRate 100× smaller, kDriftJ
/// 100× larger or kRateMemory 1; 2.23 at kRateMemory 0.95, 2.46 at 0.8.
///
/// Fixed size, no heap allocation.

#include <Eigen/Core>

#include "cosserat/lie/types.hpp"

namespace cosserat {

class SecantFilter {
 public:
  static constexpr double kDriftJ = 1e-8;      ///< process noise of J per step
  static constexpr double kDriftRate = 1e-2;   ///< process noise of D per step
  static constexpr double kRateMemory = 0.99;  ///< D decays by this factor per step

  SecantFilter() { Restart(Mat6::Identity()); }

  /// Starts over from a known (exact) Jacobian: no rate, the start covariance (unit variance on
  /// J's entries, 1e-2 on D's, uncorrelated). An exact Jacobian must restart the filter: the rate
  /// and covariance described the J it replaces.
  void Restart(const Mat6& jacobian);
  /// On to the next time step: J ← J + D, D ← ρ D, P ← F P Fᵀ + diag(kDriftJ, kDriftRate) with
  /// F = [I I; 0 ρI].
  void Advance();
  /// One measured secant: the residual changed by dr when the unknowns moved by dx.
  void Update(const Vec6& dx, const Vec6& dr);

  const Mat6& jacobian() const { return jacobian_; }
  const Mat6& rate() const { return rate_; }

 private:
  using Mat12 = Eigen::Matrix<double, 12, 12>;
  Mat6 jacobian_;
  Mat6 rate_;
  Mat12 covariance_;
};

}  // namespace cosserat
