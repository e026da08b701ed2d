#pragma once
/// \file
/// Displacement (tendon-length) control of a tendon-driven rod in statics: find the tensions
/// that make each tendon's path as long as commanded. A tendon pulls but never pushes: one whose
/// commanded length exceeds its path at zero tension goes slack and carries exactly zero.

#include <array>

#include "cosserat/lie/se3.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat {

struct TendonLengthOptions {
  /// Converged when every taut tendon's length is within tolerance × L of its command.
  double tolerance = 1e-10;
  int max_iterations = 50;
};

struct TendonLengthSummary {
  SolveStatus status = SolveStatus::kNotRun;
  int iterations = 0;         ///< Newton iterations on the tensions
  int solves = 0;             ///< static solves (each warm-started)
  int shots = 0;              ///< their shots, in all
  double residual = 0.0;  ///< the last converged static solve's residual (StaticShootingSummary)
  /// largest |ℓ − ℓ_cmd| over the taut tendons at the tensions returned, m (when not converged
  /// too, at the last accepted step; 0 when the first static solve failed)
  double length_error = 0.0;
  std::array<bool, Actuation::kMaxTendons> slack{};
  /// Converged only: how many independent ways the taut tendons' tensions could change with no
  /// change of any length (0 when the lengths fix the tensions; 1 for four parallel tendons at
  /// 90°, whose lengths make only two curvatures and a stretch; −1 when a re-solve for the count
  /// failed). The tensions returned are then one of a family with the same shape, and a taut
  /// tendon may carry 0 N. Counting takes one warm re-solve per taut tendon, and one more.
  int free_tension_directions = 0;
  bool converged() const { return status == SolveStatus::kConverged; }
};

/// Solves for the tensions (written into *actuation, whose other fields are kept and used) so
/// that the tendon path lengths (StaticShootingSolver::tendon_lengths) equal `lengths` (m) for
/// the model's tendons. Projected Newton on the tensions with τ ≥ 0; the length sensitivities
/// come from warm-started re-solves; a trial step whose static solve fails is halved like one that
/// does not reduce the mismatch. On return the solver holds the equilibrium at the last accepted
/// tensions, which *actuation holds too. Tendons that bend the rod alike are redundant (four
/// parallel ones at 90° make only two curvatures and a stretch): every reachable command then has
/// a family of tensions, and Newton's least-norm steps pick one of them.
TendonLengthSummary SolveTendonLengths(StaticShootingSolver& solver, const lie::SE3& base,
                                       const StaticLoads& loads,
                                       const std::array<double, Actuation::kMaxTendons>& lengths,
                                       Actuation* actuation,
                                       const TendonLengthOptions& options = {});

}  // namespace cosserat
