#pragma once
// Test support: the BDF2 stepper's exact shooting Jacobian (Bdf2ShootingStepper::Residual with
// J) against central differences (jacobian_check.hpp) at one point of the unknowns, for an
// equal-step BDF2 step from the stepper's current state under `in`.

#include "cosserat/strong/bdf2_stepper.hpp"
#include "jacobian_check.hpp"

namespace cosserat::testing {

inline void ExpectStepJacobianMatchesCentralDifferences(Bdf2ShootingStepper& stepper,
                                                         const StepInput& in) {
  const double dt = stepper.options().dt;
  const Bdf2ShootingStepper::Coefficients c{1.5 / dt, -2 / dt, 0.5 / dt};
  const Vec6 x = (Vec6() << 0.01, -0.3, 0.02, 0.1, -0.05, 0.2).finished();
  Mat6 J;
  stepper.Residual(in, c, false, x, &J);
  ExpectJacobianMatchesCentralDifferences(
      [&](const Vec6& y) { return stepper.Residual(in, c, false, y); }, x, J);
}

}  // namespace cosserat::testing
