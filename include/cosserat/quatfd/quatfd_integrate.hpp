#pragma once
/// \file
/// Time integration of the quaternion-FD rod through Boost.Odeint, and a factory over the
/// available integrators.
///
/// - kDopri5: odeint's explicit runge_kutta_dopri5 (order 5(4)) in a controlled stepper with the
///   same error norm as the Rosenbrock integrator. Non-stiff only: its step is bounded by the
///   fastest mode (axial, shear and rotary-inertia waves), so stiff rods need many steps.
/// - kRosenbrock: the banded linearly implicit RosenbrockIntegrator (rosenbrock.hpp), O(N) per
///   step with the exact Jacobian; its step is limited by the stability of its step map
///   (docs/performance.md), a few ms for the rubber rod, 0.2 ms for the steel string.
/// - kSdirk: the banded implicit SdirkIntegrator (sdirk.hpp, SDIRK4 with Newton iterations and a
///   reused Jacobian), O(N) per Newton iteration.
/// - kRadau: the banded implicit RadauIntegrator (radau.hpp, Radau IIA order 5, stage order 3,
///   simplified Newton with a real and a complex banded LU), O(N) per Newton iteration.

#include <memory>
#include <string>
#include <vector>

#include "cosserat/quatfd/integrator.hpp"

namespace cosserat::quatfd {

enum class IntegratorKind { kDopri5, kRosenbrock, kSdirk, kRadau };

/// "dopri5", "rosenbrock", "sdirk", "radau".
const char* ToString(IntegratorKind kind);

class Dopri5Integrator final : public QuatFdIntegrator {
 public:
  Dopri5Integrator(const QuatFdModel& model, const IntegratorOptions& options = {});
  ~Dopri5Integrator() override;
  IntegratorStatus Advance(double t_end, double* t, Eigen::Ref<Eigen::VectorXd> q,
                           Eigen::Ref<Eigen::VectorXd> v) override;
  const IntegratorStats& stats() const override { return stats_; }
  const char* name() const override { return "dopri5"; }

 private:
  struct Impl;
  const QuatFdModel& model_;
  IntegratorOptions options_;
  IntegratorStats stats_;
  std::unique_ptr<Impl> impl_;
  double dt_ = 0;
};

std::unique_ptr<QuatFdIntegrator> MakeIntegrator(IntegratorKind kind, const QuatFdModel& model,
                                                 const IntegratorOptions& options = {});

}  // namespace cosserat::quatfd
