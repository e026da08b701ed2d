#pragma once
/// \file
/// The bending stress of a result: the largest normal stress the bending moments make in each
/// node's section (`nodes.bending_stress`, Pa), and the peaks along the rod (`bending`: the
/// largest bending stress and bending curvature, with their s). The outer fibre's stress is
/// |M| r_o / I for a circle or an annulus, |M1| (h/2) / I1 + |M2| (w/2) / I2 at a rectangle's
/// corner, and sqrt((M1/I1)² + (M2/I2)²) r_e for an explicit section, r_e its equal-area radius
/// (exact when I1 = I2). Axial stress is not included: a riser's wall also carries T/A.

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run::detail {

/// Adds "nodes.bending_stress" and "bending" to result->json when the result has node moments
/// and the rod's section is uniform (a stiffness profile's section varies; not reported).
void AddBendingStressReport(const io::Problem& problem, Result* result);

}  // namespace cosserat::run::detail
