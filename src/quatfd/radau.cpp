#include "cosserat/quatfd/radau.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <string>

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
// J is refreshed for the next step when a step's Newton contraction exceeded this (0.03 and 0.3
// were measured on (a): 109 and 122 ms against 105 ms).
constexpr double kThetaRefresh = 0.1;
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
constexpr double kSafety = 0.9;

}  // namespace

RadauIntegrator::RadauIntegrator(const QuatFdModel& model, const IntegratorOptions& options,
                                 bool corotate)
    : model_(model), options_(options), corotate_(corotate) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("IntegratorOptions: " + why);
  (void)RadauIIA3();  // built here, not in the first Advance
  n_ = model.size();
  const int bw = QuatFdLayout::kBandwidth;
  jac_.Resize(model);
  Mr_.Resize(n_, bw, bw);
  Mc_.Resize(n_, bw, bw);
  for (Eigen::VectorXd* v : {&y_, &y_new_, &err_, &f0_, &tmp_, &dZ_}) v->resize(2 * n_);
  y_.setConstant(std::numeric_limits<double>::quiet_NaN());  // no state yet (Advance compares)
  for (int i = 0; i < 3; ++i) {
    Z_[i].setZero(2 * n_);
    cont_[i].setZero(2 * n_);
    K_[i].resize(n_);
    dW_[i].resize(n_);
  }
  acc_.resize(n_);
  newton_velocity_atol_ = std::min(options.abs_tol, options.velocity_abs_tol);
  for (CoRotation& c : corotation_) c.Resize(model.layout().segments);
  dt_ = options.initial_dt;
  kappa_ = kKappaDefault;
}

void RadauIntegrator::RefreshJacobian(const Eigen::Ref<const Eigen::VectorXd>& y) {
  jac_.Evaluate(model_, y, &stats_);
  factor_h_ = 0.0;
}

bool RadauIntegrator::Factorize(double h) {
  if (factor_h_ == h) return true;
  const RadauIIA3Tableau& k = RadauIIA3();
  const double ar = k.gamma / h;
  const std::complex<double> ac(k.alpha / h, k.beta / h);
  const std::complex<double> ac2 = ac * ac;
  const int n = n_, bw = QuatFdLayout::kBandwidth;
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - bw); i <= std::min(n - 1, j + bw); ++i) {
      const double a = jac_.dfdq(i, j), b = jac_.dfdv(i, j);
      Mr_(i, j) = -ar * b - a + (i == j ? ar * ar : 0.0);
      const std::complex<double> d = i == j ? ac2 : std::complex<double>(0.0);
      Mc_.Set(i, j, -ac.real() * b - a + d.real(), -ac.imag() * b + d.imag());
    }
  stats_.factorizations += 2;
  factor_h_ = 0.0;
  if (!Mr_.Factorize() || !Mc_.Factorize()) return false;
  factor_h_ = h;
  return true;
}

void RadauIntegrator::SolveReal(Eigen::Ref<Eigen::VectorXd> r) {
  // (aI − J) x = r with J = [[0, I], [A, B]], a = γ/h: x_v = M⁻¹ (a r_v + A r_q),
  // x_q = (r_q + x_v)/a; turned by the co-rotation.
  const double a = RadauIIA3().gamma / factor_h_;
  auto rq = r.head(n_);
  auto rv = r.tail(n_);
  RotateHalf(3, rq, true);
  RotateHalf(3, rv, true);
  jac_.dfdq.Multiply(rq, acc_);
  rv = a * rv + acc_;
  Mr_.Solve(rv);
  rq = (rq + rv) / a;
  RotateHalf(3, rq, false);
  RotateHalf(3, rv, false);
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
    UpdateRotations(i, tmp_);
  }
  double eta = std::pow(std::max(eta_, 1e-16), 0.8);
  double previous = 0.0;
  for (int it = 0; it < kMaxIterations; ++it) {
    for (int i = 0; i < 3; ++i) {
      tmp_ = y + Z_[i];
      if (it > 0) UpdateRotations(i, tmp_);
      model_.Acceleration(tmp_.head(n), tmp_.tail(n), K_[i]);
    }
    stats_.f_evaluations += 3;
    ++newton_.newton_iterations;
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
    Mr_.Solve(dW_[0]);
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
      const double sv = newton_velocity_atol_ + options_.rel_tol * std::abs(y[n + e]);
      const double sq = options_.abs_tol + options_.rel_tol * std::abs(y[e]);
      for (int r = 0; r < 3; ++r) {
        Z_[r][n + e] += dz[r];
        const double dq = h * (k.A[r][0] * dz[0] + k.A[r][1] * dz[1] + k.A[r][2] * dz[2]);
        d = std::max(d, std::max(std::abs(dz[r]) / sv, std::abs(dq) / sq));
      }
    }
    FillPositions(y, h);
    if (!std::isfinite(d)) return NewtonResult::kDiverged;
    if (it > 0) {
      const double theta = d / previous;
      if (theta >= 0.99) return NewtonResult::kDiverged;
      eta = theta / (1.0 - theta);
      theta_ = std::max(theta_, theta);
      if (std::pow(theta, kMaxIterations - 1 - it) / (1.0 - theta) * d > kappa_)
        return NewtonResult::kSlow;
    }
    if (eta * d <= kappa_ || d == 0.0) {
      eta_ = eta;
      last_iterations_ = it + 1;
      return NewtonResult::kConverged;
    }
    previous = d;
  }
  return NewtonResult::kSlow;
}

bool RadauIntegrator::Step(const Eigen::Ref<const Eigen::VectorXd>& y, double h,
                           Eigen::Ref<Eigen::VectorXd> y_new, Eigen::Ref<Eigen::VectorXd> error) {
  const RadauIIA3Tableau& k = RadauIIA3();
  jac_.fresh = false;
  if (!jac_.valid || refresh_next_step_) RefreshJacobian(y);
  refresh_next_step_ = false;
  theta_ = 0.0;
  if (!Factorize(h)) {
    if (jac_.fresh) return false;
    RefreshJacobian(y);
    if (!Factorize(h)) return false;
  }
  for (int attempt = 0;; ++attempt) {
    StartingValues(h);
    const NewtonResult r = Newton(y, h);
    if (r == NewtonResult::kConverged) break;
    ++newton_.newton_failures;
    if (jac_.fresh) return false;
    // The kept (turned) J does not make the iteration contract: a fresh one at y_n.
    RefreshJacobian(y);
    eta_ = 1.0;
    if (!Factorize(h)) return false;
  }
  y_new = y + Z_[2];  // stiffly accurate
  if (theta_ > kThetaRefresh) refresh_next_step_ = true;
  // Error: (γ/h I − J)⁻¹ [f(y_n) + Σ dd_i Z_i / h], turned to y_new.
  error = f0_;
  for (int i = 0; i < 3; ++i) error += (k.dd[i] / h) * Z_[i];
  UpdateRotations(3, y_new);
  SolveReal(error);
  return true;
}

IntegratorStatus RadauIntegrator::Advance(double t_end, double* t, Eigen::Ref<Eigen::VectorXd> q,
                                          Eigen::Ref<Eigen::VectorXd> v) {
  const int n = n_;
  const RadauIIA3Tableau& k = RadauIIA3();
  // Keep the extrapolation polynomial only when the caller continues from where we stopped.
  if (!(y_.head(n) == q && y_.tail(n) == v)) have_poly_ = false;
  y_.head(n) = q;
  y_.tail(n) = v;
  F(y_, f0_);
  long attempts = 0;
  bool first = !have_poly_;
  bool last_rejected = false;
  double h_acc = 0.0, err_acc = 1e-2;
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
    double err = ok ? ErrorMeasure() : 0.0;
    if (ok && err >= 1.0 && (first || last_rejected)) {
      // Hairer's second filtering for stiff components after a rejection: f at y_n + err.
      tmp_ = y_ + err_;
      F(tmp_, err_);
      for (int i = 0; i < 3; ++i) err_ += (k.dd[i] / h) * Z_[i];
      SolveReal(err_);
      err = ErrorMeasure();
    }
    if (ok && (!std::isfinite(err) || !y_new_.allFinite())) err = 1e10;
    // RADAU5's controller: safety reduced with the Newton iterations used.
    const double fac = std::min(kSafety, kSafety * (1 + 2 * kSafetyIterations) /
                                             (last_iterations_ + 2 * kSafetyIterations));
    double quot = std::clamp(std::pow(std::max(err, 1e-10), 0.25) / fac, 0.2, 8.0);
    if (!ok || err > 1.0) {
      ++stats_.rejected;
      dt_ = !ok ? kFailFactor * h : (first ? 0.1 * h : h / quot);
      if (!ok && kCapFactor > 0) newton_cap_ = kCapFactor * h;
      last_rejected = true;
      if (dt_ < options_.min_dt) {
        q = y_.head(n);
        v = y_.tail(n);
        return IntegratorStatus::kStepSizeUnderflow;
      }
      continue;
    }
    if (!first && h_acc > 0.0) {
      // Gustafsson's predictive controller.
      const double gus =
          std::clamp(h_acc / h * std::pow(err * err / err_acc, 0.25) / kSafety, 0.2, 8.0);
      quot = std::max(quot, gus);
    }
    h_acc = h;
    err_acc = std::max(1e-2, err);
    // The collocation polynomial for the next starting values (Newton form about 1, c2, c1).
    {
      const double c1 = k.c[0], c2 = k.c[1];
      cont_[0] = (Z_[1] - Z_[2]) / (c2 - 1);
      dZ_ = (Z_[0] - Z_[1]) / (c1 - c2);  // [c1, c2]
      cont_[1] = (dZ_ - cont_[0]) / (c1 - 1);
      dZ_ = (dZ_ - Z_[0] / c1) / c2;  // [c2, c1, 0]
      cont_[2] = cont_[1] - dZ_;
      h_poly_ = h;
      have_poly_ = true;
    }
    y_.swap(y_new_);
    AcceptStep(model_, options_, h, last, t_end, t, y_, &stats_);
    F(y_, f0_);
    double next = h / quot;
    if (last_rejected) next = std::min(next, h);
    // Hold h (and the LUs) for growth below 20 %.
    if (next >= h && next <= 1.2 * h) next = h;
    if (newton_cap_ > 0) {
      next = std::min(next, newton_cap_);
      newton_cap_ *= kCapGrowth;
    }
    if (!last || next < dt_) dt_ = next;
    first = false;
    last_rejected = false;
  }
  q = y_.head(n);
  v = y_.tail(n);
  return IntegratorStatus::kOk;
}

}  // namespace cosserat::quatfd
