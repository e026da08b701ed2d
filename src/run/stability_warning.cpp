#include "stability_warning.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace cosserat::run::detail {

namespace {
/// RK4's stability limit on y' = −k y, the largest k h at which its Jacobi fields are trusted.
constexpr double kMaxJacobiKh = 2.8;

/// The bowed clamped–pinned column under a dead axial load, its pin sliding on the axis: the
/// planar elastica's load rises from the Euler load to this peak, where its tip has turned 111°
/// and slid 0.454 L towards the clamp, then falls (shot from the clamp, Newton on the load and
/// the pin's lateral force). Past it no bowed equilibrium near the axis holds the load.
constexpr double kClampedPinnedPeak = 1.1396;  // of 2.0457 π² EI/L²

/// The buckled elastica of a pinned-pinned column, or of a clamped-clamped one (four of its
/// quarter-waves), pressed by `ratio` times its Euler load: P = (2K(k)/π)² P_E with
/// k = sin(θ₀/2); its mid-span deflection k L / K(k) and its chord (2E(k)/K(k) − 1) L
/// (Timoshenko & Gere 1961); 0.9 sqrt(ratio − 1) and 1 to first order. k by bisection on K(k),
/// which rises from π/2 at k = 0, with K and E from the arithmetic–geometric mean:
/// K = π / (2 a_∞), E = K (1 − Σ 2^(n−1) c_n²), c₀ = k, c_{n+1} = (a_n − b_n)/2.
struct Elastica {
  double mid_span = 0.0;  ///< L
  double chord = 1.0;     ///< L
};

Elastica ElasticaAt(double ratio) {
  const double pi = std::acos(-1.0), K = 0.5 * pi * std::sqrt(ratio);
  auto integrals = [pi](double k, double* E) {
    double a = 1.0, b = std::sqrt(1.0 - k * k), c = k, weight = 0.5, sum = weight * c * c;
    for (int i = 0; i < 40 && a - b > 1e-15 * a; ++i) {
      c = 0.5 * (a - b);
      const double mean = 0.5 * (a + b);
      b = std::sqrt(a * b);
      a = mean;
      weight *= 2.0;
      sum += weight * c * c;
    }
    const double complete_k = pi / (2.0 * a);
    if (E) *E = complete_k * (1.0 - sum);
    return complete_k;
  };
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (integrals(mid, nullptr) < K ? lo : hi) = mid;
  }
  double E = 0.0;
  const double k_of_lo = integrals(lo, &E);
  return {lo / K, 2.0 * E / k_of_lo - 1.0};
}
}  // namespace

std::string UnstableWarning(const StaticShootingSummary& s, bool searched_stable,
                            bool on_surfaces) {
  if (!s.converged() || s.stability_index <= 0) return "";
  const std::string head = "cosserat: warning: this equilibrium is unstable (" +
                           std::to_string(s.stability_index) + " unstable direction" +
                           (s.stability_index > 1 ? "s" : "") + "): ";
  if (on_surfaces)  // statics has no friction: what holds the rod sideways is the shape alone
    return head +
           "on the frictionless contact surfaces of statics the rod can slide off them (a "
           "finger pressed on a sphere slips sideways), or the loads are past a critical "
           "point; dynamics with \"friction\" on the surfaces holds it, and \"analysis\": "
           "\"buckling\" finds a critical load\n";
  return head + "the loads or the actuation are past a critical point" +
         (searched_stable ? ", and no stable equilibrium was reached from the unloaded rod" : "") +
         "; \"analysis\": \"buckling\" finds the critical load\n";
}

std::string ColumnPastEulerWarning(ColumnEnds ends, const RodModel& rod, const RodState& state,
                                   int bow_index) {
  const double factor = ends == ColumnEnds::kClampedFree ? 0.0 : EulerLoadCoefficient(ends);
  const int n = state.size();
  if (factor == 0.0 || n < 2 || !rod.section) return "";
  const double L = rod.length;
  const double EI = rod.section->At(0.5 * L, Actuation{}).min_bending_stiffness();
  const double euler = factor * EI / (L * L);
  // The least compression along the column: past the Euler load everywhere, it is more pressed
  // than the uniformly pressed column at that load (Sturm's comparison), and a heavy column
  // pressed past P_E only near its foot is not flagged (its own critical load is higher).
  double compression = std::numeric_limits<double>::infinity(), off_chord = 0.0;
  const Vec3 a = state.position_W.front(), chord = (state.position_W.back() - a).normalized();
  for (int i = 0; i < n; ++i) {
    compression = std::min(compression, -state.wrench_B[i](5));  // n_B along the tangent
    const Vec3 d = state.position_W[i] - a;
    off_chord = std::max(off_chord, (d - d.dot(chord) * chord).norm());
  }
  if (!(compression > 1.01 * euler) || off_chord > 0.05 * L) return "";
  std::ostringstream text;
  text << std::setprecision(3) << "cosserat: warning: the column is compressed by "
       << compression << " N, " << compression / euler << " times the Euler load of its ends ("
       << euler << " N), yet stands nearly straight (" << off_chord / L
       << " L off its chord): this equilibrium is unstable";
  const Elastica bow = ElasticaAt(compression / euler);
  if (ends == ColumnEnds::kPinnedPinned && bow.chord < 0.0) {
    // Past about 2.18 P_E the pins of the planar elastica have passed each other, and its
    // count (ColumnSolver::StabilityIndexFromShot) finds it unstable too, out of its plane.
    text << ", and so is the planar bow, whose ends would have passed each other ("
         << -bow.chord << " L)";
  } else if (ends == ColumnEnds::kClampedPinned && compression > kClampedPinnedPeak * euler) {
    text << ", and no bowed one holds it: a bowed clamped-pinned column carries at most "
         << kClampedPinnedPeak
         << " times its Euler load (its tip turned 111°, slid 0.45 L), and past it collapses";
  } else if (bow_index > 0) {
    text << ", and so is the bow beside it (" << bow_index << " unstable direction"
         << (bow_index > 1 ? "s" : "")
         << ", counted under a side load of 2 % of the loads): no stable equilibrium was found "
            "near its axis";
  } else {
    text << ", the stable one bows out";
    if (ends == ColumnEnds::kPinnedPinned || ends == ColumnEnds::kClampedClamped)
      text << " by about " << bow.mid_span << " L";
  }
  text << " (\"analysis\": \"buckling\" finds the critical load)\n";
  return text.str();
}

std::string AnchoredCompressionNote(const RodModel& rod, const RodState& state) {
  return UnjudgedCompressionNote(rod, state,
                                 "which may buckle it between its anchors; statics does not judge "
                                 "that, \"analysis\": \"modes\" does (a negative ω² is an "
                                 "unstable mode)");
}

std::string UnjudgedCompressionNote(const RodModel& rod, const RodState& state,
                                    const std::string& why) {
  if (state.size() < 2 || !rod.section) return "";
  const double L = rod.length;
  const double EI = rod.section->At(0.5 * L, Actuation{}).min_bending_stiffness();
  double compression = 0.0, least = INFINITY, s_max = 0.0;  // N, the largest, the least; m
  for (int i = 0; i < state.size(); ++i) {
    least = std::min(least, -state.wrench_B[i](5));
    if (-state.wrench_B[i](5) > compression) {
      compression = -state.wrench_B[i](5);
      s_max = state.s[i];
    }
  }
  if (!(compression > M_PI * M_PI * EI / (L * L))) return "";
  std::ostringstream text;
  text << std::setprecision(3) << "cosserat: note: the rod is compressed by up to "
       << compression << " N (";
  if (least >= 0.99 * compression)  // uniform: no place to name
    text << "along the whole rod";
  else
    text << "at s = " << s_max << " m";
  text << "), " << why << '\n';
  return text.str();
}

int JudgedStabilityIndex(const io::Problem& problem, const RodState& state, int index,
                         std::string* note) {
  if (index < 0 || state.size() < 2 || !problem.rod.section) return index;
  double worst = 0.0, worst_s = 0.0, worst_k = 0.0;  // k h, where (m), k (1/m)
  for (int i = 0; i + 1 < state.size(); ++i) {
    const double force =
        std::max(std::abs(state.wrench_B[i](5)), std::abs(state.wrench_B[i + 1](5)));  // N
    const double ei =
        problem.rod.section->At(state.s[i], problem.robot.actuation).min_bending_stiffness();
    const double k = ei > 0 ? std::sqrt(force / ei) : 0.0;  // 1/m
    const double kh = k * (state.s[i + 1] - state.s[i]);
    if (kh > worst) worst = kh, worst_s = state.s[i], worst_k = k;
  }
  if (!(worst > kMaxJacobiKh)) return index;
  // Tension everywhere, no surface to rest on, no moment at the tip, no tendon: no direction
  // lowers the energy (the quaternion-FD count's rule too), whatever the grid.
  const bool tension = std::all_of(state.wrench_B.begin(), state.wrench_B.end(),
                                   [](const Vec6& w) { return w(5) >= 0; });
  if (tension && problem.loads.contact.count == 0 && problem.loads.tip_moment.isZero(0.0) &&
      !problem.has_robot && problem.rod.tendons.empty())
    return 0;
  std::ostringstream o;
  o << std::setprecision(3) << "cosserat: note: the stability of this equilibrium is not judged: "
    << "at s = " << worst_s << " m the axial force makes the bending length sqrt(EI/|N|) = "
    << 1.0 / worst_k << " m, and the grid's spacing is " << worst / worst_k
    << " m (k h = " << std::setprecision(4) << worst
    << "), too coarse for the fields that count unstable directions (k h <= " << kMaxJacobiKh
    << "); rod.nodes >= "
    << static_cast<long>(std::ceil(problem.rod.length * worst_k / kMaxJacobiKh)) + 1
    << " judges it\n";
  *note = o.str();
  return -1;
}

}  // namespace cosserat::run::detail
