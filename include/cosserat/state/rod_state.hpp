#pragma once
/// \file
/// RodState: the solution along the grid, written by the solvers.

#include <vector>

#include "cosserat/lie/types.hpp"

namespace cosserat {

/// Fields sampled at the grid nodes s_i. The internal wrench W = [m; n] is the wrench the part
/// (s, L] of the rod exerts on the part [0, s]; for a linear elastic rod W = K (ξ − ξ*), which is
/// −Λ in the sign convention of FD notes 2025 (eq. 16).
struct RodState {
  std::vector<double> s;          ///< arc length, m
  std::vector<Vec3> position_W;   ///< centreline p(s), world frame, m
  std::vector<Mat3> rotation_WB;  ///< R(s): body (section) frame to world
  std::vector<Vec6> strain;       ///< ξ = [K; Γ], body frame, (1/m; –)
  std::vector<Vec6> wrench_B;     ///< W = [m; n], body frame, (N·m; N)
  std::vector<Vec6> twist_B;      ///< V = [ω; v], body frame, (rad/s; m/s); zero in statics

  void Resize(int num_nodes);
  int size() const { return static_cast<int>(s.size()); }
  const Vec3& tip_position_W() const { return position_W.back(); }
  const Mat3& tip_rotation_WB() const { return rotation_WB.back(); }
  /// The wrench the support applies to the rod at s = 0, world frame, moment about p(0):
  /// [m; n] = −[R m_B; R n_B] at s = 0. It balances the external loads.
  Vec6 BaseReaction_W() const;
  /// The largest internal force |n| over the nodes (N): a held cable's top tension.
  double MaxForce() const;
  /// Whether a shot along s ran away: some segment does (SegmentsRanAway), or some node's frame
  /// is no longer a rotation (FrameRanAway). Residuals can still vanish there (a tendon's pull
  /// is internal; a tip frame grown many times over meets a tip load with as many times the
  /// internal force), so the shooting statics and the BDF2 stepper check the state they
  /// converged on.
  bool RanAway() const;
  /// Whether some segment ran away (SegmentRanAway): a runaway more pieces cannot mend.
  bool SegmentsRanAway() const;
};

/// Whether a segment of length h along s (m) ran away in the shot: it spans more than 10 h (a
/// stretch no elastic rod takes) while its curvature turns the section by more than 1 rad on it
/// (`turn`, a bend RK4 in s cannot follow on that grid). False for NaN: not a runaway.
inline bool SegmentRanAway(double h, double span, double turn) {
  return span > 10.0 * h && turn > 1.0;
}

/// Whether a frame R carried along s by RK4 has left the rotations: |‖R‖_F² − 3| > 1. RK4's
/// polynomial in κ̂ h scales the plane it turns by |1 + iθ − θ²/2 − iθ³/6 + θ⁴/24| for a turn θ on
/// a segment (0.95 at θ = 1.45 rad, ‖R‖_F² = 2.81), and the factors compound along a shot, whose
/// frames are made rotations again only at its start (a junction of multiple shooting): one
/// segment passes the bound beyond θ ≈ 2.06 rad, twenty at 1.2 rad. False for NaN: not a
/// runaway.
inline bool FrameRanAway(const Mat3& R) { return std::abs(R.squaredNorm() - 3.0) > 1.0; }

}  // namespace cosserat
