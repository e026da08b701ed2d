#include "cosserat/run/run.hpp"

#include "bending_stress_report.hpp"
#include "contact_report.hpp"
#include "cosserat/run/run_assembly.hpp"
#include "cosserat/run/run_buckling.hpp"
#include "cosserat/run/run_dynamics.hpp"
#include "cosserat/run/run_eversion.hpp"
#include "cosserat/run/run_modes.hpp"
#include "cosserat/run/run_quatfd.hpp"
#include "cosserat/run/run_statics.hpp"

namespace cosserat::run {

namespace {

Result Dispatch(const io::Problem& problem, const RunOptions& options) {
  using io::Analysis;
  const bool dynamics = problem.analysis == Analysis::kDynamics;
  if (problem.has_assembly) return RunAssembly(problem, options);
  if (problem.analysis == Analysis::kModes) return RunModes(problem, options);
  if (problem.formulation == io::Formulation::kQuaternionFd) {
    if (problem.analysis == Analysis::kBuckling) return RunQuatFdBuckling(problem, options);
    return dynamics ? RunQuatFdDynamics(problem, options) : RunQuatFdStatics(problem, options);
  }
  if (problem.analysis == Analysis::kBuckling) return RunBuckling(problem, options);
  if (problem.has_robot && problem.robot.kind == io::RobotKind::kEversion)
    return RunEversion(problem, options);
  return dynamics ? RunDynamics(problem, options) : RunStatics(problem, options);
}

}  // namespace

Result Run(const io::Problem& problem, const RunOptions& options) {
  Result result = Dispatch(problem, options);
  detail::AddContactReport(problem, &result);
  detail::AddFrameContactForces(problem, &result);
  detail::AddBendingStressReport(problem, &result);
  return result;
}

}  // namespace cosserat::run
