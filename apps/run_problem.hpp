#pragma once
// `cosserat solve` for any runnable problem: picks the analysis and formulation's runner. Shared
// by the command-line tool and the Python module (`cosserat.solve`).

#include <ostream>

#include "cosserat/io/problem.hpp"

namespace cosserat::cli {

/// Runs `problem` (validated, and free of io::UnsupportedFeatures): the result JSON to `out`, the
/// node table to `csv` when given, a one-line summary (and any hints) to `log`. Returns true
/// when it converged.
bool RunProblem(const io::Problem& problem, std::ostream& out, std::ostream* csv,
                std::ostream& log);

}  // namespace cosserat::cli
