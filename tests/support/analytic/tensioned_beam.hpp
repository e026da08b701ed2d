#pragma once
// A pinned–pinned beam under axial tension T and a uniform lateral load q (the taut cable with
// bending stiffness: stay cables, risers). EI y'''' − T y'' = q with y = y'' = 0 at both ends.
// Source: Timoshenko & Gere, Theory of Elastic Stability (1961), ch. 1 (beam-columns, the tensile
// case).

#include <cmath>

namespace cosserat::truth {

/// Mid-span deflection (m): q L²/(8T) − (q E I/T²)(1 − 1/cosh(kL/2)), k = sqrt(T/E I). The first
/// term is the string's sag, the second what the bending stiffness takes off it.
/// \param q lateral load per length (N/m); T tension (N); EI (N·m²); L span (m).
inline double TensionedBeamMidSpanDeflection(double q, double T, double EI, double L) {
  const double k = std::sqrt(T / EI);
  return q * L * L / (8 * T) - q * EI / (T * T) * (1 - 1 / std::cosh(k * L / 2));
}

}  // namespace cosserat::truth
