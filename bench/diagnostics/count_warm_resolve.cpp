// Instruction count of a warm static re-solve (1 % load change, N = 41), for callgrind, which
// counts instructions and so gives the same figure whatever else the machine is doing:
//   valgrind --tool=callgrind build/bench/diagnostics/count_warm_resolve 100
//   valgrind --tool=callgrind build/bench/diagnostics/count_warm_resolve 1100
// (difference of the two totals) / 1000 = instructions per re-solve.
#include <cstdio>
#include <cstdlib>

#include "cosserat/strong/static_shooting.hpp"
using namespace cosserat;
int main(int argc, char** argv) {
  int n = atoi(argv[1]);
  StaticShootingSolver solver(RodModel::Uniform(0.5, CrossSection::Circle(0.001),
                                                Material::FromShearModulus(200e9, 80e9, 8000)),
                              41);
  StaticLoads a, b;
  a.tip_force = Vec3(-0.5, 0, 0);
  b.tip_force = Vec3(-0.505, 0, 0);
  solver.Solve(lie::SE3{}, a);
  double acc = 0;
  for (int i = 0; i < n; ++i) {
    acc += solver.Solve(lie::SE3{}, (i % 2) ? a : b).residual;
  }
  printf("%g\n", acc);
}
