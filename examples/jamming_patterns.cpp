// Layer-jamming robot (robots/jamming_virtual_joints.json): one tendon, three jamming segments.
// Each jam pattern makes a different "virtual joint": the compliant segments bend, the jammed
// ones stay nearly straight. Writes the shapes and the curvature per segment for a notebook.
//
//   build/examples/jamming_patterns [robots/jamming_virtual_joints.json] [notebooks-data]
// writes <dir>/jamming_patterns.csv (pattern,node,s,x,y,z,curvature).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "cosserat/io/problem.hpp"
#include "cosserat/run/solver_options.hpp"
#include "example_input.hpp"
#include "cosserat/strong/static_shooting.hpp"

int main(int argc, char** argv) {
  using namespace cosserat;
  const ExampleInput in = LoadExampleInput(argc, argv, "robots/jamming_virtual_joints.json");
  if (!in.problem) return 2;
  const io::Problem& p = *in.problem;
  const std::filesystem::path& dir = in.dir;
  const double jammed = 80000;  // Pa, ΔP of a jammed segment
  const char* names[] = {"J-C-J", "C-J-J", "J-J-C", "C-C-C"};
  const double patterns[4][3] = {
      {jammed, 0, jammed}, {0, jammed, jammed}, {jammed, jammed, 0}, {0, 0, 0}};
  std::filesystem::create_directories(dir);
  std::ofstream out(dir / "jamming_patterns.csv");
  out << "pattern,node,s,x,y,z,curvature\n";
  StaticShootingSolver solver(p.rod, p.nodes, run::StaticOptions(p), p.robot.actuation);
  for (int k = 0; k < 4; ++k) {
    Actuation a = p.robot.actuation;
    for (int seg = 0; seg < 3; ++seg) a.jamming_pressure[seg] = patterns[k][seg];
    solver.SetActuation(a);
    if (!solver.Solve(p.base, p.loads).converged()) return 1;
    const RodState& st = solver.state();
    double mean[3] = {0, 0, 0};
    int count[3] = {0, 0, 0};
    for (int i = 0; i < st.size(); ++i) {
      const double kappa = st.strain[i].head<2>().norm();
      out << names[k] << ',' << i << ',' << st.s[i] << ',' << st.position_W[i].x() << ','
          << st.position_W[i].y() << ',' << st.position_W[i].z() << ',' << kappa << '\n';
      const int seg = std::min(2, static_cast<int>(3 * st.s[i] / p.rod.length));
      mean[seg] += kappa;
      ++count[seg];
    }
    std::cout << names[k] << " (J = jammed, C = compliant): mean curvature per segment";
    for (int seg = 0; seg < 3; ++seg) std::cout << ' ' << mean[seg] / count[seg];
    std::cout << " 1/m, tip at [" << st.tip_position_W().x() << ", " << st.tip_position_W().z()
              << "] m\n";
  }
  std::cout << "wrote " << (dir / "jamming_patterns.csv") << '\n';
  return 0;
}
