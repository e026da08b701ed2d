#pragma once
/// \file
/// A note on the clamps of a rod held at both ends ("boundary": "anchored") that hold its
/// tangent far from the chord between the ends. A clamp's rotation defaults to the identity
/// (its tangent along world z): a stay cable clamped at 30° above the horizontal without a
/// rotation bent 60° in a layer at each end, and the log spoke only of the grid.

#include <string>

#include "cosserat/io/problem.hpp"

namespace cosserat::run::detail {

/// "cosserat: note: ..." lines, one per clamped end whose tangent (its rotation's third
/// column) lies over 20° from the chord; empty otherwise, and for any other boundary.
std::string ClampAlignmentNote(const io::Problem& problem);

}  // namespace cosserat::run::detail
