// Multiple shooting's continuation: the load path from the unloaded rod (or the last solution)
// to the loads, its steps, and the stiffness continuation onto stiff contact surfaces.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include "cosserat/lie/nearest_rotation.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/loads/obstacle_core.hpp"
#include "cosserat/strong/load_parameter.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"

namespace cosserat {

namespace {

// The smallest continuation step, as a fraction of the load path.
constexpr double kMinLoadStep = 1.0 / 4096.0;

// Residual tolerance of a continuation's levels short of the end (the last uses the solver's).
constexpr double kIntermediateTolerance = 1e-6;

// How much softer the surfaces are at the start of the stiffness continuation.
constexpr double kSoftening = 1e3;

}  // namespace

StaticMultipleShootingSolver::Point StaticMultipleShootingSolver::Extrapolated(const Point& a,
                                                                               const Point& b,
                                                                               double t) {
  return {b.p + t * (b.p - a.p),
          b.R * lie::SO3Exp(Vec3(t * lie::SO3Log(Mat3(a.R.transpose() * b.R)))),
          b.m + t * (b.m - a.m), b.n + t * (b.n - a.n)};
}

void StaticMultipleShootingSolver::StartUnloaded(const lie::SE3& base) {
  x_.setZero();
  Point y = BaseStart(base, x_);
  const StaticLoads none;
  for (int k = 0; k < static_cast<int>(junction_nodes_.size()); ++k) {
    y = ShootPiece(k, y, none, false);
    junctions_[k] = y;
  }
}

const RodState& StaticMultipleShootingSolver::Shot(const lie::SE3& base,
                                                   const StaticLoads& loads) {
  Point y = BaseStart(base, x_);
  for (int k = 0; k <= static_cast<int>(junction_nodes_.size()); ++k)
    y = ShootPiece(k, k == 0 ? y : junctions_[k - 1], loads, true);
  return state_;
}

namespace {

// The loads `to` less `from` (gravity, distributed force, tip wrench, flow velocity), with the
// frames, fluid and surfaces of `to`: the size of a step along a path between them. `to` alone
// when their tip loads are given in different frames.
StaticLoads LoadChange(const StaticLoads& from, const StaticLoads& to) {
  if (!StaticLoads::SameFrames(from, to)) return to;
  StaticLoads d = to;
  d.gravity_W -= from.gravity_W;
  d.distributed_force_W -= from.distributed_force_W;
  d.tip_force -= from.tip_force;
  d.tip_moment -= from.tip_moment;
  d.fluid.velocity_W -= from.fluid.velocity_W;
  return d;
}

// The largest angle (rad) between the frames of the same node in two states.
double LargestTurn(const std::vector<Mat3>& from, const std::vector<Mat3>& to) {
  double turn = 0.0;
  for (size_t i = 0; i < from.size() && i < to.size(); ++i)
    turn = std::max(turn, lie::SO3Log(Mat3(from[i].transpose() * to[i])).norm());
  return turn;
}

}  // namespace

double StaticMultipleShootingSolver::FollowPath(const lie::SE3& base,
                                                const std::function<StaticLoads(double)>& at,
                                                double first_step, double max_step, int* levels,
                                                StaticShootingSummary* summary) {
  // The accepted solution at mu and the one before it at mu_before (for the secant predictor).
  Vec6 x_accepted = x_, x_before = x_;
  std::vector<Point> accepted = junctions_, before = junctions_;
  double mu = 0.0, mu_before = -1.0, step = std::min(first_step, max_step);
  const int budget = options_.max_load_steps + static_cast<int>(std::ceil(1.0 / max_step));
  // Halvings go down to the smallest step, or 6 below the first when that is smaller (a riser
  // at T L²/EI = 5e4 starts at the smallest step and would otherwise have no second try).
  const double smallest = std::min(kMinLoadStep, step / 64.0);
  // A level that passes a node into an obstacle's core jumped through it (obstacle_core.hpp):
  // refused like a failed one, so the steps shrink until the surfaces hold the rod back.
  const ContactSurfaces surfaces = at(1.0).contact;
  const bool obstacles = HasObstacleCore(surfaces);
  const bool turns = options_.max_turn > 0.0;
  std::vector<Vec3> at_accepted;
  std::vector<Mat3> frames_accepted;
  if (obstacles || turns) {
    const RodState& start = Shot(base, at(0.0));
    if (obstacles) at_accepted = start.position_W;
    if (turns) frames_accepted = start.rotation_WB;
  }
  // The secant predictor extrapolates the change from the start, which is only a step along the
  // path if the start is an equilibrium: the unloaded rod, placed against a contact surface it
  // presses into (a pipe laid on a bore's wall at the sag its weight will give), is not, and
  // doubling its way to the first level pushed a 300 m pipe deep into the wall (Newton then failed
  // from a residual of 1 000 at every step down to the smallest).
  Eigen::VectorXd r_start(r_.size());
  const bool start_balanced =
      Residual(base, at(0.0), &r_start) && r_start.norm() < options_.tolerance;
  for (int taken = 0; mu < 1.0 && taken < budget && step >= smallest; ++taken) {
    const double mu_try = std::min(1.0, mu + step);
    ++*levels;
    if (mu_before >= 0.0) {  // secant predictor along the path: the unknowns' change per μ
      const double t = (mu_try - mu) / (mu - mu_before);
      x_ = x_accepted + t * (x_accepted - x_before);
      for (size_t k = 0; k < junctions_.size(); ++k)
        junctions_[k] = Extrapolated(before[k], accepted[k], t);
    }
    // Levels short of the end only seed the next: a looser tolerance is enough (as the single
    // shot's path), and a 300 m pipe in a bore stalls at a residual of 1.1e-10 (rounding) on
    // some levels, which at 1e-10 halved its steps down to the smallest.
    const double tolerance =
        mu_try == 1.0 ? options_.tolerance : std::max(options_.tolerance, kIntermediateTolerance);
    bool held = Newton(base, at(mu_try), tolerance, summary);
    if (held) {
      // A level whose shot ran away met its residuals with frames that are no rotations
      // (RodState::RanAway): refused like a failed one.
      const RodState& now = Shot(base, at(mu_try));
      held = !now.RanAway() &&
             (!obstacles || !ReachesObstacleCore(surfaces, at_accepted, now.position_W)) &&
             (!turns || LargestTurn(frames_accepted, now.rotation_WB) <= options_.max_turn);
      if (held && obstacles) at_accepted = now.position_W;
      if (held && turns) frames_accepted = now.rotation_WB;
    }
    if (held) {
      mu_before = mu == 0.0 && !start_balanced ? -1.0 : mu;
      mu = mu_try;
      x_before = x_accepted;
      before = accepted;
      x_accepted = x_;
      accepted = junctions_;
      step = std::min(2.0 * step, max_step);
    } else {
      x_ = x_accepted;
      junctions_ = accepted;
      step *= 0.5;
    }
  }
  return mu;
}

void StaticMultipleShootingSolver::StepsAlong(const StaticLoads& from, const StaticLoads& to,
                                              double* first_step, double* max_step) const {
  // A column's path in steps of at most max_load_increment in the load parameter of the change
  // of the loads (as ColumnSolver's): a full step from the straight column lands on another
  // branch (a clamped-clamped column at L sqrt(T/EI) = 5 under a side load of 0.3 T converged
  // 0.37 L away from the straight one's). The change, not the loads: a buckling scan's warm
  // re-solves of a 300 m pipe in a bore, each adding 1/40 of its weight, took 500 levels each.
  // With max_turn, that is the first step, and the turns of the sections bound the rest: a
  // 1 km riser column at 2 MN under a side load of 1 kN/m took 6 000 Newton iterations in steps
  // of 3, 50 with max_turn. Never below the smallest step (a rod at T L²/EI = 1e5 took none).
  const bool turns = options_.max_turn > 0.0;
  const double measure = StaticLoadParameter(model_, LoadChange(from, to));
  const double limited = std::max(
      kMinLoadStep,
      measure > options_.max_load_increment ? options_.max_load_increment / measure : 1.0);
  *max_step = options_.tip_guided && !turns ? limited : 1.0;
  *first_step = options_.tip_guided || turns ? limited : 1.0;
}

bool StaticMultipleShootingSolver::FollowOntoStiffSurfaces(const lie::SE3& base,
                                                           const StaticLoads& loads, int* levels,
                                                           StaticShootingSummary* summary) {
  // Stiff surfaces: a rod coming down onto them follows the loads on surfaces softened
  // kSoftening times, then stiffens them geometrically (the touchdown moves little while the
  // penetration shrinks), from the unloaded rod. If that fails too, the unknowns go back to
  // where they were (the first path's last level: a state under the loads asked for, scaled).
  const Vec6 x_reached = x_;
  const std::vector<Point> junctions_reached = junctions_;
  StaticLoads soft = loads;
  for (int i = 0; i < soft.contact.count; ++i) soft.contact.surface[i].stiffness /= kSoftening;
  const StaticLoads none = loads.Scaled(0.0);
  StartUnloaded(base);
  double first_step = 1.0, max_step = 1.0;
  StepsAlong(none, loads, &first_step, &max_step);
  const double mu_soft = FollowPath(
      base, [&](double m) { return m == 1.0 ? soft : StaticLoads::Blend(none, soft, m); },
      first_step, max_step, levels, summary);
  auto stiffening = [&](double m) {
    StaticLoads l = loads;
    for (int i = 0; i < l.contact.count; ++i)
      l.contact.surface[i].stiffness *= std::pow(kSoftening, m - 1.0);
    return l;
  };
  if (mu_soft == 1.0 && FollowPath(base, stiffening, first_step, max_step, levels, summary) == 1.0)
    return true;
  x_ = x_reached;
  junctions_ = junctions_reached;
  return false;
}

StaticShootingSummary StaticMultipleShootingSolver::Solve(const lie::SE3& base,
                                                          const StaticLoads& loads) {
  const auto t0 = std::chrono::steady_clock::now();
  StaticShootingSummary summary;
  summary.stability_index = -1;
  if (!loads.IsValid(nullptr) || !base.p.allFinite() || !base.R.allFinite()) {
    summary.status = SolveStatus::kNonFinite;
    return summary;
  }
  lie::RequireRotation(base.R, "StaticMultipleShootingSolver::Solve: base.R");
  const int pieces = PiecesFor(StaticShootingExponent(model_, loads, actuation_));
  if (pieces != this->pieces()) SetPieces(pieces);
  // Unknowns and residuals in the loads' force scale, as SolveFrom's in the guess's (and not
  // below it): a 300 m pipe lying in a bore carries 77 kN, 6 000 times EI/L², and its junction
  // forces stalled at a residual of 1.1e-10 in units of EI/L² (their rounding).
  SetScales(base, std::max(guess_force_, LoadForceBound(model_, loads, actuation_)));
  double first_step = 1.0, max_step = 1.0;
  // Continuation in the loads from the last solution at this base, else from the unloaded rod.
  StaticLoads start = loads.Scaled(0.0);
  summary.warm_started = has_solution_ && solved_base_.p == base.p && solved_base_.R == base.R;
  if (options_.tip_pinned && !summary.warm_started)
    throw std::logic_error(
        "StaticMultipleShootingSolver: a pinned tip starts from a guess (SolveFrom)");
  if (summary.warm_started)
    start = solved_loads_;
  else
    StartUnloaded(base);
  StepsAlong(start, loads, &first_step, &max_step);
  // The start's unknowns: a failed solve leaves them as they were, a warm start for the next.
  const Vec6 x_start = x_;
  const std::vector<Point> junctions_start = junctions_;
  int levels = 0;
  auto along_loads = [&](double mu) {
    return mu == 1.0 ? loads : StaticLoads::Blend(start, loads, mu);
  };
  double mu = FollowPath(base, along_loads, first_step, max_step, &levels, &summary);
  if (mu < 1.0 && loads.contact.count > 0 && !options_.tip_pinned &&
      FollowOntoStiffSurfaces(base, loads, &levels, &summary))
    mu = 1.0;
  summary.load_steps = levels - 1;
  const bool converged = mu == 1.0;
  // The state of the last accepted level (the solution when converged).
  Finish(base, along_loads(mu), converged, &summary);
  if (!converged && summary.status == SolveStatus::kMaxIterations) {
    // The continuation stopped short of the full load. The residual reported is that state's
    // under the loads asked for, as single shooting reports it (the last level's own is ~0).
    summary.status = SolveStatus::kLoadSteppingFailed;
    summary.load_fraction = mu;
    if (Residual(base, loads, &r_)) summary.residual = r_.norm();
  }
  if (!converged) {
    x_ = x_start;
    junctions_ = junctions_start;
  }
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

}  // namespace cosserat
