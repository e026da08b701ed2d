#pragma once
/// \file
/// A note on the clamps of a rod held at both ends ("boundary": "anchored") that hold its
/// tangent far from the direction the line takes just beyond the clamp's bending layer. A
/// clamp's rotation defaults to the identity (its tangent along world z): a stay cable clamped
/// at 30° above the horizontal without a rotation bends 60° within a few sqrt(EI/T) of each end,
/// where a grid coarser than that layer can only report the bend as too sharp for it.

#include <string>

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run::detail {

/// "cosserat: note: ..." lines, one per clamped end of an anchored rod's equilibrium (statics,
/// or the modes' about it; converged or under-resolved) whose tangent (its rotation's third
/// column) lies an angle θ over 20° from the line's direction between 3 and 6 bending lengths
/// sqrt(EI/T) from it (T the end's force), and which carries at least a twentieth of the moment
/// 2 sqrt(EI T) sin(θ/2) of the layer that turns the rod through θ. Empty for other ends,
/// boundaries and analyses, where the line turns by over 10° between 3–6 and 6–9 bending
/// lengths (no direction to hold the clamp against), and where 9 bending lengths pass a quarter
/// of the rod (a stiff rod's clamps shape it as a beam's).
std::string ClampAlignmentNote(const io::Problem& problem, const Result& result);

}  // namespace cosserat::run::detail
