#pragma once
/// \file
/// Whether a rod has passed through an obstacle. A penalty foundation (contact.hpp) lets a rod
/// press into a surface by its load per length over its stiffness: a centreline within half the
/// radius of a sphere's centre or of an outside cylinder's axis, or beyond a plane or a bore's
/// wall (pressed in by more than the rod's radius), has gone through the surface (a load step
/// that jumped it), or presses so deep that the penalty no longer stands for a rigid obstacle (a
/// stiffness too low for the load). The static solvers refuse a step that takes the rod there
/// and take smaller ones, so their answer is one the surfaces hold back. Surfaces of zero
/// stiffness push on nothing.

#include <vector>

#include "cosserat/lie/types.hpp"
#include "cosserat/loads/contact.hpp"

namespace cosserat {

/// True when a surface has a core to pass through (any surface of positive stiffness).
bool HasObstacleCore(const ContactSurfaces& surfaces);

/// True when the centreline through `after` (nodes, world frame, m: the nodes and the straight
/// segments between them) or a node's straight path from `before` to `after` (same size; empty:
/// no path) enters the core of a surface: within half its radius of a sphere's centre or an
/// outside cylinder's axis, beyond a plane or a bore's wall. A node or segment already in a core
/// in `before` is not counted again.
bool ReachesObstacleCore(const ContactSurfaces& surfaces, const std::vector<Vec3>& before,
                         const std::vector<Vec3>& after);

/// The same test, naming the surface: the index of the first one entered, or −1.
int ObstacleCoreReached(const ContactSurfaces& surfaces, const std::vector<Vec3>& before,
                        const std::vector<Vec3>& after);

}  // namespace cosserat
