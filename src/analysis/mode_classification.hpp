#pragma once
// The kind of a mode (bending, torsion, axial) from the kinetic-energy shares of its node shape,
// for both formulations' modes. Internal to src/analysis.

#include <vector>

#include "cosserat/analysis/modes.hpp"
#include "cosserat/lie/types.hpp"

namespace cosserat::detail {

/// What the kinetic-energy shares of a mode weigh, per node: the tangent (world, unit), the
/// mass (kg) and the rotational inertia (kg·m², world).
struct NodeWeights {
  std::vector<Vec3> tangent_W;
  std::vector<double> mass;
  std::vector<Mat3> inertia_W;
};

/// Fills the kinetic-energy shares and the kind of a mode from its node shape, the tangent t_n
/// (world, unit), the mass per node (kg) and the rotational inertia per node (kg·m², body
/// principal, rotated with R_n), then scales the shape (see Mode::displacement_W).
void Classify(const std::vector<Vec3>& tangent_W, const std::vector<double>& mass,
              const std::vector<Mat3>& inertia_W, double length, Mode* mode);

}  // namespace cosserat::detail
