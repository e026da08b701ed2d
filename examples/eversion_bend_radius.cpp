// Minimum bend radius of the vine robot of robots/eversion_banded_vine.json, with its bands and
// without them: a steering moment about the vertical grows until the tube kinks (the bending
// moment reaches π p r³/2 somewhere) or reaches its range, under gravity, at 0.6 m everted (at
// the full 1.2 m the body already kinks under its own weight: see eversion_growth).
//
//   build/examples/eversion_bend_radius [robots/eversion_banded_vine.json] [notebooks-data]
// prints both radii and writes <dir>/eversion_bend_radius.csv. Then the same tube with its
// proximal 2/3 layer-jammed against the plain tube, at the same turn of the tip.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cosserat/analysis/bend_radius.hpp"
#include "cosserat/io/problem.hpp"
#include "example_input.hpp"

int main(int argc, char** argv) {
  using namespace cosserat;
  const ExampleInput in = LoadExampleInput(argc, argv, "robots/eversion_banded_vine.json");
  if (!in.problem) return 2;
  const io::Problem& p = *in.problem;
  const std::filesystem::path& dir = in.dir;
  const auto* tube = dynamic_cast<const InflatedTubeSection*>(p.rod.section.get());
  if (!tube) {
    std::cerr << in.file << ": not an eversion robot (needs an \"inflated\" stiffness profile)\n";
    return 2;
  }
  const double pressure = p.robot.actuation.pressure;
  const double M_w = InflatedWrinklingMoment(pressure, tube->radius());
  StaticLoads steer;  // up to twice the plain tube's wrinkling moment, about world z
  steer.tip_moment = Vec3(0, 0, 2 * M_w);

  std::filesystem::create_directories(dir);
  std::ofstream csv(dir / "eversion_bend_radius.csv");
  csv << "variant,min_radius_m,s_m,load_factor,limit\n";
  for (bool bands : {false, true}) {
    EversionRobotDesign design = DesignFromTube(*tube, p.rod.length, p.base);
    if (!bands) design.bands.clear();
    EversionRobot robot(design, std::min(0.6, p.rod.length), pressure);
    robot.SetTailTension(p.robot.tail_tension);  // the file's, if it gives one
    const BendRadiusResult r = MinimumBendRadius(robot, p.loads, steer);
    const char* name = bands ? "with bands" : "without bands";
    std::cout << name << ": minimum bend radius " << r.min_radius << " m at s = " << r.s
              << " m (limit: " << r.limit << ", load factor " << r.load_factor << ")\n";
    csv << (bands ? "bands" : "plain") << ',' << r.min_radius << ',' << r.s << ',' << r.load_factor
        << ',' << r.limit << '\n';
  }
  std::cout << "(kink onset: R = EI(s)/M_w(s); the experiments of Suulker et al. 2026, which bend"
               " past the onset by wrinkling, report 35 mm plain and 25 mm with bands)\n";

  // Layer jamming (Do et al. 2023): the same tube without bands, its proximal 2/3
  // (0–0.4 m) jammed to 4 times the tube's EI (E_ℓ I_ℓ = 3 E_eff(p) I). At a given moment the
  // compliant part bends exactly as much as before, so the kink-limited radius does not change;
  // what jamming changes is where a given turn of the tip is made. Compared at the same turn: the
  // plain tube's tip angle at a third of its kink moment (the jammed tube needs about twice the
  // moment for it, and stays below its kink).
  const double length = std::min(0.6, p.rod.length);
  EversionRobotDesign plain_design = DesignFromTube(*tube, p.rod.length, p.base);
  plain_design.bands.clear();
  EversionRobotDesign jam_design = plain_design;
  const double EI = tube->BendingStiffnessAt(0.0, p.robot.actuation);
  const double layer_I = 1e-10, jam_pressure = 5e4;  // m⁴, Pa: only their product matters here
  jam_design.jamming = {JammingSegment{0.0, 2.0 / 3.0 * length, layer_I,
                                       ModulusLaw::Affine(0.0, 3 * EI / layer_I / jam_pressure)}};
  EversionRobot plain(plain_design, length, pressure);
  EversionRobot jammed(jam_design, length, pressure);
  plain.SetTailTension(p.robot.tail_tension);
  jammed.SetTailTension(p.robot.tail_tension);
  jammed.SetJammingPressure(0, jam_pressure);
  StaticLoads third_kink = p.loads;
  third_kink.tip_moment = steer.tip_moment / 6.0;  // M_w / 3
  third_kink.tip_moment_frame = steer.tip_moment_frame;
  if (!plain.Solve(third_kink).solve.converged()) {
    std::cerr << "the plain tube did not converge at a third of its kink moment\n";
    return 1;
  }
  const RodState& st = plain.state();
  const double turn = std::acos(std::clamp(
      st.rotation_WB.front().col(2).dot(st.tip_rotation_WB().col(2)), -1.0, 1.0));
  StaticLoads unit = steer;
  unit.tip_moment *= 1.0 / 16;  // the pattern the turn is reached with (λ scales it)
  for (bool jam : {false, true}) {
    EversionRobot& robot = jam ? jammed : plain;
    const BendRadiusResult r = BendRadiusAtTipAngle(robot, p.loads, unit, turn);
    const char* name = jam ? "jammed 0-0.4 m" : "plain";
    std::cout << name << ", tip turned " << turn * 180 / 3.14159265358979 << " deg: minimum bend radius "
              << r.min_radius << " m at s = " << r.s << " m (moment / M_w: " << r.kink_ratio
              << ", " << r.limit << ")\n";
    csv << (jam ? "jammed_same_turn" : "plain_same_turn") << ',' << r.min_radius << ',' << r.s
        << ',' << r.load_factor << ',' << r.limit << '\n';
  }
  std::cout << "(pure moment, no gravity: the compliant radius would be (1 - f + f/alpha) = 0.5 of"
               " the plain one for f = 2/3, alpha = 4)\n";
  return 0;
}
