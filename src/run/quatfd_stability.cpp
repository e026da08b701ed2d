#include "quatfd_stability.hpp"

#include <algorithm>

#include "cosserat/analysis/quatfd_buckling.hpp"
#include "cosserat/run/solver_options.hpp"

namespace cosserat::run::detail {

int QuatFdStabilityIndex(const io::Problem& problem, const Eigen::VectorXd& q,
                         const RodState& state) {
  const StaticLoads& loads = problem.loads;
  const bool conservative = loads.tip_force_frame == LoadFrame::kWorld &&
                            loads.tip_moment.isZero(0.0) && loads.fluid.velocity_W.isZero(0.0) &&
                            !problem.has_robot && problem.rod.tendons.empty() &&
                            problem.rod.chambers.empty();
  if (problem.boundary != io::Boundary::kCantilever || !conservative) return -1;
  const bool compressed = std::any_of(state.wrench_B.begin(), state.wrench_B.end(),
                                      [](const Vec6& w) { return w(5) < 0; });
  // Without compression a rod's own stiffness is positive; a convex surface it rests on (a
  // sphere, a post) can still make the equilibrium unstable.
  if (!compressed && loads.contact.count == 0) return 0;
  LoadPath path;
  path.fixed = loads;
  path.per_unit = loads.Scaled(0.0);  // its frames the fixed loads'
  QuatFdBuckling stiffness(problem.rod, problem.base, path, QuatFdModelOptions(problem));
  // Eigenvalues in units of EI/L; the stiffness is a difference quotient good to ~1e-6 of
  // that, so a root within 1e-6 of zero is marginal and not counted.
  return stiffness.StiffnessEigenvaluesBelow(0.0, q, 1e-6);
}

}  // namespace cosserat::run::detail
