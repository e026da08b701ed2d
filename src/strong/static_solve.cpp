// The static solve around the shot of static_shooting.cpp: quasi-Newton warm re-solves,
// Levenberg–Marquardt, continuation in the load and the search for a stable equilibrium.
#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "cosserat/lie/nearest_rotation.hpp"
#include "cosserat/loads/obstacle_core.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/strong/shot_newton.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat {

bool StaticShootingOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (!(std::isfinite(tolerance) && tolerance > 0)) return fail("tolerance must be positive");
  if (max_iterations < 1) return fail("max_iterations must be at least 1");
  if (!(min_load_step > 0 && min_load_step <= 1)) return fail("min_load_step must be in (0, 1]");
  if (max_load_steps < 1) return fail("max_load_steps must be at least 1");
  if (!(std::isfinite(max_load_increment) && max_load_increment > 0))
    return fail("max_load_increment must be positive");
  return true;
}

namespace {

// Tolerance of the intermediate solves of a continuation (the last one uses the solver's own).
constexpr double kIntermediateTolerance = 1e-6;

}  // namespace

int StaticShootingSolver::IndexAfterSolve(const lie::SE3& base, const StaticLoads& loads,
                                          const Vec6& x) const {
  // Levenberg–Marquardt's last Jacobian shot is at its solution: its node states and tangents
  // are the Jacobi fields the count needs, with no shot of its own.
  if (has_kept_ && kept_x_ == x && kept_base_.R == base.R && kept_base_.p == base.p &&
      kept_loads_ == loads)
    return StabilityIndexFromShot(loads, kept_record_, kept_tangents_);
  return StabilityIndex(base, loads, scale_.cwiseProduct(x));
}

std::vector<Vec3> StaticShootingSolver::ShotPositions(const lie::SE3& base,
                                                     const StaticLoads& loads, const Vec6& x) {
  Residual(base, loads, x);
  return state_.position_W;
}

bool StaticShootingSolver::HeldBack(const lie::SE3& base, const StaticLoads& loads_from,
                                    const Vec6& x_from, const StaticLoads& loads, const Vec6& x) {
  if (!HasObstacleCore(loads.contact)) return true;
  const std::vector<Vec3> before = ShotPositions(base, loads_from, x_from);
  return !ReachesObstacleCore(loads.contact, before, ShotPositions(base, loads, x));
}

bool StaticShootingSolver::FollowLoadPath(const lie::SE3& base, const StaticLoads& start,
                                          const StaticLoads& loads, const Vec6& x_start,
                                          const LoadPath& path, Vec6* x, int* steps,
                                          StaticShootingSummary* summary,
                                          double* reached_fraction) {
  Vec6 x_a = x_start, x_prev = x_start;
  double mu = 0.0, mu_prev = 0.0, dmu = path.max_fraction;
  *steps = 0;
  bool reached = false;
  // The secant predictor extrapolates from the start only if that is an equilibrium (a rod laid
  // into a contact surface is not: StaticMultipleShootingSolver::FollowPath).
  const bool start_balanced = Residual(base, start, x_start).norm() < options_.tolerance;
  while (*steps < path.max_steps) {
    const double mu_try = std::min(1.0, mu + dmu);
    const StaticLoads target = mu_try == 1.0 ? loads : StaticLoads::Blend(start, loads, mu_try);
    Vec6 guess = x_a;
    if (mu > mu_prev) guess += (x_a - x_prev) * ((mu_try - mu) / (mu - mu_prev));
    ++*steps;
    // Intermediate equilibria only seed the next step: a looser tolerance is enough.
    const double tol =
        mu_try == 1.0 ? options_.tolerance : std::max(options_.tolerance, kIntermediateTolerance);
    if (TryLevenbergMarquardt(base, target, tol, &guess, summary) &&
        (!path.require_stable || IndexAfterSolve(base, target, guess) == 0) &&
        HeldBack(base, mu == 0.0 ? start : StaticLoads::Blend(start, loads, mu), x_a, target,
                 guess)) {
      const bool secant = mu > 0.0 || start_balanced;
      x_prev = secant ? x_a : guess;
      mu_prev = secant ? mu : mu_try;
      x_a = guess;
      mu = mu_try;
      if (mu == 1.0) {
        reached = true;
        break;
      }
      dmu = std::min({2.0 * dmu, path.max_fraction, 1.0 - mu});
    } else {
      if (!path.halve_on_failure) break;
      dmu *= 0.5;
      if (dmu < options_.min_load_step) break;
    }
  }
  *x = x_a;
  if (reached_fraction) *reached_fraction = mu;
  return reached;
}

// Stability (options_.stable_branch): a Newton-type solve converges to whichever equilibrium
// is nearest its start, and past a critical load the nearest one can be unstable (a column at
// 1.15 P_cr with a small imperfection: the near-straight state beside the start, deflected
// against the imperfection). Step control on the size of the correction does not see this —
// the unstable root is the one near the predictor — so the converged equilibrium is checked
// instead, from Levenberg–Marquardt's last Jacobian shot (taken at the solution). A
// quasi-Newton warm re-solve is not checked (Solve): it continues the previous solution by steps
// that halve the residual, and takes no tangent shot (17 µs; a check would add one, ≈ 53 µs).
bool StaticShootingSolver::KeepStableBranch(const lie::SE3& base, const StaticLoads& loads,
                                            double max_fraction, Vec6* x,
                                            StaticShootingSummary* summary) {
  summary->stability_index = IndexAfterSolve(base, loads, *x);
  if (summary->stability_index <= 0) return false;  // stable, or not defined (−1)
  // Natural-parameter continuation from the unloaded rod (W ≡ 0: stable, the energy is a
  // positive definite quadratic about the rest shape) along loads(μ) = μ · loads; a step is
  // accepted only if it converges on an equilibrium without unstable directions. Along an
  // imperfect path (no bifurcation) the stable branch is connected to μ = 0, and small enough
  // steps follow it through its sharp turn near P_cr.
  const Mat6 J_first = jacobian_;  // d r/d x at x, for the next warm start if we keep x
  LoadPath path;
  path.max_fraction = max_fraction;
  path.require_stable = true;
  path.max_steps = options_.max_load_steps - summary->load_steps;
  Vec6 x_stable;
  if (FollowLoadPath(base, loads.Scaled(0.0), loads, Vec6::Zero(), path, &x_stable,
                     &summary->stable_path_steps, summary)) {
    *x = x_stable;
    summary->stability_index = 0;
  } else {
    jacobian_ = J_first;
  }
  return true;
}

Vec6 StaticShootingSolver::base_wrench_B() const { return scale_.cwiseProduct(x_); }

Vec6 StaticShootingSolver::RigidGuess(const lie::SE3& base, const StaticLoads& loads) const {
  // Base wrench that balances the loads on the undeformed (rest) shape: a good start for small
  // loads and exact in the limit of zero load.
  const int n = static_cast<int>(grid_.size());
  Vec3 n_W = Vec3::Zero(), m_W = Vec3::Zero();
  auto add_force = [&](const Vec3& r_B, const Vec3& F_W) {
    n_W += F_W;
    m_W += (base.R * r_B).cross(F_W);
  };
  for (int i = 0; i + 1 < n; ++i) {
    const double h = grid_[i + 1] - grid_[i];
    const Sample& sm = samples_[3 * i + 1];
    const Vec3 f = TotalDistributedForce_W(loads, sm.Site());
    add_force(0.5 * (rest_position_B_[i] + rest_position_B_[i + 1]), h * f);
  }
  const Mat3 R_tip = base.R * rest_rotation_B_.back();
  const SplitWrench tip = TotalTipWrench(loads);
  add_force(rest_position_B_.back(), tip.dead_W.tail<3>() + R_tip * tip.follower_B.tail<3>());
  m_W += tip.dead_W.head<3>() + R_tip * tip.follower_B.head<3>();
  Vec6 W_B;
  W_B << base.R.transpose() * m_W, base.R.transpose() * n_W;
  return W_B.cwiseQuotient(scale_);
}

bool StaticShootingSolver::TryLevenbergMarquardt(const lie::SE3& base, const StaticLoads& loads,
                                                 double tolerance, Vec6* x,
                                                 StaticShootingSummary* summary) {
  Mat6 J = Mat6::Identity();
  auto shot = [&](const Vec6& x_try, Mat6* J_try) -> Vec6 {
    if (!J_try) return Residual(base, loads, x_try);
    Vec6 r;
    *J_try = ResidualJacobianKeepingTangents(base, loads, x_try, &r);
    return r;
  };
  Vec6 xt = *x;
  const ShotSolveCounts counts =
      LevenbergMarquardtShot(shot, tolerance, options_.max_iterations, &xt, &J);
  summary->shots += counts.shots;
  summary->iterations += counts.iterations;
  // Decide on a residual evaluated here: TinySolver's final cost is not set when the first
  // evaluation is not finite.
  const double res = xt.allFinite() ? Residual(base, loads, xt).norm() : NAN;
  ++summary->shots;
  if (!std::isfinite(res)) {
    summary->status = SolveStatus::kNonFinite;
    return false;
  }
  summary->residual = res;
  *x = xt;
  if (res < tolerance) {
    // TinySolver evaluated the Jacobian at the accepted x last; keep it for the next solve.
    jacobian_ = J;
    has_jacobian_ = true;
    return true;
  }
  summary->status = SolveStatus::kMaxIterations;
  return false;
}

bool StaticShootingSolver::TryQuasiNewton(const lie::SE3& base, const StaticLoads& loads,
                                          Vec6* x_io, StaticShootingSummary* summary) {
  // Newton with the last solution's Jacobian, kept current by Broyden's rank-one update. Gives
  // up (and lets LM take over) as soon as a step fails to halve the residual.
  Vec6 x = *x_io;
  Vec6 r;
  if (state_is_solution_ && SameDistributedLoads(loads, solved_loads_)) {
    // Only the tip load changed: the stored shot of the previous solution is the shot at x, and
    // only its tip condition differs. No integration needed.
    r = StoredShotResidual(loads);
  } else {
    r = Residual(base, loads, x);
    ++summary->shots;
  }
  Mat6 J = jacobian_;
  Eigen::PartialPivLU<Mat6> lu(J);
  for (int it = 0; it <= options_.max_iterations; ++it) {
    const double norm = r.norm();
    if (!std::isfinite(norm)) return false;
    if (norm < options_.tolerance) {
      summary->residual = norm;
      *x_io = x;
      jacobian_ = J;
      return true;
    }
    if (it == options_.max_iterations) return false;
    const Vec6 dx = -lu.solve(r);
    const Vec6 r_new = Residual(base, loads, x + dx);
    ++summary->shots;
    ++summary->iterations;
    if (!(r_new.allFinite() && r_new.norm() < 0.5 * norm)) return false;
    J += (r_new - r - J * dx) * dx.transpose() / dx.squaredNorm();
    lu.compute(J);
    x += dx;
    r = r_new;
  }
  return false;
}

StaticShootingSolver::DirectAttempt StaticShootingSolver::SolveDirectly(
    const lie::SE3& base, const StaticLoads& start, const StaticLoads& loads, const Vec6& x_start,
    bool from_previous, Vec6* x, StaticShootingSummary* summary) {
  DirectAttempt a;
  if (from_previous && has_jacobian_ && options_.reuse_jacobian) {
    a.ok = a.state_current = a.via_quasi_newton = TryQuasiNewton(base, loads, x, summary);
  }
  if (!a.ok) {
    *x = from_previous ? x_ : RigidGuess(base, loads);
    a.ok = TryLevenbergMarquardt(base, loads, options_.tolerance, x, summary);
  }
  // A direct solve that lands beyond an obstacle jumped through it: the continuation then.
  if (a.ok && !HeldBack(base, start, x_start, loads, *x)) {
    a = DirectAttempt{};
    *x = x_start;
    summary->status = SolveStatus::kMaxIterations;  // without load stepping, this is the end
  }
  return a;
}

StaticShootingSummary StaticShootingSolver::Solve(const lie::SE3& base, const StaticLoads& loads) {
  const auto t0 = std::chrono::steady_clock::now();
  StaticShootingSummary summary;
  if (!loads.IsValid(nullptr) || !base.R.allFinite() || !base.p.allFinite()) {
    summary.status = SolveStatus::kNonFinite;  // NaN or Inf in the input: nothing to solve
    summary.residual = NAN;
    return summary;
  }
  lie::RequireRotation(base.R, "StaticShootingSolver::Solve: base.R");

  // Start from a known solution: the previous one at the same base, else the unloaded rod
  // (W ≡ 0 is exact at zero load, whatever the rest shape).
  // (Continuation blends loads, so their tip-load frames must match too.)
  const bool from_previous = has_solution_ && (solved_base_.R - base.R).norm() == 0.0 &&
                             (solved_base_.p - base.p).norm() == 0.0 &&
                             StaticLoads::SameFrames(solved_loads_, loads);
  summary.warm_started = from_previous;
  const StaticLoads start = from_previous ? solved_loads_ : loads.Scaled(0.0);
  const Vec6 x_start = from_previous ? x_ : Vec6::Zero();

  // How far the load moves, as the change of the rigid-body base wrench in units of EI/L and
  // EI/L² (≈ the load parameter PL²/EI, or the linear-theory rotation in rad). Newton-type
  // iterations jump between equilibrium branches when this is large, so the load is applied in
  // increments of at most options_.max_load_increment.
  const double load_change =
      (RigidGuess(base, loads) - RigidGuess(base, start)).lpNorm<Eigen::Infinity>();
  const double max_fraction =
      load_change > options_.max_load_increment ? options_.max_load_increment / load_change : 1.0;

  Vec6 x = x_start;
  double reached = 1.0;  // the load level x balances (continuation: the last one reached)
  DirectAttempt direct;
  if (max_fraction == 1.0)
    direct = SolveDirectly(base, start, loads, x_start, from_previous, &x, &summary);
  bool ok = direct.ok, state_current = direct.state_current;
  if (!ok && (options_.load_stepping || max_fraction < 1.0)) {
    // Continuation from the start to the loads, step halving on failure when load stepping is
    // on, never above max_fraction.
    const LoadPath path{max_fraction, options_.load_stepping, /*require_stable=*/false,
                        options_.max_load_steps};
    ok = FollowLoadPath(base, start, loads, x_start, path, &x, &summary.load_steps, &summary,
                        &reached);
    if (!ok) summary.load_fraction = reached;
    state_current = false;
    if (!ok && summary.status != SolveStatus::kNonFinite)
      summary.status =
          options_.load_stepping ? SolveStatus::kLoadSteppingFailed : SolveStatus::kMaxIterations;
  }

  // Stability (options_.stable_branch; KeepStableBranch says why and when).
  if (ok && options_.stable_branch && !direct.via_quasi_newton) {
    if (KeepStableBranch(base, loads, max_fraction, &x, &summary)) state_current = false;
  }

  if (!state_current) {
    const Vec6 r = Residual(base, loads, x);
    ++summary.shots;
    summary.residual = r.norm();  // against the loads asked for, reached or not
    if (!r.allFinite()) ok = false, summary.status = SolveStatus::kNonFinite;
    if (!ok && r.allFinite() && reached < 1.0) {  // the state: that level, in its equilibrium
      Residual(base, reached == 0.0 ? start : StaticLoads::Blend(start, loads, reached), x);
      ++summary.shots;
    }
  }
  if (ok && state_.RanAway()) {  // residuals met by a shot that diverged (RodState::RanAway)
    ok = false, summary.status = SolveStatus::kNonFinite;
    summary.stability_index = -1;  // no answer to count on
  }
  if (ok) {
    state_is_solution_ = true;
    summary.status = SolveStatus::kConverged;
    x_ = x;
    solved_base_ = base;
    solved_loads_ = loads;
    has_solution_ = true;
  }
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

}  // namespace cosserat
