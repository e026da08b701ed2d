#include "cosserat/quatfd/radau.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>

#include "cosserat/quatfd/quatfd_kernels.hpp"
#include "cosserat/quatfd/radau_tableau.hpp"

namespace cosserat::quatfd {
namespace {

// Newton iterations per step before it counts as failed. RADAU5's NIT is 7; 15 converge steps
// that 7 would reject (the slowly contracting quaternion rates of docs/performance.md, "What
// limits the Radau step: Newton"): (a) 1 198 → 1 109 steps, (b) 5 345 → 4 620; tips at 10 s move by
// 1e-9 m (a) and 5e-9 m (b).
constexpr int kMaxIterations = 15;
// The step-size controller's safety factor keeps RADAU5's NIT = 7 in its formula.
constexpr int kSafetyIterations = 7;
// A step whose Newton iteration fails even with a fresh J is retried at kFailFactor h, and the
// steps after it are capped at kCapFactor h, the cap growing by kCapGrowth per accepted step.
// Without the cap the controller (which sees a small error) grows h straight back into the
// failure: (b) 6 958 steps + 2 909 rejected, 1.57 s; with it 6 424 + 998, 1.25 s; (a) 123 → 63
// rejections.
constexpr double kFailFactor = 0.5;
constexpr double kCapFactor = 0.8;
constexpr double kCapGrowth = 1.05;
// Newton stops when η ‖ΔZ‖ ≤ κ in the error norm (abs_tol also on v), SDIRK's rule; 0.02 and
// 0.1 were measured: 116 and 101 ms on (a) against 105 ms. The stricter one is kept, as SDIRK's.
constexpr double kKappaDefault = 0.05;
// The first contraction d1/d0 is not judged (NewtonControl): from the extrapolated starting
// values it is often 0.5–1 where the next ones are 0.03–0.2 (the first correction removes the
// stiff components' extrapolation error), and judging it rejected most Newton failures of (a):
// at rel_tol 1e-4, 70 Newton failures, 64 rejections, 715 steps → 3, 16, 611 (37 → 31 ms CPU).
constexpr bool kFirstContractionGrace = true;
constexpr double kSafety = 0.9;

}  // namespace

RadauIntegrator::RadauIntegrator(const QuatFdModel& model, const IntegratorOptions& options,
                                 bool corotate)
    : ImplicitIntegrator(model, options, corotate, 4, kMaxIterations, kKappaDefault,
                         kFirstContractionGrace) {
  (void)RadauIIA3();  // built here, not in the first Advance
  const int bw = QuatFdLayout::kBandwidth;
  Mc_.Resize(n_, bw, bw);
  for (Eigen::VectorXd* v : {&f0_, &tmp_, &dZ_}) v->resize(2 * n_);
  for (int i = 0; i < 3; ++i) {
    Z_[i].setZero(2 * n_);
    cont_[i].setZero(2 * n_);
    K_[i].resize(n_);
    dW_[i].resize(n_);
  }
}

bool RadauIntegrator::FactorizeMatrices(double h) {
  const RadauIIA3Tableau& k = RadauIIA3();
  const std::complex<double> ac(k.alpha / h, k.beta / h);
  const std::complex<double> ac2 = ac * ac;
  jac_.AssembleShifted(k.gamma / h, &M_);
  const int n = n_, bw = QuatFdLayout::kBandwidth;
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - bw); i <= std::min(n - 1, j + bw); ++i) {
      const double a = jac_.dfdq(i, j), b = jac_.dfdv(i, j);
      const std::complex<double> d = i == j ? ac2 : std::complex<double>(0.0);
      Mc_.Set(i, j, -ac.real() * b - a + d.real(), -ac.imag() * b + d.imag());
    }
  stats_.factorizations += 2;
  return M_.Factorize() && Mc_.Factorize();
}

void RadauIntegrator::SolveReal(Eigen::Ref<Eigen::VectorXd> r) {
  // (aI − J) x = r with a = γ/h, turned by the co-rotation of the error filter (slot 3).
  SolveShifted(RadauIIA3().gamma / factor_h_, 3, r);
}

double RadauIntegrator::ErrorMeasure() const {
  return error_measure_ == RadauErrorMeasure::kComponents
             ? ErrorNorm(options_, n_, y_, y_new_, err_)
             : RotationErrorNorm(options_, model_.layout(), y_, y_new_, err_);
}

void RadauIntegrator::StartingValues(double h) {
  const RadauIIA3Tableau& k = RadauIIA3();
  if (!have_poly_) {
    for (auto& z : Z_) z.setZero();
    return;
  }
  // The collocation polynomial of the last step through (0, 0), (c1, Z1), (c2, Z2), (1, Z3),
  // in Newton form about 1, c2, c1 (cont_), evaluated at 1 + c_i h/h_poly, relative to its value
  // at 1 (= y_n up to the projection).
  const double r = h / h_poly_;
  for (int i = 0; i < 3; ++i) {
    const double s = k.c[i] * r;
    Z_[i] = s * (cont_[0] + (s - (k.c[1] - 1)) * (cont_[1] + (s - (k.c[0] - 1)) * cont_[2]));
  }
}

void RadauIntegrator::FillPositions(const Eigen::Ref<const Eigen::VectorXd>& y, double h) {
  const RadauIIA3Tableau& k = RadauIIA3();
  const int n = n_;
  for (int i = 0; i < 3; ++i) {
    auto zq = Z_[i].head(n);
    zq = (h * (k.A[i][0] + k.A[i][1] + k.A[i][2])) * y.tail(n);
    for (int j = 0; j < 3; ++j) zq += (h * k.A[i][j]) * Z_[j].tail(n);
  }
}

RadauIntegrator::NewtonResult RadauIntegrator::Newton(const Eigen::Ref<const Eigen::VectorXd>& y,
                                                      double h) {
  const RadauIIA3Tableau& k = RadauIIA3();
  const int n = n_;
  const double ar = k.gamma / h;
  const std::complex<double> ac(k.alpha / h, k.beta / h);
  const double ih = 1.0 / h;
  FillPositions(y, h);
  // The co-rotation of each stage, to its current iterate: at the starting value here, then at
  // every iteration below (cheap: N quaternion products). Once per attempt only: (b) 6 426
  // steps, 1 007 rejected, 1.21 s; every iteration: 5 345, 689, 1.04 s; (a) unchanged.
  for (int i = 0; i < 3; ++i) {
    tmp_ = y + Z_[i];
    UpdateRotation(i, tmp_);
  }
  newton_.BeginSolve();
  for (int it = 0; it < kMaxIterations; ++it) {
    for (int i = 0; i < 3; ++i) {
      tmp_ = y + Z_[i];
      if (it > 0) UpdateRotation(i, tmp_);
      StageAcceleration(k.c[i], h, tmp_.head(n), tmp_.tail(n), K_[i]);
    }
    stats_.f_evaluations += 3;
    ++newton_.stats.newton_iterations;
    // Velocity residuals G_i = K_i − (A⁻¹ Z_v)_i / h, turned back by each stage's co-rotation
    // (into dW_), then transformed: r = T⁻¹ Pᵀ G.
    for (int e = 0; e < n; ++e) {
      const double z0 = Z_[0][n + e], z1 = Z_[1][n + e], z2 = Z_[2][n + e];
      for (int r = 0; r < 3; ++r)
        dW_[r][e] = K_[r][e] - ih * (k.Ainv[r][0] * z0 + k.Ainv[r][1] * z1 + k.Ainv[r][2] * z2);
    }
    for (int r = 0; r < 3; ++r) RotateHalf(r, dW_[r], true);
    for (int e = 0; e < n; ++e) {
      const double g0 = dW_[0][e], g1 = dW_[1][e], g2 = dW_[2][e];
      for (int r = 0; r < 3; ++r) dW_[r][e] = k.Ti[r][0] * g0 + k.Ti[r][1] * g1 + k.Ti[r][2] * g2;
    }
    // (a² I − a B − A) ΔW_v = a r_v per block, a = γ/h and (α + iβ)/h.
    dW_[0] *= ar;
    M_.Solve(dW_[0]);
    for (int e = 0; e < n; ++e) {  // a (r1 + i r2), written out (no Annex G checks)
      const double x = dW_[1][e], z = dW_[2][e];
      dW_[1][e] = ac.real() * x - ac.imag() * z;
      dW_[2][e] = ac.real() * z + ac.imag() * x;
    }
    Mc_.Solve(dW_[1], dW_[2]);  // real and imaginary parts in place
    // ΔZ_v,i = P_i (T ΔW_v)_i.
    for (int e = 0; e < n; ++e) {
      const double w0 = dW_[0][e], w1 = dW_[1][e], w2 = dW_[2][e];
      for (int r = 0; r < 3; ++r) dW_[r][e] = k.T[r][0] * w0 + k.T[r][1] * w1 + k.T[r][2] * w2;
    }
    for (int r = 0; r < 3; ++r) RotateHalf(r, dW_[r], false);
    // Z_v += ΔZ_v, ΔZ_q = h A ΔZ_v (the q-half stays exact); norm over the three stages.
    double d = 0.0;
    for (int e = 0; e < n; ++e) {
      const double dz[3] = {dW_[0][e], dW_[1][e], dW_[2][e]};
      const double sv = newton_norm_.velocity_abs_tol + options_.rel_tol * std::abs(y[n + e]);
      const double sq = options_.abs_tol + options_.rel_tol * std::abs(y[e]);
      for (int r = 0; r < 3; ++r) {
        Z_[r][n + e] += dz[r];
        const double dq = h * (k.A[r][0] * dz[0] + k.A[r][1] * dz[1] + k.A[r][2] * dz[2]);
        d = std::max(d, std::max(std::abs(dz[r]) / sv, std::abs(dq) / sq));
      }
    }
    FillPositions(y, h);
    switch (newton_.Check(it, d)) {
      case NewtonControl::Verdict::kContinue:
        break;
      case NewtonControl::Verdict::kConverged:
        last_iterations_ = it + 1;
        return NewtonResult::kConverged;
      case NewtonControl::Verdict::kSlow:
        return NewtonResult::kSlow;
      case NewtonControl::Verdict::kDiverged:
        return NewtonResult::kDiverged;
    }
  }
  return NewtonResult::kSlow;
}

bool RadauIntegrator::Step(const Eigen::Ref<const Eigen::VectorXd>& y, double h,
                           Eigen::Ref<Eigen::VectorXd> y_new, Eigen::Ref<Eigen::VectorXd> error) {
  F(y, f0_);  // Advance keeps f0_ = f(y_) up to date; a caller's y needs its own
  jac_at_y_ = false;
  return Attempt(y, h, y_new, error);
}

bool RadauIntegrator::Attempt(const Eigen::Ref<const Eigen::VectorXd>& y, double h,
                              Eigen::Ref<Eigen::VectorXd> y_new,
                              Eigen::Ref<Eigen::VectorXd> error) {
  const RadauIIA3Tableau& k = RadauIIA3();
  if (!BeginStep(y, h)) return false;
  // J evaluated at y by Accepted counts as fresh for this attempt (a Newton failure then rejects
  // the step instead of evaluating the same J again).
  if (jac_at_y_) jac_.fresh = true;
  jac_at_y_ = false;
  for (int attempt = 0;; ++attempt) {
    StartingValues(h);
    const NewtonResult r = Newton(y, h);
    if (r == NewtonResult::kConverged) break;
    ++newton_.stats.newton_failures;
    if (jac_.fresh) return false;
    // The kept (turned) J does not make the iteration contract: a fresh one at y_n.
    RefreshJacobian(y);
    newton_.ForgetRate();
    if (!Factorize(h)) return false;
  }
  y_new = y + Z_[2];  // stiffly accurate
  // A slow Newton contraction: a fresh J for the next step.
  EndStep();
  // Error: (γ/h I − J)⁻¹ [f(y_n) + Σ dd_i Z_i / h], turned to y_new.
  error = f0_;
  for (int i = 0; i < 3; ++i) error += (k.dd[i] / h) * Z_[i];
  UpdateRotation(3, y_new);
  SolveReal(error);
  return true;
}

void RadauIntegrator::BeginAdvance(bool continuing) {
  // Keep the extrapolation polynomial only when the caller continues from where we stopped.
  if (!continuing) have_poly_ = false;
  if (!continuing && jac_at_y_) {  // J was taken at the state the last call ended with
    jac_at_y_ = false;
    refresh_next_step_ = true;
  }
  F(y_, f0_);
  first_ = !have_poly_;
  last_rejected_ = false;
  h_acc_ = 0.0;
  err_acc_ = 1e-2;
}

RadauIntegrator::Trial RadauIntegrator::TryStep(double h) {
  const RadauIIA3Tableau& k = RadauIIA3();
  const bool ok = Attempt(y_, h, y_new_, err_);
  double err = ok ? ErrorMeasure() : 0.0;
  if (ok && err >= 1.0 && (first_ || last_rejected_)) {
    // Hairer's second filtering for stiff components after a rejection: f at y_n + err.
    tmp_ = y_ + err_;
    F(tmp_, err_);
    for (int i = 0; i < 3; ++i) err_ += (k.dd[i] / h) * Z_[i];
    SolveReal(err_);
    err = ErrorMeasure();
  }
  return {ok, err};
}

double RadauIntegrator::StepQuotient(double err) const {
  // RADAU5's controller: safety reduced with the Newton iterations used.
  const double fac = std::min(
      kSafety, kSafety * (1 + 2 * kSafetyIterations) / (last_iterations_ + 2 * kSafetyIterations));
  return std::clamp(std::pow(std::max(err, 1e-10), 0.25) / fac, 0.2, 8.0);
}

double RadauIntegrator::Rejected(double h, const Trial& trial) {
  if (!trial.ok) {
    newton_cap_ = kCapFactor * h;
    return kFailFactor * h;
  }
  return first_ ? 0.1 * h : h / StepQuotient(trial.err);
}

double RadauIntegrator::Accepted(double h, double err) {
  double quot = StepQuotient(err);
  if (!first_ && h_acc_ > 0.0) {
    // Gustafsson's predictive controller.
    const double gus =
        std::clamp(h_acc_ / h * std::pow(err * err / err_acc_, 0.25) / kSafety, 0.2, 8.0);
    quot = std::max(quot, gus);
  }
  h_acc_ = h;
  err_acc_ = std::max(1e-2, err);
  KeepPolynomial(h);
  if (refresh_next_step_) {
    // The fresh J the next step asks for is taken here, at the new y_n, and its evaluation's
    // f(y_n) serves as f0_ (one f per refresh saved).
    RefreshJacobian(y_);
    refresh_next_step_ = false;
    jac_at_y_ = true;
    f0_.head(n_) = y_.tail(n_);
    f0_.tail(n_) = jac_.f;
  } else {
    F(y_, f0_);
  }
  double next = h / quot;
  if (last_rejected_) next = std::min(next, h);
  // Hold h (and the LUs) for growth below 20 %.
  if (next >= h && next <= 1.2 * h) next = h;
  if (newton_cap_ > 0) {
    next = std::min(next, newton_cap_);
    newton_cap_ *= kCapGrowth;
  }
  first_ = false;
  return next;
}

void RadauIntegrator::KeepPolynomial(double h) {
  const RadauIIA3Tableau& k = RadauIIA3();
  const double c1 = k.c[0], c2 = k.c[1];
  cont_[0] = (Z_[1] - Z_[2]) / (c2 - 1);
  dZ_ = (Z_[0] - Z_[1]) / (c1 - c2);  // [c1, c2]
  cont_[1] = (dZ_ - cont_[0]) / (c1 - 1);
  dZ_ = (dZ_ - Z_[0] / c1) / c2;  // [c2, c1, 0]
  cont_[2] = cont_[1] - dZ_;
  h_poly_ = h;
  have_poly_ = true;
}

}  // namespace cosserat::quatfd
