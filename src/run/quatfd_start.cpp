#include "quatfd_start.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "cosserat/rod/grid.hpp"
#include "cosserat/run/run_quatfd.hpp"

namespace cosserat::run::detail {

std::optional<RodState> QuatFdEquilibriumOnGrid(const io::Problem& problem,
                                                const lie::SE3& base, const StaticLoads& loads,
                                                const Actuation& actuation) {
  io::Problem on_fd = problem;
  on_fd.formulation = io::Formulation::kQuaternionFd;
  on_fd.analysis = io::Analysis::kStatics;
  on_fd.boundary = io::Boundary::kCantilever;
  on_fd.base = base;
  on_fd.loads = loads;
  on_fd.robot.actuation = actuation;
  // At rest: a bit at zero spin grinds with no torque, and the dynamics' drives (a spinning
  // clamp, a body at the tip, whose weight `loads` carries) have no part in the statics.
  on_fd.loads.bit = BitFriction{};
  on_fd.dynamics = io::Problem::Dynamics{};
  on_fd.has_dynamics = false;
  on_fd.gust = FluidGust{};
  if (!io::UnsupportedFeatures(on_fd).empty()) return std::nullopt;
  RodState state;
  try {
    quatfd::QuatFdModel model = MakeQuatFdModel(on_fd);
    if (!SolveQuatFdEquilibrium(on_fd, &model, &state, nullptr).converged()) return std::nullopt;
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // a rod the quaternion-FD model does not take
  }
  const std::vector<double> grid = ModelGrid(problem.rod, problem.nodes);
  if (static_cast<int>(grid.size()) != state.size()) return std::nullopt;
  for (int i = 0; i < state.size(); ++i)
    if (std::abs(state.s[i] - grid[i]) > 1e-12 * problem.rod.length) return std::nullopt;
  return state;
}

}  // namespace cosserat::run::detail
