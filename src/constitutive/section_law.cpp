#include "cosserat/constitutive/section_law.hpp"

#include <sstream>
#include <stdexcept>

#include "cosserat/constitutive/chamber_law.hpp"

namespace cosserat {

namespace {

// Every entry off the diagonal exactly zero (the diagonal may be anything: an overflowed one is
// not a coupling).
bool Diagonal(const Mat6& A) {
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      if (i != j && A(i, j) != 0.0) return false;
  return true;
}

}  // namespace

bool IsPrincipalAxes(const SectionProperties& p, std::string* why) {
  const char* which = !Diagonal(p.stiffness) ? "stiffness"
                      : !Diagonal(p.damping) ? "damping"
                      : !Diagonal(p.mass)    ? "mass"
                                             : nullptr;
  if (which && why) *why = which;
  return which == nullptr;
}

SectionProperties PrincipalAxesSectionAt(const RodModel& rod, double s,
                                         const Actuation& actuation) {
  const SectionProperties p = rod.section->At(s, actuation);
  std::string which;
  if (!IsPrincipalAxes(p, &which)) {
    std::ostringstream msg;
    msg << "section at s = " << s << " m: the " << which
        << " matrix has off-diagonal entries; sections must be principal-axes (coupling between "
           "bending, shear and stretch is not supported)";
    throw std::invalid_argument(msg.str());
  }
  return p;
}

SectionLaw SectionLaw::At(const RodModel& rod, double s, const Actuation& actuation) {
  const SectionProperties p = PrincipalAxesSectionAt(rod, s, actuation);
  SectionLaw law;
  law.stiffness = p.stiffness.diagonal();
  law.damping = p.damping.diagonal();
  law.mass = p.mass.diagonal();
  law.rest_strain = rod.RestStrainAt(s);
  if (!rod.chambers.empty())
    law.rest_strain += ChamberWrench(rod.chambers, s, actuation).cwiseQuotient(law.stiffness);
  law.outer_diameter = p.outer_diameter;
  return law;
}

}  // namespace cosserat
