#pragma once
/// \file
/// The fluid a rod stands in (sea water, air): its density, its flow and the Morison coefficients
/// of the rod in it (Morison et al. 1950; DNV-RP-C205 for the coefficients). A plain aggregate,
/// part of StaticLoads, so a controller may change the current every step without allocating.
///
/// The flow is U(p) = velocity_W · φ(h), h = a · (p − origin) the height along the profile axis a:
///   no profile:       φ = 1 (a uniform current or wind);
///   power law:        φ = (h / reference_height)^exponent for h > 0, 0 below (atmospheric wind);
///   table:            φ linear between the given (height, factor) pairs, constant beyond the
///                     first and last (a sheared current).

#include <array>
#include <string>

#include "cosserat/lie/types.hpp"

namespace cosserat {

struct FluidFlowProfile {
  enum class Kind { kUniform, kPowerLaw, kTable };
  static constexpr int kMaxPoints = 16;
  Kind kind = Kind::kUniform;
  Vec3 axis_W = Vec3::UnitZ();              ///< a, unit (the vertical)
  Vec3 origin_W = Vec3::Zero();             ///< where h = 0 (the sea bed or the ground), m
  double reference_height = 1.0;            ///< power law: m, > 0
  double exponent = 0.0;                    ///< power law: dimensionless, ≥ 0
  int points = 0;                           ///< table: number of pairs, 2 … kMaxPoints
  std::array<double, kMaxPoints> height{};  ///< table: increasing, m
  std::array<double, kMaxPoints> factor{};  ///< table: φ at each height

  /// φ(h) and dφ/dh (1/m).
  double Factor(double h, double* slope) const;
  bool operator==(const FluidFlowProfile& o) const;
};

struct Fluid {
  double density = 0.0;            ///< ρ_f, kg/m³; 0: no fluid
  Vec3 velocity_W = Vec3::Zero();  ///< flow velocity at φ = 1, world frame, m/s
  FluidFlowProfile profile;        ///< how the flow varies with height
  double drag_normal = 0.0;        ///< C_dn, dimensionless
  double drag_tangential = 0.0;    ///< C_dt, dimensionless
  double added_mass = 0.0;         ///< C_a, dimensionless
  double diameter = 0.0;           ///< D for drag, m; 0: the section's outer diameter

  bool present() const { return density > 0.0; }
  /// True when the fluid puts a force on a moving rod (drag) or on an accelerating one.
  bool has_drag() const { return present() && (drag_normal > 0.0 || drag_tangential > 0.0); }
  bool has_added_mass() const { return present() && added_mass > 0.0; }
  /// U(p_W), m/s; with grad, also dU/dp (1/s).
  Vec3 FlowVelocity_W(const Vec3& p_W, Mat3* grad = nullptr) const;
  bool operator==(const Fluid& o) const;
  /// Checks ranges; on failure writes the reason, naming the key of the problem format
  /// (environment.fluid.<key>).
  bool IsValid(std::string* why) const;
};

/// A gusting flow: the flow velocity times 1 + amplitude sin(2π t / period) (dimensionless; s).
/// Loads have no clock: the SE(3) runner applies it to the fluid of each step, the quaternion-FD
/// model to each integrator stage's time (QuatFdModel::set_time). period 0: steady.
struct FluidGust {
  double amplitude = 0.0;
  double period = 0.0;
  bool present() const { return period > 0.0 && amplitude != 0.0; }
  double Factor(double t) const;
  /// The fluid at time t: `steady` with its velocity scaled by Factor(t).
  Fluid At(const Fluid& steady, double t) const;
};

}  // namespace cosserat
