#pragma once
/// \file
/// Notes on what a drill-string run leaves out, for a reader who would expect it: the weight
/// on bit, which sets the bit's friction torque but presses on nothing, and the wall friction
/// of a spinning string, which makes no torque.

#include <string>

#include "cosserat/io/problem.hpp"

namespace cosserat::run::detail {

/// The log's note lines ("cosserat: note: ...\n") for a dynamics run whose bit friction's weight
/// on bit is not matched by a tip force, or whose clamp spins a string against a wall with
/// friction; empty for any other problem.
std::string DrillStringNotes(const io::Problem& problem);

}  // namespace cosserat::run::detail
