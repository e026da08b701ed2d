#pragma once
/// \file
/// The unloaded rod's centreline in the world: p' = R Γ*, R' = R K̂* from the clamp pose,
/// integrated with the exact exponential of the midpoint rest strain on each piece (second order
/// in the piece length; exact for a constant rest strain). For checks of the initial
/// configuration (a rod that starts inside an obstacle), not for the solvers.

#include <vector>

#include "cosserat/lie/se3.hpp"
#include "cosserat/rod/rod_model.hpp"

namespace cosserat {

/// `points` ≥ 2 centreline points, equally spaced in s from 0 to L, world frame (m).
std::vector<Vec3> RestCentreline_W(const RodModel& rod, const lie::SE3& base, int points);

}  // namespace cosserat
