#include "cosserat/quatfd/sdirk.hpp"

#include <algorithm>
#include <cmath>

#include "cosserat/quatfd/quatfd_kernels.hpp"

namespace cosserat::quatfd {
namespace {

// Hairer & Wanner, Solving ODEs II, Table IV.6.5 (SDIRK4): L-stable, stiffly accurate (b = the
// last row of A), order 4, embedded b̂ of order 3.
constexpr double kGamma = 0.25;
constexpr int kStages = 5;
constexpr double kA[kStages][kStages] = {
    {0.25, 0, 0, 0, 0},
    {0.5, 0.25, 0, 0, 0},
    {17.0 / 50, -1.0 / 25, 0.25, 0, 0},
    {371.0 / 1360, -137.0 / 2720, 15.0 / 544, 0.25, 0},
    {25.0 / 24, -49.0 / 48, 125.0 / 16, -85.0 / 12, 0.25},
};
constexpr double kC[kStages] = {0.25, 0.75, 0.55, 0.5, 1.0};
// b − b̂ with b̂ = [59/48, −17/96, 225/32, −85/12, 0].
constexpr double kE[kStages] = {25.0 / 24 - 59.0 / 48, -49.0 / 48 + 17.0 / 96,
                                125.0 / 16 - 225.0 / 32, 0.0, 0.25};

// Newton: at most kMaxIterations per stage; converged when η ‖Δ‖ ≤ kKappa in the error norm
// (Hairer–Wanner's stopping rule with η = θ/(1 − θ), θ the observed contraction). kKappa well
// below 1 keeps the iteration error a small part of the tolerance the step is controlled to.
constexpr int kMaxIterations = 7;
constexpr double kKappa = 0.05;
// Jacobian updates within one stage before the step is given up (and h halved).
constexpr int kMaxRefreshes = 2;

}  // namespace

SdirkIntegrator::SdirkIntegrator(const QuatFdModel& model, const IntegratorOptions& options,
                                 bool corotate)
    : ImplicitIntegrator(model, options, corotate, 1, kMaxIterations, kKappa) {
  for (Eigen::VectorXd* v : {&z_, &dz_, &s_, &tmp_, &k0_, &guess_}) v->resize(2 * n_);
  for (Eigen::VectorXd& k : k_) k.resize(2 * n_);
}

bool SdirkIntegrator::FactorizeMatrices(double h) { return FactorizeShifted(1.0 / (kGamma * h)); }

void SdirkIntegrator::SolveVelocity(Eigen::Ref<Eigen::VectorXd> rv) {
  // rv ← P_v M⁻¹ a P_vᵀ rv, M = a² I − a B − A (zero q-half of the right-hand side).
  const double a = 1.0 / (kGamma * factor_h_);
  RotateHalf(0, rv, true);
  rv *= a;
  M_.Solve(rv);
  RotateHalf(0, rv, false);
}

double SdirkIntegrator::IntegratedVelocityError(double h) const {
  // The velocity error of a step turns into a position error of about h·err_v over the next
  // step, which no later local estimate sees: hold it to the position tolerance, component by
  // component (v = q̇ in the same layout). Without this the step on the steel string (b) is set by
  // velocity_abs_tol alone (1e-3 m/s, independent of rel_tol/abs_tol) and the tip error does not
  // shrink with the tolerance (docs/quatfd.md, "SDIRK4 and the velocity tolerance").
  double e = 0.0;
  for (int i = 0; i < n_; ++i) {
    const double scale =
        options_.abs_tol + options_.rel_tol * std::max(std::abs(y_[i]), std::abs(y_new_[i]));
    e = std::max(e, h * std::abs(err_[n_ + i]) / scale);
  }
  return e;
}

SdirkIntegrator::StageResult SdirkIntegrator::SolveStage(int i,
                                                         const Eigen::Ref<const Eigen::VectorXd>& y,
                                                         double h) {
  const int n = n_;
  const double hg = kGamma * h, a = 1.0 / hg;
  // The q-half of the stage equation is linear, z_q = s_q + hγ (v_n + z_v): kept exact, so the
  // Newton iteration runs on z_v alone. With J = [[0, I], [A, B]] the correction is
  //   Δ_v = (a² I − a B − A)⁻¹ a r_v,  Δ_q = hγ Δ_v,  r_v = a (s_v − z_v) + f(y + z),
  // turned by the co-rotation P (which acts alike on both halves, so Δ_q = hγ Δ_v still holds).
  z_.head(n) = s_.head(n) + hg * (y.tail(n) + z_.tail(n));
  tmp_ = y + z_;
  UpdateRotation(0, tmp_);  // once per stage, at the predictor
  newton_.BeginSolve();
  for (int it = 0; it < kMaxIterations; ++it) {
    if (it > 0) tmp_ = y + z_;
    k_[i].head(n) = tmp_.tail(n);
    StageAcceleration(kC[i], h, tmp_.head(n), tmp_.tail(n), k_[i].tail(n));
    ++stats_.f_evaluations;
    ++newton_.stats.newton_iterations;
    auto dv = dz_.tail(n);
    dv = a * (s_.tail(n) - z_.tail(n)) + k_[i].tail(n);
    SolveVelocity(dv);
    dz_.head(n) = hg * dv;
    z_ += dz_;
    switch (newton_.Check(it, ErrorNorm(newton_norm_, n_, y, y, dz_))) {
      case NewtonControl::Verdict::kContinue:
        break;
      case NewtonControl::Verdict::kConverged:
        k_[i] = (z_ - s_) * a;  // F(y + Z_i) consistent with the converged stage
        return StageResult::kConverged;
      case NewtonControl::Verdict::kSlow:
        return StageResult::kSlow;
      case NewtonControl::Verdict::kDiverged:
        return StageResult::kDiverged;
    }
  }
  return StageResult::kSlow;
}

void SdirkIntegrator::Predict(int i) {
  // The known stage derivative nearest in time: F(y_n) at c = 0 or a converged stage j < i.
  // (Polynomial extrapolation through two to four of them was tried: it did not save Newton
  // iterations on the rubber rod and added rejections.)
  int best = -1;
  for (int j = 0; j < i; ++j)
    if (std::abs(kC[j] - kC[i]) < std::abs((best < 0 ? 0.0 : kC[best]) - kC[i])) best = j;
  guess_ = best < 0 ? k0_ : k_[best];
}

bool SdirkIntegrator::Step(const Eigen::Ref<const Eigen::VectorXd>& y, double h,
                           Eigen::Ref<Eigen::VectorXd> y_new, Eigen::Ref<Eigen::VectorXd> error) {
  if (!BeginStep(y, h)) return false;
  const double hg = kGamma * h;
  if (!have_k_guess_) {
    F(y, k_[kStages - 1]);
    have_k_guess_ = true;
  }
  k0_ = k_[kStages - 1];  // F(y_n), up to the projection
  for (int i = 0; i < kStages; ++i) {
    s_.setZero();
    for (int j = 0; j < i; ++j) s_ += (h * kA[i][j]) * k_[j];
    Predict(i);
    z_ = s_ + hg * guess_;
    for (int refreshes = 0;; ++refreshes) {
      const StageResult r = SolveStage(i, y, h);
      if (r == StageResult::kConverged) break;
      ++newton_.stats.newton_failures;
      if (refreshes == kMaxRefreshes) return false;
      // The iteration matrix is too far from J at the stage (the stiff directions have turned,
      // or the step is long for the nonlinearity): evaluate J at the current iterate, or at
      // the predictor after a divergence, and go on from there (a Newton method with a few
      // Jacobian updates rather than a simplified one).
      if (r == StageResult::kDiverged || !z_.allFinite()) z_ = s_ + hg * guess_;
      tmp_ = y + z_;
      RefreshJacobian(tmp_);
      if (!Factorize(h)) return false;
      newton_.ForgetRate();
    }
  }
  y_new = y + z_;  // stiffly accurate: y_{n+1} = Y_5
  // A slow Newton contraction: a fresh J for the next step.
  EndStep();
  error.setZero();
  for (int i = 0; i < kStages; ++i)
    if (kE[i] != 0.0) error += (h * kE[i]) * k_[i];
  // Filter: (I − γhJ)⁻¹ err = (aI − J)⁻¹ (a err).
  error *= 1.0 / hg;
  UpdateRotation(0, y_new);
  SolveShifted(1.0 / (kGamma * factor_h_), 0, error);
  return true;
}

void SdirkIntegrator::BeginAdvance(bool /*continuing*/) {
  have_k_guess_ = false;  // the state may have been changed by the caller
}

SdirkIntegrator::Trial SdirkIntegrator::TryStep(double h) {
  const bool ok = Step(y_, h, y_new_, err_);
  return {ok, ok ? std::max(ErrorNorm(options_, n_, y_, y_new_, err_), IntegratedVelocityError(h))
                 : 0.0};
}

double SdirkIntegrator::Rejected(double h, const Trial& trial) {
  // Newton failure even with a fresh Jacobian: halve; error too large: the controller.
  const double next =
      trial.ok ? h * std::clamp(0.9 * std::pow(trial.err, -0.25), 0.2, 0.9) : 0.5 * h;
  have_k_guess_ = true;  // k_[4] may be from the failed attempt: recompute
  F(y_, k_[kStages - 1]);
  return next;
}

double SdirkIntegrator::Accepted(double h, double err) {
  // k_[4] = F(Y_5) = F(y_{n+1}) before the projection: the next step's first predictor.
  double fac = std::clamp(0.9 * std::pow(std::max(err, 1e-10), -0.25), 0.2, 5.0);
  if (last_rejected_) fac = std::min(fac, 1.0);
  // Keep h (and the factorisation) for growth below 20 %.
  if (fac >= 1.0 && fac <= 1.2) fac = 1.0;
  return h * fac;
}

}  // namespace cosserat::quatfd
