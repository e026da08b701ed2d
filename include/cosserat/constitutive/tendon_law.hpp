#pragma once
/// \file
/// The tendon-augmented constitutive law (Rucker & Webster 2011). A tendon (rod/tendon_route.hpp)
/// under tension τ runs along the unit tangent, body frame,
///   t = q / |q|,  q = Γ + K × r + r'        (the body-frame derivative of p + R r, over R),
/// and the pair "rod + tendon" carries the total internal wrench
///   W = K (ξ − ξ*) + Σ τ_i a_i(ξ),  a_i = [r_i × t_i; t_i],
/// which obeys the balance laws of the plain rod. This is Rucker & Webster's model with its
/// distributed load and its terminal load at the anchor already summed into W: the solvers keep
/// their balance equations and only the constitutive law changes (solved for ξ per stage).

#include <array>

#include "cosserat/lie/types.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/tendon_route.hpp"

namespace cosserat {

/// Σ τ_i a_i(ξ) (body frame, [N·m; N]) and, if asked, its derivative in ξ (6 × 6) and the
/// columns a_i (derivative in τ_i).
Vec6 TendonWrench(const TendonSample& sample, const double* tension, const Vec6& xi,
                  Mat6* d_xi = nullptr, std::array<Vec6, Actuation::kMaxTendons>* a = nullptr);

/// Solves K (ξ − ξ*) + Σ τ_i a_i(ξ) = W for the strain ξ by Newton from `xi` (in: a guess, out:
/// the strain, to 1e-12 relative), keeping the first iterate's matrix while it contracts fast
/// and taking the derivative anew when it does not. If H is given, writes
/// H = K + ∂(Σ τ a)/∂ξ at the solution, so dξ = H⁻¹ dW. Returns false if it did not converge
/// within 40 iterations: a tendon path folded back (|q| → 0), which a straight tendon reaches at
/// τ d²/EI = 1 (the inside of the bend, where it runs, shrinks to zero length).
bool SolveTendonStrain(const Mat6& stiffness, const Vec6& rest_strain, const TendonSample& sample,
                       const double* tension, const Vec6& W, Vec6* xi, Mat6* H);

/// |q_i| = |Γ + K × r_i + r_i'|: the stretch of tendon i's path per unit arc length of the rod.
double TendonPathRate(const TendonSample& sample, int i, const Vec6& xi);

}  // namespace cosserat
