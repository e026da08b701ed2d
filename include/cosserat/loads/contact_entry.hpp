#pragma once
/// \file
/// How far a Newton step of a static solver may carry a rod into a contact surface. The penalty
/// foundation (contact.hpp) exerts nothing on a node clear of a surface, so a Newton step taken
/// from a clear state does not see the surface and may carry the node deep into it: a slack
/// cable hanging beside a bar jumps 29 mm into the bar on its first step, and the stiff penalty
/// then throws the iteration about. A penalty that stands for a rigid surface presses a rod in by
/// far less than its radius, so a clear node that ends deeper than its own outer radius has
/// jumped: the step is cut where it reaches that depth, and the next linearisation sees the
/// surface. A node is cut at most once per entry (after the cut it is in contact, and steps of
/// nodes already in contact are not limited), so touchdowns that move by small amounts from
/// step to step are not slowed.

#include <vector>

#include "cosserat/lie/types.hpp"
#include "cosserat/loads/contact.hpp"

namespace cosserat {

/// The fraction t ∈ (0, 1] of the straight move of the nodes from `before` to `after` (world
/// frame, m) at which the first node clear of a surface in `before` (gap ≥ 0, measured from its
/// outer radius r_o, half of `outer_diameter`, m) has entered it by max(r_o, ε), ε the
/// surface's smoothing width, with the penetration interpolated linearly along the move; 1 when
/// no clear node ends deeper. Surfaces of zero stiffness are ignored. All three vectors have
/// the same size.
double ContactEntryFraction(const ContactSurfaces& surfaces, const std::vector<Vec3>& before,
                            const std::vector<Vec3>& after,
                            const std::vector<double>& outer_diameter);

}  // namespace cosserat
