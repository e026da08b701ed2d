#include "cosserat/robots/tendon_control.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace cosserat {

namespace {

using VecT = Eigen::Matrix<double, Actuation::kMaxTendons, 1>;
using MatT = Eigen::Matrix<double, Actuation::kMaxTendons, Actuation::kMaxTendons>;

/// The Newton matrix of the active set: dℓ_i/dτ_j (m/N) by forward differences (step 1e-6 of the
/// tension scale) for active i and j, the identity elsewhere. mismatch(τ, &g) gives the lengths
/// minus the commands at τ (false if the static solve fails, and then so does this).
template <class Mismatch>
bool ActiveSensitivities(const Mismatch& mismatch, int count, const VecT& tau, const VecT& g,
                         const std::array<bool, Actuation::kMaxTendons>& active, MatT* D) {
  *D = MatT::Identity();
  const double scale = std::max(1e-3, tau.head(count).cwiseAbs().maxCoeff());
  for (int j = 0; j < count; ++j) {
    if (!active[j]) continue;
    VecT t2 = tau, g2;
    const double h = 1e-6 * scale;
    t2(j) += h;
    if (!mismatch(t2, &g2)) return false;
    for (int i = 0; i < count; ++i) (*D)(i, j) = active[i] ? (g2(i) - g(i)) / h : (i == j);
  }
  return true;
}

/// The Newton step D⁻¹ rhs as least squares of least norm: tendons that bend the rod alike
/// (four parallel ones make three strains: two curvatures and the stretch) leave D singular, with
/// a family of tensions for every reachable command, where an LU solve gives no useful step.
/// The decomposition's pivots below 1e-6 of the largest are the forward differences' error,
/// not a way the tensions move the lengths: D's rank is counted without them.
VecT LeastNormStep(const MatT& D, const VecT& rhs) {
  Eigen::CompleteOrthogonalDecomposition<MatT> cod(D);
  cod.setThreshold(1e-6);
  return cod.solve(rhs);
}

/// The number of independent ways the active tensions can change at tau with no change of the
/// lengths: the null space of the sensitivities' active block (warm re-solves), pivots below
/// 1e-6 of the largest counted as zero, as in LeastNormStep. 0 with one active tendon, or when a
/// re-solve fails. The solver is left at a perturbed equilibrium.
template <class Mismatch>
int FreeTensionDirections(const Mismatch& mismatch, int count, const VecT& tau, const VecT& g,
                          const std::array<bool, Actuation::kMaxTendons>& active) {
  MatT D;
  if (std::count(active.begin(), active.end(), true) < 2 ||
      !ActiveSensitivities(mismatch, count, tau, g, active, &D))
    return 0;
  Eigen::CompleteOrthogonalDecomposition<MatT> cod(D);
  cod.setThreshold(1e-6);
  return static_cast<int>(D.rows() - cod.rank());
}

/// The largest |ℓ − ℓ_cmd| (m) over the tendons that are taut (τ > 0) or would be (g > 0).
double TautMismatch(int count, const VecT& tau, const VecT& g) {
  double worst = 0.0;
  for (int i = 0; i < count; ++i)
    if (tau(i) > 0 || g(i) > 0) worst = std::max(worst, std::abs(g(i)));
  return worst;
}

}  // namespace

TendonLengthSummary SolveTendonLengths(StaticShootingSolver& solver, const lie::SE3& base,
                                       const StaticLoads& loads,
                                       const std::array<double, Actuation::kMaxTendons>& lengths,
                                       Actuation* actuation, const TendonLengthOptions& options) {
  TendonLengthSummary summary;
  const int count = solver.tendon_count();
  const double tol = options.tolerance * solver.length();

  // Lengths minus commands at tensions tau; false if the static solve fails.
  auto mismatch = [&](const VecT& tau, VecT* g) {
    Actuation a = *actuation;
    for (int i = 0; i < count; ++i) a.tendon_tension[i] = tau(i);
    solver.SetActuation(a);
    ++summary.solves;
    const auto s = solver.Solve(base, loads);
    summary.shots += s.shots;
    if (!s.converged()) {
      summary.status = s.status;
      return false;
    }
    summary.residual = s.residual;
    g->setZero();
    for (int i = 0; i < count; ++i) (*g)(i) = solver.tendon_lengths()[i] - lengths[i];
    return true;
  };

  VecT tau = VecT::Zero(), g;
  for (int i = 0; i < count; ++i) tau(i) = std::max(0.0, actuation->tendon_tension[i]);
  if (!mismatch(tau, &g)) return summary;
  bool sensitivities_failed = false;
  for (int it = 0; it < options.max_iterations; ++it) {
    // Active set: taut tendons, and slack ones whose path is longer than commanded (g > 0:
    // pulling shortens the path).
    std::array<bool, Actuation::kMaxTendons> active{};
    for (int i = 0; i < count; ++i) active[i] = tau(i) > 0 || g(i) > 0;
    const double worst = summary.length_error = TautMismatch(count, tau, g);
    if (worst < tol) {
      summary.status = SolveStatus::kConverged;
      for (int i = 0; i < count; ++i) {
        summary.slack[i] = !active[i];
        actuation->tendon_tension[i] = tau(i);
      }
      summary.free_tension_directions = FreeTensionDirections(mismatch, count, tau, g, active);
      summary.status = SolveStatus::kConverged;  // a failed sensitivity solve does not undo it
      VecT g_end;
      mismatch(tau, &g_end);  // the answer's equilibrium again
      return summary;
    }
    MatT D;
    if (!ActiveSensitivities(mismatch, count, tau, g, active, &D)) {
      sensitivities_failed = true;  // summary.status says why
      break;
    }
    VecT rhs = VecT::Zero();
    for (int i = 0; i < count; ++i) rhs(i) = active[i] ? -g(i) : 0.0;
    const VecT step = LeastNormStep(D, rhs);
    // Project onto τ ≥ 0; halve the step until the mismatch of the active set decreases.
    double alpha = 1.0;
    bool moved = false;
    for (int k = 0; k < 30 && !moved; ++k, alpha *= 0.5) {
      VecT trial = (tau + alpha * step).cwiseMax(0.0);
      VecT g_trial;
      if (!mismatch(trial, &g_trial)) continue;  // too far for the statics: a shorter step
      if (TautMismatch(count, trial, g_trial) < worst) {
        tau = trial;
        g = g_trial;
        moved = true;
      }
    }
    ++summary.iterations;
    if (!moved) break;
  }
  // Not converged. The solver may hold a trial's state: back to the accepted tensions'
  // equilibrium, whose tensions and mismatch are returned.
  const SolveStatus why = sensitivities_failed ? summary.status : SolveStatus::kMaxIterations;
  VecT g_back;
  mismatch(tau, &g_back);
  summary.length_error = TautMismatch(count, tau, g);
  for (int i = 0; i < count; ++i) actuation->tendon_tension[i] = tau(i);
  summary.status = why;
  return summary;
}

}  // namespace cosserat
