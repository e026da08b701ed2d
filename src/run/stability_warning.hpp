#pragma once
/// \file
/// The warning after a converged static solve whose equilibrium is unstable.

#include <string>

#include "cosserat/strong/static_shooting.hpp"

namespace cosserat::run::detail {

/// "cosserat: warning: this equilibrium is unstable (k unstable directions): ..." when
/// s.stability_index > 0 (past a critical load, no stable equilibrium reached from the unloaded
/// rod: a column pressed 19 times its buckling load stays straight, and would not); else empty.
std::string UnstableWarning(const StaticShootingSummary& s);

}  // namespace cosserat::run::detail
