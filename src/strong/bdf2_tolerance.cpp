// The residual a BDF2 step's solve must reach: the given tolerance, or the round-off floor of a
// shot when that is larger.
#include <algorithm>
#include <cmath>
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
  // P the largest world coordinate (m), into a force of up to k ε P h on each segment h, in
  // units of EI/L²; a piece of the shot gathers those of its n segments at random, sqrt(n) of
  // one. A 100 m drill pipe on a bore's wall (k = 1e6, EI = 1.2e6 N·m², h = 1 m, 6 segments a
  // piece) stalled at 1.4e-10; this floor is 4.6e-10 there.
  double k = 0.0;
  for (int i = 0; i < input.loads.contact.count; ++i)
    k = std::max(k, input.loads.contact.surface[i].stiffness);
  const double L = model_.length;
  const double segments = static_cast<double>(grid_.size()) - 1.0;
  if (k > 0.0 && segments > 0.0) {
    const double h = L / segments, per_piece = std::max(1.0, segments / ShootingPieces());
    floor = std::max(floor, kEpsilon * k * (input.base_pose.p.norm() + L) * h *
                                std::sqrt(per_piece) / scale_(3));
  }
  return std::max(options_.tolerance, floor);
}

}  // namespace cosserat
