#pragma once
/// \file
/// A statics whose loads, followed from the unloaded rod, end on an unstable equilibrium of a
/// symmetric problem (an upright rod past Greenhill's length, a hanging rod pushed up at its tip):
/// the loaded path stays straight because nothing breaks the symmetry, and the real rod falls
/// over. The settling bends the rod with a small lateral load (an imperfection, 2 % of its
/// loads, spread along it, across the chord: along the rod's own loads across it, else in its
/// softer bending plane), follows the loads
/// from the unloaded rod with it, and takes it away again in steps: on the imperfect path there
/// is no bifurcation, and the equilibrium it reaches is the stable one beside the straight one.
/// Conservative loads only (the index that judges stability is defined for them alone).

#include <Eigen/Core>
#include <string>

#include "cosserat/analysis/column.hpp"
#include "cosserat/io/problem.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/quatfd/quatfd_statics.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "statics_in_pieces.hpp"

namespace cosserat::run::detail {

/// Whether a statics may settle: a plain cantilever or column (no robot) under conservative
/// loads and without contact surfaces (a finger pressed on a sphere that slips off is left as the
/// unstable equilibrium it is, with its warning: on penalty surfaces the path is long and where
/// the rod slides to is not the loads' question).
bool MaySettle(const io::Problem& problem);

/// The problem's loads plus the imperfection for the unstable state `straight`: a uniform force
/// per length of `fraction` of the loads' total (LoadForceBound: the tip force, and L times the
/// distributed loads, weight less buoyancy included) over L, across the chord from base to tip:
/// along the loads' own part across it where they have one, else along the base frame's axis of
/// the softer bending.
/// *size receives its magnitude (N/m).
StaticLoads ImperfectLoads(const io::Problem& problem, const RodState& straight, double fraction,
                           double* size);

/// SE(3) single shot: from the unloaded rod to the imperfect loads, then the imperfection taken
/// away in steps. True, with `solver` holding the equilibrium and *summary its solve (the
/// iterations of all steps, stability_index counted), when that equilibrium has fewer unstable
/// directions than `index`; false with *summary holding the work spent.
/// *imperfection receives the lateral load's size (N/m).
bool SettleSingleShot(const io::Problem& problem, const RodState& straight, int index,
                      StaticShootingSolver* solver, StaticShootingSummary* summary,
                      double* imperfection);

/// The same for a cantilever in `pieces` multiple-shooting pieces: *out receives the
/// equilibrium, its solve and its index (out->summary the work spent when false). Where one
/// shot still resolves the rod (an exponent up to 20), the single shot settles it and the pieces
/// take up its equilibrium.
bool SettleInPieces(const io::Problem& problem, const RodState& straight, int index, int pieces,
                    StaticsInPieces* out, double* imperfection);

/// The same on the quaternion-FD grid: q (and state) receive the equilibrium, *summary its
/// solve (the work spent when false), *settled_index its unstable directions. Where its own
/// path does not settle it and one shot resolves the rod, it starts from the SE(3) single
/// shot's settled equilibrium.
bool SettleQuatFd(const io::Problem& problem, const RodState& straight, int index,
                  quatfd::QuatFdModel* model, Eigen::VectorXd* q, RodState* state,
                  quatfd::QuatFdStaticsSummary* summary, int* settled_index,
                  double* imperfection);

/// Whether a column's bowed equilibria come in a family turned about its chord: a section that
/// bends alike about both axes across it (EI₁ = EI₂, uncoupled, at every node), no rest strain,
/// no fluid and no tip moment, and loads along the chord of `straight` only. Its bow then turns
/// about the chord, with a uniform spin of the sections that restores clamps and pins, at no
/// cost: one direction of zero stiffness.
bool TurnsFreelyAboutItsChord(const io::Problem& problem, const RodState& straight);

/// The same for a column (boundary pinned-pinned, clamped-clamped or clamped-pinned) on its
/// single-shot solver: from the unloaded column to the imperfect loads, then the imperfection
/// taken away, every level required stable (at the loads of a column that turns freely about
/// its chord, up to that turn: stable with 1/256 of the imperfection left, one unstable direction
/// at most without it). True, with `solver` holding the stable equilibrium and *summary its
/// solve (its work, stability_index 0), when the path reaches the loads; false with *summary
/// holding the work spent. *bow_index receives the
/// unstable directions of the last bow counted unstable where the loads could not come in on a
/// stable one (a round clamped-clamped column's past 1.44 P_cc, out of its plane); 0 when they
/// did; −1 when no bow was counted unstable (the loads are past a peak the bow holds).
bool SettleColumn(const io::Problem& problem, const RodState& straight, ColumnSolver* solver,
                  StaticShootingSummary* summary, double* imperfection, int* bow_index);

/// The log's note on a settled statics.
std::string SettledNote(int straight_index, double imperfection);

}  // namespace cosserat::run::detail
