#include "cosserat/robots/tendon_control.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace cosserat {

namespace {

using VecT = Eigen::Matrix<double, Actuation::kMaxTendons, 1>;
using MatT = Eigen::Matrix<double, Actuation::kMaxTendons, Actuation::kMaxTendons>;

/// The Newton matrix of the active set: dℓ_i/dτ_j (m/N) by forward differences (step 1e-6 of the
/// tension scale) for active i and j; elsewhere a diagonal of the active block's largest entry,
/// so that the rank thresholds below are relative to the sensitivities (a stiff backbone's
/// stretch, n L/EA, is far below 1 m/N). mismatch(τ, &g) gives the lengths minus the commands at
/// τ (false if the static solve fails, and then so does this).
template <class Mismatch>
bool ActiveSensitivities(const Mismatch& mismatch, int count, const VecT& tau, const VecT& g,
                         const std::array<bool, Actuation::kMaxTendons>& active, MatT* D) {
  D->setZero();
  const double scale = std::max(1e-3, tau.head(count).cwiseAbs().maxCoeff());
  double largest = 0.0;
  for (int j = 0; j < count; ++j) {
    if (!active[j]) continue;
    VecT t2 = tau, g2;
    const double h = 1e-6 * scale;
    t2(j) += h;
    if (!mismatch(t2, &g2)) return false;
    for (int i = 0; i < count; ++i) {
      if (!active[i]) continue;
      (*D)(i, j) = (g2(i) - g(i)) / h;
      largest = std::max(largest, std::abs((*D)(i, j)));
    }
  }
  for (int k = 0; k < Actuation::kMaxTendons; ++k)
    if (k >= count || !active[k]) (*D)(k, k) = largest > 0.0 ? largest : 1.0;
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

/// At an answer tau: the number of independent ways the taut tensions can change with no change
/// of the lengths (`count`: the null space of the sensitivities' taut block from warm re-solves,
/// pivots below 1e-6 of the largest counted as zero, as in LeastNormStep; −1 when a re-solve
/// failed), and whether the solver holds tau's equilibrium again afterwards (`restored`).
struct FreeDirections {
  int count = 0;
  bool restored = true;
};
template <class Mismatch>
FreeDirections FreeTensionDirections(const Mismatch& mismatch, int count, const VecT& tau,
                                     const VecT& g,
                                     const std::array<bool, Actuation::kMaxTendons>& taut) {
  if (std::count(taut.begin(), taut.end(), true) < 2) return {};  // nothing to perturb
  MatT D;
  const bool measured = ActiveSensitivities(mismatch, count, tau, g, taut, &D);
  VecT g_again;
  const bool restored = mismatch(tau, &g_again);
  if (!measured || !restored) return {-1, restored};
  Eigen::CompleteOrthogonalDecomposition<MatT> cod(D);
  cod.setThreshold(1e-6);
  return {static_cast<int>(D.rows() - cod.rank()), true};
}

/// The largest |ℓ − ℓ_cmd| (m) over the tendons that are taut (τ > 0) or would be (g > 0).
double TautMismatch(int count, const VecT& tau, const VecT& g) {
  double worst = 0.0;
  for (int i = 0; i < count; ++i)
    if (tau(i) > 0 || g(i) > 0) worst = std::max(worst, std::abs(g(i)));
  return worst;
}

/// At an answer: the tendons that pull, or sit at their commanded length to the tolerance tol
/// (m: a tendon at 0 N within tol of its cable is taut whichever side round-off puts it).
std::array<bool, Actuation::kMaxTendons> TautAt(int count, const VecT& tau, const VecT& g,
                                                double tol) {
  std::array<bool, Actuation::kMaxTendons> taut{};
  for (int i = 0; i < count; ++i) taut[i] = tau(i) > 0 || g(i) > -tol;
  return taut;
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
      const std::array<bool, Actuation::kMaxTendons> taut = TautAt(count, tau, g, tol);
      for (int i = 0; i < count; ++i) {
        summary.slack[i] = !taut[i];
        actuation->tendon_tension[i] = tau(i);
      }
      const FreeDirections free = FreeTensionDirections(mismatch, count, tau, g, taut);
      summary.free_tension_directions = free.count;
      // A failed sensitivity solve does not undo the answer; a failed re-solve of it does.
      if (free.restored) summary.status = SolveStatus::kConverged;
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
