#include "run_problem.hpp"

#include "run_buckling.hpp"
#include "run_dynamics.hpp"
#include "run_eversion.hpp"
#include "run_modes.hpp"
#include "run_quatfd.hpp"
#include "run_statics.hpp"

namespace cosserat::cli {

bool RunProblem(const io::Problem& problem, std::ostream& out, std::ostream* csv,
                std::ostream& log) {
  const bool dynamics = problem.analysis == "dynamics";
  if (problem.analysis == "modes") return RunModes(problem, out, csv, log);
  if (problem.formulation == "quaternion-fd" && problem.analysis == "buckling")
    return RunQuatFdBuckling(problem, out, csv, log);
  if (problem.formulation == "quaternion-fd")
    return dynamics ? RunQuatFdDynamics(problem, out, csv, log)
                    : RunQuatFdStatics(problem, out, csv, log);
  if (problem.analysis == "buckling") return RunBuckling(problem, out, csv, log);
  if (problem.has_robot && problem.robot.kind == "eversion")
    return RunEversion(problem, out, csv, log);
  return dynamics ? RunDynamics(problem, out, csv, log) : RunStatics(problem, out, csv, log);
}

}  // namespace cosserat::cli
