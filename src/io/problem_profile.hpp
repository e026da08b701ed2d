#pragma once
/// \file
/// The "stiffness_profile" of a problem file's rod: an array of bands or a profile object (taper,
/// pressure modulus, jamming, inflated), apart from the rest of problem_rod.cpp.

#include <memory>
#include <optional>

#include "cosserat/io/json_reader.hpp"
#include "cosserat/rod/cross_section.hpp"
#include "cosserat/rod/material.hpp"
#include "cosserat/rod/section_profile.hpp"

namespace cosserat::io::detail {

using ProfilePtr = std::shared_ptr<const SectionProfile>;

/// What the profile is built on: the rod's section and material (either may be missing after an
/// error elsewhere; the profile is then only checked).
struct ProfileBase {
  std::optional<double> length;
  std::optional<CrossSection> section;
  std::optional<Material> material;
  bool complete() const { return length && section && material; }
};

/// The profile of `rod`, nullptr for none (a uniform rod), nullopt on any error (reported).
std::optional<ProfilePtr> ParseStiffnessProfile(const ObjectReader& rod, const ProfileBase& base);

}  // namespace cosserat::io::detail
