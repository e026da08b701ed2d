// SE(3) modes by frequency shooting: the roots of det B(ω) about the equilibrium of a cantilever
// or a column.
#include "cosserat/analysis/modes.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosserat/analysis/column.hpp"
#include "cosserat/analysis/frequency_shooting.hpp"
#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "frequency_roots.hpp"
#include "frequency_shot_limit.hpp"
#include "mode_classification.hpp"

namespace cosserat {
namespace {

using detail::Classify;
using detail::NodeWeights;
using Clock = std::chrono::steady_clock;
constexpr double kTwoPi = 6.283185307179586;

/// The shooting nodes' weights: trapezoid masses and inertias (rotated into the world with the
/// node frames), the tangents d3.
NodeWeights ShootingNodeWeights(const RodModel& rod, const std::vector<double>& s,
                                const FrequencyShooting& fs, const Actuation& actuation) {
  const int n = static_cast<int>(s.size());
  NodeWeights nw;
  nw.mass.resize(n);
  nw.inertia_W.resize(n);
  nw.tangent_W.resize(n);
  for (int i = 0; i < n; ++i) {
    const double w = 0.5 * ((i > 0 ? s[i] - s[i - 1] : 0.0) + (i + 1 < n ? s[i + 1] - s[i] : 0.0));
    const SectionProperties sp = PrincipalAxesSectionAt(rod, s[i], actuation);
    const Mat3& R = fs.rotation_WB()[i];
    nw.mass[i] = sp.mass(5, 5) * w;
    nw.inertia_W[i] = R * (sp.mass.diagonal().head<3>() * w).asDiagonal() * R.transpose();
    nw.tangent_W[i] = R.col(2);
  }
  return nw;
}

/// The unstable directions of an equilibrium with Morse index `index`, as the quaternion-FD
/// spectrum lists them: the roots σ of det B at ω² = −σ² (FrequencyShooting::GrowthRates),
/// reported as ω = −σ (a negative frequency, its magnitude the growth rate) ahead of the real
/// frequencies, fastest growth first, the list cut at `count`. The growth rates found (fewer
/// than index when the scan misses some) are the ones listed.
void PrependUnstableModes(const FrequencyShooting& fs, const NodeWeights& weights, double w_lo,
                          double w_hi, double step, int index, int count, bool shapes, double L,
                          ModalResult* result) {
  const FrequencyShooting growth = fs.GrowthRates();
  const std::vector<detail::Root> roots = detail::FindRoots(growth, w_lo, w_hi, step, index);
  std::vector<Mode> unstable;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
    Mode mode;
    mode.omega = -it->omega;
    mode.frequency_hz = mode.omega / kTwoPi;
    if (shapes) {
      growth.Shape(it->omega, it->x, &mode.displacement_W, &mode.rotation_W);
      Classify(weights.tangent_W, weights.mass, weights.inertia_W, L, &mode);
    }
    unstable.push_back(std::move(mode));
  }
  result->modes.insert(result->modes.begin(), unstable.begin(), unstable.end());
  if (static_cast<int>(result->modes.size()) > count) result->modes.resize(count);
}

/// The equilibrium the modes are about, as a cantilever's or a column's solver leaves it: its
/// linearisation and its count of unstable directions (−1: not defined).
struct ShootingEquilibrium {
  StaticShootingSummary statics;
  RodState state;
  std::vector<double> grid;
  std::optional<FrequencyShooting> linear;
  int stability_index = -1;
};

ShootingEquilibrium SolveEquilibrium(const RodModel& rod, int num_nodes, const lie::SE3& base,
                                     const StaticLoads& loads,
                                     const ShootingModalOptions& options,
                                     const Actuation& actuation, ColumnEnds ends) {
  const StaticShootingOptions& opt = options.statics;
  ShootingEquilibrium eq;
  if (ends == ColumnEnds::kClampedFree) {
    StaticShootingSolver solver(rod, num_nodes, opt, actuation);
    eq.statics = solver.Solve(base, loads);
    eq.state = solver.state();
    eq.grid = solver.grid();
    if (!eq.statics.converged()) return eq;
    ShootingEnds tip_body;
    tip_body.tip_mass = options.tip_mass;
    tip_body.tip_inertia = options.tip_inertia;
    eq.linear.emplace(rod, eq.grid, base, loads, solver.base_wrench_B(), actuation, tip_body);
    eq.stability_index = solver.StabilityIndex(base, loads, solver.base_wrench_B());
    return eq;
  }
  ColumnSolver solver(rod, num_nodes, ends, opt, actuation);
  const ColumnSummary c = solver.SolveFromUnloaded(base, loads);
  eq.statics.status = c.status;
  eq.statics.iterations = c.iterations;
  eq.statics.residual = c.residual;
  eq.state = solver.state();
  eq.grid = solver.grid();
  if (!c.converged()) return eq;
  ShootingEnds shooting;
  shooting.base_pinned = ends == ColumnEnds::kPinnedPinned;
  shooting.tip_guided = true;
  shooting.tip_clamped = ends == ColumnEnds::kClampedClamped;
  shooting.axes_W = base.R;
  lie::SE3 first = base;  // a pinned base's first node has turned with the rod
  first.R = eq.state.rotation_WB[0];
  eq.linear.emplace(rod, eq.grid, first, loads, eq.state.wrench_B[0], actuation, shooting);
  eq.stability_index = solver.StabilityIndexAtUnknowns(base, loads);
  return eq;
}

/// Under a load that is not conservative (a follower force, a dead tip moment) two frequencies
/// can meet and leave the real axis as a complex pair, one growing (flutter: Beck's column past
/// 20.05 EI/L²). The scan sees only the dip of det B they leave behind: the instability's text
/// for the lowest such dip, empty when there is none. Only where one shot resolves det B: past
/// λL ≈ 15, λ = (ω² ρA/EI)^¼, round-off dips appear that no pair makes (a Beck column at 8 % of
/// its flutter load showed one at 1414 Hz, λL = 30, with 20 modes asked); the real part of a
/// merged low pair sits near λL = √11 (Beck's).
std::string FlutterNear(const FrequencyShooting& fs, const StaticLoads& loads, double L,
                        const std::vector<double>& dips) {
  const SplitWrench tip = TotalTipWrench(loads);
  if (tip.follower_B.isZero(0.0) && tip.dead_W.head<3>().isZero(0.0)) return "";
  const double lambda_scale = std::sqrt(fs.mass_per_length_at_base() / fs.bending_stiffness());
  for (double w : dips) {
    if (std::sqrt(w * lambda_scale) * L > 15.0) continue;
    std::ostringstream why;
    why << "flutter: near " << w / kTwoPi
        << " Hz two frequencies have met and left the real axis under a load that is not "
           "conservative (a follower force, a tip moment): a pair that grows in time. Frequency "
           "shooting finds real frequencies only; \"formulation\": \"quaternion-fd\" gives "
           "the complex pair";
    return why.str();
  }
  return "";
}

}  // namespace

ModalResult ComputeModesShooting(const RodModel& rod, int num_nodes, const lie::SE3& base,
                                 const StaticLoads& loads, const ShootingModalOptions& options,
                                 const Actuation& actuation, ColumnEnds ends) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("ShootingModalOptions: " + why);
  if (!rod.tendons.empty())
    throw std::invalid_argument("ComputeModesShooting: rods with tendons are not supported");
  const auto start = Clock::now();
  ModalResult result;
  auto finish = [&](ModalStatus status) {
    result.status = status;
    result.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
    return result;
  };
  if (ends != ColumnEnds::kClampedFree && (options.tip_mass > 0 || !options.tip_inertia.isZero()))
    throw std::invalid_argument("ComputeModesShooting: a body at the tip needs a cantilever");
  const ShootingEquilibrium eq =
      SolveEquilibrium(rod, num_nodes, base, loads, options, actuation, ends);
  result.statics_status = eq.statics.status;
  result.statics_iterations = eq.statics.iterations;
  result.statics_residual = eq.statics.residual;
  result.s = eq.grid;
  result.equilibrium = eq.state;
  if (!eq.statics.converged()) return finish(ModalStatus::kStaticsFailed);
  const FrequencyShooting& fs = *eq.linear;

  // The scan's range, by default 0.01 to 10⁴ times the first Euler–Bernoulli cantilever
  // frequency of the rod's base section.
  const double L = rod.length;
  const double w_eb =
      1.8751 * 1.8751 / (L * L) * std::sqrt(fs.bending_stiffness() / fs.mass_per_length_at_base());
  // Its top, where one shot's round-off blurs the roots (frequency_shot_limit.hpp): roots past
  // it are not listed, so a lost partner of a pair cannot shift the list.
  const double w_limit = detail::FrequencyShotLimit(rod, actuation, eq.state);
  result.shot_limit_hz = w_limit / kTwoPi;
  const double w_lo = options.omega_min > 0 ? options.omega_min : 0.01 * w_eb;
  const double w_hi =
      std::min(options.omega_max > 0 ? options.omega_max : 1e4 * w_eb, w_limit);
  const int count = options.modal.count;
  std::vector<double> dips;
  std::vector<detail::Root> roots;
  if (w_hi > w_lo)
    roots = detail::FindRoots(fs, w_lo, w_hi, 1.0 + options.relative_step, count, &dips,
                              options.progress);
  roots.erase(std::remove_if(roots.begin(), roots.end(),
                             [&](const detail::Root& r) { return r.omega > w_limit; }),
              roots.end());

  const NodeWeights weights = ShootingNodeWeights(rod, eq.grid, fs, actuation);
  for (size_t i = 0; i < roots.size() && static_cast<int>(i) < count; ++i) {
    Mode mode;
    mode.omega = roots[i].omega;
    mode.frequency_hz = mode.omega / kTwoPi;
    if (options.modal.shapes) {
      fs.Shape(mode.omega, roots[i].x, &mode.displacement_W, &mode.rotation_W);
      Classify(weights.tangent_W, weights.mass, weights.inertia_W, L, &mode);
    }
    result.modes.push_back(std::move(mode));
  }
  result.instability = FlutterNear(fs, loads, L, dips);
  if (!result.instability.empty()) return finish(ModalStatus::kUnstable);
  if (static_cast<int>(result.modes.size()) < count) return finish(ModalStatus::kTooFewModes);
  // The scan finds real frequencies only: an unstable direction of the equilibrium (a rod pressed
  // on a convex obstacle harder than it bends back) has an imaginary one it cannot see, so the
  // equilibrium's Morse index decides (−1, not defined for drag or follower loads: stable).
  if (const int index = eq.stability_index; index > 0) {
    result.instability = "divergence: the equilibrium has " + std::to_string(index) +
                         " unstable direction" + (index > 1 ? "s" : "") + " (its Morse index)";
    PrependUnstableModes(fs, weights, w_lo, w_hi, 1.0 + options.relative_step, index, count,
                         options.modal.shapes, L, &result);
    return finish(ModalStatus::kUnstable);
  }
  return finish(ModalStatus::kConverged);
}

}  // namespace cosserat
