#pragma once
// Rods of constant curvature: a pure end moment M bends an unshearable, inextensible rod into a
// circular arc of curvature M/(E I) (Euler–Bernoulli moment–curvature law; M = 2π E I/L closes a
// full circle, M = π E I/L a half circle with its tip 2L/π from the base), and so does a rest
// curvature under no load. Source: Timoshenko & Gere, Theory of Elastic Stability (1961), ch. 2
// (the elastica's moment–curvature law); tests/reference/stability_and_moment.json, "pure end
// moment".

#include <Eigen/Core>
#include <cmath>

#include "roots.hpp"

namespace cosserat::truth {

/// End moment (N·m) that turns the tip of a uniform rod of length L by theta (rad): θ E I / L.
/// θ = 2π closes a full circle, θ = π makes a half circle.
inline double EndMomentForTurn(double theta, double EI, double L) { return theta * EI / L; }

/// Point at arc length s (m) of the circular arc of curvature kappa (1/m) that leaves the origin
/// along +z and bends towards +x (curvature about +y): ((1 − cos κs)/κ, 0, sin κs/κ). Its centre
/// is (1/κ, 0, 0).
inline Eigen::Vector3d ArcPoint(double kappa, double s) {
  return Eigen::Vector3d((1 - std::cos(kappa * s)) / kappa, 0, std::sin(kappa * s) / kappa);
}

}  // namespace cosserat::truth
