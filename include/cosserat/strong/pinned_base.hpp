#pragma once
/// \file
/// The twist axis of a column's pinned base. The base section turns as R(0) = R_WB Exp(θ),
/// θ = [a, b, 0] (rad; bending about the base frame's x and y, the third exponential coordinate
/// held). A joint that allows exactly these rotations reacts along their normal, ν(θ) (body frame
/// of R(0)), and does no work on any rotation it allows: with dead loads its equilibria are the
/// stationary points of a potential, whose second variation MorseIndexOfShot counts. (A reaction
/// held along body z, the section's axis, does work on the allowed rotations once the base has
/// turned, unless it is zero.)

#include "cosserat/lie/types.hpp"

namespace cosserat {

/// ν(a, b) = J_r(θ)⁻ᵀ e₃, the gradient (body frame) of the held coordinate: ν · J_r(θ) e_k = 0
/// for k = 0, 1; ν = e₃ at θ = 0.
Vec3 PinnedTwistAxis(double a, double b);

}  // namespace cosserat
