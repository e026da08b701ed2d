#pragma once
/// \file
/// The chamber-augmented constitutive law. A chamber (rod/chamber.hpp) at gauge pressure p holds
/// a column of fluid that pushes on every section cut through it with the force p A along the
/// section normal e3, at the chamber's offset r. The pair "rod + fluid" carries the total
/// internal wrench (body frame)
///   W = K (ξ − ξ*) − Σ_j p_j A_j [r_j × e3; e3]     over the chambers j that cover s,
/// i.e. the wall is stretched by what the fluid pushes apart. The sign is the opposite of a
/// tendon's (W = K (ξ − ξ*) + Σ τ a, tendon_law.hpp): a tendon pulls (contracts, bends towards
/// itself), a chamber pushes (extends by Σ p A / EA, bends away from itself by p A |r| / EI).
///
/// The actuation wrench w = Σ p A [r × e3; e3] is constant in the body frame (the fluid's cut is
/// the section, whatever the strain), so the law stays linear: W = K (ξ − ξ* − K⁻¹ w). SectionLaw
/// folds it into the rest strain, ξ*_p = ξ* + K⁻¹ w, and every solver of both formulations that
/// samples SectionLaw takes chambers with no code of its own. The wrench follows the deformed
/// rod (a follower actuation): a rod with chambers is exactly the rod of rest strain ξ*_p.

#include <vector>

#include "cosserat/lie/types.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/chamber.hpp"

namespace cosserat {

/// w(s) = Σ_j p_j A_j [r_j × e3; e3] over the chambers that cover s, body frame, [N·m; N]; p_j =
/// actuation.chamber_pressure[j] (Pa). Zero when no chamber covers s.
Vec6 ChamberWrench(const std::vector<Chamber>& chambers, double s, const Actuation& actuation);

}  // namespace cosserat
