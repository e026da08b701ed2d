#pragma once
/// \file
/// An eversion robot ("robot": {"kind": "eversion"}): a static solve at rod.length, or
/// quasi-static growth to it, with the kink check.

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run {

/// Result::json has the statics keys and a "robot" block (pressure, length, tip force, kink).
/// Converged when every solve converged.
Result RunEversion(const io::Problem& problem, const RunOptions& options);

}  // namespace cosserat::run
