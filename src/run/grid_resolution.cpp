#include "cosserat/run/grid_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <Eigen/Geometry>

#include "cosserat/analysis/modes.hpp"
#include "cosserat/state/solve_status.hpp"
#include "result_rows.hpp"

namespace cosserat::run {
namespace {

/// The coarse-shape line after its lead: where the section turns most per segment (`worst` rad
/// at s = `worst_s` m, `worst_k` rad/m), what that costs a constant-curvature arc
/// (`arc_error`, the scheme's own words) and the nodes that keep it below 0.25 rad.
std::string CoarseShapeLine(const std::string& lead, double worst, double worst_s,
                            double worst_k, double length, const std::string& arc_error) {
  std::ostringstream log;
  log << std::setprecision(3) << lead << "the bending turns the section by " << worst
      << " rad per segment near s = " << worst_s << " m, where a constant-curvature arc's tip "
      << arc_error << "; rod.nodes ≥ " << static_cast<long>(std::ceil(4.0 * worst_k * length)) + 1
      << " keeps it below 0.25 rad\n";
  return log.str();
}

/// The quaternion-FD twist: a segment turned by θ about the rod's axis has the discrete twist
/// (4/h) tan(θ/4), whose energy makes the rod stiffer in torsion by about θ²/12 (a tip torque's
/// twist measured 1.9 % short at 0.5 rad per segment, 0.50 % at 0.25), and the moments carried
/// through it are off by as much. A warning from 1 %, θ = 0.35 rad; empty below.
std::string TwistLine(double twist, double twist_s, double twist_rate, double length) {
  const double error = twist * twist / 12.0;
  if (!(error > 0.01)) return "";
  std::ostringstream log;
  log << std::setprecision(3) << "cosserat: warning: the grid resolves the twist coarsely: the "
      << "sections turn about the rod by " << twist << " rad per segment near s = " << twist_s
      << " m, where the quaternion-FD scheme is stiffer in torsion by about " << 100 * error
      << " % (θ²/12; the twist and the moments carried through it are off by as much); "
      << "rod.nodes ≥ " << static_cast<long>(std::ceil(twist_rate * length / std::sqrt(0.12))) + 1
      << " keeps it within 1 %\n";
  return log.str();
}

}  // namespace

GridResolution CheckGrid(const std::vector<double>& s, const std::vector<Vec3>& position,
                         const std::vector<Vec3>& curvature, double length, bool converged,
                         const std::vector<double>& stretch) {
  GridResolution out;
  double& worst = out.worst_turn;  // bending κ h (rad)
  auto bending = [](const Vec3& k) { return std::hypot(k.x(), k.y()); };
  for (size_t i = 0; i + 1 < s.size(); ++i) {
    const double h = s[i + 1] - s[i];
    const double bend = std::max(bending(curvature[i]), bending(curvature[i + 1]));
    if (bend * h > worst) worst = bend * h, out.worst_s = s[i], out.worst_k = bend;
    const double turn = std::max(curvature[i].norm(), curvature[i + 1].norm()) * h;
    const double segment = (position[i + 1] - position[i]).norm();
    if (!SegmentRanAway(h, segment, turn)) continue;
    std::ostringstream log;
    log << std::setprecision(3)
        << (converged ? "cosserat: the residuals vanished, but its shot ran away: the "
                      : "cosserat: at the last load level reached the shot ran away: the ")
        << "segment at s = " << s[i] << " m spans " << segment << " m for " << h
        << " m of rod, while the curvature turns the section by " << turn
        << " rad on it, which RK4 in s cannot follow" << (converged ? ": status non_finite" : "")
        << "; check the units of the loads, the actuation and rod.rest_curvature (rad/m)";
    // The turn of a shot that ran away may be its runaway's, not the shape's: nodes from it
    // only while they stay within 50 times the grid's (a tendon curling a rod 4.8 rad per
    // segment asks for 17 times; a 100 m pipe on a bore's wall asked for 238 193 489, and a
    // coarser one for a negative count).
    const double nodes = std::ceil(4.0 * turn / h * length) + 1;
    if (nodes <= 50.0 * static_cast<double>(s.size()))
      log << ", or give rod.nodes ≥ " << static_cast<long>(nodes);
    else
      log << "; a finer grid does not follow it (it would take over 50 times these nodes)";
    log << '\n';
    out.ran_away = true;
    out.log = log.str();
    return out;
  }
  if (worst <= 0.5) return out;
  out.under_resolved = worst > 1.5;
  std::ostringstream error;
  error << std::setprecision(3) << "is off by about " << 100 * 8e-3 * std::pow(worst, 4)
        << " % of the length (RK4 in s, fourth order in κ h)";
  // Over many turns the loss adds up: RK4 shrinks the frames it turns by |1 + z + ... + z⁴/24|,
  // z = i κ h, each step (0.23 % at 0.84 rad), and the positions with them. Measured on the
  // nodes: their spacing against the chord sinc(κh/2) h (1 + ε) of the arc between them,
  // stretched by the axial strain ε.
  double shortest = 1.0, shortest_s = 0.0;
  for (size_t i = 0; i + 1 < s.size(); ++i) {
    const double h = s[i + 1] - s[i];
    const double half = 0.25 * (bending(curvature[i]) + bending(curvature[i + 1])) * h;
    if (!(h > 0.0) || half > 0.5 * M_PI) continue;
    const double strain = stretch.size() == s.size() ? 0.5 * (stretch[i] + stretch[i + 1]) : 0.0;
    if (!std::isfinite(strain)) continue;  // a stretch not known: no shrink judged there
    const double chord = (half > 1e-8 ? h * std::sin(half) / half : h) * (1.0 + strain);
    const double ratio = (position[i + 1] - position[i]).norm() / chord;
    if (ratio < shortest) shortest = ratio, shortest_s = s[i];
  }
  if (shortest < 0.99)
    error << "; the nodes lie " << 100 * (1.0 - shortest) << " % closer than the arc between "
          << "them by s = " << shortest_s << " m, as RK4 shrinks the frames it turns and the "
          << "positions with them";
  out.log = CoarseShapeLine(
      !converged ? "cosserat: at the last load level reached, the grid resolves the shape "
                   "coarsely: "
      : out.under_resolved ? "cosserat: the grid is too coarse for this shape (status "
                             "under_resolved): "
                           : "cosserat: warning: the grid resolves the shape coarsely: ",
      worst, out.worst_s, out.worst_k, length, error.str());
  return out;
}

GridResolution CheckGrid(const RodState& state, double length, bool converged) {
  std::vector<Vec3> curvature;
  std::vector<double> stretch;  // ν₃ − 1: the backbone's own
  curvature.reserve(state.strain.size());
  for (const Vec6& xi : state.strain) {
    curvature.push_back(xi.head<3>());
    stretch.push_back(xi(5) - 1.0);
  }
  GridResolution out =
      CheckGrid(state.s, state.position_W, curvature, length, converged, stretch);
  if (out.ran_away) return out;
  int first = -1;  // the first node whose frame left the rotations
  for (int i = 0; i < state.size() && first < 0; ++i)
    if (FrameRanAway(state.rotation_WB[i])) first = i;
  if (first < 0) return out;
  std::ostringstream lead;
  lead << std::setprecision(3) << "cosserat: the residuals vanished, but the frames RK4 in s "
       << "carried along the shot are no rotations from s = " << state.s[first]
       << " m on (‖R‖² = " << state.rotation_WB[first].squaredNorm()
       << ", a rotation's 3; status non_finite): ";
  out.ran_away = true;
  out.under_resolved = false;
  out.log = CoarseShapeLine(lead.str(), out.worst_turn, out.worst_s, out.worst_k, length,
                            "is lost, as RK4 shrinks the frames it turns (check the units of "
                            "the loads, the actuation and rod.rest_curvature, rad/m)");
  return out;
}

std::string FramesLeftRotationsLine(const RodState& state, double length) {
  if (state.SegmentsRanAway()) return "";  // the nodes' own check says it
  const GridResolution g = CheckGrid(state, length);
  return g.ran_away ? g.log : "";
}

GridResolution CheckPolygon(const std::vector<double>& s, const std::vector<Vec3>& position,
                            const std::vector<Vec3>& curvature, double length,
                            const std::vector<double>& rest_twist) {
  GridResolution out;
  double worst = 0.0, worst_s = 0.0, worst_k = 0.0;  // turn (rad), where, turn / h (1/m)
  double worst_twist = 0.0, twist_s = 0.0, twist_rate = 0.0;  // rad, m, 1/m
  const size_t n = s.size();
  for (size_t i = 0; i < n; ++i) {
    const double h = 0.5 * (s[std::min(i + 1, n - 1)] - s[i > 0 ? i - 1 : 0]) *
                     (i == 0 || i + 1 == n ? 2.0 : 1.0);
    // The bending curvature at the vertex (the clamps' included), or the polygon's turn there.
    double turn = std::hypot(curvature[i].x(), curvature[i].y()) * h;
    if (i > 0 && i + 1 < n) {
      const Vec3 a = position[i] - position[i - 1], b = position[i + 1] - position[i];
      turn = std::max(turn, std::atan2(a.cross(b).norm(), a.dot(b)));
    }
    if (turn > worst) worst = turn, worst_s = s[i], worst_k = turn / h;
    const double strain = curvature[i].z() - (i < rest_twist.size() ? rest_twist[i] : 0.0);
    const double twist = 4.0 * std::atan(0.25 * std::abs(strain) * h);  // rad
    if (twist > worst_twist) worst_twist = twist, twist_s = s[i], twist_rate = twist / h;
  }
  out.log = TwistLine(worst_twist, twist_s, twist_rate, length);
  if (worst <= 0.5) return out;
  out.under_resolved = worst > 1.5;
  std::ostringstream error;
  error << std::setprecision(3) << "would be off by " << 100 * 0.08 * worst * worst
        << " % of the length (quaternion FD, second order in κ h; a bend this sharp over a "
           "short stretch costs far less)";
  out.log += CoarseShapeLine(out.under_resolved
                                ? "cosserat: the grid is too coarse for this shape (status "
                                  "under_resolved): "
                                : "cosserat: warning: the grid resolves the shape coarsely: ",
                            worst, worst_s, worst_k, length, error.str());
  return out;
}

namespace {
/// The rod's rest twist κ₃* at the result's nodes (1/m).
std::vector<double> RestTwist(const io::Problem& problem, const nlohmann::ordered_json& nodes) {
  std::vector<double> out;
  for (const auto& s : nodes["s"]) out.push_back(problem.rod.RestStrainAt(s.get<double>())(2));
  return out;
}
}  // namespace

std::string TensionLayerLine(const io::Problem& problem, const nlohmann::ordered_json& nodes) {
  if (!nodes.contains("s") || !nodes.contains("force_body") || !problem.rod.section) return "";
  const std::vector<double> s = nodes["s"].get<std::vector<double>>();
  const auto& force = nodes["force_body"];
  if (force.size() != s.size()) return "";
  double worst = 0.0, worst_s = 0.0, worst_tension = 0.0, worst_k = 0.0;  // k h, m, N, 1/m
  for (size_t i = 0; i + 1 < s.size(); ++i) {
    const double tension =
        std::max(force[i][2].get<double>(), force[i + 1][2].get<double>());  // body z: axial
    if (!(tension > 0.0)) continue;
    const double mid = 0.5 * (s[i] + s[i + 1]);
    const double ei =
        problem.rod.section->At(mid, problem.robot.actuation).min_bending_stiffness();
    const double k = std::sqrt(tension / ei), kh = k * (s[i + 1] - s[i]);
    if (kh > worst) worst = kh, worst_s = s[i], worst_tension = tension, worst_k = k;
  }
  const double z = worst;
  const double error = 1.0 - (1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24) / std::exp(z);
  if (!(error > 0.01)) return "";
  // A rod that carries no bending moment (a string hanging straight under its weight) has no
  // layer to resolve: below 1e-9 of T L the moments are round-off. Its modes still bend it.
  if (problem.analysis == io::Analysis::kStatics && nodes.contains("moment_body")) {
    double bending = 0.0;  // N·m
    for (const auto& m : nodes["moment_body"])
      bending = std::max(bending, std::hypot(m[0].get<double>(), m[1].get<double>()));
    if (bending < 1e-9 * worst_tension * problem.rod.length) return "";
  }
  std::ostringstream line;
  line << std::setprecision(3) << "cosserat: warning: the grid is coarse for the bending layer of "
       << "the tension: k h = sqrt(T/EI) h reaches " << worst << " (T = " << worst_tension
       << " N near s = " << worst_s << " m), where RK4 in s follows e^(k h) only to about "
       << 100 * error << " %, so the moments and reactions where the bending changes over 1/k = "
       << 1 / worst_k << " m (at clamps, supports and point loads) may be off by as much; "
       << "rod.nodes ≥ "
       << static_cast<long>(std::ceil(worst_k * problem.rod.length)) + 1
       << " keeps k h below 1\n";
  return line.str();
}

namespace {

/// The backbone's axial strain at each node of a "nodes" block with "force_body" (body z, the
/// section's whole force): (n₃ − ΣT)/EA, less the tensions T of the tendons that run past the
/// node, which the backbone carries in compression (their axial part; EA of the section there).
/// NaN where it is not known (a tendon robot under length control, whose tensions are solved
/// for); empty without those lists.
std::vector<double> AxialStrain(const io::Problem& problem, const nlohmann::ordered_json& nodes) {
  std::vector<double> strain;
  if (!problem.rod.section || !nodes.contains("force_body") || !nodes.contains("s")) return strain;
  const auto& s = nodes["s"];
  const auto& force = nodes["force_body"];
  if (force.size() != s.size()) return strain;
  const Actuation& a = problem.robot.actuation;
  for (size_t i = 0; i < s.size(); ++i) {
    const double si = s[i].get<double>();
    const double ea = problem.rod.section->At(si, a).stiffness(5, 5);
    double n3 = force[i][2].is_number() ? force[i][2].get<double>() : NAN;
    for (size_t k = 0; k < problem.rod.tendons.size(); ++k) {
      const double anchor = problem.rod.tendons[k].anchor;  // 0: the tip
      if (anchor == 0.0 || si < anchor)
        n3 -= problem.robot.tendon_lengths ? NAN : a.tendon_tension[k];
    }
    strain.push_back(ea > 0.0 ? n3 / ea : NAN);
  }
  return strain;
}

}  // namespace

void CheckGridResolution(const io::Problem& problem, Result* result) {
  // Statics, the equilibrium the modes are about, and the final state of dynamics (the
  // result's nodes).
  const bool equilibrium = problem.analysis != io::Analysis::kBuckling;
  // A statics stopped short writes the last load level reached: its grid may be why.
  const std::string status = result->json.value("status", "");
  const bool stopped_short =
      !result->converged && status == ToString(SolveStatus::kLoadSteppingFailed);
  // Modes the grid resolves too coarsely (run_modes.cpp) are about an equilibrium, which may
  // itself have run away.
  const bool coarse_modes =
      !result->converged && status == ToString(SolveStatus::kUnderResolved);
  // A solver that found its shot ran away (RodState::RanAway) said non_finite (modes:
  // statics_failed): say why.
  const bool diverged = !result->converged && (status == ToString(SolveStatus::kNonFinite) ||
                                               status == ToString(ModalStatus::kStaticsFailed));
  if ((!result->converged && !stopped_short && !coarse_modes && !diverged) || !equilibrium ||
      !result->json.contains("nodes"))
    return;
  const nlohmann::ordered_json& nodes = result->json["nodes"];
  if (!nodes.contains("s") || !nodes.contains("position") || !nodes.contains("curvature")) return;
  const bool polygon = problem.formulation == io::Formulation::kQuaternionFd;
  if (polygon && stopped_short) return;
  const std::vector<double> s = nodes["s"].get<std::vector<double>>();
  const std::vector<Vec3> position = detail::Vectors(nodes["position"]);
  const std::vector<Vec3> curvature = detail::Vectors(nodes["curvature"]);
  const GridResolution g =
      polygon ? CheckPolygon(s, position, curvature, problem.rod.length, RestTwist(problem, nodes))
              : CheckGrid(s, position, curvature, problem.rod.length, !stopped_short,
                          AxialStrain(problem, nodes));
  if (diverged) {
    if (g.ran_away) result->log += g.log;
    return;
  }
  result->log += g.log;
  if (!polygon && !stopped_short && !g.ran_away && !g.under_resolved &&
      problem.analysis != io::Analysis::kDynamics)
    result->log += TensionLayerLine(problem, nodes);
  if (stopped_short || (!g.ran_away && !g.under_resolved)) return;
  if (coarse_modes && !g.ran_away) return;  // under_resolved already
  result->converged = false;
  result->json["status"] =
      ToString(g.ran_away ? SolveStatus::kNonFinite : SolveStatus::kUnderResolved);
}

}  // namespace cosserat::run
