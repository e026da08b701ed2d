#include "tendon_law_limit.hpp"

#include <iomanip>
#include <sstream>

#include "cosserat/run/run_statics.hpp"

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

namespace cosserat::run {

std::string TendonLawHint(const io::Problem& problem, const Actuation& actuation,
                          SolveStatus status) {
  if (status != SolveStatus::kNonFinite || problem.rod.tendons.empty()) return "";
  const detail::TendonLawLoad worst = detail::LargestTendonLawLoad(problem, actuation);
  // Far below the limit (the helical tendons of the three-tendon robot fail from 0.76) the law
  // is not the likely cause, and the hint would mislead.
  if (worst.ratio < 0.5) return "";
  std::ostringstream hint;
  hint << "cosserat: hint: the tendon strain law had no solution along the rod: tendon \""
       << worst.name << "\" pulls with tension x offset^2 / EI = " << std::setprecision(3)
       << worst.ratio
       << " (at 1 the inside of the bend, where a tendon runs, shrinks to zero length); lower "
          "the tensions or stiffen the backbone\n";
  return hint.str();
}

}  // namespace cosserat::run
