#pragma once
/// \file
/// The hint after a static solve with contact that failed on a grid too coarse for a surface's
/// foundation length ℓ = (4EI/k)^¼, the length over which the rod settles into it (EI the larger
/// bending stiffness at the base, k the surface's stiffness per length).

#include <string>

#include "cosserat/io/problem.hpp"

namespace cosserat::run::detail {

/// For the first contact surface whose ℓ the grid spacing h exceeds `spacings_per_length` × ℓ:
/// the line "cosserat: hint: the grid spacing h m is coarse for environment.contact[k]'s
/// foundation length ... m, <why>: try <advice>rod.nodes >= n<more>", n the node count for
/// h = spacings_per_length × ℓ. Empty when the grid resolves every surface.
std::string FoundationHint(const io::Problem& problem, double spacings_per_length,
                           const std::string& why, const std::string& advice,
                           const std::string& more);

/// After a converged quaternion-FD statics whose tip force presses its touching tip into a surface
/// (a point load on the foundation; a load spread along the rod settles it far more smoothly:
/// the seabed riser's anchor force and peak curvature move by 1e-5 from h = 0.17 ℓ to 0.04 ℓ):
/// the grid's second-order error in how the rod settles into it, about 0.2 (h/ℓ)² of the
/// penetration there and 0.42
/// (h/ℓ)² of the slope (Hetényi's beam on an elastic foundation under a tip load: penetration
/// −13, −3.5, −0.9, −0.21 % and slope −27, −7.7, −2.0, −0.50 % at h/ℓ = 0.8, 0.4, 0.2, 0.1; the
/// far field's is exact). A warning from h > 0.16 ℓ (1 % of the slope), with the nodes for
/// h = 0.1 ℓ; empty otherwise.
std::string FoundationGridWarning(const io::Problem& problem);

}  // namespace cosserat::run::detail
