#include "cosserat/run/grid_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "cosserat/state/solve_status.hpp"

namespace cosserat::run {

GridResolution CheckGrid(const std::vector<double>& s, const std::vector<Vec3>& position,
                         const std::vector<Vec3>& curvature, double length) {
  GridResolution out;
  double worst = 0.0, worst_s = 0.0, worst_k = 0.0;  // bending κ h (rad), where, κ (1/m)
  auto bending = [](const Vec3& k) { return std::hypot(k.x(), k.y()); };
  for (size_t i = 0; i + 1 < s.size(); ++i) {
    const double h = s[i + 1] - s[i];
    const double bend = std::max(bending(curvature[i]), bending(curvature[i + 1]));
    if (bend * h > worst) worst = bend * h, worst_s = s[i], worst_k = bend;
    const double turn = std::max(curvature[i].norm(), curvature[i + 1].norm()) * h;
    const double segment = (position[i + 1] - position[i]).norm();
    if (segment <= 10.0 * h || turn <= 1.0) continue;
    std::ostringstream log;
    log << std::setprecision(3) << "cosserat: the solve converged, but its shot ran away: the "
        << "segment at s = " << s[i] << " m spans " << segment << " m for " << h
        << " m of rod, while the curvature turns the section by " << turn
        << " rad on it, which RK4 in s cannot follow: status non_finite; check the loads' and "
           "the actuation's units, or give rod.nodes ≥ "
        << static_cast<long>(std::ceil(4.0 * turn / h * length)) + 1 << '\n';
    out.ran_away = true;
    out.log = log.str();
    return out;
  }
  if (worst <= 0.5) return out;
  out.under_resolved = worst > 1.5;
  std::ostringstream log;
  log << std::setprecision(3)
      << (out.under_resolved ? "cosserat: the grid is too coarse for this shape (status "
                               "under_resolved): "
                             : "cosserat: warning: the grid resolves the shape coarsely: ")
      << "the bending turns the section by " << worst << " rad per segment near s = " << worst_s
      << " m, where a constant-curvature arc's tip is off by about "
      << 100 * 8e-3 * std::pow(worst, 4) << " % of the length (RK4 in s, fourth order in κ h); "
      << "rod.nodes ≥ " << static_cast<long>(std::ceil(4.0 * worst_k * length)) + 1
      << " keeps it below 0.25 rad\n";
  out.log = log.str();
  return out;
}

void CheckGridResolution(const io::Problem& problem, Result* result) {
  // Statics, and the equilibrium the modes are about (the result's nodes).
  const bool equilibrium =
      problem.analysis == io::Analysis::kStatics || problem.analysis == io::Analysis::kModes;
  if (!result->converged || problem.formulation != io::Formulation::kSe3Shooting ||
      !equilibrium || !result->json.contains("nodes"))
    return;
  const nlohmann::ordered_json& nodes = result->json["nodes"];
  if (!nodes.contains("s") || !nodes.contains("position") || !nodes.contains("curvature")) return;
  auto rows = [](const nlohmann::ordered_json& a) {
    std::vector<Vec3> out;
    for (const auto& r : a)
      out.emplace_back(r[0].get<double>(), r[1].get<double>(), r[2].get<double>());
    return out;
  };
  const GridResolution g = CheckGrid(nodes["s"].get<std::vector<double>>(),
                                     rows(nodes["position"]), rows(nodes["curvature"]),
                                     problem.rod.length);
  result->log += g.log;
  if (!g.ran_away && !g.under_resolved) return;
  result->converged = false;
  result->json["status"] =
      ToString(g.ran_away ? SolveStatus::kNonFinite : SolveStatus::kUnderResolved);
}

}  // namespace cosserat::run
