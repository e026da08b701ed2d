// Solves the pure-moment half circle through the installed library: the tip lands at 2L/π.
#include <cmath>
#include <cstdio>

#include "cosserat/strong/static_shooting.hpp"

int main() {
  using namespace cosserat;
  const double L = 1.0, pi = 3.14159265358979323846;
  const RodModel rod = RodModel::Uniform(L, CrossSection::Circle(0.005),
                                         Material::FromShearModulus(200e9, 80e9, 8000));
  StaticShootingSolver solver(rod, 41);
  StaticLoads loads;
  loads.tip_moment = Vec3(0, pi * rod.section->At(0, {}).stiffness(0, 0) / L, 0);
  if (!solver.Solve(lie::SE3{}, loads).converged()) return 1;
  const double d = solver.state().tip_position_W().norm();
  std::printf("tip distance %.9f, expected %.9f\n", d, 2 * L / pi);
  return std::abs(d - 2 * L / pi) < 1e-6 ? 0 : 1;
}
