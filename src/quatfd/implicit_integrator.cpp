#include "cosserat/quatfd/implicit_integrator.hpp"

#include <algorithm>
#include <cmath>

namespace cosserat::quatfd {

void NewtonControl::BeginSolve() {
  eta_ = std::pow(std::max(eta_memory_, 1e-16), 0.8);
  previous_ = 0.0;
}

NewtonControl::Verdict NewtonControl::Check(int iteration, double d) {
  if (!std::isfinite(d)) return Verdict::kDiverged;
  if (iteration > 0) {
    const double theta = d / previous_;
    max_theta_ = std::max(max_theta_, theta);
    const bool judged = !(grace_ && iteration == 1);
    if (theta >= 0.99) {
      if (judged) return Verdict::kDiverged;
      previous_ = d;
      return Verdict::kContinue;
    }
    eta_ = theta / (1.0 - theta);
    // Would the iteration still need too many iterations at this rate?
    if (judged && std::pow(theta, max_iterations_ - 1 - iteration) / (1.0 - theta) * d > kappa_)
      return Verdict::kSlow;
  }
  if (eta_ * d <= kappa_ || d == 0.0) {
    eta_memory_ = eta_;
    return Verdict::kConverged;
  }
  previous_ = d;
  return Verdict::kContinue;
}

ImplicitIntegrator::ImplicitIntegrator(const QuatFdModel& model, const IntegratorOptions& options,
                                       bool corotate, int rotation_slots, int max_newton_iterations,
                                       double kappa, bool first_contraction_grace)
    : AdaptiveIntegrator(model, options),
      corotate_(corotate),
      newton_(max_newton_iterations, kappa, first_contraction_grace),
      newton_norm_(options),
      corotation_(rotation_slots, CoRotation(model.layout().segments)) {
  jac_.Resize(model);
  const int bw = QuatFdLayout::kBandwidth;
  M_.Resize(n_, bw, bw);
  acc_.resize(n_);
  newton_norm_.velocity_abs_tol = std::min(options.abs_tol, options.velocity_abs_tol);
}

void ImplicitIntegrator::RefreshJacobian(const Eigen::Ref<const Eigen::VectorXd>& y) {
  jac_.Evaluate(model_, y, &stats_);
  factor_h_ = 0.0;
}

bool ImplicitIntegrator::Factorize(double h) {
  if (factor_h_ == h) return true;
  factor_h_ = 0.0;
  if (!FactorizeMatrices(h)) return false;
  factor_h_ = h;
  return true;
}

bool ImplicitIntegrator::FactorizeShifted(double a) {
  jac_.AssembleShifted(a, &M_);
  ++stats_.factorizations;
  return M_.Factorize();
}

bool ImplicitIntegrator::BeginStep(const Eigen::Ref<const Eigen::VectorXd>& y, double h) {
  jac_.fresh = false;
  if (!jac_.valid || refresh_next_step_) RefreshJacobian(y);
  refresh_next_step_ = false;
  newton_.BeginStep();
  if (Factorize(h)) return true;
  if (jac_.fresh) return false;
  RefreshJacobian(y);
  return Factorize(h);
}

void ImplicitIntegrator::SolveShifted(double a, int slot, Eigen::Ref<Eigen::VectorXd> r) {
  RotateHalf(slot, r.head(n_), true);
  RotateHalf(slot, r.tail(n_), true);
  jac_.SolveShifted(a, M_, r, acc_);
  RotateHalf(slot, r.head(n_), false);
  RotateHalf(slot, r.tail(n_), false);
}

}  // namespace cosserat::quatfd
