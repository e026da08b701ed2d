#include "foundation_hint.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace cosserat::run::detail {

std::string FoundationHint(const io::Problem& problem, double spacings_per_length,
                           const std::string& why, const std::string& advice,
                           const std::string& more) {
  const SectionProperties p = problem.rod.section->At(0.0, problem.robot.actuation);
  const double ei = p.max_bending_stiffness();  // N·m²
  const double h = problem.rod.length / (problem.nodes - 1);
  for (int k = 0; k < problem.loads.contact.count; ++k) {
    const double stiffness = problem.loads.contact.surface[k].stiffness;
    if (!(stiffness > 0)) continue;
    const double foundation = std::pow(4 * ei / stiffness, 0.25);  // m
    if (h <= spacings_per_length * foundation) continue;
    std::ostringstream hint;
    hint << "cosserat: hint: the grid spacing " << std::setprecision(3) << h
         << " m is coarse for environment.contact[" << k
         << "]'s foundation length (4EI/k)^(1/4) = " << foundation << " m, " << why << ": try "
         << advice << "rod.nodes >= "
         << static_cast<long>(std::ceil(problem.rod.length / (spacings_per_length * foundation))) +
                1
         << more << "\n";
    return hint.str();
  }
  return "";
}

}  // namespace cosserat::run::detail
