#include "grid_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "cosserat/state/solve_status.hpp"

namespace cosserat::run::detail {
namespace {

/// Row i of an N × 3 array of the result's nodes as a vector.
Vec3 Row(const nlohmann::ordered_json& rows, size_t i) {
  return Vec3(rows[i][0].get<double>(), rows[i][1].get<double>(), rows[i][2].get<double>());
}

}  // namespace

void CheckGridResolution(const io::Problem& problem, Result* result) {
  if (!result->converged || problem.formulation != io::Formulation::kSe3Shooting ||
      problem.analysis != io::Analysis::kStatics || !result->json.contains("nodes"))
    return;
  const nlohmann::ordered_json& nodes = result->json["nodes"];
  if (!nodes.contains("s") || !nodes.contains("position") || !nodes.contains("curvature")) return;
  const nlohmann::ordered_json &s = nodes["s"], &p = nodes["position"], &k = nodes["curvature"];
  double worst = 0.0, worst_s = 0.0, worst_k = 0.0;  // κ h (rad), where, κ (1/m)
  for (size_t i = 0; i + 1 < s.size(); ++i) {
    const double h = s[i + 1].get<double>() - s[i].get<double>();
    const double kappa = std::max(Row(k, i).norm(), Row(k, i + 1).norm());
    if (kappa * h > worst) worst = kappa * h, worst_s = s[i].get<double>(), worst_k = kappa;
    const double segment = (Row(p, i + 1) - Row(p, i)).norm();
    if (segment <= 10.0 * h) continue;
    std::ostringstream log;
    log << std::setprecision(3) << "cosserat: the solve converged, but its shot ran away: the "
        << "segment at s = " << s[i].get<double>() << " m spans " << segment << " m for " << h
        << " m of rod (its curvature, " << kappa << " 1/m, turns the section by " << kappa * h
        << " rad per segment, which RK4 in s cannot follow): status non_finite; check the "
           "loads' and the actuation's units, or give rod.nodes ≥ "
        << static_cast<long>(std::ceil(4.0 * kappa * problem.rod.length)) + 1 << '\n';
    result->converged = false;
    result->json["status"] = ToString(SolveStatus::kNonFinite);
    result->log += log.str();
    return;
  }
  if (worst <= 0.5) return;
  std::ostringstream log;
  log << std::setprecision(3) << "cosserat: warning: the grid resolves the shape coarsely: "
      << "the curvature turns the section by " << worst << " rad per segment near s = "
      << worst_s << " m, where a constant-curvature arc's tip is off by about "
      << 100 * 8e-3 * std::pow(worst, 4) << " % of the length (RK4 in s, fourth order in κ h); "
      << "rod.nodes ≥ " << static_cast<long>(std::ceil(4.0 * worst_k * problem.rod.length)) + 1
      << " keeps it below 0.25 rad\n";
  result->log += log.str();
}

}  // namespace cosserat::run::detail
