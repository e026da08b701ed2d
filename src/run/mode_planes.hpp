#pragma once
/// \file
/// Which way a held rod's modes move: in the plane of its equilibrium (the chord and its sag, a
/// cable's in-plane modes) or out of it (sideways). A bridge engineer reads a stay cable's modes
/// as pairs of these, and every mode's kind said only "bending".

#include <optional>
#include <string>
#include <vector>

#include "cosserat/analysis/modes.hpp"
#include "cosserat/state/rod_state.hpp"

namespace cosserat::run::detail {

/// "in-plane" or "out-of-plane" per mode: whether its displacement's share along the normal of
/// the equilibrium's plane (through the chord and the node farthest from it; a straight rod's
/// through the chord and gravity) exceeds its share across the chord within the plane. Empty
/// when the plane is not defined (a straight rod with no gravity across it, or along it) or the
/// modes carry no shapes.
std::vector<std::string> ModePlanes(const RodState& equilibrium, const std::vector<Mode>& modes,
                                    const Vec3& gravity_W);

}  // namespace cosserat::run::detail
