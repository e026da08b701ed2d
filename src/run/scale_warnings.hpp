#pragma once
/// \file
/// Warnings for answers that only a slip of units gives: a "rod" shorter than twice its
/// diameter (a radius in mm on a rod in m, or length and radius swapped), and a rod stretched or
/// compressed between two nodes by more than half its length (a modulus in MPa where Pa is
/// meant makes a steel rod as soft as a gel) in a converged answer (a diverged iterate's stretch
/// says nothing of the units) or by more than a tenth (beyond any material's linear range), and
/// loads no elastic rod carries (a force over ten times EA, a
/// moment turning the rod through 1e4 rad). Each is a valid input, so the run goes on and its
/// log says what looks wrong and which fields to check.

#include "cosserat/io/problem.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run::detail {

/// Appends the warnings that apply to result->log.
void AddScaleWarnings(const io::Problem& problem, Result* result);

}  // namespace cosserat::run::detail
