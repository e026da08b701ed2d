#pragma once
/// \file
/// Running a problem file: the one entry point the `cosserat` command and the Python module
/// (`cosserat.solve`) share.

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run {

/// Runs `problem` (validated by the parser and free of io::UnsupportedFeatures) with the runner
/// its analysis, formulation and robot call for: statics, dynamics, buckling or modes, on the
/// SE(3) shooting or the quaternion-FD path, eversion growth, or an assembly of rods and bodies.
Result Run(const io::Problem& problem, const RunOptions& options = {});

}  // namespace cosserat::run
