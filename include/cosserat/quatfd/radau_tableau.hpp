#pragma once
/// \file
/// The 3-stage Radau IIA tableau (order 5; Hairer & Wanner, Solving ODEs II, Table IV.5.6) and
/// the quantities RADAU5's transformed Newton iteration and error estimate need, computed once
/// from A (no hand-copied 20-digit constants). Used by RadauIntegrator (radau.hpp).

namespace cosserat::quatfd {

struct RadauIIA3Tableau {
  double c[3];        ///< nodes
  double A[3][3];     ///< coefficients
  double Ainv[3][3];  ///< A⁻¹
  /// T⁻¹ A⁻¹ T = [[γ, 0, 0], [0, α, −β], [0, β, α]]: one real and one complex eigenvalue pair.
  double T[3][3], Ti[3][3];
  double gamma, alpha, beta;
  /// Error estimate (Hairer–Wanner IV.8.19–20): err = (γ/h I − J)⁻¹ [f(y_n) + Σ dd_i Z_i / h].
  double dd[3];
};

/// The tableau, built on first use.
const RadauIIA3Tableau& RadauIIA3();

}  // namespace cosserat::quatfd
