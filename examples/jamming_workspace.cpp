// Workspace of the layer-jamming robot (robots/jamming_virtual_joints.json): every jam pattern of
// its three segments (8) times 125 tendon tensions, 1 000 static solves on all cores. Writes the
// reachable tip points for a plot (scripts/plot_workspace.py).
//
//   build/examples/jamming_workspace [robots/jamming_virtual_joints.json] [notebooks-data]
// writes <dir>/jamming_workspace.csv (pattern,tension_N,x,y,z,status).
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cosserat/analysis/sweep.hpp"
#include "cosserat/io/problem.hpp"
#include "cosserat/run/solver_options.hpp"
#include "example_input.hpp"

int main(int argc, char** argv) {
  using namespace cosserat;
  const ExampleInput in = LoadExampleInput(argc, argv, "robots/jamming_virtual_joints.json");
  if (!in.problem) return 2;
  const io::Problem& p = *in.problem;
  const std::filesystem::path& dir = in.dir;
  const double jammed = 80000;  // Pa
  std::vector<Actuation> points;
  std::vector<int> pattern_of;
  for (int pattern = 0; pattern < 8; ++pattern)
    for (int k = 0; k < 125; ++k) {
      Actuation a = p.robot.actuation;
      for (int seg = 0; seg < 3; ++seg) a.jamming_pressure[seg] = (pattern >> seg & 1) ? jammed : 0;
      a.tendon_tension[0] = 2.0 * k / 124;  // N
      points.push_back(a);
      pattern_of.push_back(pattern);
    }
  const WorkspaceSweep w =
      SweepWorkspace(p.rod, p.nodes, run::StaticOptions(p), p.base, p.loads, points);
  std::filesystem::create_directories(dir);
  std::ofstream out(dir / "jamming_workspace.csv");
  out << "pattern,tension_N,x,y,z,status\n";
  for (size_t i = 0; i < points.size(); ++i) {
    std::string name;
    for (int seg = 0; seg < 3; ++seg) name += (pattern_of[i] >> seg & 1) ? 'J' : 'C';
    const Vec3& t = w.tip_position_W[i];
    out << name << ',' << points[i].tendon_tension[0] << ',' << t.x() << ',' << t.y() << ','
        << t.z() << ',' << ToString(w.status[i]) << '\n';
  }
  std::cout << w.converged() << " of " << points.size() << " points converged on " << w.threads
            << " threads in " << w.wall_time_s << " s; wrote " << (dir / "jamming_workspace.csv")
            << '\n';
  return w.converged() == static_cast<int>(points.size()) ? 0 : 1;
}
