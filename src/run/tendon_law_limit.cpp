#include "tendon_law_limit.hpp"

namespace cosserat::run::detail {

TendonLawLoad LargestTendonLawLoad(const io::Problem& problem, const Actuation& actuation) {
  TendonLawLoad out;
  if (problem.rod.tendons.empty()) return out;
  const SectionProperties p = problem.rod.section->At(0.0, actuation);
  const double ei = p.min_bending_stiffness();  // N·m²
  for (size_t i = 0; i < problem.rod.tendons.size(); ++i) {
    const double r = problem.rod.tendons[i].route.MaxOffset();  // m
    const double ratio = actuation.tendon_tension[i] * r * r / ei;
    if (ratio > out.ratio) out.ratio = ratio, out.name = problem.rod.tendons[i].name;
  }
  return out;
}

}  // namespace cosserat::run::detail
