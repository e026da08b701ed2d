#pragma once
/// \file
/// How well an SE(3) static solve's grid resolves its shape, judged from the result's nodes.
/// RK4 in s turns each section through κ h per segment: a constant-curvature arc's tip is off by
/// about 8e-3 (κ h)⁴ L (measured: 5.2e-4 L at κ h = 0.5, 8.1e-3 L at 1, 3.8e-2 L at 1.5), and far
/// beyond that the shot's frames leave rotation and its positions run away (a pneumatic chamber
/// at 1e9 Pa on a gel rod, κ h = 90: a "converged" tip at 1e255 m, since no load asked anything
/// of the shot).

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run::detail {

/// A converged SE(3) statics result whose segment runs away (longer than 10 h) becomes
/// non_finite, saying so; one whose curvature takes κ h above 0.5 rad on some segment gets a
/// warning with the error it implies and the nodes that would keep κ h below 0.25.
void CheckGridResolution(const io::Problem& problem, Result* result);

}  // namespace cosserat::run::detail
