#pragma once
/// \file
/// Energy, momentum, mass and centre of mass of a rod state, as free functions of its quadrature
/// points: the stage points of the spatial scheme (spatial_scheme.hpp) with the scheme's weights,
/// so that the integrals use exactly the quadrature the shot sums the balance laws with (linear
/// momentum is then conserved to round-off when no force acts). Bdf2ShootingStepper::
/// QuadraturePoints() gives them for its current state.

#include <vector>

#include "cosserat/lie/types.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/strong/cosserat_rhs.hpp"

namespace cosserat {

/// Kinetic, elastic and potential energy of the rod (J).
struct RodEnergy {
  double kinetic = 0.0;
  double elastic = 0.0;
  double potential = 0.0;  ///< of the distributed dead loads (gravity, distributed force)
  double total() const { return kinetic + elastic + potential; }
};

/// Linear momentum (kg·m/s) and angular momentum about the world origin (kg·m²/s), world frame.
struct RodMomentum {
  Vec3 linear_W = Vec3::Zero();
  Vec3 angular_W = Vec3::Zero();
};

/// One quadrature point: the section there, the state there and the weight (m).
struct RodQuadraturePoint {
  const rhs::SectionSample* section = nullptr;
  Vec3 position_W = Vec3::Zero();  ///< m
  Mat3 rotation_WB = Mat3::Identity();
  Vec6 twist_B = Vec6::Zero();  ///< [ω; v], rad/s and m/s
  Vec6 strain = Vec6::Zero();   ///< ξ = [K; Γ]
  double weight = 0.0;          ///< m
};
using RodQuadrature = std::vector<RodQuadraturePoint>;

/// ½ Vᵀ M V + ½ (ξ − ξ*)ᵀ K (ξ − ξ*) per unit length, and the potential of the distributed dead
/// loads of `loads`, integrated (J). The kinetic part includes ½ m_a |v_n|², the fluid's added
/// mass m_a (kg/m) moving with v_n, the velocity across d3. The rod only: a tip body's energy is
/// not included.
RodEnergy Energy(const RodQuadrature& points, const StaticLoads& loads);
/// ∫ ρA R v ds and ∫ (p × ρA R v + R J ω) ds (the rod only).
RodMomentum Momentum(const RodQuadrature& points);
/// ∫ ρA ds, kg.
double Mass(const RodQuadrature& points);
/// ∫ ρA p ds / ∫ ρA ds, m (world).
Vec3 CentreOfMass_W(const RodQuadrature& points);

/// A rigid body carried by the tip section (Bdf2Options::tip_mass, kg, and tip_inertia_B, its
/// principal inertia in the tip frame, kg·m²), which the rod's integrals leave out: kinetic
/// ½ m |v|² + ½ ωᵀ J ω from the tip's twist, and its weight's potential −m g·p(L) (J).
RodEnergy TipBodyEnergy(double mass, const Vec3& inertia_B, const Vec3& gravity_W,
                        const RodState& state);
/// Its momentum: m R v and p(L) × m R v + R J ω (world frame, about the origin).
RodMomentum TipBodyMomentum(double mass, const Vec3& inertia_B, const RodState& state);

}  // namespace cosserat
