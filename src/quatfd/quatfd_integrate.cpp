#include "cosserat/quatfd/quatfd_integrate.hpp"

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <stdexcept>

#include "cosserat/quatfd/radau.hpp"
#include "cosserat/quatfd/rosenbrock.hpp"
#include "cosserat/quatfd/sdirk.hpp"

namespace cosserat::quatfd {

namespace odeint = boost::numeric::odeint;
using State = std::vector<double>;

const char* ToString(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::kDopri5:
      return "dopri5";
    case IntegratorKind::kRosenbrock:
      return "rosenbrock";
    case IntegratorKind::kRadau:
      return "radau";
    case IntegratorKind::kSdirk:
      break;
  }
  return "sdirk";
}

namespace {

/// y' = [v; f(q, v)] for odeint, counting evaluations.
struct System {
  const QuatFdModel* model;
  long* count;
  void operator()(const State& y, State& dydt, double t) const {
    const int n = model->size();
    model->set_time(t);
    Eigen::Map<const Eigen::VectorXd> yy(y.data(), 2 * n);
    Eigen::Map<Eigen::VectorXd> d(dydt.data(), 2 * n);
    d.head(n) = yy.tail(n);
    model->Acceleration(yy.head(n), yy.tail(n), d.tail(n));
    ++*count;
  }
};

}  // namespace

struct Dopri5Integrator::Impl {
  // odeint's error stepper (5th order with the embedded 4th-order estimate, FSAL); the step-size
  // control is ours so all integrators share ErrorNorm and the per-block tolerances. odeint's
  // state is a std::vector: y mirrors y_ at every trial.
  odeint::runge_kutta_dopri5<State> stepper;
  State y, dydt, y_new, dydt_new, err;
};

namespace {

/// The order-5 controller's factor clamp(0.9 err^(−1/5), 0.2, 5).
double StepFactor(double err) {
  return std::clamp(0.9 * std::pow(std::max(err, 1e-300), -0.2), 0.2, 5.0);
}

}  // namespace

Dopri5Integrator::Dopri5Integrator(const QuatFdModel& model, const IntegratorOptions& options)
    : AdaptiveIntegrator(model, options) {
  impl_ = std::make_unique<Impl>();
  for (State* s : {&impl_->y, &impl_->dydt, &impl_->y_new, &impl_->dydt_new, &impl_->err})
    s->resize(2 * n_);
}

Dopri5Integrator::~Dopri5Integrator() = default;

void Dopri5Integrator::BeginAdvance(bool /*continuing*/) {
  Impl& m = *impl_;
  Eigen::Map<Eigen::VectorXd>(m.y.data(), 2 * n_) = y_;
  // FSAL: the derivative at the start of the interval.
  System{&model_, &stats_.f_evaluations}(m.y, m.dydt, step_start_);
}

AdaptiveIntegrator::Trial Dopri5Integrator::TryStep(double h) {
  Impl& m = *impl_;
  const System sys{&model_, &stats_.f_evaluations};
  m.stepper.do_step(sys, m.y, m.dydt, step_start_, m.y_new, m.dydt_new, h, m.err);
  y_new_ = Eigen::Map<const Eigen::VectorXd>(m.y_new.data(), 2 * n_);
  err_ = Eigen::Map<const Eigen::VectorXd>(m.err.data(), 2 * n_);
  return {true, ErrorNorm(options_, n_, y_, y_new_, err_)};
}

double Dopri5Integrator::Rejected(double h, const Trial& trial) {
  return h * std::min(StepFactor(trial.err), 0.9);
}

double Dopri5Integrator::Accepted(double h, double err) {
  Impl& m = *impl_;
  Eigen::Map<Eigen::VectorXd>(m.y.data(), 2 * n_) = y_;  // the new state, projected
  m.dydt = m.dydt_new;
  if (options_.project)  // the FSAL derivative of the projected state
    System{&model_, &stats_.f_evaluations}(m.y, m.dydt, step_start_);
  return h * StepFactor(err);
}

std::unique_ptr<QuatFdIntegrator> MakeIntegrator(IntegratorKind kind, const QuatFdModel& model,
                                                 const IntegratorOptions& options) {
  if (kind == IntegratorKind::kDopri5) return std::make_unique<Dopri5Integrator>(model, options);
  if (kind == IntegratorKind::kSdirk) return std::make_unique<SdirkIntegrator>(model, options);
  if (kind == IntegratorKind::kRadau) return std::make_unique<RadauIntegrator>(model, options);
  return std::make_unique<RosenbrockIntegrator>(model, options);
}

}  // namespace cosserat::quatfd
