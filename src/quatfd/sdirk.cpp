#include "cosserat/quatfd/sdirk.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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
// A step whose iterations contracted by less than this (θ above it) refreshes J for the next
// step: on the rubber rod a J + LU (~20 µs at N = 10) costs less than the extra iterations.
constexpr double kThetaRefresh = 0.1;

}  // namespace

SdirkIntegrator::SdirkIntegrator(const QuatFdModel& model, const IntegratorOptions& options,
                                 bool corotate)
    : model_(model), options_(options), corotate_(corotate) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("IntegratorOptions: " + why);
  n_ = model.size();
  const int bw = QuatFdLayout::kBandwidth;
  jac_.Resize(model);
  M_.Resize(n_, bw, bw);
  for (Eigen::VectorXd* v : {&y_, &y_new_, &err_, &z_, &dz_, &s_, &tmp_, &k0_, &guess_})
    v->resize(2 * n_);
  for (Eigen::VectorXd& k : k_) k.resize(2 * n_);
  acc_.resize(n_);
  newton_norm_ = options;
  newton_norm_.velocity_abs_tol = std::min(options.abs_tol, options.velocity_abs_tol);
  corotation_.Resize(model.layout().segments);
  dt_ = options.initial_dt;
}

void SdirkIntegrator::RefreshJacobian(const Eigen::Ref<const Eigen::VectorXd>& y) {
  jac_.Evaluate(model_, y, &stats_);
  factor_h_ = 0.0;
}

bool SdirkIntegrator::Factorize(double h) {
  if (factor_h_ == h) return true;
  const double a = 1.0 / (kGamma * h);
  const int n = n_, bw = QuatFdLayout::kBandwidth;
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - bw); i <= std::min(n - 1, j + bw); ++i)
      M_(i, j) = -a * jac_.dfdv(i, j) - jac_.dfdq(i, j) + (i == j ? a * a : 0.0);
  ++stats_.factorizations;
  if (!M_.Factorize()) {
    factor_h_ = 0.0;
    return false;
  }
  factor_h_ = h;
  return true;
}

void SdirkIntegrator::Rotate(Eigen::Ref<Eigen::VectorXd> r, bool transpose) const {
  corotation_.Apply(r.head(n_), transpose);
  corotation_.Apply(r.tail(n_), transpose);
}

void SdirkIntegrator::Solve(Eigen::Ref<Eigen::VectorXd> r) {
  // With the co-rotation P (corotation.hpp): x = P (aI − J)⁻¹ Pᵀ r, i.e. the iteration matrix
  // of J(y_J) turned to the iterate's segment orientations.
  if (corotate_) Rotate(r, true);
  // w = M⁻¹ (a r_v + A r_q), x_q = (r_q + w)/a, x_v = w (the Rosenbrock integrator's reduction).
  const double a = 1.0 / (kGamma * factor_h_);
  auto rq = r.head(n_);
  auto rv = r.tail(n_);
  jac_.dfdq.Multiply(rq, acc_);
  rv = a * rv + acc_;
  M_.Solve(rv);
  rq = (rq + rv) / a;
  if (corotate_) Rotate(r, false);
}

void SdirkIntegrator::SolveVelocity(Eigen::Ref<Eigen::VectorXd> rv) {
  // rv ← P_v M⁻¹ a P_vᵀ rv, M = a² I − a B − A (zero q-half of the right-hand side).
  const double a = 1.0 / (kGamma * factor_h_);
  if (corotate_) corotation_.Apply(rv, true);
  rv *= a;
  M_.Solve(rv);
  if (corotate_) corotation_.Apply(rv, false);
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
  UpdateRotations(tmp_);  // once per stage, at the predictor
  double eta = std::pow(std::max(eta_, 1e-16), 0.8);
  double previous = 0.0;
  for (int it = 0; it < kMaxIterations; ++it) {
    if (it > 0) tmp_ = y + z_;
    k_[i].head(n) = tmp_.tail(n);
    model_.Acceleration(tmp_.head(n), tmp_.tail(n), k_[i].tail(n));
    ++stats_.f_evaluations;
    ++newton_.newton_iterations;
    auto dv = dz_.tail(n);
    dv = a * (s_.tail(n) - z_.tail(n)) + k_[i].tail(n);
    SolveVelocity(dv);
    dz_.head(n) = hg * dv;
    z_ += dz_;
    const double d = ErrorNorm(newton_norm_, n_, y, y, dz_);
    if (!std::isfinite(d)) return StageResult::kDiverged;
    if (it > 0) {
      const double theta = d / previous;
      if (theta >= 0.99) return StageResult::kDiverged;
      eta = theta / (1.0 - theta);
      max_theta_ = std::max(max_theta_, theta);
      // Would the iteration still need too many iterations at this rate?
      if (std::pow(theta, kMaxIterations - 1 - it) / (1.0 - theta) * d > kKappa)
        return StageResult::kSlow;
    }
    if (eta * d <= kKappa || d == 0.0) {
      eta_ = eta;
      k_[i] = (z_ - s_) * a;  // F(y + Z_i) consistent with the converged stage
      return StageResult::kConverged;
    }
    previous = d;
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
  jac_.fresh = false;
  if (!jac_.valid || refresh_next_step_) RefreshJacobian(y);
  max_theta_ = 0.0;
  refresh_next_step_ = false;
  if (!Factorize(h)) {
    if (jac_.fresh) return false;
    RefreshJacobian(y);
    if (!Factorize(h)) return false;
  }
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
      ++newton_.newton_failures;
      if (refreshes == kMaxRefreshes) return false;
      // The iteration matrix is too far from J at the stage (the stiff directions have turned,
      // or the step is long for the nonlinearity): evaluate J at the current iterate, or at
      // the predictor after a divergence, and go on from there (a Newton method with a few
      // Jacobian updates rather than a simplified one).
      if (r == StageResult::kDiverged || !z_.allFinite()) z_ = s_ + hg * guess_;
      tmp_ = y + z_;
      RefreshJacobian(tmp_);
      if (!Factorize(h)) return false;
      eta_ = 1.0;
    }
  }
  y_new = y + z_;  // stiffly accurate: y_{n+1} = Y_5
  // Slow contraction: a fresh Jacobian at the next step costs less than the extra iterations.
  if (max_theta_ > kThetaRefresh) refresh_next_step_ = true;
  error.setZero();
  for (int i = 0; i < kStages; ++i)
    if (kE[i] != 0.0) error += (h * kE[i]) * k_[i];
  // Filter: (I − γhJ)⁻¹ err = (aI − J)⁻¹ (a err).
  error *= 1.0 / hg;
  UpdateRotations(y_new);
  Solve(error);
  return true;
}

IntegratorStatus SdirkIntegrator::Advance(double t_end, double* t, Eigen::Ref<Eigen::VectorXd> q,
                                          Eigen::Ref<Eigen::VectorXd> v) {
  const int n = n_;
  y_.head(n) = q;
  y_.tail(n) = v;
  have_k_guess_ = false;  // the state may have been changed by the caller
  long attempts = 0;
  while (*t < t_end) {
    if (++attempts > options_.max_steps) {
      q = y_.head(n);
      v = y_.tail(n);
      return IntegratorStatus::kMaxSteps;
    }
    if (options_.max_dt > 0) dt_ = std::min(dt_, options_.max_dt);
    const bool last = *t + dt_ * (1 + 1e-12) >= t_end;
    const double h = last ? t_end - *t : dt_;
    const bool ok = Step(y_, h, y_new_, err_);
    double err = ok ? std::max(ErrorNorm(options_, n, y_, y_new_, err_), IntegratedVelocityError(h))
                    : 0.0;
    if (ok && (!std::isfinite(err) || !y_new_.allFinite())) err = 1e10;
    if (!ok || err > 1.0) {
      ++stats_.rejected;
      // Newton failure even with a fresh Jacobian: halve; error too large: the controller.
      dt_ = ok ? h * std::clamp(0.9 * std::pow(err, -0.25), 0.2, 0.9) : 0.5 * h;
      last_rejected_ = true;
      have_k_guess_ = true;  // k_[4] may be from the failed attempt: recompute
      F(y_, k_[kStages - 1]);
      if (dt_ < options_.min_dt) {
        q = y_.head(n);
        v = y_.tail(n);
        return IntegratorStatus::kStepSizeUnderflow;
      }
      continue;
    }
    y_.swap(y_new_);
    AcceptStep(model_, options_, h, last, t_end, t, y_, &stats_);
    // k_[4] = F(Y_5) = F(y_{n+1}) before the projection: the next step's first predictor.
    double fac = std::clamp(0.9 * std::pow(std::max(err, 1e-10), -0.25), 0.2, 5.0);
    if (last_rejected_) fac = std::min(fac, 1.0);
    // Keep h (and the factorisation) for growth below 20 %.
    if (fac >= 1.0 && fac <= 1.2) fac = 1.0;
    const double next = h * fac;
    if (!last || next < dt_) dt_ = next;
    last_rejected_ = false;
  }
  q = y_.head(n);
  v = y_.tail(n);
  return IntegratorStatus::kOk;
}

}  // namespace cosserat::quatfd
