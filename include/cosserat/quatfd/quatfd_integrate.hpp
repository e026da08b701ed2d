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

/// odeint's runge_kutta_dopri5 (5th order with the embedded 4th-order estimate, FSAL) as the
/// trial step of the shared step loop (AdaptiveIntegrator), with an order-5 step-size controller:
/// h_new = h · clamp(0.9 err^(−1/5), 0.2, 5), at most 0.9 h after a rejection.
class Dopri5Integrator final : public AdaptiveIntegrator {
 public:
  Dopri5Integrator(const QuatFdModel& model, const IntegratorOptions& options = {});
  ~Dopri5Integrator() override;
  const char* name() const override { return "dopri5"; }

 private:
  void BeginAdvance(bool continuing) override;
  Trial TryStep(double h) override;
  double Rejected(double h, const Trial& trial) override;
  double Accepted(double h, double err) override;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

std::unique_ptr<QuatFdIntegrator> MakeIntegrator(IntegratorKind kind, const QuatFdModel& model,
                                                 const IntegratorOptions& options = {});

}  // namespace cosserat::quatfd
