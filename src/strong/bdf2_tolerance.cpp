// The residual a BDF2 step's solve must reach: the given tolerance, or the round-off floor of a
// shot when that is larger.
#include <algorithm>
#include <limits>

#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat {

double Bdf2ShootingStepper::Tolerance(const Vec6& x, const StepInput& input) const {
  // The residual is computed to about 1e3 ε of the unknowns it is shot from (round-off through
  // the shot's gain): a 10 kg payload on a 0.5 mm wire carries 1e4 times the force scale EI/L²,
  // and its steps stalled between 1e-10 and 1e-9. Below that the tolerance stands as given.
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  double floor = 1e3 * kEpsilon * x.lpNorm<Eigen::Infinity>();
  // A contact surface of stiffness k (N/m per m) turns the round-off of the positions, ε P with
  // P the largest world coordinate (m), into forces of up to k ε P L over the rod, in units of
  // EI/L²: a 100 m drill pipe on a bore's wall (k = 1e6, EI = 1.2e6 N·m²) stalled at 1.4e-10.
  double k = 0.0;
  for (int i = 0; i < input.loads.contact.count; ++i)
    k = std::max(k, input.loads.contact.surface[i].stiffness);
  const double L = model_.length;
  if (k > 0.0)
    floor = std::max(floor, kEpsilon * k * (input.base_pose.p.norm() + L) * L / scale_(3));
  return std::max(options_.tolerance, floor);
}

}  // namespace cosserat
