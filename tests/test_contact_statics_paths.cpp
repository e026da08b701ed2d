// SE(3) statics on contact surfaces it used to leave through: a rod lying on a table or in a
// bore, against the closed form of the penalty law (contact.hpp: k φ = w per metre, φ = δ − ε/2
// once the penetration δ passes the smoothing ε), and the geometric truth that the centreline
// stays on the surface's free side. Quaternion-FD statics on a nearly rigid floor keep their
// clamp where it is held.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "cosserat/io/problem.hpp"
#include "cosserat/run/run.hpp"
#include "nlohmann/json.hpp"

namespace cosserat::run {
namespace {

Result RunText(const std::string& text) {
  const io::ParseResult parsed = io::ParseProblem(text);
  EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
  return Run(*parsed.problem);
}

std::string Number(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

/// Weight per metre of a steel rod (ρ = 8000) of radius r, N/m.
double Weight(double r) { return 8000 * M_PI * r * r * 9.81; }

std::string SteelRod(double length, int nodes, double r) {
  return R"("rod": {"length": )" + std::to_string(length) + R"(, "nodes": )" +
         std::to_string(nodes) + R"(, "section": {"shape": "circle", "radius": )" +
         std::to_string(r) + R"(}, "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9,
         "density": 8000}})";
}

// A 4.4 m rod (r = 5 mm) clamped level on the bottom of a bore (R = 2 cm, k = 1e4) at the depth
// where it lies: the straight rod, pressed in uniformly by δ = w/k + ε/2, is an equilibrium
// with no wrench at the clamp. The single shot ((k/4EI)^¼ L = 9.9) had "converged" to the rod
// folded back 2.3 m and 0.23 m out of the bore; shot in pieces it is the straight rod.
TEST(ContactStaticsPaths, ARodLyingInABoreIsTheStraightRod) {
  const double r = 0.005, k = 1e4, eps = 1e-5;
  const double depth = 0.02 - r + Weight(r) / k + eps / 2;  // the axis below the bore's, m
  const Result out = RunText(R"({"format": "cosserat-problem/1", )" + SteelRod(4.4, 101, r) +
                             R"(, "base": {"position": [0, 0, )" + Number(-depth) +
                             R"(], "rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
      "loads": {"gravity": [0, 0, -9.81]},
      "environment": {"contact": [{"shape": "cylinder", "point": [0, 0, 0], "axis": [1, 0, 0],
          "radius": 0.02, "side": "inside", "stiffness": 1e4, "smoothing": 1e-5}]}})");
  ASSERT_TRUE(out.converged) << out.log;
  // Exact but for round-off: 1e-9 m of the straight line, and no moment at the clamp beyond
  // what the solve tolerance leaves (an offset Δ there costs 2 EI β² Δ ≈ 1e3 Δ N·m).
  const auto& tip = out.json["tip"]["position"];
  EXPECT_NEAR(tip[0].get<double>(), 4.4, 1e-9);
  EXPECT_NEAR(tip[2].get<double>(), -depth, 1e-8);
  for (const auto& m : out.json["base_wrench"]["moment"]) EXPECT_NEAR(m.get<double>(), 0, 1e-6);
}

// examples/rod_on_table.json clamped touching the table (k = 2500, ε by default 1e-3 of the
// diameter): the tip lies on it at z = r − w/k − ε/2. The single shot failed at the first load
// step and wrote an iterate 0.89 m above the table.
TEST(ContactStaticsPaths, ARodClampedOnATableLiesOnIt) {
  const double r = 0.002, k = 2500, eps = 1e-3 * 2 * r;
  const Result out = RunText(R"({"format": "cosserat-problem/1", )" + SteelRod(2.5, 251, r) +
                             R"(, "base": {"position": [0, 0, 0.002],
          "rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
      "loads": {"gravity": [0, 0, -9.81]},
      "environment": {"contact": [{"shape": "plane", "point": [0, 0, 0], "normal": [0, 0, 1],
          "stiffness": 2500}]}})");
  ASSERT_TRUE(out.converged) << out.log;
  // The far end lies flat: the clamp's offset from lying (≈ 4e-4 m) dies out as e^{-βx} with
  // β = (k/4EI)^¼ = 4 1/m, to 5e-5 of it at the tip (2e-8 m, doubled by the free end's
  // reflection); 2e-7 m holds that, against the 0.89 m iterate of the failure.
  EXPECT_NEAR(out.json["tip"]["position"][2].get<double>(), r - Weight(r) / k - eps / 2, 2e-7);
  EXPECT_NE(out.log.find("shot in 2 pieces"), std::string::npos) << out.log;
}

// A pinned column (4.4 m, r = 5 mm) in the same bore, its ends 2 mm above the bottom, pressed by
// 60 N: well below the critical loads of a column on that support (2√(EI k) = 1981 N), so it
// lies on the bottom. The continuation had jumped the rod 0.32 m through the wall, converged,
// and warned it was past the free column's Euler load (50 N), which a supported column is not.
TEST(ContactStaticsPaths, APressedColumnStaysInTheBore) {
  const double r = 0.005, k = 1e4;
  const Result out = RunText(R"({"format": "cosserat-problem/1", )" + SteelRod(4.4, 201, r) +
                             R"(, "boundary": "pinned-pinned",
      "base": {"position": [0, 0, -0.0136214], "rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
      "loads": {"gravity": [0, 0, -9.81], "tip_force": [-60, 0, 0]},
      "environment": {"contact": [{"shape": "cylinder", "point": [0, 0, 0], "axis": [1, 0, 0],
          "radius": 0.02, "side": "inside", "stiffness": 1e4, "smoothing": 1e-5}]}})");
  ASSERT_TRUE(out.converged) << out.log;
  // Within the bore, less the rod's radius, by at most twice the weight's penetration w/k (the
  // compression amplifies the sag into the wall by 1/(1 − 60/1981), and the lifted ends bend it).
  double farthest = 0;
  for (const auto& p : out.json["nodes"]["position"])
    farthest = std::max(farthest, std::hypot(p[1].get<double>(), p[2].get<double>()));
  EXPECT_LT(farthest, 0.02 - r + 2 * Weight(r) / k);
  EXPECT_EQ(out.log.find("Euler load"), std::string::npos) << out.log;
}

// examples/finger_on_sphere.json: a finger pressed on a frictionless sphere slips off sideways,
// one unstable direction (the SE(3) statics' index, and a negative ω² in the modes). No node
// is compressed, and the quaternion-FD statics had called it stable (index 0) on that ground.
// On a contact surface the statics do not settle beside it (run/settle_beside_instability.hpp):
// the equilibrium stays, with its warning, which names sliding off the surface first.
TEST(ContactStaticsPaths, AFingerOnASphereIsUnstableInBothFormulations) {
  const io::ParseResult parsed = io::LoadProblemFile(std::string(COSSERAT_SOURCE_DIR) +
                                                     "/examples/finger_on_sphere.json");
  ASSERT_TRUE(parsed.ok());
  for (const auto formulation : {io::Formulation::kQuaternionFd, io::Formulation::kSe3Shooting}) {
    io::Problem problem = *parsed.problem;
    problem.formulation = formulation;
    const Result out = cosserat::run::Run(problem);
    ASSERT_TRUE(out.converged) << out.log;
    EXPECT_EQ(out.json["stability_index"].get<int>(), 1) << out.log;
    EXPECT_NE(out.log.find("the rod can slide off them"), std::string::npos) << out.log;
  }
  // An SE(3) run from it: on the frictionless sphere the start is unstable, and the log says so;
  // with friction, which may hold the finger, the frictionless count does not judge it.
  for (const double friction : {0.0, 0.5}) {
    io::Problem problem = *parsed.problem;
    problem.analysis = io::Analysis::kDynamics;
    problem.formulation = io::Formulation::kSe3Shooting;
    problem.dynamics.dt = problem.dynamics.duration = 1e-3;
    problem.loads.contact.surface[0].friction = friction;
    const Result out = cosserat::run::Run(problem);
    ASSERT_TRUE(out.converged) << out.log;
    EXPECT_EQ(out.log.find("starts from an unstable equilibrium (1 unstable direction)") !=
                  std::string::npos,
              friction == 0.0)
        << friction << ": " << out.log;
  }
}

// A soft rod (E = 9 MPa, r = 5 mm, 1 m) clamped level 0.155 m above a floor sags onto it. At
// k = 1e20 N/m² the floor's rows in the Newton matrix are 1e20 times the clamp's unit rows, and
// the elimination had let round-off move the clamped node 88 mm, "converged". The clamp is a
// boundary condition, so it holds exactly; the weight is carried by the clamp and the floor;
// and the clamp's force is the rigid floor's: the same rod at k = 1e8, whose penetration w/k
// (8e-9 m) is 5e-8 of the clearance, gives it. Tolerance 1e-4: the two differ by 3e-6 (the
// penetration and the smoothing's share), against the 17 % the moved clamp had added.
TEST(ContactStaticsPaths, AQuaternionFdClampHoldsOnANearlyRigidFloor) {
  const auto sag = [](const std::string& stiffness) {
    return RunText(R"({"format": "cosserat-problem/1", "formulation": "quaternion-fd",
        "rod": {"length": 1, "nodes": 201, "section": {"shape": "circle", "radius": 0.005},
                "material": {"youngs_modulus": 9e6, "poisson_ratio": 0.5, "density": 1000}},
        "base": {"position": [0, 0, 0.155], "rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
        "loads": {"gravity": [0, 0, -9.81]},
        "environment": {"contact": [{"shape": "plane", "point": [0, 0, 0], "normal": [0, 0, 1],
            "stiffness": )" + stiffness + "}]}}");
  };
  const Result rigid = sag("1e20"), firm = sag("1e8");
  ASSERT_TRUE(rigid.converged) << rigid.log;
  ASSERT_TRUE(firm.converged) << firm.log;
  const auto& clamp = rigid.json["nodes"]["position"][0];
  EXPECT_EQ(clamp[0].get<double>(), 0.0);
  EXPECT_EQ(clamp[1].get<double>(), 0.0);
  EXPECT_EQ(clamp[2].get<double>(), 0.155);
  const double weight = 1000 * M_PI * 0.005 * 0.005 * 9.81;  // N, over the 1 m rod
  const double base = rigid.json["base_wrench"]["force"][2].get<double>();
  // The balance holds to the solve's residual (1e-7 of the force scale) and the trapezoid sum
  // of the contact force: 3e-7 of the weight; 1e-5 is well clear of that, and of no use to a
  // clamp that moves.
  EXPECT_NEAR(base + rigid.json["contact"]["total_force"][2].get<double>(), weight,
              1e-5 * weight);
  EXPECT_NEAR(base, firm.json["base_wrench"]["force"][2].get<double>(), 1e-4 * base);
}

}  // namespace
}  // namespace cosserat::run
