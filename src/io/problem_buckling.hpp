#pragma once
/// \file
/// "buckling" of a problem file: the load searched and how far (docs/problem-format.md), and the
/// checks that need the rest of the problem: an actuation load needs what it drives, and a
/// searched load must be able to act.

#include "cosserat/io/json_reader.hpp"
#include "cosserat/io/problem.hpp"

namespace cosserat::io::detail {

/// Reads "load", "direction" (normalised), "max" and "tendons" into *b, reporting every error.
void ParseBuckling(const ObjectReader& o, Problem::Buckling* b);

/// The checks of a "tendon_tension" or "pressure" load that need the robot and the rod.
void CheckBucklingActuation(const ObjectReader& top, const Problem& p);

/// A searched load that cannot act: a tip force across a column's axis, which the guide takes
/// whole (the search ran to its max and said "not found"); gravity on a rod with no mass and no
/// fluid to buoy it. Needs the rod's section.
void CheckBucklingLoadActs(const ObjectReader& top, const Problem& p);

}  // namespace cosserat::io::detail
