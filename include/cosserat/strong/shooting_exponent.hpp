#pragma once
/// \file
/// How ill-conditioned single shooting is for a BDF2 time step: along s the time-discretised rod
/// bends like e^{λs} with λ(s) = (c0² ρA(s) / EI(s))^{1/4}, c0 = 1.5/dt (BDF2's first
/// coefficient), and a shot amplifies errors in its base unknowns by about e^{λL}
/// (docs/dynamics.md, "Where it stops": converges up to λL ≈ 10–15; multiple shooting in pieces
/// of λL/pieces ≲ 5 beyond).
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/state/rod_state.hpp"

namespace cosserat {

/// λL = ∫₀ᴸ (c0² ρA(s) / EI_min(s))^{1/4} ds for the step dt (s), with EI_min the smaller of the
/// two bending stiffnesses (N·m²) and ρA the mass per length (kg/m), integrated by the midpoint
/// rule on 200 pieces. Dimensionless.
double SingleShootingExponent(const RodModel& rod, double dt, const Actuation& actuation = {});

/// The same under the axial tension T(s) of `state` (N, its wrench's body z force, interpolated
/// between nodes; compression counts as none): the shot grows like e^{μs} with
/// EI μ⁴ − T μ² − c0² ρA = 0, i.e. μ² = (T + √(T² + 4 EI c0² ρA)) / (2 EI), which is λ without
/// tension and √(T/EI) in statics (dt = ∞, c0 = 0). A taut wire, a hanging pipe or a held
/// payload needs the tension term: 1 m of 1 mm steel wire under 100 N has μL = 25 at any dt.
double SingleShootingExponent(const RodModel& rod, double dt, const Actuation& actuation,
                              const RodState& state);

/// The multiple-shooting pieces that bring each piece's exponent to about 5, at least 1.
int SuggestedShootingSegments(double exponent);

/// The automatic choice of the solvers that pick their own pieces: one while a single shot's
/// exponent is at most 10, else SuggestedShootingSegments, at most max_pieces.
int AutomaticShootingPieces(double exponent, int max_pieces);

}  // namespace cosserat
