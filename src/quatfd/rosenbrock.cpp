#include "cosserat/quatfd/rosenbrock.hpp"

#include <algorithm>
#include <cmath>

namespace cosserat::quatfd {
namespace {

// Coefficients of the 4th-order L-stable Rosenbrock method with 3rd-order embedded estimate, as
// in boost/numeric/odeint/stepper/rosenbrock4.hpp (autonomous system: the d_i ∂f/∂t terms vanish).
constexpr double kGamma = 0.25;
constexpr double c21 = -0.5668800000000000e+01, a21 = 0.1544000000000000e+01;
constexpr double c31 = -0.2430093356833875e+01, c32 = -0.2063599157091915e+00;
constexpr double a31 = 0.9466785280815826e+00, a32 = 0.2557011698983284e+00;
constexpr double c41 = -0.1073529058151375e+00, c42 = -0.9594562251023355e+01,
                 c43 = -0.2047028614809616e+02;
constexpr double a41 = 0.3314825187068521e+01, a42 = 0.2896124015972201e+01,
                 a43 = 0.9986419139977817e+00;
constexpr double c51 = 0.7496443313967647e+01, c52 = -0.1024680431464352e+02,
                 c53 = -0.3399990352819905e+02, c54 = 0.1170890893206160e+02;
constexpr double a51 = 0.1221224509226641e+01, a52 = 0.6019134481288629e+01,
                 a53 = 0.1253708332932087e+02, a54 = -0.6878860361058950e+00;
constexpr double c61 = 0.8083246795921522e+01, c62 = -0.7981132988064893e+01,
                 c63 = -0.3152159432874371e+02, c64 = 0.1631930543123136e+02,
                 c65 = -0.6058818238834054e+01;

// Step-size quotient of odeint's rosenbrock4_controller: h_new = h / clamp(err^¼/0.9, 1/6, 5).
double Quotient(double err) { return std::clamp(std::pow(err, 0.25) / 0.9, 1.0 / 6.0, 5.0); }

}  // namespace

RosenbrockIntegrator::RosenbrockIntegrator(const QuatFdModel& model,
                                           const IntegratorOptions& options)
    : AdaptiveIntegrator(model, options) {
  const int bw = QuatFdLayout::kBandwidth;
  jac_.Resize(model);
  M_.Resize(n_, bw, bw);
  tmp_.resize(2 * n_);
  for (Eigen::VectorXd& g : g_) g.resize(2 * n_);
  acc_.resize(n_);
}

void RosenbrockIntegrator::SolveStage(Eigen::Ref<Eigen::VectorXd> r) {
  jac_.SolveShifted(a_, M_, r, acc_);
}

bool RosenbrockIntegrator::Step(const Eigen::Ref<const Eigen::VectorXd>& y, double h,
                                Eigen::Ref<Eigen::VectorXd> y_new,
                                Eigen::Ref<Eigen::VectorXd> error) {
  const int n = n_;
  // Jacobian (and f) at y; the iteration matrix M = a² I − a B − A.
  jac_.Evaluate(model_, y, &stats_);
  a_ = 1.0 / (kGamma * h);
  jac_.AssembleShifted(a_, &M_);
  ++stats_.factorizations;
  if (!M_.Factorize()) return false;

  Eigen::VectorXd &g1 = g_[0], &g2 = g_[1], &g3 = g_[2], &g4 = g_[3], &g5 = g_[4];
  g1.head(n) = y.tail(n);
  g1.tail(n) = jac_.f;
  SolveStage(g1);

  tmp_ = y + a21 * g1;
  F(tmp_, g2);
  g2 += (c21 / h) * g1;
  SolveStage(g2);

  tmp_ = y + a31 * g1 + a32 * g2;
  F(tmp_, g3);
  g3 += (c31 * g1 + c32 * g2) / h;
  SolveStage(g3);

  tmp_ = y + a41 * g1 + a42 * g2 + a43 * g3;
  F(tmp_, g4);
  g4 += (c41 * g1 + c42 * g2 + c43 * g3) / h;
  SolveStage(g4);

  tmp_ = y + a51 * g1 + a52 * g2 + a53 * g3 + a54 * g4;
  F(tmp_, g5);
  g5 += (c51 * g1 + c52 * g2 + c53 * g3 + c54 * g4) / h;
  SolveStage(g5);

  tmp_ += g5;
  F(tmp_, error);
  error += (c61 * g1 + c62 * g2 + c63 * g3 + c64 * g4 + c65 * g5) / h;
  SolveStage(error);
  y_new = tmp_ + error;
  return true;
}

RosenbrockIntegrator::Trial RosenbrockIntegrator::TryStep(double h) {
  // A singular iteration matrix counts as a huge error: rejected, the step shrunk 6×.
  const bool ok = Step(y_, h, y_new_, err_);
  return {ok, ok ? ErrorNorm(options_, n_, y_, y_new_, err_) : 1e10};
}

double RosenbrockIntegrator::Rejected(double h, const Trial& trial) {
  return h / Quotient(trial.err);
}

double RosenbrockIntegrator::Accepted(double h, double err) {
  // After a rejection, do not grow at once.
  const double fac = Quotient(err);
  return last_rejected_ ? std::min(h, h / fac) : h / fac;
}

}  // namespace cosserat::quatfd
