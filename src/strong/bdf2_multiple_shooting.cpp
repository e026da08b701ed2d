// Multiple shooting for one BDF2 step (Bdf2Options::shooting_segments > 1).
//
// Single shooting integrates the whole rod from the 6 unknowns at s = 0; an error there grows
// like e^{λL}, λ ≈ (c0² ρA / EI)^{1/4} (the BDF2 inertia against bending), which for small dt
// exceeds what double precision can resolve (the peer rod at dt = 0.5 ms: e^17). Here the shot
// restarts at interior junctions from 18 extra unknowns each (pose, wrench and twist there,
// as displacements from the last accepted state) and continuity at each junction joins the tip
// condition as residual. Same discrete equations, so the same solution as single shooting; each
// piece amplifies by only e^{λL/pieces}.
//
// The Jacobian is by forward differences (6 + 18 (pieces − 1) shots); its inverse is kept
// across steps and Broyden-updated, and renewed only when a step fails to halve the residual
// (after one retry with the failed step's secant), as in single shooting. Newton only; a step
// that does not converge fails and is halved by the caller.

#include <algorithm>
#include <cmath>

#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat {

bool Bdf2ShootingStepper::SolveStepMultiple(const StepInput& input, const Coefficients& c,
                                            double h, StepSummary* summary) {
  const Eigen::Index nz = junction_z_.size();
  const Eigen::Index n_all = 6 + nz;
  // Residual [tip (6); junction mismatches] at the unknowns X = [x (6); z].
  auto evaluate = [&](const Eigen::VectorXd& X, Eigen::VectorXd* R) {
    junction_z_ = X.tail(nz);
    R->head<6>() = Residual(input, c, false, X.head<6>());
    R->tail(nz) = junction_mismatch_;
    ++summary->shots;
    return R->allFinite();
  };
  bool fresh = false;  // ms_inverse_ is the finite-difference inverse at ms_x_, not yet updated
  // Forward differences at ms_x_, whose residual is ms_r_. The unknowns are dimensionless and
  // O(1) at most, so an absolute step of 1e-7 balances truncation (~1e-7 relative, the shot is
  // smooth) against round-off (~1e-16 × the piece's gain / 1e-7); a Jacobian this accurate only
  // slows Newton from quadratic to fast linear convergence.
  auto renew_jacobian = [&]() {
    ms_r_base_ = ms_r_;
    for (Eigen::Index j = 0; j < n_all; ++j) {
      const double step = 1e-7 * std::max(1.0, std::abs(ms_x_(j)));
      ms_x_new_ = ms_x_;
      ms_x_new_(j) += step;
      evaluate(ms_x_new_, &ms_r_new_);
      ms_jacobian_.col(j) = (ms_r_new_ - ms_r_base_) / step;
    }
    ms_lu_.compute(ms_jacobian_);
    ms_inverse_ = ms_lu_.inverse();
    ms_jacobian_c0_ = c.c0;
    ++summary->jacobians;
    fresh = true;
  };
  // Broyden's ("good") update of the inverse H for the secant dx ↦ dr = r_new − r:
  // H += (dx − H dr) dxᵀ H / (dxᵀ H dr), O(n²) against one LU's O(n³).
  auto broyden = [&](const Eigen::VectorXd& dx) {
    ms_u_.noalias() = ms_inverse_ * (ms_r_new_ - ms_r_);
    const double denominator = dx.dot(ms_u_);
    if (!(std::abs(denominator) > 1e-300)) return;
    ms_u_ = dx - ms_u_;
    ms_w_.noalias() = ms_inverse_.transpose() * dx;
    ms_inverse_.noalias() += (ms_u_ / denominator) * ms_w_.transpose();
  };

  junctions_active_ = true;
  // First guess: x extrapolated like single shooting's; the junction states moving on by the
  // change of the last step (run_.junction_unknowns is that change).
  ms_x_.head<6>() = run_.unknowns.Predict(h);
  ms_x_.tail(nz) = run_.junction_unknowns;
  bool ok = false;
  if (evaluate(ms_x_, &ms_r_)) {
    double norm = ms_r_.norm();
    if (ms_jacobian_c0_ != c.c0 && norm >= options_.tolerance) renew_jacobian();
    bool retried = false;
    for (int it = 0; it < options_.max_iterations; ++it) {
      if (norm < options_.tolerance) {
        ok = true;
        break;
      }
      ms_dx_.noalias() = -ms_inverse_ * ms_r_;
      ms_x_new_ = ms_x_ + ms_dx_;
      const bool finite = evaluate(ms_x_new_, &ms_r_new_);
      const double new_norm = ms_r_new_.norm();
      ++summary->iterations;
      if (finite && new_norm < 0.5 * norm) {
        broyden(ms_dx_);
        std::swap(ms_x_, ms_x_new_);
        std::swap(ms_r_, ms_r_new_);
        norm = new_norm;
        fresh = false;
      } else if (finite && !fresh && !retried) {
        broyden(ms_dx_);  // the failed step still measured the secant along dx: retry with it
        retried = true;
      } else if (!fresh) {
        // ms_r_ is still the residual at ms_x_: renew the Jacobian there (this leaves the trial
        // state at a perturbed point, but norm ≥ tolerance, so an evaluation follows before any
        // acceptance).
        renew_jacobian();
      } else {
        break;  // a fresh Jacobian's Newton step does not halve the residual: the step fails
      }
    }
  }
  junctions_active_ = false;
  summary->residual = ms_r_.norm();
  if (!ok) {
    summary->status =
        std::isfinite(summary->residual) ? SolveStatus::kMaxIterations : SolveStatus::kNonFinite;
    return false;
  }
  solved_unknowns_ = ms_x_.head<6>();
  predictor_term_ = solved_unknowns_;
  run_.junction_unknowns = ms_x_.tail(nz);
  return true;
}

}  // namespace cosserat
