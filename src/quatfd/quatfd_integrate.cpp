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
  void operator()(const State& y, State& dydt, double /*t*/) const {
    const int n = model->size();
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
  // control is ours so both integrators share ErrorNorm and the per-block tolerances.
  odeint::runge_kutta_dopri5<State> stepper;
  State y, dydt, y_new, dydt_new, err;
};

Dopri5Integrator::Dopri5Integrator(const QuatFdModel& model, const IntegratorOptions& options)
    : model_(model), options_(options) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("IntegratorOptions: " + why);
  impl_ = std::make_unique<Impl>();
  for (State* s : {&impl_->y, &impl_->dydt, &impl_->y_new, &impl_->dydt_new, &impl_->err})
    s->resize(2 * model.size());
  dt_ = options.initial_dt;
}

Dopri5Integrator::~Dopri5Integrator() = default;

IntegratorStatus Dopri5Integrator::Advance(double t_end, double* t, Eigen::Ref<Eigen::VectorXd> q,
                                           Eigen::Ref<Eigen::VectorXd> v) {
  const int n = model_.size();
  Impl& m = *impl_;
  Eigen::Map<Eigen::VectorXd> ym(m.y.data(), 2 * n), ynm(m.y_new.data(), 2 * n),
      em(m.err.data(), 2 * n);
  ym.head(n) = q;
  ym.tail(n) = v;
  const System sys{&model_, &stats_.f_evaluations};
  sys(m.y, m.dydt, *t);  // FSAL: the derivative at the start of the interval
  long attempts = 0;
  IntegratorStatus status = IntegratorStatus::kOk;
  while (*t < t_end) {
    if (++attempts > options_.max_steps) {
      status = IntegratorStatus::kMaxSteps;
      break;
    }
    if (options_.max_dt > 0) dt_ = std::min(dt_, options_.max_dt);
    const bool last = *t + dt_ * (1 + 1e-12) >= t_end;
    const double h = last ? t_end - *t : dt_;
    m.stepper.do_step(sys, m.y, m.dydt, *t, m.y_new, m.dydt_new, h, m.err);
    double err = ErrorNorm(options_, n, ym, ynm, em);
    if (!std::isfinite(err) || !ynm.allFinite()) err = 1e10;
    // Order-5 controller: h_new = h · clamp(0.9 err^(−1/5), 0.2, 5).
    const double fac = std::clamp(0.9 * std::pow(std::max(err, 1e-300), -0.2), 0.2, 5.0);
    if (err > 1.0) {
      ++stats_.rejected;
      dt_ = h * std::min(fac, 0.9);
      if (dt_ < options_.min_dt) {
        status = IntegratorStatus::kStepSizeUnderflow;
        break;
      }
      continue;
    }
    ym = ynm;  // copies keep the maps valid
    m.dydt = m.dydt_new;
    AcceptStep(model_, options_, h, last, t_end, t, ym, &stats_);
    if (options_.project) sys(m.y, m.dydt, *t);  // the FSAL derivative of the projected state
    const double next = h * fac;
    if (!last || next < dt_) dt_ = next;
  }
  q = ym.head(n);
  v = ym.tail(n);
  return status;
}

std::unique_ptr<QuatFdIntegrator> MakeIntegrator(IntegratorKind kind, const QuatFdModel& model,
                                                 const IntegratorOptions& options) {
  if (kind == IntegratorKind::kDopri5) return std::make_unique<Dopri5Integrator>(model, options);
  if (kind == IntegratorKind::kSdirk) return std::make_unique<SdirkIntegrator>(model, options);
  if (kind == IntegratorKind::kRadau) return std::make_unique<RadauIntegrator>(model, options);
  return std::make_unique<RosenbrockIntegrator>(model, options);
}

}  // namespace cosserat::quatfd
