#pragma once
/// \file
/// A pipe full of a fluid (a riser's or drill string's mud, a pipeline's contents): the fluid in
/// the bore moves with the pipe sideways and along it, so it adds its mass per length ρ_c A_i
/// (kg/m) to the translational mass. Its weight then enters every load that weighs the section,
/// and with an outer fluid's buoyancy on the outer area the rod carries the apparent weight
/// (ρ A + ρ_c A_i − ρ_w A_o) g. The fluid adds no stiffness and, not turning with the section,
/// no rotary inertia. The internal force the rod then carries along its axis is the effective
/// tension (the wall tension less p_i A_i, plus p_o A_o), the one that governs its bending.

#include <memory>
#include <string>
#include <vector>

#include "cosserat/rod/section_profile.hpp"

namespace cosserat {

class FilledPipeSection final : public SectionProfile {
 public:
  /// `contents_mass_per_length`: ρ_c A_i, kg/m, ≥ 0.
  FilledPipeSection(std::shared_ptr<const SectionProfile> pipe, double contents_mass_per_length);
  SectionProperties At(double s, const Actuation& actuation) const override;
  std::vector<double> Breakpoints() const override { return pipe_->Breakpoints(); }
  bool IsValid(double length, std::string* why) const override;
  double contents_mass_per_length() const { return contents_; }
  /// The pipe itself (its section, for its stresses).
  const SectionProfile& pipe() const { return *pipe_; }

 private:
  std::shared_ptr<const SectionProfile> pipe_;
  double contents_;
};

}  // namespace cosserat
