#include "settle_beside_instability.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

#include "cosserat/lie/quaternion.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/state/resampled_state.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "cosserat/run/solver_options.hpp"
#include "quatfd_stability.hpp"

namespace cosserat::run::detail {
namespace {

/// The imperfection is taken away in steps of at most an eighth, halved on a failed solve down
/// to 1/256: a stable equilibrium moves smoothly with it.
constexpr double kFirstStep = 1.0 / 8.0, kSmallestStep = 1.0 / 256.0;

/// Walks μ from 0 to 1 by `solve(μ)` (true on convergence), halving the step on failure.
template <class Solve>
bool TakeAway(const Solve& solve) {
  double mu = 0.0, step = kFirstStep;
  while (mu < 1.0) {
    const double next = std::min(1.0, mu + step);
    if (solve(next)) {
      mu = next;
      step = kFirstStep;
    } else if ((step *= 0.5) < kSmallestStep) {
      return false;
    }
  }
  return true;
}

/// An SE(3) solver (single shot or in pieces, each continuing from its last solution) taken to
/// the imperfect loads, then through the take-away; *total sums every solve, *last the final.
template <class Solver>
bool FollowAway(const io::Problem& problem, const StaticLoads& imperfect, Solver* solver,
                StaticShootingSummary* total, StaticShootingSummary* last) {
  *total = solver->Solve(problem.base, imperfect);
  if (!total->converged()) return false;
  return TakeAway([&](double mu) {
    *last = solver->Solve(problem.base, StaticLoads::Blend(imperfect, problem.loads, mu));
    total->CountWorkOf(*last);
    return last->converged();
  });
}

}  // namespace

bool MaySettle(const io::Problem& problem) {
  const io::Boundary b = problem.boundary;
  const bool ends = b == io::Boundary::kCantilever || b == io::Boundary::kPinnedPinned ||
                    b == io::Boundary::kClampedClamped || b == io::Boundary::kClampedPinned;
  return ends && !problem.has_robot && problem.rod.tendons.empty() &&
         problem.loads.contact.count == 0 && LoadsAreConservative(problem.loads);
}

StaticLoads ImperfectLoads(const io::Problem& problem, const RodState& straight, double fraction,
                           double* size) {
  const SectionProperties p = problem.rod.section->At(0.0, problem.robot.actuation);
  const double L = problem.rod.length;
  const double total = LoadForceBound(problem.rod, problem.loads);  // N
  // Bending about d1 (stiffness(0, 0)) moves the rod along d2: the softer plane's direction.
  const Mat3& R = problem.base.R;
  Vec3 across = p.stiffness(0, 0) <= p.stiffness(1, 1) ? R.col(1) : R.col(0);
  const Vec3 chord = straight.tip_position_W() - straight.position_W.front();
  if (chord.norm() > 0) {
    const Vec3 c = chord.normalized();
    Vec3 normal = across - across.dot(c) * c;
    if (normal.norm() < 0.1) normal = R.col(0) + R.col(1) - (R.col(0) + R.col(1)).dot(c) * c;
    across = normal.normalized();
    // The rod's own loads across the chord, where it has them, choose the side it bends to:
    // the other side holds an equilibrium too (bent against them), stable but not theirs.
    const Vec3 spread = L * TotalDistributedForce_W(
                                problem.loads, LoadSite{0.5 * L, 1.0, p.mass(3, 3),
                                                        p.outer_diameter});
    const Vec3 tip = problem.loads.tip_force_frame == LoadFrame::kWorld ? problem.loads.tip_force
                                                                         : Vec3::Zero();
    const Vec3 lateral = (spread + tip) - (spread + tip).dot(c) * c;
    if (lateral.norm() > 1e-9 * total) across = lateral.normalized();
  }
  *size = fraction * total / L;
  StaticLoads imperfect = problem.loads;
  imperfect.distributed_force_W += *size * across;
  return imperfect;
}

bool SettleSingleShot(const io::Problem& problem, const RodState& straight, int index,
                      StaticShootingSolver* solver, StaticShootingSummary* summary,
                      double* imperfection) {
  const StaticLoads imperfect = ImperfectLoads(problem, straight, 0.02, imperfection);
  StaticShootingSummary last;
  *summary = StaticShootingSummary{};
  if (!FollowAway(problem, imperfect, solver, summary, &last)) return false;
  const int settled =
      solver->StabilityIndex(problem.base, problem.loads, solver->base_wrench_B());
  if (settled < 0 || settled >= index) return false;
  summary->status = last.status;
  summary->residual = last.residual;
  summary->stability_index = settled;
  return true;
}

namespace {

/// The pieces' equilibrium as the settled one when it has fewer unstable directions than
/// `index`: *out receives it with *total (status and residual of `last`) and its index.
bool AcceptInPieces(const io::Problem& problem, const StaticMultipleShootingSolver& solver,
                    int index, StaticShootingSummary total, const StaticShootingSummary& last,
                    StaticsInPieces* out) {
  const int settled = IndexInPieces(problem, ColumnEnds::kClampedFree, problem.base,
                                    problem.loads, solver.state(), solver.pieces());
  if (settled < 0 || settled >= index) return false;
  total.status = last.status;
  total.residual = last.residual;
  total.stability_index = settled;
  out->summary = total;
  out->state = solver.state();
  out->pieces = solver.pieces();
  return true;
}

/// Far past the critical load the paths of the imperfection in pieces, or on the quaternion-FD
/// grid, land near the straight branch (a wire pushed at its tip by 40 times it came back
/// straight, or S-bent with 4 unstable directions): the pieces grow their steps while the
/// sections turn little. The single shot's path keeps to the stable branch, and where one shot
/// still resolves the rod (an exponent up to 20 amplifies round-off by 5e8) its settled
/// equilibrium is the start the others take up. Empty otherwise; *work receives its solves.
std::optional<RodState> SettledByOneShot(const io::Problem& problem, const RodState& straight,
                                         int index, StaticShootingSummary* work,
                                         double* imperfection) {
  if (StaticShootingExponent(problem.rod, problem.loads, problem.robot.actuation) > 20.0)
    return std::nullopt;
  StaticShootingSolver single(problem.rod, problem.nodes, StaticOptions(problem),
                              problem.robot.actuation);
  if (!SettleSingleShot(problem, straight, index, &single, work, imperfection))
    return std::nullopt;
  return single.state();
}

}  // namespace

bool SettleInPieces(const io::Problem& problem, const RodState& straight, int index, int pieces,
                    StaticsInPieces* out, double* imperfection) {
  StaticShootingSummary spent;  // a one-shot route that did not settle it
  if (const auto shot = SettledByOneShot(problem, straight, index, &spent, imperfection)) {
    StaticMultipleShootingSolver solver(
        problem.rod, problem.nodes,
        PiecesOptions(problem, ColumnEnds::kClampedFree, pieces, false));
    const StaticShootingSummary last = solver.SolveFrom(problem.base, problem.loads, *shot);
    spent.CountWorkOf(last);
    if (last.converged() && AcceptInPieces(problem, solver, index, spent, last, out)) return true;
  }
  const StaticLoads imperfect = ImperfectLoads(problem, straight, 0.02, imperfection);
  StaticMultipleShootingSolver solver(
      problem.rod, problem.nodes, PiecesOptions(problem, ColumnEnds::kClampedFree, pieces, true));
  StaticShootingSummary total, last;
  const bool reached = FollowAway(problem, imperfect, &solver, &total, &last);
  total.CountWorkOf(spent);
  if (reached && AcceptInPieces(problem, solver, index, total, last, out)) return true;
  out->summary = total;  // the work of the routes that did not settle it
  return false;
}

namespace {

/// The quaternion-FD path of the imperfection: from the unloaded rod to the imperfect loads,
/// then the imperfection taken away; x receives the state, *total the solves' work.
bool QuatFdImperfectPath(const io::Problem& problem, const StaticLoads& imperfect,
                         quatfd::QuatFdModel* model, Eigen::VectorXd* x,
                         quatfd::QuatFdStaticsSummary* total) {
  // The loaded path from the unloaded rod (a direct Newton solve lands on the bent-back state
  // beside the straight one).
  quatfd::QuatFdStaticsOptions options = QuatFdLoadedPathOptions(problem);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(model->size());
  model->RestState(*x, v);
  *total = quatfd::SolveStatics(model, imperfect, *x, options);
  if (!total->converged()) return false;
  options.load_stepping = false;  // Newton from the last level
  options.direct_solve = true;
  quatfd::QuatFdStaticsSummary last = *total;
  const bool reached = TakeAway([&](double mu) {
    Eigen::VectorXd trial = *x;
    last = quatfd::SolveStatics(model, StaticLoads::Blend(imperfect, problem.loads, mu), trial,
                                options);
    total->iterations += last.iterations;
    total->wall_time_s += last.wall_time_s;
    if (last.converged()) *x = trial;
    return last.converged();
  });
  total->status = last.status;
  total->residual = last.residual;
  return reached;
}

/// The single shot's settled equilibrium (SettledByOneShot) carried onto the quaternion-FD
/// unknowns (its nodes as the vertices, each segment's quaternion the geodesic midpoint of its
/// end frames) and taken up there by Newton.
bool QuatFdFromSettledShot(const io::Problem& problem, const RodState& straight, int index,
                           quatfd::QuatFdModel* model, Eigen::VectorXd* x,
                           quatfd::QuatFdStaticsSummary* total, double* imperfection) {
  StaticShootingSummary by_shot;
  const std::optional<RodState> settled =
      SettledByOneShot(problem, straight, index, &by_shot, imperfection);
  total->wall_time_s += by_shot.wall_time_s;  // its Newton iterations are not the grid's
  if (!settled) return false;
  const RodState& shot = *settled;
  const int segments = model->layout().segments;
  if (shot.size() != segments + 1) return false;
  for (int n = 0; n <= segments; ++n)  // the vertices at the shot's nodes
    if (std::abs(model->grid()[n] - shot.s[n]) > 1e-12 * problem.rod.length) return false;
  using L = quatfd::QuatFdLayout;
  std::vector<double> midpoints(segments);
  for (int nu = 0; nu < segments; ++nu) midpoints[nu] = 0.5 * (shot.s[nu] + shot.s[nu + 1]);
  const RodState mid = ResampledState(shot, midpoints);  // frames on the geodesics between nodes
  Vec4 last = Vec4::Zero();
  for (int n = 0; n <= segments; ++n) x->segment<3>(L::X(n)) = shot.position_W[n];
  for (int nu = 0; nu < segments; ++nu) {
    Vec4 p = lie::RotationToQuat(mid.rotation_WB[nu]);
    if (p.dot(last) < 0.0) p = -p;  // one hemisphere along the rod
    x->segment<4>(L::P(nu)) = last = p;
  }
  quatfd::QuatFdStaticsOptions options = QuatFdStaticOptions(problem);
  options.load_stepping = false;
  options.direct_solve = true;
  const quatfd::QuatFdStaticsSummary solved =
      quatfd::SolveStatics(model, problem.loads, *x, options);
  total->iterations += solved.iterations;
  total->wall_time_s += solved.wall_time_s;
  total->status = solved.status;
  total->residual = solved.residual;
  return solved.converged();
}

}  // namespace

bool SettleQuatFd(const io::Problem& problem, const RodState& straight, int index,
                  quatfd::QuatFdModel* model, Eigen::VectorXd* q, RodState* state,
                  quatfd::QuatFdStaticsSummary* summary, int* settled_index,
                  double* imperfection) {
  const StaticLoads imperfect = ImperfectLoads(problem, straight, 0.02, imperfection);
  Eigen::VectorXd x(model->size()), v = Eigen::VectorXd::Zero(model->size());
  quatfd::QuatFdStaticsSummary total;
  RodState settled_state;
  int settled = -1;
  auto judge = [&] {
    model->ToRodState(x, v, &settled_state);
    settled = QuatFdStabilityIndex(problem, x, settled_state);
    return settled >= 0 && settled < index;
  };
  const bool own = QuatFdImperfectPath(problem, imperfect, model, &x, &total);
  model->set_loads(problem.loads);
  *summary = total;  // its work, settled or not
  if (!(own && judge())) {
    const bool from_shot =
        QuatFdFromSettledShot(problem, straight, index, model, &x, &total, imperfection);
    model->set_loads(problem.loads);
    *summary = total;
    if (!(from_shot && judge())) return false;
  }
  *q = x;
  *state = settled_state;
  *settled_index = settled;
  return true;
}

bool TurnsFreelyAboutItsChord(const io::Problem& problem, const RodState& straight) {
  const RodModel& rod = problem.rod;
  const int n = straight.size();
  if (n < 2 || !rod.section || rod.rest_strain) return false;
  for (int i = 0; i < n; ++i) {
    const Mat6 K = rod.section->At(straight.s[i], problem.robot.actuation).stiffness;
    if (std::abs(K(0, 0) - K(1, 1)) > 1e-12 * K(0, 0) || K(0, 1) != 0.0) return false;
  }
  const StaticLoads& loads = problem.loads;
  if (loads.fluid.density > 0.0 || !loads.tip_moment.isZero()) return false;
  const Vec3 chord = (straight.tip_position_W() - straight.position_W.front()).normalized();
  auto along_chord = [&](const Vec3& v) {  // to rounding of the chord's direction
    return (v - v.dot(chord) * chord).norm() <= 1e-9 * v.norm();
  };
  const bool tip_along = loads.tip_force_frame == LoadFrame::kWorld
                             ? along_chord(loads.tip_force)
                             : loads.tip_force.head<2>().isZero();
  return tip_along && along_chord(loads.gravity_W) && along_chord(loads.distributed_force_W);
}

bool SettleColumn(const io::Problem& problem, const RodState& straight, ColumnSolver* solver,
                  StaticShootingSummary* summary, double* imperfection, int* bow_index) {
  const StaticLoads imperfect = ImperfectLoads(problem, straight, 0.02, imperfection);
  *bow_index = -1;
  // Three legs, each without a bifurcation: the imperfection alone bends the column (a beam
  // across its span); the loads come in on the bent column, which stays on the side they bend
  // it to (all at once from the straight column, the steps jump to the state beside the path
  // past the critical load); the imperfection is taken away.
  StaticLoads bend_only = problem.loads.Scaled(0.0);
  bend_only.distributed_force_W = imperfect.distributed_force_W - problem.loads.distributed_force_W;
  StaticShootingSummary total;
  auto count = [&](const ColumnSummary& s) {
    total.iterations += s.iterations;
    total.shots += s.shots;
    total.load_steps += s.load_steps;
    total.status = s.status;
    total.residual = s.residual;
    return s.converged();
  };
  // Without the imperfection a column that turns freely about its chord keeps that turn as a
  // direction of zero stiffness, which the count reads either way: at the loads themselves it
  // is taken stable when it has one unstable direction at most and none with 1/256 of the
  // imperfection left (which gives the turn its stiffness).
  const bool turns = TurnsFreelyAboutItsChord(problem, straight);
  int last_unstable_bow = -1;
  auto stable_just_before = [&](const StaticLoads& from) {
    const Vec6 at_loads = solver->unknowns();
    const StaticLoads near = StaticLoads::Blend(from, problem.loads, 1.0 - kSmallestStep);
    const bool stable = count(solver->Solve(problem.base, near)) &&
                        solver->StabilityIndexAtUnknowns(problem.base, near) == 0;
    solver->set_unknowns(at_loads);
    return stable && count(solver->Solve(problem.base, problem.loads));  // records it again
  };
  // A level is taken only on a stable equilibrium: Newton from the last one can still land on
  // the state beside the path (a flat bar at 1.5 P_E, from 0.06 L with the side load to 0.03 L
  // against it), which leaves the branch.
  auto along = [&](const StaticLoads& from, const StaticLoads& to, bool to_the_loads) {
    return TakeAway([&](double mu) {
      const StaticLoads level = StaticLoads::Blend(from, to, mu);
      const Vec6 last = solver->unknowns();
      if (count(solver->Solve(problem.base, level))) {
        const int index = solver->StabilityIndexAtUnknowns(problem.base, level);
        if (!to_the_loads) last_unstable_bow = index > 0 ? index : -1;  // the last level tried
        if (index == 0) return true;
        if (to_the_loads && mu == 1.0 && turns && index == 1 && stable_just_before(from))
          return true;
      }
      solver->set_unknowns(last);
      return false;
    });
  };
  auto reached = [&] {
    if (!count(solver->SolveFromUnloaded(problem.base, bend_only))) return false;
    if (!along(bend_only, imperfect, false)) {
      *bow_index = last_unstable_bow;  // the loads came in as far as the bow stayed stable
      return false;
    }
    *bow_index = 0;
    return along(imperfect, problem.loads, true);
  };
  const bool settled = reached();
  if (settled) total.stability_index = 0;  // the loads' level was counted stable on the way
  *summary = total;  // its work, settled or not
  return settled;
}

std::string SettledNote(int straight_index, double imperfection) {
  std::ostringstream note;
  note << std::setprecision(3) << "cosserat: note: the equilibrium these loads reach from the "
       << "unloaded rod is unstable (" << straight_index << " unstable direction"
       << (straight_index > 1 ? "s" : "") << "), and the rod settles beside it: the one "
       << "written is the stable equilibrium reached by bending it with a lateral load of "
       << imperfection << " N/m (2 % of its loads) and taking that away\n";
  return note.str();
}

}  // namespace cosserat::run::detail
