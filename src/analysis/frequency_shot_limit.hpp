#pragma once
// How far in frequency one SE(3) shot resolves the roots of det B(ω). A perturbation at ω grows
// along the rod as e^{∫ μ ds}, μ the fastest root of the tensioned beam EI w'''' − T w'' =
// ρA ω² w: μ² = (T + sqrt(T² + 4 EI ρA ω²)) / (2 EI) (T the axial force, compression
// negative). One shot carries round-off up by that exponent; past about 28 (e²⁸ ε ≈ 2e-4) the
// two roots of a repeated pair blur into one minimum of σ_min and a partner is lost: a 0.5 m,
// 1 mm steel cantilever's bending pairs are all found up to an exponent of 26.7 and none at
// 29.8; a taut wire at L sqrt(T/EI) = 25 up to 28.2, not at 29.7. Internal to src/analysis.

#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/state/rod_state.hpp"

namespace cosserat::detail {

/// The exponent past which the scan's roots are not listed.
constexpr double kMaxFrequencyShotExponent = 28.0;

/// The ω (rad/s) where ∫ μ ds over the equilibrium (trapezoid on its nodes, with their axial
/// force wrench_B(5) and the least bending stiffness and ρA of their sections) reaches
/// kMaxFrequencyShotExponent (bisection; it grows with ω): 0 when the equilibrium's tension
/// already passes it, infinity when no ω does (no bending stiffness).
double FrequencyShotLimit(const RodModel& rod, const Actuation& actuation,
                          const RodState& equilibrium);

}  // namespace cosserat::detail
