#pragma once
/// \file
/// Buoyancy (Archimedes): a dead force −ρ_f A_o g per unit length, A_o = π d_o²/4 the area the
/// section displaces (its outer diameter d_o: an annulus displaces the full disc). A rod as dense
/// as the fluid is weightless; one of density ρ weighs as a dry rod of ρ − ρ_f.

#include <cmath>

#include "cosserat/loads/fluid.hpp"
#include "cosserat/loads/load.hpp"

namespace cosserat {

class Buoyancy final : public Load {
 public:
  /// \param[in] fluid_density ρ_f, kg/m³
  /// \param[in] gravity_W acceleration of gravity, world frame, m/s²
  Buoyancy(double fluid_density, const Vec3& gravity_W) : rho_(fluid_density), g_W_(gravity_W) {}
  Vec3 DistributedForce_W(const LoadSite& site) const override {
    const double area = 0.25 * M_PI * site.outer_diameter * site.outer_diameter;
    return -(rho_ * area * site.length) * g_W_;
  }

 private:
  double rho_;
  Vec3 g_W_;
};

}  // namespace cosserat
