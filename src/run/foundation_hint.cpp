#include "foundation_hint.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace cosserat::run::detail {

namespace {
/// The first contact surface whose foundation length ℓ (m) the grid spacing h exceeds
/// `spacings_per_length` × ℓ: its index, or −1.
int CoarseFoundation(const io::Problem& problem, double spacings_per_length, double* h,
                     double* foundation) {
  const SectionProperties p = problem.rod.section->At(0.0, problem.robot.actuation);
  const double ei = p.max_bending_stiffness();  // N·m²
  *h = problem.rod.length / (problem.nodes - 1);
  for (int k = 0; k < problem.loads.contact.count; ++k) {
    const double stiffness = problem.loads.contact.surface[k].stiffness;
    if (!(stiffness > 0)) continue;
    *foundation = std::pow(4 * ei / stiffness, 0.25);
    if (*h > spacings_per_length * *foundation) return k;
  }
  return -1;
}

/// `advice`, "rod.nodes >= N" for a spacing of `spacings_per_length` foundation lengths, and
/// `more`; past the most nodes a problem may have (a stiffness of 1e25 N/m² asked for 9.8e6,
/// 1e300 overflowed), the stiffness to lower instead (the other formulation needs such a grid
/// too).
std::string NodesFor(const io::Problem& problem, int k, double spacings_per_length,
                     double foundation, const std::string& advice = "",
                     const std::string& more = "") {
  const double nodes = std::ceil(problem.rod.length / (spacings_per_length * foundation)) + 1;
  std::ostringstream text;
  if (nodes <= io::kMaxRodNodes)
    text << advice << "rod.nodes >= " << static_cast<long>(nodes) << more;
  else
    text << "a lower environment.contact[" << k << "].stiffness (the grid it needs, "
         << std::setprecision(3) << nodes << " nodes, is over the " << io::kMaxRodNodes
         << " a problem may have)";
  return text.str();
}
}  // namespace

std::string FoundationHint(const io::Problem& problem, double spacings_per_length,
                           const std::string& why, const std::string& advice,
                           const std::string& more) {
  double h = 0.0, foundation = 0.0;
  const int k = CoarseFoundation(problem, spacings_per_length, &h, &foundation);
  if (k < 0) return "";
  std::ostringstream hint;
  hint << "cosserat: hint: the grid spacing " << std::setprecision(3) << h
       << " m is coarse for environment.contact[" << k
       << "]'s foundation length (4EI/k)^(1/4) = " << foundation << " m, " << why << ": try "
       << NodesFor(problem, k, spacings_per_length, foundation, advice, more)
       << "\n";
  return hint.str();
}

std::string FoundationGridWarning(const io::Problem& problem) {
  double h = 0.0, foundation = 0.0;
  const int k = CoarseFoundation(problem, 0.16, &h, &foundation);
  if (k < 0) return "";
  const double ratio = h / foundation;
  std::ostringstream warning;
  warning << "cosserat: warning: the grid spacing " << std::setprecision(3) << h
          << " m is coarse for environment.contact[" << k
          << "]'s foundation length (4EI/k)^(1/4) = " << foundation
          << " m: where the rod settles into the surface its penetration may be off by about "
          << 100 * 0.2 * ratio * ratio << " % and its slope by " << 100 * 0.42 * ratio * ratio
          << " % (quaternion FD, second order in h/ℓ); "
          << NodesFor(problem, k, 0.1, foundation) << " brings them below 0.5 %\n";
  return warning.str();
}

}  // namespace cosserat::run::detail
