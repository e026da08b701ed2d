// Tendon-driven robot (robots/tendon_three_tendon.json): sweeps the tension of the first tendon,
// writes the backbone shapes and the tip Jacobian in the tensions for a notebook.
//
//   build/examples/tendon_robot [robots/tendon_three_tendon.json] [notebooks-data]
// writes <dir>/tendon_shapes.csv (tension_N,node,s,x,y,z) and <dir>/tendon_jacobian.csv.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cosserat/io/problem.hpp"
#include "cosserat/run/solver_options.hpp"
#include "example_input.hpp"
#include "cosserat/strong/static_shooting.hpp"

int main(int argc, char** argv) {
  using namespace cosserat;
  const ExampleInput in = LoadExampleInput(argc, argv, "robots/tendon_three_tendon.json");
  if (!in.problem) return 2;
  const io::Problem& p = *in.problem;
  const std::filesystem::path& dir = in.dir;
  std::filesystem::create_directories(dir);
  std::ofstream shapes(dir / "tendon_shapes.csv"), jac(dir / "tendon_jacobian.csv");
  shapes << "tension_N,node,s,x,y,z\n";
  jac << "tension_N,tendon,dx_dtau,dy_dtau,dz_dtau,dthx_dtau,dthy_dtau,dthz_dtau\n";

  Actuation a = p.robot.actuation;
  StaticShootingSolver solver(p.rod, p.nodes, run::StaticOptions(p), a);
  for (int k = 0; k <= 10; ++k) {
    a.tendon_tension[0] = 0.3 * k;  // N: the sweep warm-starts each solve from the last
    solver.SetActuation(a);
    if (!solver.Solve(p.base, p.loads).converged()) {
      std::cerr << "did not converge at " << a.tendon_tension[0] << " N\n";
      return 1;
    }
    const RodState& st = solver.state();
    for (int i = 0; i < st.size(); ++i)
      shapes << a.tendon_tension[0] << ',' << i << ',' << st.s[i] << ',' << st.position_W[i].x()
             << ',' << st.position_W[i].y() << ',' << st.position_W[i].z() << '\n';
    StaticShootingSolver::TensionJacobian J;
    if (!solver.TipJacobianWrtTensions(p.base, p.loads, &J)) continue;  // no equilibrium here
    for (int t = 0; t < solver.tendon_count(); ++t) {
      jac << a.tendon_tension[0] << ',' << t;
      for (int r = 0; r < 6; ++r) jac << ',' << J(r, t);
      jac << '\n';
    }
    const Vec3 tip = st.tip_position_W();
    std::cout << "tension " << a.tendon_tension[0] << " N: tip at [" << tip.x() << ", " << tip.y()
              << ", " << tip.z() << "] m\n";
  }
  std::cout << "wrote " << (dir / "tendon_shapes.csv") << " and " << (dir / "tendon_jacobian.csv")
            << '\n';
  return 0;
}
