// The quaternion-FD statics and buckling search follow the loaded path of a cantilever column
// (steel, L = 0.5 m, r = 1 mm, P_cr = π²EI/4L² = 1.5503 N) onto its stable equilibrium, against
// the post-buckled elastica (Timoshenko & Gere 1961, §2.7); and inertia-only loads (added mass)
// leave its static stiffness alone.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cosserat/io/problem.hpp"
#include "cosserat/run/run.hpp"
#include "nlohmann/json.hpp"
#include "support/analytic/elastica.hpp"

namespace cosserat::run {
namespace {

const double kEI = 200e9 * M_PI * 1e-12 / 4;               // N·m²
const double kEulerLoad = M_PI * M_PI * kEI / (4 * 0.25);  // N, π²EI/4L²

/// The column with `extra` (JSON members) added to the problem, run as the tool runs it.
Result RunColumn(const std::string& extra) {
  const io::ParseResult parsed = io::ParseProblem(R"({
    "format": "cosserat-problem/1", "formulation": "quaternion-fd",
    "rod": {"length": 0.5, "nodes": 41, "section": {"shape": "circle", "radius": 0.001},
            "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
    )" + extra + "}");
  EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
  return Run(*parsed.problem);
}

/// The tip's deflection and height, over L, against the elastica at P/P_cr. Tolerance 2e-3:
/// the side force of 1e-3 P (an imperfection) moves the tip by about that fraction of its
/// deflection; the grid (h = L/40, O(h²)) and extension ((r/L)² = 4e-6) by far less.
void ExpectElastica(const Result& r, double ratio) {
  const truth::PostBuckledCantilever e = truth::PostBuckledCantileverAtLoad(ratio);
  const auto& tip = r.json["tip"]["position"];
  EXPECT_NEAR(std::hypot(tip[0].get<double>(), tip[1].get<double>()) / 0.5, e.deflection, 2e-3);
  EXPECT_NEAR(tip[2].get<double>() / 0.5, e.axial, 2e-3);
}

// Pressed to 2 P_cr with a side force of 1e-3 P: the direct Newton solve converged on the
// nearly straight shape bent against the side force (unstable: 2 directions) and said so with
// a warning only. The continuation from the unloaded rod reaches the stable elastica.
TEST(QuatFdLoadedPaths, StaticsPastTheEulerLoadReachesTheStableElastica) {
  const double P = 2 * kEulerLoad;
  const Result r = RunColumn(R"("loads": {"tip_force": [)" + std::to_string(1e-3 * P) +
                             ", 0, " + std::to_string(-P) + "]}");
  ASSERT_TRUE(r.converged) << r.log;
  EXPECT_EQ(r.json["stability_index"].get<int>(), 0) << r.log;
  EXPECT_EQ(r.log.find("unstable"), std::string::npos) << r.log;
  ExpectElastica(r, 2.0);
}

// A search for the critical tip force on top of a side force of 6e-4 N (4e-4 P_cr): the path
// bends smoothly and stays stable, so there is no critical load. The scan had jumped to the
// unstable near-straight branch past P_cr and called a grid point "found" (1.75, 2.25, 2.5 N
// for a max of 10, 30, 50 N). Now: not found whatever the max, a note why, and the state at
// the max is the stable elastica there.
TEST(QuatFdLoadedPaths, ASearchOnTopOfASideForceFollowsTheStablePath) {
  for (const double max : {10.0, 30.0}) {
    SCOPED_TRACE(max);
    const Result r = RunColumn(R"("analysis": "buckling", "loads": {"tip_force": [6e-4, 0, 0]},
        "buckling": {"load": "tip_force", "direction": [0, 0, -1], "max": )" +
                               std::to_string(max) + "}");
    EXPECT_EQ(r.json["buckling"]["status"], "not_found") << r.log;
    EXPECT_DOUBLE_EQ(r.json["buckling"]["load_reached"].get<double>(), max);
    EXPECT_NE(r.log.find("an imperfection"), std::string::npos) << r.log;
    ExpectElastica(r, max / kEulerLoad);
  }
}

// Added mass is inertia (C_a ρ_f A on normal accelerations): the critical load stays Euler's
// (to the grid's 1e-3) and a stable compressed rod stays stable. It had made the scan's first
// stiffness indefinite: "preload_past_critical", 24 unstable directions.
TEST(QuatFdLoadedPaths, AddedMassLeavesTheStiffnessAlone) {
  const std::string fluid =
      R"("environment": {"fluid": {"density": 1025, "added_mass": 1.0}}, )";
  const Result b = RunColumn(fluid + R"("analysis": "buckling",
      "buckling": {"load": "tip_force", "direction": [0, 0, -1], "max": 2})");
  ASSERT_EQ(b.json["buckling"]["status"], "found") << b.log;
  EXPECT_NEAR(b.json["buckling"]["critical_load"].get<double>() / kEulerLoad, 1.0, 1e-3);
  const Result s = RunColumn(fluid + R"("loads": {"tip_force": [0.01, 0, -0.5]})");
  ASSERT_TRUE(s.converged) << s.log;
  EXPECT_EQ(s.json["stability_index"].get<int>(), 0) << s.log;
}

}  // namespace
}  // namespace cosserat::run
