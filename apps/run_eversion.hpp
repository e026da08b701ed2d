#pragma once
/// \file
/// `cosserat solve` for an eversion robot (problem "robot": {"kind": "eversion"}): a static
/// solve at rod.length, or quasi-static growth to it, with the kink check.

#include <ostream>

#include "cosserat/io/problem.hpp"

namespace cosserat::cli {

/// Writes the result JSON to `out` (with a "robot" block: pressure, length, tip force, kink),
/// the node table to `csv` if given, a summary to `log`. True when every solve converged.
bool RunEversion(const io::Problem& problem, std::ostream& out, std::ostream* csv,
                 std::ostream& log);

}  // namespace cosserat::cli
