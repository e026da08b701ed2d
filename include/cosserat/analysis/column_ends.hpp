#pragma once
/// \file
/// The end conditions of a column, by name: what the column solver, buckling and modes share.

#include <string>

namespace cosserat {

/// End conditions of a column (base at s = 0, tip at s = L).
enum class ColumnEnds {
  kClampedFree,     ///< the cantilever: clamped base, free tip
  kPinnedPinned,    ///< pinned base, pinned guided tip
  kClampedClamped,  ///< clamped base, clamped guided tip
  kClampedPinned,   ///< clamped base, pinned guided tip
};

/// "cantilever", "pinned-pinned", "clamped-clamped", "clamped-pinned" (the problem-format names).
const char* ToString(ColumnEnds ends);
/// The inverse of ToString; false (and *ends untouched) for any other name.
bool ParseColumnEnds(const std::string& name, ColumnEnds* ends);
/// The Euler load of a uniform column with these ends is this times EI/L²: π²/(K²) with the
/// effective length factor K = 2, 1, 0.6992 (clamped-pinned: 20.19, from tan x = x), 0.5.
double EulerLoadCoefficient(ColumnEnds ends);

}  // namespace cosserat
