#pragma once
/// \file
/// The warning after a converged static solve whose equilibrium is unstable.

#include <string>

#include "cosserat/analysis/column.hpp"
#include "cosserat/io/problem.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat::run::detail {

/// "cosserat: warning: this equilibrium is unstable (k unstable directions): ..." when
/// s.stability_index > 0 (past a critical load: a column pressed 19 times its buckling load
/// stays straight, and would not); else empty. searched_stable: the solver looked for a stable
/// equilibrium from the unloaded rod and found none (the cantilever's does; the column's
/// follows its straight branch).
/// On contact surfaces (`on_surfaces`) it names sliding off them first.
std::string UnstableWarning(const StaticShootingSummary& s, bool searched_stable = true,
                            bool on_surfaces = false);

/// A column (pinned or clamped at both ends) that stands nearly straight (no node off its chord
/// by 5 % of the length) while compressed everywhere beyond 1.01 times the Euler load of its
/// ends (π², 20.19 or 4π² EI/L² for pinned–pinned, clamped–pinned, clamped–clamped; Timoshenko
/// & Gere 1961; EI at mid-length) is on the unstable branch: the stable one bows out (pinned
/// ends: by about 0.9 √(P/P_E − 1) L, the elastica's amplitude to first order). The warning says
/// so; empty otherwise. For columns whose stability index is not defined (a tip moment, a
/// follower force, drag), or to say more than the index does. Not for columns on contact
/// surfaces, which hold them laterally (the caller's rule). The bow is not offered where there
/// is none: past the pins' crossing (pinned–pinned), past the clamped–pinned bow's peak load,
/// or where `bow_index` (the bow's unstable directions under a side load, SettleColumn; −1:
/// unknown) counts it unstable too.
std::string ColumnPastEulerWarning(ColumnEnds ends, const RodModel& rod, const RodState& state,
                                   int bow_index);

/// A rod held at both ends ("anchored") compressed somewhere by more than π²EI/L² (below that
/// no part of it can buckle, whatever the ends): its statics have no stability index, so a note
/// says where and points at "modes", whose negative ω² judges it (a riser short of top
/// tension). Empty otherwise (EI at mid-length).
std::string AnchoredCompressionNote(const RodModel& rod, const RodState& state);

/// The same note for any rod whose stability the solve could not judge, with `why` after "the
/// rod is compressed by up to P N (at s = … m), ".
std::string UnjudgedCompressionNote(const RodModel& rod, const RodState& state,
                                    const std::string& why);

/// The SE(3) statics' stability index as the run reports it. The index counts the conjugate
/// points of Jacobi fields shot by RK4 on the grid, which grow or turn at the rate
/// k = sqrt(|N|/EI) of the axial force N; past k h = 2.8 (RK4's limit on a decaying exponential)
/// they no longer do so faithfully, and a 2 km drill string hanging in tension everywhere counted
/// 2 unstable directions on 101 nodes (k h = 16), 1 on 201 and 0 on 401. There a rod in tension
/// everywhere (no contact surface, tip moment or tendon) is stable, 0; any other's `index`
/// becomes −1 (not judged) and `note` says why and how many nodes judge it. Elsewhere `index` as
/// it is.
int JudgedStabilityIndex(const io::Problem& problem, const RodState& state, int index,
                         std::string* note);

}  // namespace cosserat::run::detail
