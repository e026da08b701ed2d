#pragma once
/// \file
/// A note on a column's tip guide ("pinned-pinned", "clamped-clamped", "clamped-pinned"): the
/// guide lets the tip slide along the column's axis only, so it takes a tip force's part across
/// that axis whole. Such a force bends nothing and is in no result field; a user who meant a
/// point load on a beam held at both ends needs to hear that.

#include <string>

#include "cosserat/analysis/column_ends.hpp"
#include "cosserat/io/problem.hpp"

namespace cosserat::run::detail {

/// "cosserat: note: ..." when `ends` is a column's and loads.tip_force has a part across the
/// axis (base.rotation's third column; a "body" tip force in the tip's frame, whose axis is
/// e₃) above 1e-12 of its size; empty otherwise.
std::string GuideTakesTipForceNote(const io::Problem& problem, ColumnEnds ends);

}  // namespace cosserat::run::detail
