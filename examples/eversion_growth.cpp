// Grows a vine (eversion) robot horizontally under gravity, quasi-statically, with and without
// constrictive bands, and writes the shapes and the tip trajectory as CSV.
//
//   ./eversion_growth [output_dir]        (default: notebooks-data)
//
// Files (per variant "plain" and "banded"):
//   eversion_<variant>_shapes.csv  step,length_m,s_m,x_m,y_m,z_m            every node, every step
//   eversion_<variant>_tip.csv     step,length_m,x_m,y_m,z_m,kink_ratio,kink_s_m,kink_status
//
// Parameters: typical values from the vine-robot literature, not one specific robot. Thin LDPE
// tube (Hawkes et al., Sci. Robotics 2017, use LDPE tubing a few cm across, walls ≈ 50–100 µm,
// growing at a few kPa): r = 25 mm, t = 75 µm, ρ = 920 kg/m³, ν = 0.45, p = 3 kPa. Effective
// wall modulus E_eff(p) = 100 MPa + 10⁴ p (LDPE film E ≈ 0.1–0.3 GPa; the pressure slope is
// illustrative, Suulker et al. 2026 fit such a law from tip-deflection tests). Bands: halve the
// diameter with α = 0.36 (Suulker et al. 2026), 20 mm wide every 0.3 m.
#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cosserat/robots/eversion_robot.hpp"

using namespace cosserat;

namespace {

bool MakeDir(const std::string& dir) { return ::mkdir(dir.c_str(), 0755) == 0 || errno == EEXIST; }

EversionRobotDesign Design(bool bands) {
  EversionRobotDesign d;
  d.radius = 0.025;
  d.wall_thickness = 75e-6;
  d.wall_modulus = ModulusLaw::Affine(100e6, 1e4);
  d.poisson_ratio = 0.45;
  d.wall_density = 920.0;
  d.max_length = 1.6;
  d.base.R.col(0) = Vec3::UnitZ();  // grows along world +x, gravity along −z
  d.base.R.col(1) = -Vec3::UnitY();
  d.base.R.col(2) = Vec3::UnitX();
  if (bands)
    for (double s = 0.3; s < 1.6; s += 0.3) d.bands.push_back({s, s + 0.02, 0.5, 0.36});
  return d;
}

int Run(const std::string& dir, const std::string& variant, bool bands) {
  const double pressure = 3e3, L0 = 0.1, L1 = 1.5;
  const int steps = 70;  // 2 cm per step
  EversionRobot robot(Design(bands), L0, pressure);
  std::ofstream shapes(dir + "/eversion_" + variant + "_shapes.csv");
  std::ofstream tip(dir + "/eversion_" + variant + "_tip.csv");
  if (!shapes || !tip) {
    std::cerr << "cannot write into " << dir << "\n";
    return 1;
  }
  shapes << "step,length_m,s_m,x_m,y_m,z_m\n";
  tip << "step,length_m,x_m,y_m,z_m,kink_ratio,kink_s_m,kink_status\n";
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  const GrowthSummary g = robot.Grow(
      L1, steps, loads, [&](int k, const EversionSolveSummary& sum, const EversionRobot& r) {
        const RodState& st = r.state();
        for (int i = 0; i < st.size(); ++i) {
          const Vec3& x = st.position_W[i];
          shapes << k << ',' << sum.length << ',' << st.s[i] << ',' << x.x() << ',' << x.y() << ','
                 << x.z() << '\n';
        }
        const Vec3& x = st.tip_position_W();
        tip << k << ',' << sum.length << ',' << x.x() << ',' << x.y() << ',' << x.z() << ','
            << sum.kink.max_ratio << ',' << sum.kink.s_max << ',' << ToString(sum.kink.status)
            << '\n';
      });
  std::printf("%-6s: %s after %d steps, L = %.3f m, tip sag %.1f mm, tip force %.2f N\n",
              variant.c_str(), ToString(g.status), g.steps, g.length,
              -1e3 * robot.state().tip_position_W().z(), robot.TipForce());
  if (g.first_kink_step > 0)
    std::printf("        first kink at L = %.3f m (step %d); worst |m|/M_w = %.2f at s = %.3f m\n",
                g.first_kink_length, g.first_kink_step, g.worst_kink.max_ratio, g.worst_kink.s_max);
  else
    std::printf("        no kink: largest |m|/M_w = %.2f\n", g.worst_kink.max_ratio);
  return g.converged() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "notebooks-data";
  if (!MakeDir(dir)) {
    std::cerr << "cannot create " << dir << "\n";
    return 1;
  }
  int rc = Run(dir, "plain", false);
  rc |= Run(dir, "banded", true);
  return rc;
}
