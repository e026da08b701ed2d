#pragma once
/// \file
/// The added mass of a fluid on a rod (Morison et al. 1950): C_a ρ_f A_o per unit length on the
/// part of the centreline's acceleration normal to the rod, A_o = π d_o²/4 the displaced area.
/// Its force −C_a ρ_f A_o (I − t tᵀ) a enters the dynamics as a mass (BDF2: a term of the mass
/// matrix; modes: part of the mass). The flow is taken as steady, so the fluid's own acceleration
/// adds no Froude–Krylov force.

#include <cmath>

#include "cosserat/loads/load.hpp"

namespace cosserat {

class AddedMass final : public Load {
 public:
  /// \param[in] coefficient C_a, dimensionless
  /// \param[in] fluid_density ρ_f, kg/m³
  AddedMass(double coefficient, double fluid_density) : c_rho_(coefficient * fluid_density) {}
  double NormalAddedMass(const LoadSite& site) const override {
    return c_rho_ * 0.25 * M_PI * site.outer_diameter * site.outer_diameter * site.length;
  }

 private:
  double c_rho_;  // C_a ρ_f, kg/m³
};

}  // namespace cosserat
