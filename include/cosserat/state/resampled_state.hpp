#pragma once
/// \file
/// A rod state carried onto other nodes: the guess for a solve on another grid or length.

#include <vector>

#include "cosserat/state/rod_state.hpp"

namespace cosserat {

/// `from` sampled at the arc lengths `s` (m, increasing, from from.s.front()): positions,
/// strains, wrenches and twists linear between from's nodes; rotations along the geodesic
/// R_i Exp(t Log(R_iᵀ R_{i+1})). Past from's tip the rod goes on straight along its tip tangent
/// (material a growing rod has just added): position p_tip + (s − s_tip) R_tip e_z, the tip's
/// rotation, strain and wrench. Throws std::invalid_argument for a state of fewer than 2 nodes
/// or an `s` that is not increasing or starts before from.s.front().
RodState ResampledState(const RodState& from, const std::vector<double>& s);

}  // namespace cosserat
