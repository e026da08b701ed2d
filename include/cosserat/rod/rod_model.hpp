#pragma once
/// \file
/// RodModel: everything about a rod that stays constant during a run (the "Model" of the
/// Model/Data split). Solvers keep their own workspaces.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cosserat/lie/types.hpp"
#include "cosserat/rod/chamber.hpp"
#include "cosserat/rod/section_profile.hpp"
#include "cosserat/rod/tendon_route.hpp"

namespace cosserat {

/// Reference (rest) strain ξ*(s) = [K*; Γ*] in the body frame (1/m; dimensionless).
using RestStrainFunction = std::function<Vec6(double s)>;

/// Straight, unstretched rest shape: ξ* = [0, 0, 0, 0, 0, 1].
Vec6 StraightRestStrain();

/// Constant rest curvature [k1, k2, k3] (1/m) with Γ* = e3.
RestStrainFunction ConstantRestCurvature(const Vec3& curvature);

struct RodModel {
  double length = 0.0;                            ///< L, m
  std::shared_ptr<const SectionProfile> section;  ///< K(s), M(s), D(s)
  RestStrainFunction rest_strain;                 ///< ξ*(s); empty means straight
  /// Tendons routed through the rod (at most Actuation::kMaxTendons); their tensions are part of
  /// the Actuation. Empty for a plain rod.
  std::vector<Tendon> tendons;
  /// Pressurised chambers (at most Actuation::kMaxChambers); their pressures are part of the
  /// Actuation (constitutive/chamber_law.hpp). Empty for a plain rod.
  std::vector<Chamber> chambers;

  /// A uniform straight rod.
  static RodModel Uniform(double length, const CrossSection& section, const Material& material);

  Vec6 RestStrainAt(double s) const { return rest_strain ? rest_strain(s) : StraightRestStrain(); }
  /// Interior arc lengths where the section or the actuation jumps (m): the section profile's
  /// breakpoints and the chambers' ends. The grid puts nodes there.
  std::vector<double> Breakpoints() const;

  bool IsValid(std::string* why) const;
};

}  // namespace cosserat
