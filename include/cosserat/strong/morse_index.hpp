#pragma once
/// \file
/// The Morse index of a rod equilibrium found by shooting (the number of unstable directions of
/// the second variation of its potential energy), by a Sturm count of the Jacobi fields along s:
/// conjugate points in (0, L) plus the negative eigenvalues of the tip stiffness on the tip
/// variations the end conditions admit (src/strong/morse_index.cpp has the argument).

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "cosserat/state/rod_state.hpp"

namespace cosserat {

/// A shot's tangent at one node along 6 directions of its unknowns (StaticShootingSolver::
/// StateTangent): rows d p_W (0–2, m), d(R_WB e₀,₁,₂) (3–11), d m_B (12–14, N·m), d n_B (15–17, N).
using ShotTangent = Eigen::Matrix<double, 18, 6>;

/// Tip variations η(L) = [δθ_B; δp_B] (tip body frame; rad, m) the end conditions admit, one
/// column each: all 6 for a free tip; a guided tip keeps its lateral position, a clamped one its
/// rotation too.
using TipVariations = Eigen::Matrix<double, 6, Eigen::Dynamic>;

/// The Jacobi fields inside segment i (from node i to node i + 1): the node states and tangents
/// at parts + 1 points from s_i to s_{i+1}, both included, shot again from node i's state and
/// tangent in `parts` steps. False when it cannot be done (a rod with tendons).
using RefineSegment =
    std::function<bool(int i, int parts, RodState* states, std::vector<ShotTangent>* tangents)>;

/// The index from a shot whose 6 tangent directions span the Jacobi fields that satisfy the base
/// end conditions (clamped: the base wrench; pinned: the two free base rotations, the twist
/// reaction and the force), with `record` its node states and `nodes` its tangents. The tip term
/// counts eigenvalues below −zero (N·m, in units where a rotation of 1 rad and a displacement of
/// `length` m weigh alike). The whole tip wrench counts as dead in the world frame, so the loads
/// must be conservative (the caller checks). −1 when the Jacobi fields are singular to rounding
/// at a node (no count).
/// With `refine`, a segment whose Prüfer count depends on the scale it is read in (two
/// conjugate points and two eigenvalues rising through zero look alike from its ends) is
/// counted again on its refinement.
int MorseIndexOfShot(const RodState& record, const std::vector<ShotTangent>& nodes,
                     const TipVariations& tip, double length, double zero,
                     const RefineSegment& refine = nullptr);

}  // namespace cosserat
