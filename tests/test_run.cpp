// run::Run, the entry point the command-line tool and the Python module share: what a Result
// holds, and that the runner follows the problem's analysis and formulation.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <iomanip>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "cosserat/io/problem.hpp"
#include "cosserat/io/text_file.hpp"
#include "nlohmann/json.hpp"
#include "support/source_json.hpp"
#include "cosserat/lie/types.hpp"
#include "cosserat/run/grid_resolution.hpp"
#include "cosserat/run/run.hpp"
#include "support/analytic/beam_vibration.hpp"
#include "support/analytic/clamped_pinned_elastica.hpp"
#include "support/analytic/elastica.hpp"
#include "support/noted_estimate.hpp"

namespace cosserat::run {
namespace {

io::Problem Load(const std::string& relative_path) {
  const io::ParseResult r =
      io::LoadProblemFile(std::string(COSSERAT_SOURCE_DIR) + "/" + relative_path);
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors.front());
  return r.problem.value_or(io::Problem());
}

long Lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

// A problem's text with its "FORMULATION" placeholder set, parsed and run.
Result RunWithFormulation(std::string text, const char* formulation) {
  text.replace(text.find("FORMULATION"), 11, formulation);
  const io::ParseResult parsed = io::ParseProblem(text);
  if (!parsed.ok()) {
    ADD_FAILURE() << parsed.errors.front();
    return {};
  }
  return cosserat::run::Run(*parsed.problem);
}

TEST(Run, ResultHoldsTheDocumentTheNodeTableAndTheSummary) {
  const io::Problem problem = Load("examples/cantilever.json");
  const Result plain = cosserat::run::Run(problem);
  EXPECT_TRUE(plain.converged);
  EXPECT_EQ(plain.json["status"], "converged");
  EXPECT_EQ(plain.json["nodes"]["s"].size(), static_cast<size_t>(problem.nodes));
  EXPECT_TRUE(plain.nodes_csv.empty());  // not asked for
  EXPECT_EQ(plain.log.rfind("cosserat: converged", 0), 0u) << plain.log;
  EXPECT_EQ(Lines(plain.log), 1);

  RunOptions options;
  options.nodes_csv = true;
  const Result with_nodes = cosserat::run::Run(problem, options);
  EXPECT_EQ(with_nodes.nodes_csv.rfind("s,x,y,z,k1,k2,k3\n", 0), 0u);
  EXPECT_EQ(Lines(with_nodes.nodes_csv), problem.nodes + 1);  // the header, one row per node
  EXPECT_EQ(with_nodes.json["tip"], plain.json["tip"]);       // the same solve
}

TEST(Run, FollowsTheFormulation) {
  io::Problem problem = Load("examples/cantilever.json");
  problem.formulation = io::Formulation::kQuaternionFd;
  const Result fd = cosserat::run::Run(problem);
  EXPECT_TRUE(fd.converged);
  EXPECT_NE(fd.log.find("(quaternion-fd)"), std::string::npos) << fd.log;
  problem.analysis = io::Analysis::kModes;
  problem.modes.count = 2;
  const Result modes = cosserat::run::Run(problem);
  EXPECT_EQ(modes.json["modes"]["formulation"], "quaternion-fd");
  EXPECT_EQ(modes.json["modes"]["frequencies_hz"].size(), 2u);
}

// Every result holds the contract's fields (status, iterations, residual, wall_time_s, tip,
// base_wrench, nodes), and contact adds contact.total_force and nodes.contact_force, in every
// analysis. The modes' fields describe the equilibrium they are about: the same numbers as the
// statics of the same problem (the same solver on the same grid: equal to round-off, 1e-12 of
// the rod's weight, since the modes' statics may start from another guess only in iterations).
TEST(Run, EveryAnalysisWritesTheContractsFieldsAndTheContact) {
  io::Problem problem = Load("examples/rod_on_table.json");
  problem.nodes = 61;
  problem.rod.length = 1.0;
  const double weight = 8000 * M_PI * 0.002 * 0.002 * 1.0 * 9.81;  // N
  for (io::Formulation formulation :
       {io::Formulation::kSe3Shooting, io::Formulation::kQuaternionFd}) {
    problem.formulation = formulation;
    problem.analysis = io::Analysis::kStatics;
    const Result statics = cosserat::run::Run(problem);
    problem.analysis = io::Analysis::kModes;
    problem.modes.count = 2;
    const Result modes = cosserat::run::Run(problem);
    problem.analysis = io::Analysis::kDynamics;
    problem.dynamics.duration = 4 * problem.dynamics.dt;
    const Result dynamics = cosserat::run::Run(problem);
    const std::string name = io::ToString(formulation);
    for (const Result* r : {&statics, &modes, &dynamics}) {
      ASSERT_TRUE(r->converged) << name << r->log;
      for (const char* key :
           {"status", "iterations", "residual", "wall_time_s", "tip", "base_wrench", "nodes"})
        EXPECT_TRUE(r->json.contains(key)) << name << ": " << key << " in " << r->log;
      ASSERT_TRUE(r->json.contains("contact")) << name << r->log;
      EXPECT_EQ(r->json["nodes"]["contact_force"].size(), static_cast<size_t>(problem.nodes));
    }
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(modes.json["base_wrench"]["force"][i].get<double>(),
                  statics.json["base_wrench"]["force"][i].get<double>(), 1e-12 * weight)
          << name;
      EXPECT_NEAR(modes.json["contact"]["total_force"][i].get<double>(),
                  statics.json["contact"]["total_force"][i].get<double>(), 1e-12 * weight)
          << name;
    }
  }
}

// A cantilever standing in a bore, pushed at its tip into the wall, touches it over a short
// stretch near the tip; its weight pulls along the bore's axis. The surfaces' force is radial:
// its total must carry nothing along the axis, and balance the tip force, the weight and the
// clamp's reaction sideways. The SE(3) report takes it from the rod's balance less the weight
// (by construction sideways), which RK4 keeps to O(h⁴) only, as it carries n in the body frame:
// measured 9e-8 N along the axis at 41 nodes, 6e-9 at 81; 2e-7 N bounds it, and a weight left
// in (0.12 N) or the trapezoid's 2 % of 0.07 N fail it by far. The quaternion-FD model lumps
// the contact and the weight on its vertices, so its trapezoid is its own balance, to its
// statics residual (1e-10 of EI/L², or its round-off floor 1e-6 of it: 6e-7 N, inside 1e-5 of
// the tip force). The formulations differ by their grids (1e-3 of the total; 5e-3 bounds it).
TEST(Run, TheContactTotalBalancesTheTipForceAndTheReaction) {
  const io::ParseResult parsed = io::ParseProblem(R"({
    "format": "cosserat-problem/1",
    "rod": {"length": 0.5, "nodes": 41, "section": {"shape": "circle", "radius": 0.001},
            "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
    "loads": {"tip_force": [0.1, 0, 0], "gravity": [0, 0, -9.81]},
    "environment": {"contact": [{"shape": "cylinder", "point": [0, 0, 0], "axis": [0, 0, 1],
                                 "radius": 0.01, "side": "inside", "stiffness": 1e5}]}})");
  ASSERT_TRUE(parsed.ok());
  io::Problem problem = *parsed.problem;
  Vec3 totals[2];
  for (int k = 0; k < 2; ++k) {
    problem.formulation = k == 0 ? io::Formulation::kSe3Shooting : io::Formulation::kQuaternionFd;
    const Result r = cosserat::run::Run(problem);
    ASSERT_TRUE(r.converged) << r.log;
    Vec3 reaction, total;
    for (int i = 0; i < 3; ++i) {
      reaction[i] = r.json["base_wrench"]["force"][i].get<double>();
      total[i] = r.json["contact"]["total_force"][i].get<double>();
    }
    const Vec3 tip_force(0.1, 0, 0);
    const Vec3 weight(0, 0, -8000 * M_PI * 1e-6 * 0.5 * 9.81);  // ρ A L g, N
    if (k == 1)
      EXPECT_LT((total + reaction + tip_force + weight).norm(), 1e-5 * 0.1) << "quaternion-fd";
    EXPECT_LT(std::abs(total.z()), k == 0 ? 2e-7 : 1e-5 * 0.1) << io::ToString(problem.formulation);
    totals[k] = total;
  }
  std::printf("bore contact: SE(3) total [%.6e, %.6e] N, quaternion FD [%.6e, %.6e] N\n",
              totals[0].x(), totals[0].y(), totals[1].x(), totals[1].y());
  EXPECT_LT((totals[0] - totals[1]).norm(), 5e-3 * totals[0].norm());
}

// A pinned-pinned steel riser column of length L (outer and inner radii ro, ri) at tension T
// under a current's q N/m, run on `nodes` nodes; and its tensioned-beam midspan bow
// δ = q L²/8T − (q EI/T²)(1 − sech(kL/2)), k = sqrt(T/EI).
struct TautRiser {
  double L, ro, ri, T, q;
  int nodes;
  Result Run() const {
    std::ostringstream text;
    text.precision(17);
    text << R"({"format": "cosserat-problem/1", "boundary": "pinned-pinned",
        "rod": {"length": )" << L << R"(, "nodes": )" << nodes << R"(,
          "section": {"shape": "annulus", "outer_radius": )" << ro << R"(, "inner_radius": )"
         << ri << R"(},
          "material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3, "density": 7850}},
        "loads": {"tip_force": [0, 0, )" << T << R"(], "distributed_force": [)" << q
         << ", 0, 0]}}";
    const io::ParseResult parsed = io::ParseProblem(text.str());
    EXPECT_TRUE(parsed.ok()) << parsed.errors.front();
    return cosserat::run::Run(*parsed.problem);
  }
  double Bow() const {
    const double EI = 207e9 * M_PI / 4 * (std::pow(ro, 4) - std::pow(ri, 4));
    const double k = std::sqrt(T / EI);
    return q * L * L / (8 * T) - q * EI / (T * T) * (1 - 1 / std::cosh(k * L / 2));
  }
};

// A top-tensioned riser: 300 m of 21 in steel pipe at 1 MN under a current's 273 N/m,
// L sqrt(T/EI) = 19, beyond a single shot (which converged, looped, with the tip 62 m short).
// The run takes multiple shooting and bows as a tensioned beam, 3.01 m: 1 % bounds the
// geometric nonlinearity (slope 4δ/L = 0.04; its square 2e-3 enters the tension's lateral
// component) and the stretch (T/EA = 1.4e-4). Its load path starts with a step of 3 in the load
// parameter and grows while the sections turn little: 6 levels (124 when every step stayed at
// 3). And 1 km of 0.27 m pipe at 2 MN under 500 N/m: T L²/EI = 4.4e4, so its path's first step
// was the smallest the continuation takes, and one failed level ended it at once
// (load_stepping_failed, for every pair of ends). It bows 31.2 m (slope 0.12, whose square
// bounds the nonlinearity to about 1 %; it lands 0.33 % short), and each pin carries half the
// current, q L/2 (to 1e-6: the solve's tolerance in units of the 2 MN force scale).
TEST(Run, TautRiserColumnsBeyondASingleShotBowAsTensionedBeams) {
  const TautRiser short_riser{300, 0.2667, 0.2445, 1e6, 273.3675, 101};
  const Result r = short_riser.Run();
  ASSERT_TRUE(r.converged) << r.log;
  EXPECT_GT(r.json["shooting_segments"].get<int>(), 1);
  EXPECT_NEAR(r.json["nodes"]["position"][50][0].get<double>() / short_riser.Bow(), 1.0, 1e-2);
  EXPECT_LT(r.json["load_steps"].get<int>(), 20);

  const TautRiser long_riser{1000, 0.135, 0.115, 2e6, 500, 401};
  const Result l = long_riser.Run();
  ASSERT_TRUE(l.converged) << l.log;
  EXPECT_NEAR(l.json["nodes"]["position"][200][0].get<double>() / long_riser.Bow(), 1.0, 1e-2);
  EXPECT_NEAR(std::abs(l.json["base_wrench"]["force"][0].get<double>()) / (500 * 1000 / 2), 1.0,
              1e-6);
}

// A column pulled far harder (T L²/EI = 1e5: a 100 m drill pipe at 11.5 MN): its first step of 3
// in the load parameter, 3e-5 of the load, was below the smallest step the continuation takes,
// and the run stopped at once (load_stepping_failed at 0). It stays straight, stretched by
// T/EA: the tip at L (1 + T/EA), within 1e-8 m (1e-10 of L, the solve's tolerance; it lands
// 4e-13 m off).
TEST(Run, AColumnPulledFarPastItsBendingStiffnessStretchesByTOverEA) {
  const io::ParseResult parsed = io::ParseProblem(R"({
    "format": "cosserat-problem/1", "analysis": "statics", "boundary": "pinned-pinned",
    "rod": {"length": 100, "nodes": 201,
            "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.0545},
            "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 7850}},
    "loads": {"tip_force": [0, 0, 1.153e7]}})");
  ASSERT_TRUE(parsed.ok());
  const Result r = cosserat::run::Run(*parsed.problem);
  ASSERT_TRUE(r.converged) << r.log;
  const double EA = 200e9 * M_PI * (0.0635 * 0.0635 - 0.0545 * 0.0545);
  EXPECT_NEAR(r.json["tip"]["position"][2].get<double>(), 100 * (1 + 1.153e7 / EA), 1e-8);
}

// A 100 m pipe (outer radius 0.0635 m, inner 0.0543 m) lying in a stiff bore (1e7 N/m per m,
// touching it along its length) and pushed along its axis at its free end: βL = 120, and one
// shot from the clamp overflows at once. The search is made again in pieces. Far from the clamp
// (the foundation's decay length (4EI/k)^¼ ≈ 5 m) the free end buckles as a semi-infinite beam
// on a Winkler foundation, w = e^{−αx}(A cos βx + B sin βx): the free end's conditions w'' = 0
// and EI w''' + P w' = 0 hold together where EI |r|² = P, with |r|⁴ = k/EI: P_cr = sqrt(k EI)
// (Hetényi 1946), k = w/d the bore's lateral stiffness (Dawson & Paslay 1984; the pipe's centre
// sits in the penalty's smoothing ramp, δ = sqrt(2 ε w/k_c)). The model's shear lowers the load
// by P/κGA ≈ 6e-4: tolerance 1.5e-3.
TEST(Run, ALongPipeInAStiffBoreIsSearchedInPieces) {
  const io::ParseResult parsed = io::ParseProblem(R"({
    "format": "cosserat-problem/1", "analysis": "buckling", "formulation": "se3-shooting",
    "rod": {"length": 100, "nodes": 101,
            "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.0543},
            "material": {"youngs_modulus": 200e9, "poisson_ratio": 0.3, "density": 7850}},
    "base": {"position": [0, 0, -0.0445], "rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
    "loads": {"gravity": [0, 0, -9.81]},
    "environment": {"contact": [{"shape": "cylinder", "point": [0, 0, 0], "axis": [1, 0, 0],
                                 "radius": 0.108, "side": "inside", "stiffness": 1e7}]},
    "buckling": {"load": "tip_force", "direction": [-1, 0, 0], "max": 2e5}})");
  ASSERT_TRUE(parsed.ok());
  const Result r = cosserat::run::Run(*parsed.problem);
  ASSERT_TRUE(r.converged) << r.log;
  ASSERT_EQ(r.json["buckling"]["status"], "found") << r.log;
  EXPECT_NE(r.log.find("searched again by multiple shooting"), std::string::npos) << r.log;
  const double ro = 0.0635, ri = 0.0543;
  const double EI = 200e9 * M_PI / 4 * (std::pow(ro, 4) - std::pow(ri, 4));
  const double w = 7850 * M_PI * (ro * ro - ri * ri) * 9.81, eps = 1e-3 * 2 * ro;
  const double k = w / (0.0445 + std::sqrt(2 * eps * w / 1e7));
  const double P = r.json["buckling"]["critical_load"].get<double>();
  EXPECT_NEAR(P / std::sqrt(k * EI), 1.0, 1.5e-3) << P;
  // The mode is lateral and lives near the free end: its largest sideways displacement within
  // a few decay lengths of the tip, nothing in the vertical plane.
  const auto& d = r.json["buckling"]["mode"]["displacement"];
  double largest = 0, s_largest = 0, vertical = 0;
  for (size_t i = 0; i < d.size(); ++i) {
    const double y = std::abs(d[i][1].get<double>());
    if (y > largest) largest = y, s_largest = static_cast<double>(i);  // nodes 1 m apart
    vertical = std::max(vertical, std::abs(d[i][2].get<double>()));
  }
  EXPECT_GT(s_largest, 80.0);
  EXPECT_LT(vertical, 1e-3 * largest);
}

// A buckling search that fails before any load and cannot be made in pieces (a tendon robot,
// whose tendons multiple shooting does not take, in a bore so stiff that one shot overflows)
// reports no equilibrium: the node fields are null (NaN), not memory nobody wrote (positions of
// 1e-310 m, a tip "rotation" with two equal rows), and the log says why.
TEST(Run, ABucklingSearchThatFailsAtOnceReportsNoState) {
  io::ParseResult parsed =
      io::LoadProblemFile(std::string(COSSERAT_SOURCE_DIR) + "/robots/tendon_three_tendon.json");
  ASSERT_TRUE(parsed.ok());
  io::Problem p = *parsed.problem;
  p.analysis = io::Analysis::kBuckling;
  p.has_buckling = true;
  p.buckling.load = io::BucklingLoad::kTendonTension;
  p.buckling.max = 50;
  p.loads.gravity_W = Vec3(-9.81, 0, 0);
  p.loads.contact.count = 1;
  ContactSurface& bore = p.loads.contact.surface[0];
  bore.shape = ContactSurface::Shape::kCylinder;
  bore.point_W = Vec3::Zero();
  bore.direction_W = Vec3(0, 0, 1);
  bore.radius = 0.05;
  bore.inside = true;
  bore.stiffness = 1e13;
  const Result r = cosserat::run::Run(p);
  ASSERT_FALSE(r.converged) << r.log;
  for (const auto& x : r.json["nodes"]["position"])
    for (const auto& c : x) EXPECT_TRUE(c.is_null() || std::isnan(c.get<double>())) << x.dump();
  EXPECT_NE(r.log.find("hint: a single SE(3) shot"), std::string::npos) << r.log;
  EXPECT_TRUE(r.json["residual"].is_null() || std::isnan(r.json["residual"].get<double>()));
}

// A cantilever (0.5 m, 1 mm wire) pressed along its axis 19.35 times past its buckling load
// P_cr = π²EI/4L² (1.55 N) with a side force of 1 mN. The loads reach a near-straight state
// with 4 unstable directions; bent by a lateral load along the side force, the rod settles on
// the post-buckled elastica folded over its clamp (Timoshenko & Gere 1961, §2.7: tip at
// 0.144719 m across and 0.355272 m below the clamp). Within 1e-4 m: the side force moves it by
// about 3e-5 of L, shear and stretch P/EA by 5e-5. Below P_cr it stands, stable, nothing said.
// Far past P_cr, solved in multiple-shooting pieces, it settles on the elastica too.
TEST(Run, APressedCantileverSettlesOnItsElastica) {
  const std::string problem = R"({
    "format": "cosserat-problem/1",
    "rod": {"length": 0.5, "nodes": 41, "section": {"shape": "circle", "radius": 0.001},
            "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
    "loads": {"tip_force": [-0.001, 0, FZ]}})";
  auto run = [&](const std::string& fz) {
    std::string text = problem;
    text.replace(text.find("FZ"), 2, fz);
    const io::ParseResult parsed = io::ParseProblem(text);
    EXPECT_TRUE(parsed.ok());
    return cosserat::run::Run(*parsed.problem);
  };
  const Result pressed = run("-30");
  ASSERT_TRUE(pressed.converged) << pressed.log;
  EXPECT_EQ(pressed.json["stability_index"].get<int>(), 0) << pressed.log;
  EXPECT_NE(pressed.log.find("unstable (4 unstable directions), and the rod settles beside it"),
            std::string::npos)
      << pressed.log;
  const double EI = 200e9 * M_PI * 1e-12 / 4, L = 0.5;
  const truth::PostBuckledCantilever e =
      truth::PostBuckledCantileverAtLoad(30.0 / (M_PI * M_PI * EI / (4 * L * L)));
  const auto& tip = pressed.json["tip"]["position"];
  EXPECT_NEAR(tip[0].get<double>(), -e.deflection * L, 1e-4);  // with the side force
  EXPECT_NEAR(tip[2].get<double>(), e.axial * L, 1e-4);
  const Result light = run("-1");  // below P_cr: stable, no warning
  ASSERT_TRUE(light.converged) << light.log;
  EXPECT_EQ(light.json["stability_index"].get<int>(), 0);
  EXPECT_EQ(light.log.find("unstable"), std::string::npos);
  // 70 N (45 P_cr): L sqrt(P/EI) = 10.6, past one shot's reach, so the statics run in pieces,
  // and settle there too. The grid check puts RK4's error at 0.06 % of L (3e-4 m) for the
  // 0.53 rad per segment at the clamp: 5e-4 m asserted.
  const Result far = run("-70");
  ASSERT_TRUE(far.converged) << far.log;
  EXPECT_TRUE(far.json.contains("shooting_segments")) << far.log;
  EXPECT_EQ(far.json["stability_index"].get<int>(), 0) << far.log;
  const truth::PostBuckledCantilever f =
      truth::PostBuckledCantileverAtLoad(70.0 / (M_PI * M_PI * EI / (4 * L * L)));
  const auto& far_tip = far.json["tip"]["position"];
  EXPECT_NEAR(std::hypot(far_tip[0].get<double>(), far_tip[1].get<double>()), f.deflection * L,
              5e-4);
  EXPECT_NEAR(far_tip[2].get<double>(), f.axial * L, 5e-4);
  // The quaternion-FD path settles there too (from the SE(3) single shot's equilibrium, where
  // its own path of the imperfection lands near the straight branch), on its second-order
  // approximation of the elastica: the tip's distance from it shrinks by about 4 from 41 to 81
  // nodes (more than 3 asserted), and is below 0.3 % of L at 41 (0.53 rad per segment).
  auto fd_tip_error = [&](int nodes) {
    std::string text = problem;
    text.replace(text.find("FZ"), 2, "-70");
    const std::string forty_one = "\"nodes\": 41";
    text.replace(text.find(forty_one), forty_one.size(), "\"nodes\": " + std::to_string(nodes));
    nlohmann::json doc = nlohmann::json::parse(text);
    doc["formulation"] = "quaternion-fd";
    const io::ParseResult parsed = io::ParseProblem(doc.dump());
    EXPECT_TRUE(parsed.ok());
    const Result fd = cosserat::run::Run(*parsed.problem);
    EXPECT_TRUE(fd.converged) << fd.log;
    EXPECT_EQ(fd.json["stability_index"].get<int>(), 0) << fd.log;
    const auto& tip = fd.json["tip"]["position"];
    return std::hypot(std::hypot(tip[0].get<double>(), tip[1].get<double>()) - f.deflection * L,
                      tip[2].get<double>() - f.axial * L);
  };
  const double coarse = fd_tip_error(41), fine = fd_tip_error(81);
  EXPECT_LT(coarse, 3e-3 * L);
  EXPECT_GT(coarse / fine, 3.0) << coarse << " " << fine;
}

// A cantilever pushed sideways at its tip (0.3 N) onto a sphere beside it (R = 10 mm): the
// surface turns away from the rod, so the equilibrium is unstable to sliding round it (its
// sideways stiffness −N/(R + r) ≈ −51 N/m against the rod's 17 N/m). On a contact surface the
// statics do not settle (where the rod would slide to is not the loads' question): the result
// says unstable, with a warning.
TEST(Run, AnUnstableEquilibriumIsFlagged) {
  const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
      "rod": {"length": 0.5, "nodes": 41, "section": {"shape": "circle", "radius": 0.001},
              "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
      "loads": {"tip_force": [0.3, 0, 0]},
      "environment": {"contact": [{"shape": "sphere", "center": [0.012, 0, 0.3],
                                   "radius": 0.01, "stiffness": 1e5}]}})");
  ASSERT_TRUE(parsed.ok());
  const Result r = cosserat::run::Run(*parsed.problem);
  ASSERT_TRUE(r.converged) << r.log;
  EXPECT_GT(r.json["stability_index"].get<int>(), 0);
  EXPECT_NE(r.log.find("warning: this equilibrium is unstable"), std::string::npos) << r.log;
}

// The grid check reads the shape, and only what RK4 in s gets wrong: a straight rod stretched
// 13-fold (a gel under a large pull) is a long segment but no runaway (it was non_finite), a
// straight rod twisted 3 rad per segment moves no point (it was "off by 64 %"), and an arc
// at 0.75 rad of bending per segment warns with RK4's 8e-3 (κ h)⁴ (0.253 % of L). A state of
// NaN (a failed shot) is no runaway: nothing is said of it.
TEST(Run, TheGridCheckJudgesBendingNotStretchOrTwist) {
  const int n = 21;
  const double L = 1.0, h = L / (n - 1);
  std::vector<double> s(n);
  std::vector<Vec3> straight(n), stretched(n), arc(n), none(n, Vec3::Zero()), twist(n), bend(n);
  for (int i = 0; i < n; ++i) {
    s[i] = i * h;
    straight[i] = Vec3(0, 0, s[i]);
    stretched[i] = Vec3(0, 0, 13.0 * s[i]);
    twist[i] = Vec3(0, 0, 3.0 / h);
    bend[i] = Vec3(0, 0.75 / h, 0);
    const double k = 0.75 / h;
    arc[i] = Vec3((1 - std::cos(k * s[i])) / k, 0, std::sin(k * s[i]) / k);
  }
  EXPECT_FALSE(run::CheckGrid(s, stretched, none, L).ran_away);
  EXPECT_TRUE(run::CheckGrid(s, stretched, none, L).log.empty());
  EXPECT_TRUE(run::CheckGrid(s, straight, twist, L).log.empty());
  const run::GridResolution coarse = run::CheckGrid(s, arc, bend, L);
  EXPECT_FALSE(coarse.ran_away);
  EXPECT_NE(coarse.log.find("0.75 rad per segment"), std::string::npos) << coarse.log;
  EXPECT_NE(coarse.log.find("about 0.253 %"), std::string::npos) << coarse.log;
  const std::vector<Vec3> nan(n, Vec3::Constant(std::nan("")));
  EXPECT_FALSE(run::CheckGrid(s, nan, nan, L).ran_away);
  EXPECT_TRUE(run::CheckGrid(s, nan, nan, L).log.empty());
}

// The quaternion-FD polygon is second order: an arc at 0.75 rad per segment warns with
// 0.08 (κ h)² (4.5 % of L), one at 2 rad is under_resolved. A straight rod twisted 3 rad per
// segment is not bent at all: only its twist is warned of, unless it rests twisted so.
TEST(Run, TheQuaternionFdGridCheckJudgesTheBendOfItsPolygon) {
  const int n = 21;
  const double L = 1.0, h = L / (n - 1);
  auto arc = [&](double turn, std::vector<Vec3>* x, std::vector<Vec3>* k) {
    const double kappa = turn / h;
    for (int i = 0; i < n; ++i) {
      (*x)[i] = Vec3((1 - std::cos(kappa * i * h)) / kappa, 0, std::sin(kappa * i * h) / kappa);
      (*k)[i] = Vec3(0, kappa, 0);
    }
  };
  std::vector<double> s(n);
  std::vector<Vec3> x(n), k(n), straight(n), twist(n, Vec3(0, 0, 3.0 / h));
  for (int i = 0; i < n; ++i) s[i] = i * h, straight[i] = Vec3(0, 0, s[i]);
  const run::GridResolution twisted = run::CheckPolygon(s, straight, twist, L);
  EXPECT_FALSE(twisted.under_resolved);
  EXPECT_EQ(twisted.log.find("bending"), std::string::npos) << twisted.log;
  EXPECT_NE(twisted.log.find("resolves the twist coarsely"), std::string::npos) << twisted.log;
  // Twisted as it rests, the sections carry no torsion strain: nothing to warn of.
  const std::vector<double> rest_twist(n, 3.0 / h);
  EXPECT_TRUE(run::CheckPolygon(s, straight, twist, L, rest_twist).log.empty());
  arc(0.75, &x, &k);
  const run::GridResolution coarse = run::CheckPolygon(s, x, k, L);
  EXPECT_FALSE(coarse.under_resolved);
  EXPECT_NE(coarse.log.find("0.75 rad per segment"), std::string::npos) << coarse.log;
  EXPECT_NE(coarse.log.find("off by 4.5 %"), std::string::npos) << coarse.log;
  arc(2.0, &x, &k);
  EXPECT_TRUE(run::CheckPolygon(s, x, k, L).under_resolved);
}

// A steel shaft (1 m, r = 5 mm) twisted by a tip torque T = 10 GJ/L: φ = T L/GJ = 10 rad. The
// quaternion-FD twist is stiff by about θ²/12 per segment turn θ (grid_resolution.cpp): on 21
// nodes (0.5 rad per segment) the note's estimate must be within [0.7, 1.3] of the tip's twist
// error, measured against φ (its next term, O(θ⁴), is 2 % of it; the clamp's half element
// adds little); on 41 nodes (0.52 % expected) it says nothing.
TEST(Run, AQuaternionFdShaftTwistedCoarselyIsWarnedWithItsError) {
  const double G = 80e9, r = 0.005, GJ = G * M_PI * std::pow(r, 4) / 2, phi = 10.0;
  for (int nodes : {21, 41}) {
    std::ostringstream text;
    text.precision(17);
    text << R"({"format": "cosserat-problem/1", "formulation": "quaternion-fd",
        "rod": {"length": 1, "nodes": )" << nodes << R"(,
                "section": {"shape": "circle", "radius": 0.005},
                "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
        "loads": {"tip_moment": [0, 0, )" << phi * GJ << "]}}";
    const io::ParseResult parsed = io::ParseProblem(text.str());
    ASSERT_TRUE(parsed.ok());
    const Result r = cosserat::run::Run(*parsed.problem);
    ASSERT_TRUE(r.converged) << r.log;
    const auto& R = r.json["tip"]["rotation"];
    const double turned = std::atan2(R[1][0].get<double>(), R[0][0].get<double>());
    const double error = std::abs(std::remainder(turned - phi, 2 * M_PI)) / phi;
    const size_t at = r.log.find("stiffer in torsion by about ");
    std::printf("%d nodes: twist %.4g %% short; %s", nodes, 100 * error, r.log.c_str());
    if (nodes == 41) {
      EXPECT_EQ(at, std::string::npos) << r.log;
      EXPECT_LT(error, 0.01);
      continue;
    }
    testing::ExpectEstimateWithin(r.log, "stiffer in torsion by about ", true, error, 0.7, 1.3);
  }
}

// A tip moment of 100 N·m on the 0.5 m steel wire of examples/cantilever.json curls it into
// coils of 1.6 mm radius, M/EI = 637 /m: on 41 nodes, 8 rad per segment. The quaternion-FD
// statics converge on a polygon that cannot be that shape, and say so (under_resolved, exit 1);
// the SE(3) load steps stop short, and the log says that the level they reached already has a
// shot RK4 cannot follow (the shape written is that level's equilibrium).
TEST(Run, CoilsTighterThanTheGridAreCalledSoInBothFormulations) {
  std::string text, why;
  ASSERT_TRUE(io::ReadTextFile(std::string(COSSERAT_SOURCE_DIR) + "/examples/cantilever.json",
                               &text, &why))
      << why;
  for (const char* formulation : {"quaternion-fd", "se3-shooting"}) {
    nlohmann::json doc = nlohmann::json::parse(text);
    doc["formulation"] = formulation;
    doc["loads"]["tip_moment"] = {0, 100, 0};
    const io::ParseResult parsed = io::ParseProblem(doc.dump());
    ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
    const Result r = cosserat::run::Run(*parsed.problem);
    EXPECT_FALSE(r.converged) << r.log;
    if (std::string(formulation) == "quaternion-fd") {
      EXPECT_EQ(r.json["status"], "under_resolved") << r.log;
    } else {
      EXPECT_EQ(r.json["status"], "load_stepping_failed") << r.log;
      EXPECT_NE(r.log.find("at the last load level reached the shot ran away"), std::string::npos)
          << r.log;
    }
  }
}

// Modes on coarse grids: the log's promise is checked against Euler–Bernoulli's cantilever
// (examples/modes_cantilever.json, 3 bending pairs; the sag under its weight moves them by
// < 0.05 %). Where the run says nothing, every frequency is within 1.2 % of the beam's; where it
// says under_resolved, one is more than 5 % off (SE(3) at 3 nodes: 44 %; quaternion FD at 9:
// 12 %). At 3 nodes SE(3) modes once said "converged" with the second pair 19.5 % low.
TEST(Run, ModesOnAGridTooCoarseForThemSaySo) {
  const nlohmann::json example = testing::SourceJson("examples/modes_cantilever.json");
  const double r = 0.001, E = 200e9, rho = 8000, L = 0.5;
  const double EI = E * M_PI * std::pow(r, 4) / 4, rhoA = rho * M_PI * r * r;
  int silent = 0, under = 0;
  for (const char* formulation : {"se3-shooting", "quaternion-fd"}) {
    for (int nodes : {3, 5, 9, 17, 33, 101}) {
      nlohmann::json doc = example;
      doc["formulation"] = formulation;
      doc["rod"]["nodes"] = nodes;
      doc["modes"]["count"] = 6;
      const io::ParseResult parsed = io::ParseProblem(doc.dump());
      ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
      const Result run = cosserat::run::Run(*parsed.problem);
      const auto& f = run.json["modes"]["frequencies_hz"];
      ASSERT_EQ(f.size(), 6u) << run.log;
      double worst = 0;
      for (int m = 0; m < 6; ++m) {
        const double beam =
            truth::EulerBernoulliOmega(truth::CantileverBetaL(m / 2 + 1), EI, rhoA, L) / (2 * M_PI);
        worst = std::max(worst, std::abs(f[m].get<double>() / beam - 1));
      }
      const bool warned = run.log.find("coarse") != std::string::npos;
      std::printf("%s, %d nodes: worst %.3g, %s\n", formulation, nodes, worst,
                  run.json["status"].get<std::string>().c_str());
      if (!warned) {
        ++silent;
        EXPECT_LT(worst, 0.012) << formulation << nodes << run.log;
      }
      if (run.json["status"] == "under_resolved") {
        ++under;
        EXPECT_GT(worst, 0.05) << formulation << nodes << run.log;
      }
      EXPECT_EQ(run.converged, run.json["status"] == "converged");
    }
  }
  EXPECT_GE(silent, 4);  // both formulations' fine grids
  EXPECT_GE(under, 3);   // SE(3) at 3 nodes; quaternion FD at 3, 5 and 9
}

// A pipe in a fluid without contents_density is sealed and empty, which drill pipe never is (a
// 1 000 m string in mud hung 48 % light): the log notes it with the bore's lift ρ g π r_i² and
// the density that fills it; not when the file fills the bore, and not for a solid rod. The
// two rods hang apart by that lift (the solves' balance: the clamp's force to 1e-9).
TEST(Run, APipeInAFluidTakenSealedIsNoted) {
  const double ri = 0.054, L = 10, rho = 1200, lift = rho * 9.81 * M_PI * ri * ri;  // N/m
  auto hang = [](const std::string& section) {
    const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
        "rod": {"length": 10, "nodes": 21, "section": )" + section + R"(,
            "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 7850}},
        "base": {"rotation": [[1, 0, 0], [0, -1, 0], [0, 0, -1]]},
        "loads": {"gravity": [0, 0, -9.81]}, "environment": {"fluid": {"density": 1200}}})");
    EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
    return cosserat::run::Run(*parsed.problem);
  };
  const Result sealed = hang(R"({"shape": "annulus", "outer_radius": 0.0635,
                                 "inner_radius": 0.054})");
  const Result full = hang(R"({"shape": "annulus", "outer_radius": 0.0635,
                               "inner_radius": 0.054, "contents_density": 1200})");
  const Result solid = hang(R"({"shape": "circle", "radius": 0.0635})");
  std::ostringstream note;
  note << std::setprecision(3) << "taken sealed and empty: its bore's volume lifts it by " << lift
       << " N/m; an open pipe (drill pipe, a flooded riser) is full of the fluid, "
          "\"contents_density\": 1200";
  EXPECT_NE(sealed.log.find(note.str()), std::string::npos) << sealed.log;
  EXPECT_EQ(full.log.find("sealed"), std::string::npos) << full.log;
  EXPECT_EQ(solid.log.find("sealed"), std::string::npos) << solid.log;
  const double hook_sealed = sealed.json["base_wrench"]["force"][2].get<double>();
  const double hook_full = full.json["base_wrench"]["force"][2].get<double>();
  EXPECT_NEAR(std::abs(hook_full - hook_sealed), lift * L, 1e-9 * std::abs(hook_full)) << rho;
}

// A pipe given as an explicit section with its outer diameter floats, drags and touches as the
// same pipe given as an annulus (it took the disc of the steel's area: 0.08 m against 0.1385 m,
// 1/3 of the buoyancy and 58 % of the drag). Statics in still water with a current; the two
// differ only by the shear coefficient (explicit 1, annulus Cowper's ≈ 0.53), which a 10 m
// pipe bent over its length barely sees (shear strain ~ (r/L)² of the bending): 1e-5 of L.
TEST(Run, AnExplicitSectionWithItsOuterDiameterIsThePipe) {
  const double ro = 0.06925, ri = 0.05, A = M_PI * (ro * ro - ri * ri);
  const double I = M_PI * (std::pow(ro, 4) - std::pow(ri, 4)) / 4;
  auto tip = [](const std::string& section) {
    const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
        "rod": {"length": 10, "nodes": 41, "section": )" + section + R"(,
            "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 7850}},
        "loads": {"gravity": [0, 0, -9.81]},
        "environment": {"fluid": {"density": 1025, "velocity": [0, 1.5, 0],
                                  "drag_normal": 1.2}}})");
    EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
    const Result r = cosserat::run::Run(*parsed.problem);
    EXPECT_TRUE(r.converged) << r.log;
    const auto& p = r.json["tip"]["position"];
    return Vec3(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  };
  const Vec3 annulus = tip(R"({"shape": "annulus", "outer_radius": 0.06925,
                                "inner_radius": 0.05})");
  auto number = [](double x) {
    std::ostringstream out;
    out.precision(17);
    out << x;
    return out.str();
  };
  const Vec3 explicit_pipe =
      tip(R"({"area": )" + number(A) + R"(, "I1": )" + number(I) + R"(, "I2": )" + number(I) +
          R"(, "J": )" + number(2 * I) + R"(, "outer_diameter": 0.1385})");
  EXPECT_LT((annulus - explicit_pipe).norm(), 1e-4) << annulus.transpose() << " / "
                                                     << explicit_pipe.transpose();
  EXPECT_GT((annulus - Vec3(0, 0, 10)).norm(), 0.05);  // it does bend: 0.093 m
}

// A search to 1e4 N for the cantilever of examples/cantilever.json (P_cr = π²EI/4L² = 1.5503 N):
// its first step was max/2560 = 3.9 N, past the double root, which then showed neither a sign
// change of det J nor a dip: "found" 13.95 N (the second root, 9 P_cr). The first step now
// scales with EI/L². A search to 1e9 P_cr had not ended at all; one to 5e-324 N looped forever.
TEST(Run, ABucklingSearchFarBeyondTheCriticalLoadStillFindsTheFirst) {
  auto search = [](const std::string& max) {
    const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
        "analysis": "buckling", "rod": {"length": 0.5, "nodes": 41,
        "section": {"shape": "circle", "radius": 0.001},
        "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
        "buckling": {"load": "tip_force", "direction": [0, 0, -1], "max": )" + max + "}}");
    EXPECT_TRUE(parsed.ok());
    return cosserat::run::Run(*parsed.problem);
  };
  const double euler = M_PI * M_PI * 200e9 * M_PI * 1e-12 / 4 / (4 * 0.25);
  for (const char* max : {"1e4", "2.1e9"}) {
    const Result r = search(max);
    ASSERT_EQ(r.json["buckling"]["status"], "found") << max << ": " << r.log;
    // The grid's error at 41 nodes (O(h²), 2e-4) and shear (r/L)² bound the difference.
    EXPECT_NEAR(r.json["buckling"]["critical_load"].get<double>() / euler, 1.0, 1e-3) << max;
  }
  EXPECT_EQ(search("5e-324").json["buckling"]["status"], "path_failed");
}

// The pinned column of examples/buckling_column.json (L = 0.5 m, r = 1 mm, P_E = π²EI/L² =
// 6.2012 N) searched on 5 nodes: k h = π/4 per segment, and the critical load is 5.1e-3 high.
// A note says the grid is coarse, with an upper estimate of the error (1.5e-2 (k h)⁴ = 5.8e-3)
// that must not understate it, and the nodes that bring it below 3e-5; at those there is no
// note, and the load is within 5e-5 of Euler's: the grid's 3e-5 and the model's shear and
// shortening, P_E/EA − P_E/κGA = −1.8e-5 here (Engesser 1891).
TEST(Run, ABucklingSearchOnACoarseGridSaysSo) {
  auto search = [](int nodes) {
    const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
        "analysis": "buckling", "boundary": "pinned-pinned",
        "rod": {"length": 0.5, "nodes": )" + std::to_string(nodes) + R"(,
        "section": {"shape": "circle", "radius": 0.001},
        "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
        "buckling": {"load": "tip_force", "direction": [0, 0, -1], "max": 20}})");
    EXPECT_TRUE(parsed.ok());
    return cosserat::run::Run(*parsed.problem);
  };
  const double euler = M_PI * M_PI * 200e9 * M_PI * 1e-12 / 4 / 0.25;
  const Result coarse = search(5);
  ASSERT_EQ(coarse.json["buckling"]["status"], "found") << coarse.log;
  const double error = coarse.json["buckling"]["critical_load"].get<double>() / euler - 1;
  const size_t at = coarse.log.find("up to about ");
  ASSERT_NE(at, std::string::npos) << coarse.log;
  const double estimate = std::stod(coarse.log.substr(at + 12));
  EXPECT_GT(error, 1e-4);
  EXPECT_GE(estimate, error) << coarse.log;
  const size_t nodes_at = coarse.log.find("\"nodes\": ");
  ASSERT_NE(nodes_at, std::string::npos) << coarse.log;
  const int nodes = std::stoi(coarse.log.substr(nodes_at + 9));
  const Result fine = search(nodes);
  EXPECT_EQ(fine.log.find("coarse"), std::string::npos) << fine.log;
  EXPECT_NEAR(fine.json["buckling"]["critical_load"].get<double>() / euler, 1.0, 5e-5) << nodes;
}

// examples/cantilever.json pulled by 10 kN: at 41 nodes the bending turns a section by 3.6 rad
// per segment near the clamp, and the "converged" base force was 5 191 N against the 10 000 N
// (and 0.12 N of weight) it must balance. Not converged (exit 1): the continuation's last levels
// meet their residuals only with frames RK4 no longer keeps rotations, which are refused, so it
// stops short (load_stepping_failed) and the log names the nodes that resolve the shape. With
// those, the base balances the loads (to 1e-4: the tolerance's share of a 10 kN load on a rod
// stretched 1.6 %).
TEST(Run, AShapeTheGridCannotFollowIsUnderResolved) {
  auto pull = [](int nodes) {
    const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
        "rod": {"length": 0.5, "nodes": )" + std::to_string(nodes) + R"(,
        "section": {"shape": "circle", "radius": 0.001},
        "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
        "loads": {"gravity": [-9.81, 0, 0], "tip_force": [-10000, 0, 0]}})");
    EXPECT_TRUE(parsed.ok());
    return cosserat::run::Run(*parsed.problem);
  };
  const Result coarse = pull(41);
  EXPECT_FALSE(coarse.converged);
  EXPECT_EQ(coarse.json["status"], "load_stepping_failed") << coarse.log;
  EXPECT_NE(coarse.log.find("rod.nodes ≥ 571"), std::string::npos) << coarse.log;
  const Result fine = pull(571);
  ASSERT_TRUE(fine.converged) << fine.log;
  const double weight = 8000 * M_PI * 1e-6 * 0.5 * 9.81;
  EXPECT_NEAR(fine.json["base_wrench"]["force"][0].get<double>() / (10000 + weight), 1.0, 1e-4);
}

// A clamp spun at Ω = 1 rad/s on a rubber rod (E = 1 MPa, ν = 0.5, 0.5 m, r = 5 mm) sends a
// torsion wave down it at c = sqrt(G/ρ) = 18 m/s: until it reflects (2L/c = 55 ms) the clamp's
// work, T Ω t with T = Ω J sqrt(Gρ) the wave's torque, is all the rod's energy. On 121 nodes
// (the shear wave's exponent 0.7 per segment at dt = 0.5 ms) the run converges with that energy,
// less BDF2's damping of the front (2.4 % at 20 ms: 10 % allowed) and plus what the abrupt start
// counts again (an impulse in the first step counts 1.5 times: about dt/2t = 1.25 % of the
// work, 3 % allowed above it). On 41 nodes (2.2 per segment) steps that all converged grew an
// oscillation of the grid instead, 1e5 times the clamp's work within 7 steps: the run stops as
// under_resolved once it is a thousandfold in five steps, and its energy is far past the work.
TEST(Run, ASpunClampsEnergyIsItsWorkOrTheRunStopsAsUnderResolved) {
  auto spin = [](int nodes) {
    const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
        "analysis": "dynamics",
        "rod": {"length": 0.5, "nodes": )" + std::to_string(nodes) + R"(,
        "section": {"shape": "circle", "radius": 0.005},
        "material": {"youngs_modulus": 1e6, "poisson_ratio": 0.5, "density": 1000}},
        "dynamics": {"dt": 0.0005, "duration": 0.02, "base_spin": 1.0}})");
    EXPECT_TRUE(parsed.ok());
    return cosserat::run::Run(*parsed.problem);
  };
  const double G = 1e6 / 3, rho = 1000, J = M_PI * std::pow(0.005, 4) / 2;
  const double torque = 1.0 * J * std::sqrt(G * rho);  // N·m
  auto energy = [](const Result& r) {
    return r.json["energy"]["kinetic"].get<double>() + r.json["energy"]["elastic"].get<double>();
  };
  const Result fine = spin(121);
  ASSERT_TRUE(fine.converged) << fine.log;
  const double work = torque * 1.0 * 0.02;  // J
  EXPECT_GT(energy(fine), 0.9 * work);
  EXPECT_LT(energy(fine), 1.03 * work);
  const Result coarse = spin(41);
  EXPECT_FALSE(coarse.converged);
  EXPECT_EQ(coarse.json["status"], "under_resolved") << coarse.log;
  const double t = coarse.json["failed_at_t"].get<double>();
  EXPECT_LE(t, 0.005);
  EXPECT_GT(energy(coarse), 100 * torque * t) << "the grid's oscillation, far past the work";
  EXPECT_NE(coarse.log.find("an oscillation of the grid at this dt"), std::string::npos)
      << coarse.log;
}

// A tip moment M = 6π EI/L curls the steel wire into three whole turns: the tip frame is the
// base's (a rotation by ML/EI = 6π about y). RK4 in s left the written rotation off SO(3) (det
// 0.994 at 41 nodes), which a user could not give back as a pose: it is now a rotation to
// round-off, and its angle from the truth falls at RK4's fourth order (256× from 41 to 161
// nodes; ≥ 100× asked).
TEST(Run, TheTipRotationIsARotation) {
  auto curl = [](int nodes) {
    const double EI = 200e9 * M_PI * 1e-12 / 4;
    const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
        "rod": {"length": 0.5, "nodes": )" + std::to_string(nodes) + R"(,
        "section": {"shape": "circle", "radius": 0.001},
        "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
        "loads": {"tip_moment": [0, )" + std::to_string(6 * M_PI * EI / 0.5) + ", 0]}}");
    EXPECT_TRUE(parsed.ok());
    const Result r = cosserat::run::Run(*parsed.problem);
    EXPECT_TRUE(r.converged) << r.log;
    Mat3 R;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R(i, j) = r.json["tip"]["rotation"][i][j].get<double>();
    EXPECT_LT((R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
    return Eigen::AngleAxisd(R).angle();  // from the truth, the identity
  };
  const double coarse = curl(41), fine = curl(161);
  EXPECT_LT(coarse, 1e-2);
  EXPECT_GT(coarse / fine, 100.0) << coarse << " " << fine;
}

// The modes of a rod coiled 12.5 rad per segment (rest curvature 1000 1/m on a 12.5 mm grid)
// are about an equilibrium whose shot ran away (its tip at 1e116 m): the statics refuse it
// (statics_failed, and the log says why), not "converged" with frequencies of 34 kHz.
TEST(Run, ModesAboutARunawayEquilibriumAreNotConverged) {
  const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
      "analysis": "modes", "rod": {"length": 0.5, "nodes": 41,
      "section": {"shape": "circle", "radius": 0.001},
      "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000},
      "rest_curvature": [0, 1000, 0]}})");
  ASSERT_TRUE(parsed.ok());
  const Result r = cosserat::run::Run(*parsed.problem);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.json["status"], "statics_failed") << r.log;
  EXPECT_NE(r.log.find("its shot ran away"), std::string::npos) << r.log;
  EXPECT_TRUE(r.json["modes"]["frequencies_hz"].empty()) << r.log;
}

namespace {

// A pinned steel column (L = 1 m) pressed past its Euler load P_E along z, in the problem file.
// A straight steel column (E 200 GPa, G 80 GPa, ρ 8000 kg/m³) along z with the given ends,
// length (m), nodes and section (JSON), pressed at its tip by P (N), with `more_loads` (JSON
// members after the tip force) beside it.
Result PressedColumn(const std::string& ends, double length, int nodes,
                     const std::string& section, double P, const std::string& more_loads = "") {
  std::ostringstream text;
  text.precision(17);
  text << R"({"format": "cosserat-problem/1", "boundary": ")" << ends << R"(",
      "rod": {"length": )" << length << R"(, "nodes": )" << nodes << R"(, "section": )"
       << section << R"(,
              "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
      "loads": {"tip_force": [0, 0, )" << -P << "]" << more_loads << "}}";
  const io::ParseResult parsed = io::ParseProblem(text.str());
  EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
  return cosserat::run::Run(*parsed.problem);
}

// A pinned steel column (L = 1 m) pressed past its Euler load P_E along z, with a side load of
// `side` P_E per metre along x.
Result PressedPinnedColumn(const std::string& section, double EI, double ratio, double side) {
  const double P = M_PI * M_PI * EI;
  std::ostringstream side_load;
  side_load.precision(17);
  side_load << R"(, "distributed_force": [)" << side * P << ", 0, 0]";
  return PressedColumn("pinned-pinned", 1.0, 41, section, ratio * P, side_load.str());
}

/// The mid-span deflection over L of the pinned elastica at P/P_E = ratio: two cantilever
/// elasticas of length L/2 (Timoshenko & Gere 1961), each pressed at that ratio of its own
/// critical load.
double PinnedElasticaMidSpan(double ratio) {
  return 0.5 * truth::PostBuckledCantileverAtLoad(ratio).deflection;
}

}  // namespace

// A straight round column (r = 1 mm) at 1.1 and 2 P_E: nothing breaks its symmetry, so the
// loads reach the straight state, which has an unstable direction in each plane (2). It settles
// beside it on the elastica (mid-span within 2e-3 L of 0.254 and 0.398 L), stable up to the
// bow's free turn about its chord. At 2.5 P_E it stays straight, with a warning. At 0.9 P_E,
// under a side load of 1e-3 P_E per metre, it stands bent with the load: index 0, nothing said.
TEST(Run, AStraightColumnPastItsEulerLoadSettlesOrIsFlagged) {
  const std::string round = R"({"shape": "circle", "radius": 0.001})";
  const double EI = 200e9 * M_PI * 1e-12 / 4;
  for (const double ratio : {1.1, 2.0}) {
    const Result past = PressedPinnedColumn(round, EI, ratio, 0.0);
    ASSERT_TRUE(past.converged) << past.log;
    EXPECT_NE(past.log.find("the rod settles beside it"), std::string::npos) << past.log;
    EXPECT_EQ(past.json["stability_index"].get<int>(), 0) << past.log;
    const auto& p = past.json["nodes"]["position"][20];
    EXPECT_NEAR(std::hypot(p[0].get<double>(), p[1].get<double>()),
                PinnedElasticaMidSpan(ratio), 2e-3) << ratio;
  }
  // At 2.5 P_E the planar elastica's pins have passed each other (its chord, 2E(k)/K(k) − 1,
  // is −0.0960 L), and its count finds it unstable too: the log must not offer it as stable.
  const Result crossed = PressedPinnedColumn(round, EI, 2.5, 0.0);
  ASSERT_TRUE(crossed.converged) << crossed.log;
  std::ostringstream passed;
  passed << "whose ends would have passed each other (" << std::setprecision(3)
         << -truth::PostBuckledCantileverAtLoad(2.5).axial << " L)";
  EXPECT_NE(crossed.log.find(passed.str()), std::string::npos) << crossed.log;
  EXPECT_EQ(crossed.log.find("the stable one"), std::string::npos) << crossed.log;
  const Result below = PressedPinnedColumn(round, EI, 0.9, 1e-3);
  ASSERT_TRUE(below.converged) << below.log;
  EXPECT_EQ(below.log.find("unstable"), std::string::npos) << below.log;
  EXPECT_EQ(below.json["stability_index"].get<int>(), 0) << below.log;
}

// A flat bar (5 × 20 mm, soft across x) at 1.1 P_E under a side load of 1e-3 P_E per metre
// along x. The load steps from the unloaded column land on the state beside the sharp turn of
// the path near P_E, bent 1.3 mm against the load (unstable). The column settles beside it
// (settle_beside_instability.hpp) on its bent branch: index 0, a note and no warning, mid-span
// with the load and within 2e-3 L of the elastica's 0.254 L (the side load adds about 7e-4 L,
// shear and stretch ~1e-4).
TEST(Run, AnImperfectColumnPastItsEulerLoadSettlesOnItsBentBranch) {
  const std::string bar = R"({"shape": "rectangle", "width": 0.005, "height": 0.02})";
  const double EI = 200e9 * 0.02 * std::pow(0.005, 3) / 12;  // the soft axis, N·m²
  const Result r = PressedPinnedColumn(bar, EI, 1.1, 1e-3);
  ASSERT_TRUE(r.converged) << r.log;
  EXPECT_EQ(r.json["stability_index"].get<int>(), 0) << r.log;
  EXPECT_NE(r.log.find("the rod settles beside it"), std::string::npos) << r.log;
  EXPECT_EQ(r.log.find("warning"), std::string::npos) << r.log;
  const double mid = r.json["nodes"]["position"][20][0].get<double>();
  EXPECT_NEAR(mid, PinnedElasticaMidSpan(1.1), 2e-3);
}

// Deeper on the bent branch, where the pins have turned by 1–1.5 rad: the bar and a round
// column (r = 1 mm) at 1.5 and 2 P_E settle as at 1.1 P_E, mid-span within 2e-3 L of the
// elastica's 0.394 and 0.398 L (the side load adds less there: the bent column is stiffer).
TEST(Run, ImperfectColumnsFarPastTheirEulerLoadSettleOnTheirBentBranch) {
  const std::string bar = R"({"shape": "rectangle", "width": 0.005, "height": 0.02})";
  const std::string round = R"({"shape": "circle", "radius": 0.001})";
  const double EI_bar = 200e9 * 0.02 * std::pow(0.005, 3) / 12, EI_round = 200e9 * M_PI / 4e12;
  for (const double ratio : {1.5, 2.0}) {
    for (const bool is_round : {false, true}) {
      const Result r =
          PressedPinnedColumn(is_round ? round : bar, is_round ? EI_round : EI_bar, ratio, 1e-3);
      ASSERT_TRUE(r.converged) << r.log;
      EXPECT_EQ(r.json["stability_index"].get<int>(), 0) << ratio << r.log;
      EXPECT_EQ(r.log.find("warning"), std::string::npos) << r.log;
      const double mid = r.json["nodes"]["position"][20][0].get<double>();
      EXPECT_NEAR(mid, PinnedElasticaMidSpan(ratio), 2e-3) << ratio << (is_round ? " round" : "");
    }
  }
}

// Perfect round columns (r = 1 mm, L = 0.5 m, GJ/EI = 0.8) pressed along their axis. Without a
// side load the bow turns freely about the chord (with a uniform spin of the sections): one
// direction of zero stiffness, which the count reads either way. A pinned column at 1.2 P_E
// settles (mid-span within 2e-3 L of the elastica's 0.324 L), and so does a clamped one at
// 1.3 P_cc (the same 0.3615 L as a pinned one at 1.3 P_E: four quarter-waves of it). An
// independent discrete-rod Hessian of the clamped bow finds it stable at 1.3 P_cc (least
// eigenvalue 7.9 EI/L², the turn's zero aside) and unstable from 1.444 P_cc on, out of its plane
// (−3.64 EI/L² at 1.5 P_cc): there the warning must not offer the bow as stable.
TEST(Run, PerfectRoundColumnsSettleUpToTheirTurnAboutTheChord) {
  const double L = 0.5, EI = 200e9 * M_PI * 1e-12 / 4;
  auto press = [&](const char* ends, double euler, double ratio) {
    return PressedColumn(ends, L, 101, R"({"shape": "circle", "radius": 0.001})",
                         ratio * euler * EI / (L * L));
  };
  auto mid_span = [&](const Result& r) {
    const auto& p = r.json["nodes"]["position"][50];
    return std::hypot(p[0].get<double>(), p[1].get<double>()) / L;
  };
  const Result pinned = press("pinned-pinned", M_PI * M_PI, 1.2);
  ASSERT_TRUE(pinned.converged) << pinned.log;
  EXPECT_EQ(pinned.json["stability_index"].get<int>(), 0) << pinned.log;
  EXPECT_NEAR(mid_span(pinned), PinnedElasticaMidSpan(1.2), 2e-3) << pinned.log;
  const Result clamped = press("clamped-clamped", 4 * M_PI * M_PI, 1.3);
  ASSERT_TRUE(clamped.converged) << clamped.log;
  EXPECT_EQ(clamped.json["stability_index"].get<int>(), 0) << clamped.log;
  EXPECT_NEAR(mid_span(clamped), PinnedElasticaMidSpan(1.3), 2e-3) << clamped.log;
  const Result past = press("clamped-clamped", 4 * M_PI * M_PI, 1.5);
  ASSERT_TRUE(past.converged) << past.log;
  EXPECT_GT(past.json["stability_index"].get<int>(), 0) << past.log;
  EXPECT_NE(past.log.find("and so is the bow beside it"), std::string::npos) << past.log;
  EXPECT_EQ(past.log.find("the stable one"), std::string::npos) << past.log;
}

// A clamped-pinned flat bar (1 × 4 mm, L = 0.5 m) pressed along its axis, its pin sliding on
// it: the planar elastica's load (truth::ClampedPinnedElastica, shot independently) rises from
// P_cp = 2.0457 π² EI/L² to 1.1396 P_cp and falls. Below the peak (1.05, 1.12 P_cp) the column
// settles on it: index 0, its tip's slide and largest offset within 2e-3 L (the rod's stretch
// and shear are ~1e-5 here; the grid's RK4 error ~1e-6). Past it (1.2 P_cp) no bowed state
// exists: the warning says so, and does not offer one.
TEST(Run, AClampedPinnedColumnSettlesBelowItsPeakLoadAndIsToldItCollapsesPastIt) {
  const double L = 0.5, EI = 200e9 * 0.004 * 1e-9 / 12, Pcp = 2.0457 * M_PI * M_PI * EI / (L * L);
  auto press = [&](double ratio) {
    return PressedColumn("clamped-pinned", L, 101,
                         R"({"shape": "rectangle", "width": 0.004, "height": 0.001})", ratio * Pcp);
  };
  const double euler = 2.0457 * M_PI * M_PI;  // the truth's, EI = L = 1
  for (const double ratio : {1.05, 1.12}) {
    truth::ClampedPinnedElastica bow;
    ASSERT_TRUE(truth::ClampedPinnedElasticaAtLoad(ratio * euler, &bow));
    const Result r = press(ratio);
    ASSERT_TRUE(r.converged) << r.log;
    EXPECT_EQ(r.json["stability_index"].get<int>(), 0) << ratio << r.log;
    EXPECT_EQ(r.log.find("warning"), std::string::npos) << r.log;
    const auto& x = r.json["nodes"]["position"];
    double offset = 0.0;
    for (const auto& p : x)
      offset = std::max(offset, std::hypot(p[0].get<double>(), p[1].get<double>()));
    EXPECT_NEAR(x.back()[2].get<double>() / L, bow.axial_tip, 2e-3) << ratio;
    EXPECT_NEAR(offset / L, bow.largest_offset, 2e-3) << ratio;
  }
  const truth::ClampedPinnedElastica peak = truth::ClampedPinnedElasticaPeak();
  EXPECT_NEAR(peak.load / euler, 1.1396, 1e-4);  // the peak the warning states
  truth::ClampedPinnedElastica none;
  EXPECT_FALSE(truth::ClampedPinnedElasticaAtLoad(1.2 * euler, &none));
  const Result past = press(1.2);
  ASSERT_TRUE(past.converged) << past.log;
  EXPECT_GT(past.json["stability_index"].get<int>(), 0) << past.log;
  EXPECT_NE(past.log.find("carries at most 1.14 times its Euler load"), std::string::npos)
      << past.log;
  EXPECT_EQ(past.log.find("the stable one"), std::string::npos) << past.log;
}

// Quaternion-FD buckling of the steel cantilever column (examples/buckling_column.json as a
// cantilever): the grid's error is second order and low, about −0.084 (k h)². Where it passes
// 1e-3 a note estimates it: within [0.8, 1.25] of the error against Euler's π²EI/(4L²) (shear
// shifts that by ~(r/L)² = 4e-6) on 3, 5 and 9 nodes; the nodes it asks for bring the error
// below 1e-4; on 65 nodes (5.5e-5) it says nothing.
TEST(Run, QuaternionFdBucklingOnACoarseGridSaysByHowMuch) {
  nlohmann::json doc = testing::SourceJson("examples/buckling_column.json");
  doc.erase("boundary");
  doc["formulation"] = "quaternion-fd";
  const double EI = 200e9 * M_PI * 1e-12 / 4, L = 0.5, euler = M_PI * M_PI * EI / (4 * L * L);
  auto search = [&](int nodes) {
    doc["rod"]["nodes"] = nodes;
    const io::ParseResult parsed = io::ParseProblem(doc.dump());
    EXPECT_TRUE(parsed.ok());
    const Result r = cosserat::run::Run(*parsed.problem);
    EXPECT_EQ(r.json["buckling"]["status"], "found") << r.log;
    return r;
  };
  for (int nodes : {3, 5, 9}) {
    const Result r = search(nodes);
    const double error = std::abs(r.json["buckling"]["critical_load"].get<double>() / euler - 1);
    testing::ExpectEstimateWithin(r.log, "(quaternion FD), about ", false, error, 0.8, 1.25);
    if (nodes != 3) continue;
    const size_t asked = r.log.find("\"nodes\": ");
    ASSERT_NE(asked, std::string::npos) << r.log;
    const Result finer = search(std::stoi(r.log.substr(asked + 9)));
    EXPECT_LT(std::abs(finer.json["buckling"]["critical_load"].get<double>() / euler - 1), 1e-4);
  }
  const Result fine = search(65);
  EXPECT_EQ(fine.log.find("coarse"), std::string::npos) << fine.log;
}

// An eversion robot grids its body by length as it grows: at rod.nodes' density over its
// length, and at least 40 nodes per metre. The banded vine (1.2 m, two bands whose ends are
// nodes) asked for 401 nodes gets them (and more at its band ends); asked for 9 (the fewest
// its breakpoints allow), it keeps 40 per metre (55 nodes) and says so.
TEST(Run, AnEversionRobotTakesTheGridItIsAskedForAndSaysWhenItRefinesIt) {
  nlohmann::json doc = testing::SourceJson("robots/eversion_banded_vine.json");
  auto run = [&](int nodes) {
    doc["rod"]["nodes"] = nodes;
    const io::ParseResult parsed = io::ParseProblem(doc.dump());
    EXPECT_TRUE(parsed.ok());
    return cosserat::run::Run(*parsed.problem);
  };
  const Result fine = run(401);
  ASSERT_TRUE(fine.converged) << fine.log;
  EXPECT_GE(fine.json["nodes"]["s"].size(), 401u);
  // A grown solve reports its Newton work and its last residual, not placeholders of 0, and the
  // length it first kinked at is one of its steps' (the file's growth from 0.1 m in 55 steps).
  EXPECT_GT(fine.json["iterations"].get<int>(), 0);
  EXPECT_GT(fine.json["residual"].get<double>(), 0.0);
  const double kinked = fine.json["robot"]["first_kink_length"].get<double>();
  const double step = (1.2 - 0.1) / 55, k = (kinked - 0.1) / step;
  EXPECT_NEAR(k, std::round(k), 1e-9) << kinked;
  EXPECT_EQ(fine.log.find("gridded at"), std::string::npos) << fine.log;
  const Result coarse = run(9);
  ASSERT_TRUE(coarse.converged) << coarse.log;
  EXPECT_EQ(coarse.json["nodes"]["s"].size(), 55u);
  EXPECT_NE(coarse.log.find("rod.nodes (9) gives 6.67 nodes per metre"), std::string::npos)
      << coarse.log;
}

// A grown robot's result holds every growth step: robot.growth lists each step's length (the
// file's L0 + k (L − L0)/steps, L0 = 0.1 m, 55 steps to 1.2 m), tip and wrinkling ratio, the last
// step's tip the result's; and its VTK series has one frame per step, at t = that length, with
// the radius of its own nodes: the tube's 25 mm away from the bands (a radius taken from the
// final grid would put a band's 12.5 mm on other nodes of the shorter bodies).
TEST(Run, AGrownRobotKeepsEveryGrowthStep) {
  nlohmann::json doc = testing::SourceJson("robots/eversion_banded_vine.json");
  doc["rod"]["nodes"] = 9;  // the robot's own 40 per metre
  const io::ParseResult parsed = io::ParseProblem(doc.dump());
  ASSERT_TRUE(parsed.ok());
  RunOptions options;
  options.frames = true;
  const Result r = cosserat::run::Run(*parsed.problem, options);
  ASSERT_TRUE(r.converged) << r.log;
  const auto& growth = r.json["robot"]["growth"];
  ASSERT_EQ(growth["length"].size(), 55u);
  ASSERT_EQ(growth["tip"].size(), 55u);
  ASSERT_EQ(growth["max_moment_ratio"].size(), 55u);
  ASSERT_EQ(r.frames.size(), 55u);
  const std::vector<std::pair<double, double>> bands = {{0.30, 0.32}, {0.60, 0.62}, {0.90, 0.92}};
  for (int k = 0; k < 55; ++k) {
    const double length = growth["length"][k].get<double>();
    EXPECT_NEAR(length, 0.1 + (k + 1) * (1.2 - 0.1) / 55, 1e-12) << k;
    const io::VtkFrame& frame = r.frames[k];
    EXPECT_EQ(frame.t, length);
    ASSERT_EQ(frame.rods.size(), 1u);
    ASSERT_EQ(frame.radius.size(), 1u);
    const RodState& body = frame.rods[0];
    ASSERT_EQ(frame.radius[0].size(), body.s.size()) << k;
    EXPECT_NEAR(body.s.back(), length, 1e-12) << k;
    for (int i = 0; i < body.size(); ++i) {
      bool near_band = false;
      for (const auto& [a, b] : bands) near_band |= body.s[i] > a - 1e-9 && body.s[i] < b + 1e-9;
      if (!near_band) EXPECT_EQ(frame.radius[0][i], 0.025) << "step " << k << " s " << body.s[i];
    }
    const nlohmann::json& tip = growth["tip"][k];
    for (int c = 0; c < 3; ++c) EXPECT_EQ(tip[c].get<double>(), body.tip_position_W()[c]);
  }
  EXPECT_EQ(growth["tip"][54], r.json["tip"]["position"]);
}

// The inflated tube's laws are thin-walled (I = π r³ t drops terms of order t/r): a wall of 0.8
// of the radius is noted with that fraction, a 75 µm one on a 25 mm tube (0.003) is not.
TEST(Run, AThickWalledInflatedTubeIsNoted) {
  for (const double wall : {7.5e-5, 0.02}) {  // m
    std::ostringstream text;
    text << R"({"format": "cosserat-problem/1",
      "rod": {"length": 0.6, "nodes": 61, "section": {"shape": "circle", "radius": 0.025},
              "material": {"youngs_modulus": 1e8, "poisson_ratio": 0.45, "density": 920},
              "stiffness_profile": {"kind": "inflated", "wall_thickness": )" << wall << R"(,
                                    "pressure": 3000, "modulus": {"E0": 1e8, "slope": 1e4}}},
      "loads": {"gravity": [0, 0, -9.81]}})";
    const io::ParseResult parsed = io::ParseProblem(text.str());
    ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
    const Result r = cosserat::run::Run(*parsed.problem);
    ASSERT_TRUE(r.converged) << r.log;
    // π r³ t against π (r⁴ − (r − t)⁴)/4 at t = 0.8 r: 0.8 / (0.25 (1 − 0.2⁴)) = 3.21.
    EXPECT_EQ(r.log.find("wall_thickness is 0.8 of the tube's radius: its thin-wall bending "
                         "stiffness (I = π r³ t) is 3.21 times") != std::string::npos,
              wall > 0.01)
        << r.log;
  }
}

// A steel wire (L = 0.5 m, r = 1 mm, EI = 0.157 N·m²) pushed at its free tip by 62 N settles
// folded back (the elastica's tip 0.10 m aside, 0.40 m behind the clamp) with κ ≈ 40 /m at the
// clamp: 0.49 rad per segment on 41 nodes, whose nodes then lie a chord apart, 1 % short of the
// segment. Its axial strain is P/EA = 9.9e-5, far below steel's 1 % warning: none is due.
TEST(Run, AWireFoldedBackIsNotReadAsCompressed) {
  const io::ParseResult parsed = io::ParseProblem(R"({
    "format": "cosserat-problem/1",
    "rod": {"length": 0.5, "nodes": 41, "section": {"shape": "circle", "radius": 0.001},
            "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
    "loads": {"tip_force": [0, 0, -62], "tip_force_frame": "world"}})");
  ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
  const Result r = cosserat::run::Run(*parsed.problem);
  ASSERT_TRUE(r.converged) << r.log;
  EXPECT_LT(r.json["tip"]["position"][2].get<double>(), -0.3) << r.log;  // folded back
  EXPECT_EQ(r.log.find("stretched or compressed"), std::string::npos) << r.log;
  // Quaternion-FD vertices are joined by straight segments |Γ| h long, not arcs: the same wire
  // bent by an 11 N side force on 11 nodes (0.5 rad per segment, strain 1.7e-5) is no more
  // compressed than its segments are.
  const io::ParseResult side = io::ParseProblem(R"({
    "format": "cosserat-problem/1", "formulation": "quaternion-fd",
    "rod": {"length": 0.5, "nodes": 11, "section": {"shape": "circle", "radius": 0.001},
            "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
    "loads": {"tip_force": [11, 0, 0], "tip_force_frame": "world"}})");
  ASSERT_TRUE(side.ok()) << side.errors.front();
  const Result bent = cosserat::run::Run(*side.problem);
  ASSERT_TRUE(bent.converged) << bent.log;
  EXPECT_EQ(bent.log.find("stretched or compressed"), std::string::npos) << bent.log;
}

// A wire held between anchors farther apart than its length stretches by their ratio, uniformly:
// steel (E = 200 GPa) at 2.6 % carries 5 GPa, past any steel's strength, and is warned; at 0.5 %
// it is not. A rubber cord (E = 1 MPa, of any density) stretched 5 % is within its linear
// range's reach (warned from 10 %).
TEST(Run, AMetalStretchedPastWhatItBearsIsWarned) {
  auto pulled = [](double E, double density, double stretch) {
    std::ostringstream text;
    text << std::setprecision(17) << R"({"format": "cosserat-problem/1",
      "formulation": "quaternion-fd",
      "rod": {"length": 10, "nodes": 21, "section": {"shape": "circle", "radius": 0.002},
              "material": {"youngs_modulus": )" << E << R"(, "poisson_ratio": 0.3,
                           "density": )" << density << R"(}},
      "boundary": "anchored", "anchor": {"position": [)" << 10 * (1 + stretch) << R"(, 0, 0]},
      "base": {"rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]}})";
    const io::ParseResult parsed = io::ParseProblem(text.str());
    EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
    const Result r = cosserat::run::Run(*parsed.problem);
    EXPECT_TRUE(r.converged) << r.log;
    return r.log.find("warning: the rod is stretched or compressed") != std::string::npos;
  };
  EXPECT_TRUE(pulled(200e9, 7850, 0.026));
  EXPECT_FALSE(pulled(200e9, 7850, 0.005));
  EXPECT_FALSE(pulled(1e6, 1000, 0.05));
  EXPECT_FALSE(pulled(1e6, 1e-3, 0.05));  // a rubber cord made nearly weightless is still rubber
}

// A 0.6 m vine (r = 25 mm, wall 75 µm, E = 1e8 + 1e4 p Pa at p = 3 kPa: EI = 0.479 N·m²) pushed
// along its axis stands straight either side of its Euler load π²EI/4L² = 3.28 N, which the
// pressure does not raise (a closed vessel): at half of it the log is silent, at 1.6 times
// (5.25 N, still under the wall's pπr² = 5.89 N) it warns that the straight body is unstable.
TEST(Run, AVinePushedPastItsEulerLoadIsWarnedUnstable) {
  const double EI = (1e8 + 1e4 * 3000) * M_PI * std::pow(0.025, 3) * 7.5e-5;  // N·m²
  const double euler = M_PI * M_PI * EI / (4 * 0.36);                          // N
  for (const double share : {0.5, 1.6}) {
    const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
      "rod": {"length": 0.6, "nodes": 61, "section": {"shape": "circle", "radius": 0.025},
              "material": {"youngs_modulus": 1e8, "poisson_ratio": 0.45, "density": 920},
              "stiffness_profile": {"kind": "inflated", "wall_thickness": 7.5e-5,
                                    "pressure": 3000, "modulus": {"E0": 1e8, "slope": 1e4}}},
      "loads": {"tip_force": [0, 0, )" + std::to_string(-share * euler) + R"(]},
      "robot": {"kind": "eversion", "actuation": {"pressure": 3000}}})");
    ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
    const Result r = cosserat::run::Run(*parsed.problem);
    ASSERT_TRUE(r.converged) << r.log;
    EXPECT_EQ(r.log.find("warning: this equilibrium is unstable") != std::string::npos,
              share > 1.0)
        << share << " of the Euler load\n" << r.log;
  }
}

// Hetényi's semi-infinite beam on an elastic foundation: a 5 m steel rod (r = 5 mm) lying on a
// penalty plane (k = 1e5 N/m², ℓ = (4EI/k)^¼ = 0.25 m, βL = 20) under its weight q and a tip
// load P = 8 N sinks at its tip by q/k + ε/2 + 2Pβ/k (ε the penalty's smoothing, 1e-3 of the
// diameter). On the quaternion-FD grid the penetration's error is second order in h/ℓ: the
// warning's estimate must be within [0.8, 1.25] of the tip's (26 and 51 nodes: h/ℓ = 0.8, 0.4);
// on 201 nodes (0.21 %) it says nothing. The far field, q/k + ε/2, is exact on every grid.
TEST(Run, AQuaternionFdRodOnAFoundationTheGridDoesNotResolveIsWarned) {
  const double r = 0.005, EI = 200e9 * M_PI * std::pow(r, 4) / 4, k = 1e5, P = 8.0;
  const double q = 8000 * M_PI * r * r * 9.81, beta = std::pow(k / (4 * EI), 0.25);
  const double sunk = q / k + 0.5e-3 * 2 * r + 2 * P * beta / k;  // m
  auto lying = [](int nodes, const std::string& tip_force) {
    const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
        "formulation": "quaternion-fd",
        "rod": {"length": 5, "nodes": )" + std::to_string(nodes) + R"(,
                "section": {"shape": "circle", "radius": 0.005},
                "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
        "base": {"position": [0, 0, 0.005], "rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
        "loads": {"gravity": [0, 0, -9.81], "tip_force": )" + tip_force + R"(},
        "environment": {"contact": [{"shape": "plane", "point": [0, 0, 0], "normal": [0, 0, 1],
                                     "stiffness": 1e5}]}})");
    EXPECT_TRUE(parsed.ok());
    return cosserat::run::Run(*parsed.problem);
  };
  // Pulled along the bed instead, the tip presses nothing in: no word.
  EXPECT_EQ(lying(26, "[50, 0, 0]").log.find("penetration"), std::string::npos);
  for (int nodes : {26, 51, 201}) {
    const Result run = lying(nodes, "[0, 0, -8]");
    ASSERT_TRUE(run.converged) << run.log;
    const double tip = r - run.json["tip"]["position"][2].get<double>();
    const double error = std::abs(tip / sunk - 1);
    const size_t at = run.log.find("penetration may be off by about ");
    if (nodes == 201) {
      EXPECT_EQ(at, std::string::npos) << run.log;
      EXPECT_LT(error, 5e-3);
      continue;
    }
    testing::ExpectEstimateWithin(run.log, "penetration may be off by about ", true, error, 0.8,
                                  1.25);
  }
}

// The finger of examples/finger_on_sphere.json on the SE(3) path: contact.total_force is the force
// the solve applied (the rod's balance, RK4's stages between the nodes included); the nodes'
// contact_force, summed by the trapezoid rule, samples the patch at the nodes only. On 11 nodes
// the two differ by 10 %: a note says so, with that figure, and the nodes it asks for bring the
// difference within 1 %; on 41 (1.3 %) nothing is said.
TEST(Run, ANarrowContactPatchTheNodesUndersampleIsNoted) {
  nlohmann::json doc = testing::SourceJson("examples/finger_on_sphere.json");
  doc["formulation"] = "se3-shooting";
  auto run = [&](int nodes, double* off) {
    doc["rod"]["nodes"] = nodes;
    const io::ParseResult parsed = io::ParseProblem(doc.dump());
    EXPECT_TRUE(parsed.ok());
    const Result r = cosserat::run::Run(*parsed.problem);
    EXPECT_TRUE(r.converged) << r.log;
    const auto& s = r.json["nodes"]["s"];
    const auto& f = r.json["nodes"]["contact_force"];
    Vec3 sum = Vec3::Zero(), total;
    for (size_t i = 1; i < s.size(); ++i)
      for (int j = 0; j < 3; ++j)
        sum(j) += 0.5 * (s[i].get<double>() - s[i - 1].get<double>()) *
                  (f[i][j].get<double>() + f[i - 1][j].get<double>());
    for (int j = 0; j < 3; ++j) total(j) = r.json["contact"]["total_force"][j].get<double>();
    *off = (sum - total).norm() / total.norm();
    return r;
  };
  double off = 0.0;
  const Result coarse = run(11, &off);
  EXPECT_GT(off, 0.05);
  const size_t at = coarse.log.find("their sum along s is ");
  ASSERT_NE(at, std::string::npos) << coarse.log;
  EXPECT_NEAR(std::stod(coarse.log.substr(at + 21)), 100 * off, 0.01 * 100 * off);
  const size_t asked = coarse.log.find("rod.nodes ≥ ", at);
  ASSERT_NE(asked, std::string::npos) << coarse.log;
  run(std::stoi(coarse.log.substr(asked + std::string("rod.nodes ≥ ").size())), &off);
  EXPECT_LT(off, 0.01);
  const Result fine = run(41, &off);
  EXPECT_EQ(fine.log.find("samples the contact"), std::string::npos) << fine.log;
  // The patch on 11 nodes lies on one node: a note says the force and the shape depend on the
  // grid there, with the nodes that put five on it, where it is said no more.
  const std::string narrow = "note: the contact at s = 0.07 m spans 1 node of the grid";
  EXPECT_NE(coarse.log.find(narrow), std::string::npos) << coarse.log;
  const size_t five = coarse.log.find("rod.nodes ≥ ", coarse.log.find(narrow));
  ASSERT_NE(five, std::string::npos) << coarse.log;
  const Result resolved =
      run(std::stoi(coarse.log.substr(five + std::string("rod.nodes ≥ ").size())), &off);
  EXPECT_EQ(resolved.log.find("note: the contact at"), std::string::npos) << resolved.log;
}

// A steel cantilever (L = 0.5 m, r = 5 mm) tilted down 0.02 rad, its tip pressed δ = 4 mm into
// a plane of k = 1e9 N/m²: a point load at the end, P = 3 EI δ / L³ = 9.425 N in beam theory.
// The nodes' values per metre sum to 200 % off it on any grid (the end node's half interval
// takes the patch), so the note says to read the total and asks for no nodes. Tolerance 1 %:
// the finite stiffness lets the tip sink in, the total rising 9.37, 9.39, 9.41 N for k = 1e8,
// 1e9, 1e10 towards P; shear adds (r/L)² = 1e-4.
TEST(Run, ATipPressedOnAPlaneIsAPointContactTheNoteDoesNotAskNodesFor) {
  const double alpha = 0.02, r = 0.005, delta = 0.004, L = 0.5;
  const double EI = 200e9 * M_PI * std::pow(r, 4) / 4;  // N·m²
  const double c = std::cos(alpha), s = std::sin(alpha);
  std::ostringstream text;
  text << std::setprecision(17) << R"({"format": "cosserat-problem/1",
      "rod": {"length": 0.5, "nodes": 101, "section": {"shape": "circle", "radius": 0.005},
              "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
      "base": {"position": [0, 0, 0], "rotation": [[)" << -s << ", 0, " << c << "], [0, 1, 0], ["
       << -c << ", 0, " << -s << R"(]]},
      "environment": {"contact": [{"shape": "plane", "point": [0, 0, )" << -L * s - r + delta
       << R"(], "normal": [0, 0, 1], "stiffness": 1e9}]}})";
  const io::ParseResult parsed = io::ParseProblem(text.str());
  ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
  const Result out = cosserat::run::Run(*parsed.problem);
  ASSERT_TRUE(out.converged) << out.log;
  const double P = 3 * EI * delta / (L * L * L);
  EXPECT_NEAR(out.json["contact"]["total_force"][2].get<double>(), P, 0.01 * P);
  EXPECT_NE(out.log.find("the contact is a point at an end of the rod"), std::string::npos)
      << out.log;
  EXPECT_EQ(out.log.find("rod.nodes ≥"), std::string::npos) << out.log;
}

namespace {
// A steel column (L = 0.5 m, r = 1 mm) in SE(3) dynamics, its tip guided on the axis, pressed by
// `ratio` times `euler` EI/L² (none at 0) and let go from, or held by, a small side load.
Result ColumnInTime(const std::string& ends, double euler, double ratio, double dt,
                    double duration, const std::string& side, bool damped, bool frames) {
  const double L = 0.5, EI = 200e9 * M_PI * 1e-12 / 4, P = ratio * euler * EI / (L * L);
  std::ostringstream text;
  text.precision(17);
  text << R"({"format": "cosserat-problem/1", "analysis": "dynamics", "boundary": ")" << ends
       << R"(", "rod": {"length": 0.5, "nodes": 41,
                "section": {"shape": "circle", "radius": 0.001},
                "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000)"
       << (damped ? R"(, "damping": {"bending": 2e-3})" : "") << R"(}},
        "loads": {"tip_force": [0, 0, )" << -P << "]" << side << R"(},
        "dynamics": {"dt": )" << dt << R"(, "duration": )" << duration
       << R"(, "output_interval": )" << (frames ? dt : duration) << R"(,
                     "initial_loads": {"tip_force": [0, 0, )" << -P
       << R"(], "distributed_force": [0.05, 0, 0]}}})";
  const io::ParseResult parsed = io::ParseProblem(text.str());
  EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
  RunOptions options;
  options.frames = frames;
  return cosserat::run::Run(*parsed.problem, options);
}
}  // namespace

// Clamped–clamped and clamped–pinned columns vibrate in time, their tips sliding on the axis, at
// the first frequency their modes give (frequency shooting about the same equilibrium, an
// independent method; 35.61, 24.54 Hz, and 25.39 Hz pressed by half the clamped Euler load).
// Let go from a side load of 0.05 N/m, the mid-span's period from its zero crossings over 0.2 s
// (7 periods, the third mode mixed in: ~1.5e-4) against BDF2's phase error, about 0.4 (ω dt)²
// (measured 2.6e-3, 4.2e-4, 2.3e-4 at ω dt = 0.089, 0.045, 0.022): 3.5e-4 at dt = 0.1 ms. The
// guided tip stays on the axis to rounding.
TEST(Run, ColumnsVibrateInTimeAtTheFrequencyOfTheirModes) {
  const struct {
    const char* ends;
    double euler, ratio;
  } cases[] = {{"clamped-clamped", 4 * M_PI * M_PI, 0.0},
               {"clamped-pinned", 2.0457 * M_PI * M_PI, 0.0},
               {"clamped-clamped", 4 * M_PI * M_PI, 0.5}};
  for (const auto& c : cases) {
    const double dt = 1e-4;
    const Result r = ColumnInTime(c.ends, c.euler, c.ratio, dt, 0.2, "", false, true);
    ASSERT_TRUE(r.converged) << r.log;
    std::vector<double> mid;
    for (const io::VtkFrame& f : r.frames) {
      mid.push_back(f.rods[0].position_W[20].x());
      EXPECT_LT(f.rods[0].tip_position_W().head<2>().norm(), 1e-9);
    }
    double mean = 0;
    for (double x : mid) mean += x / mid.size();
    std::vector<double> crossings;
    for (size_t i = 0; i + 1 < mid.size(); ++i)
      if (mid[i] - mean > 0 && mid[i + 1] - mean <= 0)
        crossings.push_back(dt * (i + (mid[i] - mean) / (mid[i] - mid[i + 1])));
    ASSERT_GE(crossings.size(), 5u) << c.ends;
    const double f_time = (crossings.size() - 1) / (crossings.back() - crossings.front());
    const double L = 0.5, EI = 200e9 * M_PI * 1e-12 / 4;
    std::ostringstream text;
    text.precision(17);
    text << R"({"format": "cosserat-problem/1", "analysis": "modes", "boundary": ")" << c.ends
         << R"(", "rod": {"length": 0.5, "nodes": 41, "section": {"shape": "circle", "radius":
         0.001}, "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
         "loads": {"tip_force": [0, 0, )" << -c.ratio * c.euler * EI / (L * L) << R"(]},
         "modes": {"count": 2}})";
    const io::ParseResult parsed = io::ParseProblem(text.str());
    ASSERT_TRUE(parsed.ok());
    const Result m = cosserat::run::Run(*parsed.problem);
    ASSERT_TRUE(m.converged) << m.log;
    const double f_modes = m.json["modes"]["frequencies_hz"][0].get<double>();
    EXPECT_NEAR(f_time / f_modes, 1.0, 3.5e-4) << c.ends << " " << c.ratio;
  }
}

// Pressed past its Euler load, a column let go from a side load's bow falls onto its bent branch
// in time: with Kelvin–Voigt damping (τ = 2 ms in bending) and a side load of 1e-3 N/m left it
// settles within 3 s on an elastica (on either side: it swings through the axis, and the small
// load does not choose): clamped–clamped at 1.2 P_cc to the mid-span of four quarter-waves,
// 0.324 L; clamped–pinned at 1.1 P_cp to its largest offset, 0.288 L
// (truth::ClampedPinnedElastica). Within 2e-3 L: the side load moves it by ~7e-4 L, stretch and
// shear by ~1e-5.
TEST(Run, AColumnPastItsEulerLoadBucklesInTimeOntoItsElastica) {
  const std::string side = R"(, "distributed_force": [1e-3, 0, 0])";
  const Result cc = ColumnInTime("clamped-clamped", 4 * M_PI * M_PI, 1.2, 1e-3, 3.0, side, true,
                                 false);
  ASSERT_TRUE(cc.converged) << cc.log;
  EXPECT_NEAR(std::abs(cc.json["nodes"]["position"][20][0].get<double>()) / 0.5,
              PinnedElasticaMidSpan(1.2), 2e-3);
  const Result cp = ColumnInTime("clamped-pinned", 2.0457 * M_PI * M_PI, 1.1, 1e-3, 3.0, side,
                                 true, false);
  ASSERT_TRUE(cp.converged) << cp.log;
  double offset = 0.0;
  for (const auto& p : cp.json["nodes"]["position"])
    offset = std::max(offset, std::abs(p[0].get<double>()));
  truth::ClampedPinnedElastica bow;
  ASSERT_TRUE(truth::ClampedPinnedElasticaAtLoad(1.1 * 2.0457 * M_PI * M_PI, &bow));
  EXPECT_NEAR(offset / 0.5, bow.largest_offset, 2e-3);
}

// A steel pipe (outer radius 0.0635 m, inner 0.054 m, in air) lying in a horizontal bore of
// radius 0.108 m (penalty stiffness k_c N/m per m), pinned where its weight w holds it: the
// penalty's k_c φ(δ) = w, φ = δ − ε/2 past the smoothing ε = 1e-3 of the diameter, δ²/2ε within
// it. The bore holds it sideways like a Winkler foundation of w/d per metre (d: its centreline's
// distance from the bore's axis; Dawson & Paslay 1984): its lateral modes sin(nπx/L) buckle at
// P_n = EI a² + (w/d)/a², a = nπ/L.
struct PipeInBore {
  double L, k_c;
  double w = 7850 * M_PI * (0.0635 * 0.0635 - 0.054 * 0.054) * 9.81;  // N/m
  double EI = 200e9 * M_PI / 4 * (std::pow(0.0635, 4) - std::pow(0.054, 4));
  double eps = 1e-3 * 0.127;
  double Depth() const {
    return w / k_c > eps / 2 ? w / k_c + eps / 2 : std::sqrt(2 * eps * w / k_c);
  }
  std::vector<double> Roots() const {  // ascending
    std::vector<double> P;
    for (int n = 1; n < 60; ++n) {
      const double a = n * M_PI / L;
      P.push_back(EI * a * a + w / (0.0445 + Depth()) / (a * a));
    }
    std::sort(P.begin(), P.end());
    return P;
  }
  Result Run(double P, const std::string& more_loads = "") const {
    std::ostringstream text;
    text.precision(17);
    text << R"({"format": "cosserat-problem/1", "boundary": "pinned-pinned",
        "rod": {"length": )" << L << R"(, "nodes": )" << static_cast<int>(4 * L) + 1 << R"(,
          "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.054},
          "material": {"youngs_modulus": 200e9, "poisson_ratio": 0.3, "density": 7850}},
        "base": {"position": [0, 0, 0], "rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
        "loads": {"gravity": [0, 0, -9.81], "tip_force": [)" << -P << ", 0, 0]" << more_loads
         << R"(},
        "environment": {"contact": [{"shape": "cylinder", "point": [0, 0, )"
         << 0.0445 + Depth() << R"(], "axis": [1, 0, 0], "radius": 0.108, "side": "inside",
          "stiffness": )" << k_c << "}]}}";
    const io::ParseResult parsed = io::ParseProblem(text.str());
    EXPECT_TRUE(parsed.ok()) << parsed.errors.front();
    return cosserat::run::Run(*parsed.problem);
  }
};

// Pressed at half its first root (at 30 m, 1e5 N: 7.5 times the Euler load of the free pinned
// column) the pipe is stable: index 0 and no warning. Pressed between two roots (at the
// geometric mean of each pair among the first four, at least 2 % from both, against the model's
// 1e-3 of shear and shortening) it has one unstable direction per root below, and a warning.
// At 20 m on a stiff bore (1e7 N/m per m) the solve takes five pieces; between its third and
// fourth roots a conjugate point and an
// eigenvalue of the stiffness rising through zero fell between the same two nodes, and a count
// that looked only where the number of negative eigenvalues changed missed it.
// At 60 m (six pieces; roots 1.6 to 7 % apart) one shot from the base does not reproduce the
// solution (residual 1.7e-5 to 1e-3): the Jacobi fields are carried piece by piece.
TEST(Run, APipePressedInABoreCountsTheWinklerRootsBelowItsLoad) {
  for (const PipeInBore pipe : {PipeInBore{30, 2e4}, PipeInBore{20, 1e7}, PipeInBore{60, 2e5}}) {
    const std::vector<double> P = pipe.Roots();
    std::vector<double> loads{0.5 * P[0]};
    std::vector<int> below{0};
    for (int i = 0; loads.size() < 4; ++i)
      if (P[i + 1] > 1.04 * P[i]) {  // 2 % from both
        loads.push_back(std::sqrt(P[i] * P[i + 1]));
        below.push_back(i + 1);
      }
    for (size_t i = 0; i < loads.size(); ++i) {
      const Result r = pipe.Run(loads[i]);
      ASSERT_TRUE(r.converged) << r.log;
      ASSERT_TRUE(r.json.contains("stability_index")) << pipe.L << " m, " << loads[i] << " N\n"
                                                       << r.log;
      EXPECT_EQ(r.json["stability_index"].get<int>(), below[i])
          << pipe.L << " m, " << loads[i] << " N";
      EXPECT_EQ(r.log.find("unstable") == std::string::npos, i == 0) << r.log;
    }
  }
}

// A drill pipe clamped on the axis of a bore (8.5 in, 1e7 N/m per m), sagging onto its low side
// and pushed at its tip by 0.2 and 0.3 of the Dawson–Paslay load 2 sqrt(EI w/r_c) (170 kN), far
// below where it buckles: stable in both formulations. Between two nodes of the lifted span two
// eigenvalues of the stiffness rose through zero together, which read from the two nodes alone
// exactly as a double conjugate point; a count that took the larger of its readings said 2
// unstable directions. Such a segment is now shot again in 16 steps and counted there.
TEST(Run, ADrillPipeSaggingInABoreBelowItsCriticalLoadIsStableInBothFormulations) {
  const double EI = 207e9 * M_PI / 4 * (std::pow(0.0635, 4) - std::pow(0.0543, 4));
  const double w = 7850 * M_PI * (0.0635 * 0.0635 - 0.0543 * 0.0543) * 9.81;
  const double dawson_paslay = 2 * std::sqrt(EI * w / (0.108 - 0.0635));
  for (const double length : {60.0, 100.0}) {
    for (const double share : {0.2, 0.3}) {
      std::ostringstream text;
      text.precision(17);
      text << R"({"format": "cosserat-problem/1", "formulation": "FORMULATION",
          "rod": {"length": )" << length << R"(, "nodes": 101,
            "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.0543},
            "material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3, "density": 7850}},
          "base": {"rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
          "loads": {"gravity": [0, 0, -9.81], "tip_force": [)" << -share * dawson_paslay
           << R"(, 0, 0]},
          "environment": {"contact": [{"shape": "cylinder", "point": [0, 0, 0],
            "axis": [1, 0, 0], "radius": 0.108, "side": "inside", "stiffness": 1e7}]}})";
      for (const char* formulation : {"se3-shooting", "quaternion-fd"}) {
        const Result r = RunWithFormulation(text.str(), formulation);
        ASSERT_TRUE(r.converged) << formulation << ": " << r.log;
        EXPECT_EQ(r.json["stability_index"].get<int>(), 0)
            << formulation << " at " << length << " m, " << share << " of F_DP";
      }
    }
  }
}

// The same pipe pressed by 1.2e5 N past the free column's Euler load with a dead tip moment of
// 100 N·m, a load that is not conservative in 3-D: its stability index is not defined, and the
// log says that stability is not judged rather than nothing.
TEST(Run, APipeInABoreUnderATipMomentSaysItsStabilityIsNotJudged) {
  const Result r = PipeInBore{30, 2e4}.Run(1.2e5, R"(, "tip_moment": [0, 100, 0])");
  ASSERT_TRUE(r.converged) << r.log;
  EXPECT_FALSE(r.json.contains("stability_index")) << r.log;
  EXPECT_NE(r.log.find("its stability is not judged"), std::string::npos) << r.log;
}

// A round pipe column (L = 100 m, pinned at both ends, no weight) pressed by 50 and 90 Euler
// loads stays straight; its bending roots n² P_E are double (both planes), so its index is
// 2 #{n: n² < P/P_E}: 14 and 18. One shot from its base overflows (sqrt(P/EI) L ≈ 30), so the
// statics take five or six pieces and the Jacobi fields are carried piece by piece. The Prüfer
// angles turned by more than π between nodes in the units first tried, and the count said 16 at
// 90 P_E; the units are now chosen so that they do not.
TEST(Run, APinnedColumnPressedByManyEulerLoadsCountsThemInPieces) {
  const double EI = 200e9 * M_PI / 4 * (std::pow(0.0635, 4) - std::pow(0.0545, 4));
  const double euler = M_PI * M_PI * EI / 1e4;
  for (const double ratio : {50.0, 90.0}) {
    std::ostringstream text;
    text.precision(17);
    text << R"({"format": "cosserat-problem/1", "boundary": "pinned-pinned",
        "rod": {"length": 100, "nodes": 201,
          "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.0545},
          "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 7850}},
        "loads": {"tip_force": [0, 0, )" << -ratio * euler << "]}}";
    const io::ParseResult parsed = io::ParseProblem(text.str());
    ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
    const Result r = cosserat::run::Run(*parsed.problem);
    ASSERT_TRUE(r.converged) << r.log;
    EXPECT_GT(r.json["shooting_segments"].get<int>(), 1);
    int below = 0;
    for (int n = 1; n * n < ratio; ++n) ++below;
    ASSERT_TRUE(r.json.contains("stability_index")) << r.log;
    EXPECT_EQ(r.json["stability_index"].get<int>(), 2 * below) << ratio;
  }
}

// A 300 m pipe lying in a stiff bore (1e6 N/m per m: its weight w = 257 N/m presses it 0.3 mm
// in), pinned at both ends where its weight holds it. Its statics stopped at once
// (load_stepping_failed at 0 of the load): the unloaded pipe laid at that depth is pressed out by
// the wall, not at equilibrium, and the path's secant predictor extrapolated from it pushed the
// pipe deep into the wall. Now it lies straight on the wall, every node at the pins' depth (to
// 1e-9 m: the solve's tolerance is 1e-10 of the length scales, it lands within 1e-15 m), and the
// bore carries the whole weight, w L (to 1e-9 of it).
io::ParseResult PipeLyingInABore(const std::string& more) {
  return io::ParseProblem(R"({"format": "cosserat-problem/1",
    "boundary": "pinned-pinned",
    "rod": {"length": 300, "nodes": 601,
      "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.0545},
      "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 7850}},
    "base": {"position": [-0.044820428956811535, 0, 0]},
    "loads": {"gravity": [-9.81, 0, 0]},
    "environment": {"contact": [{"shape": "cylinder", "point": [0, 0, 0], "axis": [0, 0, 1],
      "radius": 0.108, "side": "inside", "stiffness": 1e6}]})" + more + "}");
}

TEST(Run, ALongPipeLyingInABoreRestsOnItsWall) {
  const io::ParseResult parsed = PipeLyingInABore("");
  ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
  const Result r = cosserat::run::Run(*parsed.problem);
  ASSERT_TRUE(r.converged) << r.log;
  for (const auto& p : r.json["nodes"]["position"])
    EXPECT_NEAR(p[0].get<double>(), -0.044820428956811535, 1e-9);
  const double w = 7850 * M_PI * (0.0635 * 0.0635 - 0.0545 * 0.0545) * 9.81;
  EXPECT_NEAR(r.json["contact"]["total_force"][0].get<double>() / (w * 300), 1.0, 1e-9);
}

// The same pipe pushed along its axis: it buckles sideways at the lowest Winkler root
// P_n = EI a² + (w/d)/a², a = nπ/L, d its centreline's distance from the bore's axis (Dawson &
// Paslay 1984), here n = 25. Its search in pieces stopped at 2/3 of the weight: each warm
// re-solve took steps sized by the whole load rather than its change, and at 1e-10 in units of
// EI/L² the junction forces (77 kN, 6 000 times that unit) stall at their rounding. Shear
// lowers the bending part EI a² of the root by EI a²/κGA, 3e-4 of the load: tolerance 1e-3
// (roots 25 and 26 lie 1.4e-3 apart).
TEST(Run, AThreeHundredMetrePipeInABoreBucklesAtItsWinklerRoot) {
  const io::ParseResult parsed = PipeLyingInABore(R"(, "analysis": "buckling",
    "buckling": {"load": "tip_force", "direction": [0, 0, -1], "max": 327402})");
  ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
  const Result r = cosserat::run::Run(*parsed.problem);
  ASSERT_TRUE(r.converged) << r.log;
  const double EI = 200e9 * M_PI / 4 * (std::pow(0.0635, 4) - std::pow(0.0545, 4));
  const double w = 7850 * M_PI * (0.0635 * 0.0635 - 0.0545 * 0.0545) * 9.81;
  const double k = w / 0.044820428956811535;  // N/m per m
  double lowest = INFINITY;
  for (int n = 1; n < 80; ++n) {
    const double a = n * M_PI / 300;
    lowest = std::min(lowest, EI * a * a + k / (a * a));
  }
  EXPECT_NEAR(r.json["buckling"]["critical_load"].get<double>() / lowest, 1.0, 1e-3);
}

// When such a continuation does stop (here cut to 2 Newton iterations a level), the hint says
// that steps through a surface are refused, and names the surface's stiffness as a cause only
// when the rod's load would press it a fifth of its radius in: 0.3 mm is not (the bore was once
// blamed).
TEST(Run, AStiffBoreIsNotBlamedForAContinuationThatStops) {
  const io::ParseResult parsed = PipeLyingInABore(R"(, "solver": {"max_iterations": 2})");
  ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
  const Result r = cosserat::run::Run(*parsed.problem);
  ASSERT_FALSE(r.converged) << "two iterations a level now follow this pipe: cut them further";
  EXPECT_NE(r.log.find("are refused"), std::string::npos) << r.log;
  EXPECT_EQ(r.log.find("stiffness may be too low"), std::string::npos) << r.log;
}

// A silicone rod (r = 5 mm, E = 1 MPa) standing upright under its own weight: Greenhill's
// critical length (7.837 EI/q)^⅓ = 0.166 m, the second (55.98 EI/q)^⅓ = 0.319 m (Timoshenko &
// Gere 1961). At 0.15 m it stands. At 0.3 m the straight equilibrium its loads reach from the
// unloaded rod has the first, double root behind it, two unstable directions (the quaternion-FD
// statics once said a plain "converged" there), and the rod falls over: both formulations say
// so and write the stable equilibrium beside it, which they agree on to the quaternion-FD grid's
// second-order error (0.49 mm on 41 nodes, 0.13 mm on 81; 1 mm asserted).
Result RunUprightSiliconeRod(const char* formulation, double length, int nodes) {
  const std::string text = std::string(R"({"format": "cosserat-problem/1", "formulation": ")") +
                           formulation + R"(", "rod": {"length": )" + std::to_string(length) +
                           R"(, "nodes": )" + std::to_string(nodes) +
                           R"(, "section": {"shape": "circle", "radius": 0.005},
      "material": {"youngs_modulus": 1e6, "poisson_ratio": 0.5, "density": 1100}},
      "loads": {"gravity": [0, 0, -9.81]}})";
  const io::ParseResult parsed = io::ParseProblem(text);
  EXPECT_TRUE(parsed.ok());
  return cosserat::run::Run(*parsed.problem);
}

TEST(Run, AnUprightRodPastGreenhillsLengthFallsOverInBothFormulations) {
  auto run = [](const char* formulation, double length) {
    return RunUprightSiliconeRod(formulation, length, 41);
  };
  std::vector<Vec3> fallen;
  for (const char* formulation : {"se3-shooting", "quaternion-fd"}) {
    const Result below = run(formulation, 0.15), past = run(formulation, 0.3);
    ASSERT_TRUE(below.converged && past.converged) << formulation;
    EXPECT_EQ(below.json["stability_index"].get<int>(), 0) << formulation;
    EXPECT_EQ(below.log.find("unstable"), std::string::npos) << formulation << below.log;
    EXPECT_EQ(past.json["stability_index"].get<int>(), 0) << formulation;
    EXPECT_NE(past.log.find("from the unloaded rod is unstable (2 unstable directions), and the "
                            "rod settles beside it"),
              std::string::npos)
        << formulation << ": " << past.log;
    const auto& p = past.json["tip"]["position"];
    fallen.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    EXPECT_LT(fallen.back().z(), 0.0) << formulation;  // fallen below its clamp
  }
  EXPECT_LT((fallen[0] - fallen[1]).norm(), 1e-3)
      << fallen[0].transpose() << " vs " << fallen[1].transpose();
}

// The same rod at 0.38 m, between Greenhill's second and third critical lengths (0.319 m and
// (148.5 EI/q)^⅓ = 0.441 m): two double roots behind its straight equilibrium, index 4, counted
// on the quaternion-FD path at 201 nodes by the inertia of its banded stiffness. It falls
// over to where the SE(3) statics put it (4e-5 m apart measured; 1e-4 m asserted).
TEST(Run, AnUprightRodPastTwoGreenhillLengthsCountsFourOnAFineQuaternionFdGrid) {
  std::vector<Vec3> fallen;
  for (const char* formulation : {"quaternion-fd", "se3-shooting"}) {
    const Result r = RunUprightSiliconeRod(formulation, 0.38, 201);
    ASSERT_TRUE(r.converged) << r.log;
    EXPECT_NE(r.log.find("is unstable (4 unstable directions)"), std::string::npos) << r.log;
    EXPECT_EQ(r.json["stability_index"].get<int>(), 0) << r.log;
    const auto& p = r.json["tip"]["position"];
    fallen.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  }
  EXPECT_LT((fallen[0] - fallen[1]).norm(), 1e-4)
      << fallen[0].transpose() << " vs " << fallen[1].transpose();
}

// The same count on grids past where a dense stiffness is affordable (the banded stiffness is
// built and factorised in time linear in the nodes): index 4 on 101, 401 and 1601 nodes, and the
// fallen rod's tip converges at second order in h, the quaternion-FD grid's order: successive
// differences over h = L/100, L/400, L/1600 shrink by 4² = 16 (measured 15.9; 12–20 asserted,
// as the third difference is one sixteenth of the second and rounding is far below both).
TEST(Run, TheQuaternionFdStabilityCountHoldsOnFineGridsAndTheFallenRodConverges) {
  std::vector<double> tip_y;
  for (const int nodes : {101, 401, 1601}) {
    const Result r = RunUprightSiliconeRod("quaternion-fd", 0.38, nodes);
    ASSERT_TRUE(r.converged) << r.log;
    EXPECT_NE(r.log.find("is unstable (4 unstable directions)"), std::string::npos) << r.log;
    EXPECT_EQ(r.json["stability_index"].get<int>(), 0) << r.log;
    tip_y.push_back(std::hypot(r.json["tip"]["position"][0].get<double>(),
                               r.json["tip"]["position"][1].get<double>()));
  }
  const double ratio = (tip_y[0] - tip_y[1]) / (tip_y[1] - tip_y[2]);
  EXPECT_GT(ratio, 12.0) << tip_y[0] << " " << tip_y[1] << " " << tip_y[2];
  EXPECT_LT(ratio, 20.0) << tip_y[0] << " " << tip_y[1] << " " << tip_y[2];
}

// A 2 km drill string (5" pipe, mud inside) hanging from its clamp is in tension everywhere, so
// stable: no direction lowers its energy. On 101 nodes the spacing is 16 bending lengths
// sqrt(EI/T) at the top, where the count of unstable directions (Jacobi fields shot by RK4) once
// said 2, with a warning; in tension everywhere it is 0 on any grid now. A wire lying on a table
// and pulled along it by 2 kN on 11 nodes (k h = 7 at the tip) rests on a surface, which can make
// it unstable: its count is not judged there, and the note names the nodes (k h <= 2.8: 27).
TEST(Run, AHangingDrillStringIsNotCalledUnstableOnACoarseGrid) {
  const io::ParseResult parsed = io::ParseProblem(
      R"({"format": "cosserat-problem/1", "rod": {"length": 2000, "nodes": 101,
      "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.054,
      "contents_density": 1200}, "material": {"youngs_modulus": 2e11, "poisson_ratio": 0.3,
      "density": 7850}}, "base": {"rotation": [[1, 0, 0], [0, -1, 0], [0, 0, -1]]},
      "loads": {"gravity": [0, 0, -9.81]}})");
  ASSERT_TRUE(parsed.ok());
  const Result hanging = cosserat::run::Run(*parsed.problem);
  ASSERT_TRUE(hanging.converged) << hanging.log;
  EXPECT_EQ(hanging.json["stability_index"].get<int>(), 0) << hanging.log;
  EXPECT_EQ(hanging.log.find("unstable"), std::string::npos) << hanging.log;
  EXPECT_EQ(hanging.log.find("not judged"), std::string::npos) << hanging.log;

  nlohmann::json table = testing::SourceJson("examples/rod_on_table.json");
  table["formulation"] = "se3-shooting";
  table["rod"]["nodes"] = 11;
  table["loads"]["tip_force"] = {2000, 0, 0};
  const io::ParseResult pulled = io::ParseProblem(table.dump());
  ASSERT_TRUE(pulled.ok());
  const Result coarse = cosserat::run::Run(*pulled.problem);
  ASSERT_TRUE(coarse.converged) << coarse.log;
  EXPECT_FALSE(coarse.json.contains("stability_index")) << coarse.log;
  EXPECT_NE(coarse.log.find("the stability of this equilibrium is not judged"), std::string::npos)
      << coarse.log;
  EXPECT_NE(coarse.log.find("rod.nodes >= 27 judges it"), std::string::npos) << coarse.log;
}

// A soft rod (E 0.5 MPa, 0.5 m, r 3 mm) hanging from its clamp, its tip pushed up by 0.02 N: the
// compressed length near the tip is past its critical load, and the straight equilibrium both
// formulations reach has two unstable directions. They settle beside it, the SE(3) statics in
// pieces (the weight's tension puts its single shot past its exponent), onto the same bent
// shape: 5e-5 m apart on 101 nodes (the quaternion-FD grid's second-order error; 5e-4 asserted).
TEST(Run, AHangingRodPushedUpAtItsTipBucklesSidewaysInBothFormulations) {
  std::vector<Vec3> tips;
  for (const char* formulation : {"se3-shooting", "quaternion-fd"}) {
    const io::ParseResult parsed = io::ParseProblem(std::string(R"({"format": "cosserat-problem/1",
        "formulation": ")") + formulation + R"(",
        "rod": {"length": 0.5, "nodes": 101, "section": {"shape": "circle", "radius": 0.003},
          "material": {"youngs_modulus": 5e5, "poisson_ratio": 0.5, "density": 1100}},
        "base": {"rotation": [[1, 0, 0], [0, -1, 0], [0, 0, -1]]},
        "loads": {"gravity": [0, 0, -9.81], "tip_force": [0, 0, 0.02]}})");
    ASSERT_TRUE(parsed.ok());
    const Result r = cosserat::run::Run(*parsed.problem);
    ASSERT_TRUE(r.converged) << r.log;
    EXPECT_NE(r.log.find("is unstable (2 unstable directions), and the rod settles beside it"),
              std::string::npos)
        << r.log;
    EXPECT_EQ(r.json["stability_index"].get<int>(), 0) << r.log;
    const auto& p = r.json["tip"]["position"];
    tips.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    EXPECT_GT(std::hypot(tips.back().x(), tips.back().y()), 0.05) << formulation;  // bent aside
  }
  EXPECT_LT((tips[0] - tips[1]).norm(), 5e-4) << tips[0].transpose() << " vs "
                                              << tips[1].transpose();
}

// Silicone-soft rods (E = 0.1 MPa) held out level under their weight hang from their clamps:
// 1 m of radius 1 cm (w L³/EI = 430) on 201 nodes, and 0.6 m of radius 4 mm on 121. Their
// statics go in pieces (their weight puts the single shot's exponent past 10). A whole load step
// from the straight rod converged on an equilibrium looped up over the clamp: the first with 8
// unstable directions (the tip 0.19 m above where it hangs), the second with its count not
// formed on the loop and a plain "converged" (the tip 6.5 cm off). The solve now follows the
// load path instead. The two formulations then agree: the same continuum equations on the same
// grid, each second order, 1.7e-4 m apart on the first and 3.9e-4 m on the second, so within
// 1e-3 m.
TEST(Run, SoftRodsHeldOutLevelHangFromTheirClampsInBothFormulations) {
  for (const char* rod : {R"("length": 1.0, "nodes": 201, "section": {"shape": "circle",
                              "radius": 0.01})",
                          R"("length": 0.6, "nodes": 121, "section": {"shape": "circle",
                              "radius": 0.004})"}) {
    const std::string text = std::string(R"({"format": "cosserat-problem/1",
        "formulation": "FORMULATION", "rod": {)") + rod + R"(,
          "material": {"youngs_modulus": 1e5, "poisson_ratio": 0.5, "density": 1100}},
        "base": {"rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
        "loads": {"gravity": [0, 0, -9.81]}})";
    const Result se3 = RunWithFormulation(text, "se3-shooting");
    const Result fd = RunWithFormulation(text, "quaternion-fd");
    ASSERT_TRUE(se3.converged && fd.converged) << se3.log << fd.log;
    EXPECT_EQ(se3.json["stability_index"].get<int>(), 0) << se3.log;
    EXPECT_EQ(se3.log.find("unstable"), std::string::npos) << se3.log;
    const auto tip = [](const Result& r) {
      const auto& p = r.json["tip"]["position"];
      return Vec3(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    };
    EXPECT_LT((tip(se3) - tip(fd)).norm(), 1e-3) << tip(se3).transpose() << " vs "
                                                  << tip(fd).transpose();
    // Hanging, stretched by its weight: the tip below the clamp by more than the rod's length
    // (1.048 m of the 1 m rod, 0.616 m of the 0.6 m one).
    EXPECT_LT(tip(fd).z(), -fd.json["nodes"]["s"].back().get<double>()) << tip(fd).transpose();
  }
}

// An undamped soft cantilever (E = 1 MPa, 0.3 m, 51 nodes) held straight, released into gravity:
// its equations conserve energy, so what the run loses is BDF2's (its numerical damping of the
// modes the sudden load excites and dt resolves in few steps). The result carries the start's
// total, and the log says how much went whenever it is 1 % of the largest kinetic energy: at
// dt = 5 ms about 43 % in 1 s, less at 1.25 ms; with Kelvin–Voigt damping (a loss the rod
// really has), no note.
TEST(Run, AnUndampedRunSaysWhatEnergyBdf2TookAway) {
  auto run = [](double dt, double tau) {
    std::string damping;
    if (tau > 0) {
      const double r = 0.005, A = 3.14159265358979 * r * r, I = A * r * r / 4, E = 1e6;
      damping = R"(, "damping": {"bending": )" + std::to_string(tau * E * I) +
                R"(, "torsion": )" + std::to_string(tau * E / 3 * 2 * I) +
                R"(, "shear": )" + std::to_string(tau * E / 3 * A) +
                R"(, "extension": )" + std::to_string(tau * E * A) + "}";
    }
    const std::string text =
        R"({"format": "cosserat-problem/1", "analysis": "dynamics",
            "rod": {"length": 0.3, "nodes": 51, "section": {"shape": "circle", "radius": 0.005},
                    "material": {"youngs_modulus": 1e6, "poisson_ratio": 0.5, "density": 1100)" +
        damping + R"(}},
            "base": {"rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
            "loads": {"gravity": [0, 0, -9.81]},
            "dynamics": {"dt": )" +
        std::to_string(dt) + R"(, "duration": 1.0, "initial_loads": {"gravity": [0, 0, 0]}}})";
    const io::ParseResult parsed = io::ParseProblem(text);
    EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
    return cosserat::run::Run(*parsed.problem);
  };
  auto loss = [](const Result& r) {
    const auto& e = r.json["energy"];
    return e["initial_total"].get<double>() -
           (e["kinetic"].get<double>() + e["elastic"].get<double>() + e["potential"].get<double>());
  };
  const Result coarse = run(0.005, 0), fine = run(0.00125, 0), damped = run(0.005, 0.01);
  ASSERT_TRUE(coarse.converged && fine.converged && damped.converged);
  std::printf("undamped release: BDF2 took %.4g J at dt = 5 ms, %.4g J at 1.25 ms\n", loss(coarse),
              loss(fine));
  EXPECT_GT(loss(coarse), loss(fine));
  EXPECT_GT(loss(fine), 0.0);
  EXPECT_NE(coarse.log.find("note: the rod is undamped, yet its total energy fell by"),
            std::string::npos)
      << coarse.log;
  EXPECT_EQ(damped.log.find("note: the rod is undamped"), std::string::npos) << damped.log;
}

// A pneumatic finger whose chamber is pressurised at t = 0 (from the initial actuation's 0 to
// 20 kPa): the switch moves the rest strain, and its work is in no energy term, so the result
// has no initial_total to balance against (the unpressurised start's 0 J would make a run that
// loses 60 % to BDF2 seem to gain energy). Pressurised from the start, the start's total is
// there.
TEST(Run, AnActuationSwitchedAtTheStartLeavesTheEnergyBalanceOut) {
  auto run = [](double initial_pressure) {
    const std::string text = R"({"format": "cosserat-problem/1", "analysis": "dynamics",
        "rod": {"length": 0.1, "nodes": 41, "section": {"shape": "circle", "radius": 0.008},
                "material": {"youngs_modulus": 1e6, "poisson_ratio": 0.5, "density": 1100}},
        "base": {"rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
        "loads": {"gravity": [0, 0, 0]},
        "dynamics": {"dt": 0.0005, "duration": 0.05},
        "robot": {"kind": "pneumatic",
                  "chambers": [{"offset": [-0.004, 0], "area": 2.827e-5}],
                  "initial_actuation": {"chamber_pressure": [)" +
                             std::to_string(initial_pressure) + R"(]},
                  "actuation": {"chamber_pressure": [20000]}}})";
    const io::ParseResult parsed = io::ParseProblem(text);
    EXPECT_TRUE(parsed.ok());
    return cosserat::run::Run(*parsed.problem);
  };
  const Result switched = run(0.0), steady = run(20000.0);
  ASSERT_TRUE(switched.converged && steady.converged);
  EXPECT_FALSE(switched.json["energy"].contains("initial_total")) << switched.json["energy"];
  EXPECT_TRUE(steady.json["energy"].contains("initial_total")) << steady.json["energy"];
}

// The note on energy BDF2 took is about motion, so it neither depends on where the rod is (the
// steel cantilever of examples/cantilever_release.json released from a 2 mN preload loses
// 9.1e-8 J, 18 % of its largest kinetic energy, with its base at the origin or 1 km away, where
// its potential energy is 123 J) nor speaks of a rod left at rest in its static equilibrium
// (the same rod, no preload: a drift of the step solves' size).
TEST(Run, TheEnergyNoteSpeaksOfMotionWhereverTheRodIs) {
  const nlohmann::json example = testing::SourceJson("examples/cantilever_release.json");
  auto run = [&](const Vec3& base, bool preload) {
    nlohmann::json doc = example;
    doc["base"]["position"] = {base.x(), base.y(), base.z()};
    doc["dynamics"]["duration"] = 5.0;
    if (preload) {
      doc["dynamics"]["initial_loads"] = doc["loads"];
      doc["dynamics"]["initial_loads"]["tip_force"] = {-0.002, 0, 0};
    } else {
      doc["dynamics"].erase("initial_loads");
    }
    const io::ParseResult parsed = io::ParseProblem(doc.dump());
    EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
    return cosserat::run::Run(*parsed.problem);
  };
  const std::string note = "note: the rod is undamped, yet its total energy fell by";
  for (const Vec3& base : {Vec3(0, 0, 0), Vec3(1000, 0, 0)}) {
    const Result released = run(base, true), resting = run(base, false);
    ASSERT_TRUE(released.converged && resting.converged);
    EXPECT_NE(released.log.find(note), std::string::npos) << base.x() << ": " << released.log;
    EXPECT_EQ(resting.log.find(note), std::string::npos) << base.x() << ": " << resting.log;
  }
}

// A drill pipe (5 in: r_o 63.5 mm, r_i 54.3 mm) hanging 1000 m in 1.2 SG mud and full of it.
// Pipe and mud weigh (ρ A + ρ_m A_i) g per metre and the mud outside buoys the outer area
// ρ_m A_o g: the hook load is the apparent weight (ρ − ρ_m) A g L, exactly, whatever the shape
// (a straight hanging pipe; statics balances its loads to the residual, ~1e-10 of them). Empty
// (sealed), it would be (ρ A − ρ_m A_o) g L: 49 % lighter here.
TEST(Run, AFilledPipeHangsWithItsApparentWeight) {
  const std::string base = R"({
    "format": "cosserat-problem/1", "formulation": "FORMULATION",
    "rod": {"length": 1000, "nodes": 101,
            "section": {"shape": "annulus", "outer_radius": 0.0635, "inner_radius": 0.0543,
                        "contents_density": 1200},
            "material": {"youngs_modulus": 200e9, "poisson_ratio": 0.3, "density": 7850}},
    "base": {"rotation": [[1, 0, 0], [0, -1, 0], [0, 0, -1]]},
    "loads": {"gravity": [0, 0, -9.81]},
    "environment": {"fluid": {"density": 1200}}})";
  const double A = M_PI * (0.0635 * 0.0635 - 0.0543 * 0.0543);
  const double expected = (7850 - 1200) * A * 9.81 * 1000;  // N, up on the pipe at the hook
  for (const char* formulation : {"se3-shooting", "quaternion-fd"}) {
    const Result r = RunWithFormulation(base, formulation);
    ASSERT_TRUE(r.converged) << r.log;
    const double hook = r.json["base_wrench"]["force"][2].get<double>();
    std::printf("%s: hook load %.6f kN, apparent weight %.6f kN\n", formulation, hook / 1e3,
                expected / 1e3);
    EXPECT_NEAR(hook / expected, 1.0, 1e-8) << formulation;
    EXPECT_TRUE(r.json.contains("bending")) << "the pipe's stresses are still reported";
    // Hanging straight, it carries no moment, so no grid can get its moments wrong: no warning
    // of the tension's bending layer (k h = 2.6).
    EXPECT_EQ(r.log.find("bending layer of the tension"), std::string::npos) << r.log;
  }
}

// The contents move with the pipe: a water-filled steel cantilever (2 m, r_o 10 mm, r_i 8 mm)
// vibrates slower by sqrt(ρA / (ρA + ρ_w A_i)) in both formulations (the first bending mode's
// rotary inertia is ~(r/L)² = 2.5e-5 of it, which the contents do not change: 1e-4 bounds the
// ratio's departure).
TEST(Run, AFilledPipeVibratesWithItsContents) {
  const std::string base = R"({
    "format": "cosserat-problem/1", "analysis": "modes", "formulation": "FORMULATION",
    "rod": {"length": 2, "nodes": 41,
            "section": {"shape": "annulus", "outer_radius": 0.01, "inner_radius": 0.008 CONTENTS},
            "material": {"youngs_modulus": 200e9, "poisson_ratio": 0.3, "density": 7850}},
    "modes": {"count": 1}})";
  const double A = M_PI * (1e-4 - 0.64e-4), Ai = M_PI * 0.64e-4;
  const double expected = std::sqrt(7850 * A / (7850 * A + 1000 * Ai));
  for (const char* formulation : {"se3-shooting", "quaternion-fd"}) {
    double f[2];
    for (int filled = 0; filled < 2; ++filled) {
      std::string text = base;
      text.replace(text.find(" CONTENTS"), 9, filled ? ", \"contents_density\": 1000" : "");
      const Result r = RunWithFormulation(text, formulation);
      ASSERT_TRUE(r.converged) << r.log;
      f[filled] = r.json["modes"]["frequencies_hz"][0].get<double>();
    }
    EXPECT_NEAR(f[1] / f[0] / expected, 1.0, 1e-4) << formulation;
  }
}

// The envelope of a run that stays at rest is its equilibrium: a steel wire hanging from its
// clamp, started in equilibrium, carries T(s) = ρ A g (L − s) at every frame, so both the
// largest and the smallest tension of every node are that (to the solvers' tolerances, 1e-6 of
// the top tension), and no bending moment. A released cantilever's envelope bounds its final
// state.
TEST(Run, TheLoadEnvelopeOfAHangingWireIsItsWeight) {
  const std::string base = R"({
    "format": "cosserat-problem/1", "analysis": "dynamics", "formulation": "FORMULATION",
    "rod": {"length": 1, "nodes": 21, "section": {"shape": "circle", "radius": 0.001},
            "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
    "base": {"rotation": [[1, 0, 0], [0, -1, 0], [0, 0, -1]]},
    "loads": {"gravity": [0, 0, -9.81]},
    "dynamics": {"dt": 0.001, "duration": 0.05, "output_interval": 0.01}})";
  const double top = 8000 * M_PI * 1e-6 * 9.81;  // ρ A g L, N
  for (const char* formulation : {"se3-shooting", "quaternion-fd"}) {
    const Result r = RunWithFormulation(base, formulation);
    ASSERT_TRUE(r.converged) << r.log;
    const auto& e = r.json["envelope"];
    const auto& s = r.json["nodes"]["s"];
    ASSERT_EQ(e["tension_max"].size(), s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double expected = top * (1 - s[i].get<double>());
      EXPECT_NEAR(e["tension_max"][i].get<double>(), expected, 1e-6 * top) << formulation << i;
      EXPECT_NEAR(e["tension_min"][i].get<double>(), expected, 1e-6 * top) << formulation << i;
      EXPECT_LT(e["moment_max"][i].get<double>(), 1e-6 * top) << formulation << i;
    }
  }
  const Result release = cosserat::run::Run(
      *io::LoadProblemFile(std::string(COSSERAT_SOURCE_DIR) + "/examples/cantilever_release.json")
           .problem);
  const auto& e = release.json["envelope"];
  const auto& moment = release.json["nodes"]["moment_body"];
  for (std::size_t i = 0; i < moment.size(); ++i)
    EXPECT_GE(e["moment_max"][i].get<double>(),
              std::hypot(moment[i][0].get<double>(), moment[i][1].get<double>()));
}

// The bending stress is the backbone's: a straight tendon at r_t = 8 mm pulled with 1.5 N bends
// a 0.8 mm steel backbone to κ = T r_t / EI with no external load, so its outer fibre carries
// T r_t r / I = 239 MPa, while the section's resultant moment (backbone plus tendon) is zero.
// It was reported as 0 Pa. To the tendon law's solve (1e-10 relative).
/// A weightless 0.25 m steel backbone (r = 0.4 mm) on `nodes` nodes, bent by one straight tendon
/// `offset` m out (spacer disks 10 mm in radius) pulled with `tension` N, run as the command runs
/// it.
Result OneTendonBackbone(int nodes, double offset, double tension) {
  std::ostringstream text;
  text << std::setprecision(17) << R"({"format": "cosserat-problem/1",
    "rod": {"length": 0.25, "nodes": )" << nodes << R"(,
            "section": {"shape": "circle", "radius": 0.0004},
            "material": {"youngs_modulus": 210e9, "shear_modulus": 80e9, "density": 7800}},
    "robot": {"kind": "tendon", "disk_radius": 0.01,
              "tendons": [{"route": "parallel", "offset": [)" << offset << R"(, 0]}],
              "actuation": {"tension": [)" << tension << "]}}}";
  const io::ParseResult parsed = io::ParseProblem(text.str());
  EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
  return parsed.ok() ? cosserat::run::Run(*parsed.problem) : Result{};
}

TEST(Run, ATendonBentBackboneReportsItsBendingStress) {
  const Result r = OneTendonBackbone(21, 0.008, 1.5);
  ASSERT_TRUE(r.converged) << r.log;
  const double I = M_PI * std::pow(0.0004, 4) / 4;
  const double expected = 1.5 * 0.008 * 0.0004 / I;  // Pa
  for (const auto& sigma : r.json["nodes"]["bending_stress"])
    EXPECT_NEAR(sigma.get<double>() / expected, 1.0, 1e-8);
}

// Two straight tendons 8 mm out pulled with 50 N coil a 0.8 mm steel backbone at 134 1/m,
// 0.84 rad per segment on 41 nodes, five turns, while the tension stretches it by 0.09 %. RK4
// in s shrinks the frames it turns by |1 + z + z²/2 + z³/6 + z⁴/24| per step (z = i κ h), and
// the positions with them: by 39 steps the nodes lie 1 − 0.9978³⁹ = 8.2 % closer than the arc
// between them, which is no stretch (no warning of one, with advice about anchors and tendon
// lengths); the grid's warning names the shrink, to 0.6 points of the amplification factor's: the
// step's own position error, about (κh)⁴/120 = 0.4 % of a segment, adds to the frames' (measured
// 0.43 points), and no stretch is reported.
TEST(Run, ACoilOnACoarseGridIsNotReadAsAStretch) {
  const io::ParseResult parsed = io::ParseProblem(R"({
    "format": "cosserat-problem/1",
    "rod": {"length": 0.25, "nodes": 41, "section": {"shape": "circle", "radius": 0.0004},
            "material": {"youngs_modulus": 210e9, "shear_modulus": 80e9, "density": 7800}},
    "loads": {"tip_force": [0, 0, -0.05]},
    "robot": {"kind": "tendon", "disk_radius": 0.01,
              "tendons": [{"route": "parallel", "offset": [0.008, 0]},
                          {"route": "parallel", "offset": [0, 0.008]}],
              "actuation": {"tension": [50, 50]}}})");
  ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
  const Result r = cosserat::run::Run(*parsed.problem);
  ASSERT_TRUE(r.converged) << r.log;
  EXPECT_EQ(r.log.find("stretched or compressed"), std::string::npos) << r.log;
  const auto& k = r.json["nodes"]["curvature"][0];
  const double theta = std::hypot(k[0].get<double>(), k[1].get<double>()) * 0.25 / 40;  // rad
  const std::complex<double> z(0.0, theta);
  const double per_step = std::abs(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0);
  const double expected = 100 * (1 - std::pow(per_step, 39));  // %
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.log, m, std::regex("the nodes lie ([0-9.]+) % closer"))) << r.log;
  EXPECT_NEAR(std::stod(m[1].str()), expected, 0.6) << r.log;
}

// A soft rod (E = 1 MPa, r = 5 mm: EA = 78.5 N) pressed by a 1.5 N follower force shortens by
// 1.9 % while a tip moment bends it 0.59 rad per segment: its nodes lie 1.9 % closer than the
// arc of its reference length, which is its strain, not RK4 shrinking its frames (0.02 % at
// this turn over 10 steps): the grid's warning does not blame RK4 for it.
// A tendon 4 mm out pulled with 2 N bends a soft backbone (E = 1 MPa, r = 5 mm: EA = 78.5 N)
// 0.815 rad per segment on 7 nodes and compresses it by T/EA = 2.5 %, which the section's
// resultant force (zero at a free tip) does not show. Left out, the spacing's shortfall is RK4's
// alone: 1 − 0.99824⁵ = 0.88 % by the fifth segment, to 0.6 points (the step's own position
// error, (κh)⁴/120 = 0.37 % of a segment, adds to it); it read 3.8 %.
TEST(Run, ATendonsCompressionIsNotBlamedOnRk4) {
  const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
    "rod": {"length": 0.3, "nodes": 7, "section": {"shape": "circle", "radius": 0.005},
            "material": {"youngs_modulus": 1e6, "shear_modulus": 3.4e5, "density": 1100}},
    "robot": {"kind": "tendon", "disk_radius": 0.006,
              "tendons": [{"route": "parallel", "offset": [0.004, 0]}],
              "actuation": {"tension": [2.0]}}})");
  ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
  const Result r = cosserat::run::Run(*parsed.problem);
  ASSERT_TRUE(r.converged) << r.log;
  const double theta = 2.0 * 0.004 / (1e6 * M_PI * std::pow(0.005, 4) / 4) * 0.05;  // κ h, rad
  const std::complex<double> z(0.0, theta);
  const double per_step = std::abs(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.log, m, std::regex("the nodes lie ([0-9.]+) % closer"))) << r.log;
  EXPECT_NEAR(std::stod(m[1].str()), 100 * (1 - std::pow(per_step, 5)), 0.6) << r.log;
}

TEST(Run, ACompressedRodsShorterSpacingIsNotBlamedOnRk4) {
  const io::ParseResult parsed = io::ParseProblem(R"({"format": "cosserat-problem/1",
    "rod": {"length": 1.0, "nodes": 11, "section": {"shape": "circle", "radius": 0.005},
            "material": {"youngs_modulus": 1e6, "shear_modulus": 4e5, "density": 1000}},
    "loads": {"tip_moment": [0.0029, 0, 0], "tip_force": [0, 0, -1.5],
              "tip_force_frame": "body"}})");
  ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
  const Result r = cosserat::run::Run(*parsed.problem);
  ASSERT_TRUE(r.converged) << r.log;
  EXPECT_NE(r.log.find("the grid resolves the shape coarsely"), std::string::npos) << r.log;
  EXPECT_EQ(r.log.find("RK4 shrinks the frames"), std::string::npos) << r.log;
}

// A straight tendon 4 mm out bends a weightless 0.25 m steel backbone (r = 0.4 mm) into a circle
// of κ = T r_t / EI: at κ L = 7.5 rad (T = 31.7 N) it closes more than a full turn and lies
// on itself, which the model, with no self-contact, lets it pass through; at κ L = 5 rad
// (T = 21.1 N) its ends stay 0.1 sin(2.5) = 60 mm apart, 75 diameters. The note comes with the
// first only.
TEST(Run, ARodThatPassesThroughItselfIsNoted) {
  const double EI = 210e9 * M_PI * std::pow(0.0004, 4) / 4;  // N·m²
  for (const double kappa : {30.0, 20.0}) {  // 1/m
    const Result r = OneTendonBackbone(101, 0.004, kappa * EI / 0.004);
    ASSERT_TRUE(r.converged) << r.log;
    EXPECT_EQ(r.log.find("the rod passes within its outer diameter (0.0008 m) of itself") !=
                  std::string::npos,
              kappa * 0.25 > 2 * M_PI)
        << "kappa L = " << kappa * 0.25 << "\n" << r.log;
  }
}

// A 10 kg plate on four 1 mm wires (625 times the most compliant rod's EI/L²) stalled at a
// balance of 2.6e-10 to 5e-10 of round-off under the default tolerance 1e-10 and ended
// load_stepping_failed. With the round-off floor it converges, and the wires share the weight as
// on a rigid plate over equal wires: T_i = W/4 (1 + e_x x_i/a² + e_y y_i/b²), corners (x_i, y_i)
// = (∓0.4, ∓0.25) m about their centre, the mass e = (0.1, −0.05) m from it. The plate tilts
// by ~3e-5 rad, which moves the lever arms by as much: 1e-4 bounds the difference.
TEST(Run, APlateOnTautWiresConvergesAndSharesItsWeightLinearly) {
  const Result r = cosserat::run::Run(Load("tests/cli/plate_on_four_wires.json"));
  ASSERT_TRUE(r.converged) << r.log;
  const double W = 10 * 9.81, x[] = {-0.4, 0.4, 0.4, -0.4}, y[] = {-0.25, -0.25, 0.25, 0.25};
  for (int i = 0; i < 4; ++i) {
    const double tension = r.json["assembly"]["rods"][i]["base_wrench"]["force"][2].get<double>();
    const double expected = W / 4 * (1 + 0.1 * x[i] / 0.16 - 0.05 * y[i] / 0.0625);
    EXPECT_NEAR(tension / expected, 1.0, 1e-4) << i;
  }
}

// A 10 kg payload hanging on 1 m of steel wire of radius r from a clamp, pushed aside by 2 N
// (the initial loads) and let go, at time step dt.
io::Problem PayloadOnAWire(double radius, double dt, double duration) {
  nlohmann::json doc = nlohmann::json::parse(R"({
    "format": "cosserat-problem/1", "analysis": "dynamics",
    "rod": {"length": 1.0, "nodes": 41, "section": {"shape": "circle"},
            "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
    "base": {"rotation": [[1, 0, 0], [0, -1, 0], [0, 0, -1]]},
    "loads": {"gravity": [0, 0, -9.81]},
    "dynamics": {"tip_mass": 10,
                 "initial_loads": {"gravity": [0, 0, -9.81], "tip_force": [2, 0, 0]}}})");
  doc["rod"]["section"]["radius"] = radius;
  doc["dynamics"]["dt"] = dt;
  doc["dynamics"]["duration"] = duration;
  const io::ParseResult parsed = io::ParseProblem(doc.dump());
  EXPECT_TRUE(parsed.ok()) << parsed.errors.front();
  return parsed.problem.value_or(io::Problem());
}

// The crossings of zero by x(t), interpolated linearly.
std::vector<double> ZeroCrossings(const std::vector<double>& t, const std::vector<double>& x) {
  std::vector<double> crossings;
  for (size_t i = 0; i + 1 < t.size(); ++i)
    if (x[i] * x[i + 1] < 0)
      crossings.push_back(t[i] + x[i] / (x[i] - x[i + 1]) * (t[i + 1] - t[i]));
  return crossings;
}

// A payload's swing against the tensioned-beam pendulum: starts at x₀ = (F/T) L_e and swings
// with ω² = g/L_e, L_e = L − tanh(κL)/κ, κ = √(T/EI) (small-deflection theory of a tensioned
// beam with a free tip under a lateral force F: δ = (F/T) L_e). The wire's own weight (0.25 % of
// the payload's for 1 mm) is left out of T, and its mass out of the pendulum's: 1 % covers both.
// Returns L_e.
double ExpectPendulumSwing(const Result& r, double radius) {
  const double T = 10 * 9.81, EI = 200e9 * M_PI * std::pow(radius, 4) / 4;
  const double kappa = std::sqrt(T / EI), L_e = 1.0 - std::tanh(kappa) / kappa;
  std::vector<double> x;
  for (const auto& p : r.json["trajectory"]["tip_position"]) x.push_back(p[0].get<double>());
  EXPECT_NEAR(x.front() / (2.0 / T * L_e), 1.0, 1e-2) << radius;
  const std::vector<double> crossings =
      ZeroCrossings(r.json["trajectory"]["t"].get<std::vector<double>>(), x);
  EXPECT_GE(crossings.size(), 3u) << radius;
  if (crossings.size() >= 3)
    EXPECT_NEAR((crossings[2] - crossings[0]) / (2 * M_PI * std::sqrt(L_e / 9.81)), 1.0, 1e-2)
        << radius;
  return L_e;
}

// On 1 mm wire the tension T ≈ m g gives κL = L √(T/EI) = 25: one shot from the clamp cannot
// resolve it, and from a rigid-body guess it settled on a looped shape or did not converge.
TEST(Run, APayloadOnAWireStartsInEquilibriumAndSwingsAsAPendulum) {
  const io::Problem problem = PayloadOnAWire(0.001, 0.005, 2.5);
  const Result r = cosserat::run::Run(problem);
  ASSERT_TRUE(r.converged) << r.log;
  const double L_e = ExpectPendulumSwing(r, 0.001);

  // The energy, the payload's included: at 2.5 s (1.27 periods, near the bottom of the swing)
  // as after the first step, to 1 % of the swing's ½ k x₀² = ½ (T/L_e) x₀² (BDF2 takes ~4e-4 of
  // it over two periods; without the payload's share the total moved by all of it).
  auto total = [](const Result& run) {
    const auto& e = run.json["energy"];
    return e["kinetic"].get<double>() + e["elastic"].get<double>() + e["potential"].get<double>();
  };
  io::Problem first_step = problem;
  first_step.dynamics.duration = first_step.dynamics.dt;
  const Result start = cosserat::run::Run(first_step);
  ASSERT_TRUE(start.converged) << start.log;
  const double T = 10 * 9.81, x0 = 2.0 / T * L_e, swing = 0.5 * T / L_e * x0 * x0;
  EXPECT_NEAR(total(r), total(start), 1e-2 * swing);
}

// The same payload on a 0.5 mm wire (κL = 100, L_e = 0.99 m) at dt = 2 ms: the wire carries
// 1e4 times the force scale EI/L², and its steps stalled between residuals 1e-10 and 1e-9 (the
// shot's round-off) short of the tolerance; the stepper now asks no less than 1e3 ε of its
// unknowns.
TEST(Run, APayloadOnAThinWireSwingsPastTheShotsRoundOff) {
  const Result r = cosserat::run::Run(PayloadOnAWire(0.0005, 0.002, 2.6));
  ASSERT_TRUE(r.converged) << r.log;
  ExpectPendulumSwing(r, 0.0005);
}

// The same on four wires: a plate on taut wires pushed aside by 0.5 N swings as a parallelogram
// pendulum, x₀ = (F/mg) L_e and ω² = g/L_e with the wire's L_e (the wires are pinned to the
// plate, free of moment like the free tip above). Wires of 1 mm (κL = 12.5) and 2 mm (3.1): the
// rods' own start used to fail for the first (one shot from the clamp, 1.7e-6 of tip position
// short), and the body's for the second (the Jacobian's 1 µm moved a wire's tension by 10 %).
// The wires' mass is 0.0025 % of the plate's and their tension's change over a swing ~1e-6 of
// it: 1 % covers the time step.
TEST(Run, APlateOnTautWiresSwingsAsAParallelogramPendulum) {
  for (const double radius : {0.001, 0.002}) {
    // Four wires from the ceiling (z = 1 m) to the corners of a 0.8 m × 0.5 m plate at z = 0.
    nlohmann::json rods = nlohmann::json::array();
    for (const auto& corner : {std::array<double, 2>{-0.4, -0.25}, {0.4, -0.25}, {0.4, 0.25},
                               {-0.4, 0.25}}) {
      rods.push_back(nlohmann::json::parse(R"({
        "rod": {"length": 1.0, "nodes": 21, "section": {"shape": "circle"},
                "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 80}},
        "base": {"rotation": [[1, 0, 0], [0, -1, 0], [0, 0, -1]]},
        "tip": {"joint": "pinned", "body": "plate"}})"));
      rods.back()["name"] = "w" + std::to_string(rods.size());
      rods.back()["rod"]["section"]["radius"] = radius;
      rods.back()["base"]["position"] = {corner[0], corner[1], 1.0};
      rods.back()["tip"]["attachment"]["position"] = {corner[0], corner[1], 0.0};
    }
    nlohmann::json doc = nlohmann::json::parse(R"({
      "format": "cosserat-problem/1", "analysis": "dynamics",
      "loads": {"gravity": [0, 0, -9.81]},
      "assembly": {"bodies": [{"name": "plate", "mass": 10, "inertia": [0.3, 0.3, 0.6],
                               "pose": {"position": [0, 0, 0]}, "initial_force": [0.5, 0, 0]}]},
      "dynamics": {"dt": 0.01, "duration": 2.5}})");
    doc["assembly"]["rods"] = rods;
    const io::ParseResult parsed = io::ParseProblem(doc.dump());
    ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
    const Result r = cosserat::run::Run(*parsed.problem);
    ASSERT_TRUE(r.converged) << radius << ": " << r.log;
    const double T = 10 * 9.81 / 4, EI = 200e9 * M_PI * std::pow(radius, 4) / 4;
    const double kappa = std::sqrt(T / EI), L_e = 1.0 - std::tanh(kappa) / kappa;
    const auto& body = r.json["trajectory"]["bodies"][0]["position"];
    const std::vector<double> t = r.json["trajectory"]["t"].get<std::vector<double>>();
    EXPECT_NEAR(body[0][0].get<double>() / (0.5 / (4 * T) * L_e), 1.0, 1e-2) << radius;
    std::vector<double> x;
    for (const auto& p : body) x.push_back(p[0].get<double>());
    const std::vector<double> crossings = ZeroCrossings(t, x);
    ASSERT_GE(crossings.size(), 3u) << radius;
    EXPECT_NEAR((crossings[2] - crossings[0]) / (2 * M_PI * std::sqrt(L_e / 9.81)), 1.0, 1e-2)
        << radius;
  }
}

// A diverged solve's iterate (a 105 m cable of EI = 0.1 N·m² on a 0.5 m grid: a tip 30 km off)
// is stretched by millions of percent: the log's hint names the grid, and no warning blames the
// units for it (the stretch warning is for converged answers).
TEST(Run, ADivergedSolveIsNotBlamedOnTheUnits) {
  const io::ParseResult parsed = io::ParseProblem(R"({
    "format": "cosserat-problem/1", "analysis": "statics",
    "rod": {"length": 105.0, "nodes": 201,
            "section": {"area": 0.001, "I1": 1e-12, "I2": 1e-12, "J": 2e-12},
            "material": {"youngs_modulus": 1e11, "poisson_ratio": 0.3, "density": 7850}},
    "boundary": "anchored", "anchor": {"position": [100.0, 0, 20.0]},
    "loads": {"gravity": [0, 0, -9.81]}})");
  ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
  const Result r = cosserat::run::Run(*parsed.problem);
  ASSERT_FALSE(r.converged);
  EXPECT_NE(r.log.find("coarse for the bending boundary layers"), std::string::npos) << r.log;
  EXPECT_EQ(r.log.find("check the units"), std::string::npos) << r.log;
}

// The same plate pushed sideways by 0.01 and 0.5 N at its centre of mass: the wires lean, each
// with the lateral stiffness T/L_e of a tensioned beam clamped at the top and free of moment at
// the plate (L_e = L − tanh(κL)/κ, κ = √(T/EI)), and the tension-weighted centre of the wires
// is the centre of mass, so the plate moves x = F / Σ T_i/L_e,i without turning. Its load steps
// used to stall (a tip tangent converted with Rᵀ where the shot's R had drifted, round-off in the
// taut wires' tension, and at 0.5 N a push before the wires were taut). 1 %: the wires'
// different L_e turn the plate by ~1e-4 rad.
TEST(Run, APlatePushedSidewaysOnTautWiresMovesAsTheirLateralStiffnessSays) {
  const double W = 10 * 9.81, EI = 200e9 * M_PI * 1e-12 / 4;
  const double x[] = {-0.4, 0.4, 0.4, -0.4}, y[] = {-0.25, -0.25, 0.25, 0.25};
  double stiffness = 0.0;  // N/m
  for (int i = 0; i < 4; ++i) {
    const double T = W / 4 * (1 + 0.1 * x[i] / 0.16 - 0.05 * y[i] / 0.0625);
    const double kappa = std::sqrt(T / EI);
    stiffness += T / (1.0 - std::tanh(kappa) / kappa);
  }
  std::string text, why;
  ASSERT_TRUE(io::ReadTextFile(
      std::string(COSSERAT_SOURCE_DIR) + "/tests/cli/plate_on_four_wires.json", &text, &why))
      << why;
  // 0.5 N moves it 4.7 mm, still linear. The last case, on 41 nodes with wires of some weight,
  // came back "converged" turned 125° above the clamps while the push was applied to slack wires.
  struct Case {
    double force;  // N
    int nodes;
    double density;  // kg/m³
  };
  for (const Case c : {Case{0.01, 21, 0.0}, Case{0.5, 21, 0.0}, Case{0.01, 41, 80.0}}) {
    nlohmann::json doc = nlohmann::json::parse(text);
    doc["assembly"]["bodies"][0]["force"] = {c.force, 0, 0};
    for (auto& rod : doc["assembly"]["rods"]) {
      rod["rod"]["nodes"] = c.nodes;
      rod["rod"]["material"]["density"] = c.density;
    }
    const io::ParseResult parsed = io::ParseProblem(doc.dump());
    ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
    const double force = c.force;
    const Result r = cosserat::run::Run(*parsed.problem);
    ASSERT_TRUE(r.converged) << force << ": " << r.log;
    const double moved = r.json["assembly"]["bodies"][0]["position"][0].get<double>() - 0.1;
    EXPECT_NEAR(moved / (force / stiffness), 1.0, 1e-2) << force;
  }
}

// A statics whose load steps stop short says how far they got: a silicone rod (E 0.1 MPa, 1 m,
// r 5 mm) held out level under gravity on 21 nodes (it hangs, bent by several radians per
// segment near the clamp) stops at about half its weight; the result's load_reached lies in
// (0, 1) and the hint names it.
TEST(Run, StaticsThatStopShortSayHowFarTheLoadsGot) {
  const io::ParseResult parsed = io::ParseProblem(R"({
    "format": "cosserat-problem/1",
    "rod": {"length": 1.0, "nodes": 21, "section": {"shape": "circle", "radius": 0.005},
            "material": {"youngs_modulus": 1e5, "poisson_ratio": 0.5, "density": 1100}},
    "base": {"rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
    "loads": {"gravity": [0, 0, -9.81]}})");
  ASSERT_TRUE(parsed.ok());
  const Result r = cosserat::run::Run(*parsed.problem);
  ASSERT_FALSE(r.converged);
  ASSERT_EQ(r.json["status"], "load_stepping_failed");
  const double reached = r.json["load_reached"].get<double>();
  EXPECT_GT(reached, 0.0);
  EXPECT_LT(reached, 1.0);
  EXPECT_NE(r.log.find("stopped short of the full load, at"), std::string::npos) << r.log;
}

// A solve that converges onto NaN (a rod of 1e-300 m: the quaternion-FD segment length
// underflows in its strains) is reported as non_finite, not as a converged result with nulls.
TEST(Run, ANonFiniteAnswerIsNotConverged) {
  io::Problem problem = Load("examples/cantilever.json");
  problem.formulation = io::Formulation::kQuaternionFd;
  problem.nodes = 5;
  problem.rod.length = 1e-300;
  const Result r = cosserat::run::Run(problem);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.json["status"], "non_finite") << r.log;
  EXPECT_NE(r.log.find("NaN or Inf"), std::string::npos) << r.log;
}

// A dynamics result says how the default scheme in s stepped: the peer release's 40 nodes are 39
// equal segments, 2hλ ≈ 0.44 ≤ ½ at dt = 2 ms, so 19 pairs and one segment alone: 20 steps; with
// "rk4" every segment is a step.
TEST(Run, ADynamicsResultReportsTheStepsOfTheShot) {
  io::Problem problem = Load("examples/cantilever_release.json");
  problem.dynamics.duration = 0.01;
  EXPECT_EQ(cosserat::run::Run(problem).json["shot_steps"], 20);
  problem.dynamics.spatial_scheme = io::ShotScheme::kRk4;
  EXPECT_EQ(cosserat::run::Run(problem).json["shot_steps"], 39);
}

// The contract: frames every output_interval from t = 0, and the end of the run when it falls
// between two. 0.025 s at 0.01 s intervals: 0, 0.01, 0.02, 0.025 in both formulations (the
// quaternion-FD run used to skip the frame at 0.02).
TEST(Run, FramesComeEveryOutputIntervalAndAtTheEnd) {
  io::Problem problem = Load("examples/cantilever_release.json");
  problem.dynamics.duration = 0.025;
  problem.dynamics.dt = 0.005;
  problem.dynamics.output_interval = 0.01;
  for (const io::Formulation f : {io::Formulation::kSe3Shooting, io::Formulation::kQuaternionFd}) {
    problem.formulation = f;
    const Result r = cosserat::run::Run(problem);
    ASSERT_TRUE(r.converged) << r.log;
    const std::vector<double> t = r.json["trajectory"]["t"].get<std::vector<double>>();
    const std::vector<double> expected{0.0, 0.01, 0.02, 0.025};
    ASSERT_EQ(t.size(), expected.size()) << io::ToString(f);
    // The times are k dt or k × output_interval in floating point: 1e-12 s covers their
    // rounding and fails on a frame moved by any step (5 ms) or skipped.
    for (size_t k = 0; k < t.size(); ++k) EXPECT_NEAR(t[k], expected[k], 1e-12) << io::ToString(f);
  }
}

// The bending stress at the clamp of a weightless cantilever under a tip force F (world) is fixed by
// the moment balance about the base, M = |x_tip × F|, whatever the deflection: σ = M r / I for the
// wire's circle. The report's largest stress is there (the moment falls to zero at the tip). The
// solve's residual (1e-10 of EI/L) bounds the tolerance; 1e-8 relative is ample.
TEST(Run, ReportsTheBendingStressTheMomentBalanceGives) {
  io::Problem problem = Load("examples/cantilever.json");
  problem.loads.gravity_W.setZero();
  const Vec3 F(-0.2, 0.1, 0.0);
  problem.loads.tip_force = F;
  const Result r = cosserat::run::Run(problem);
  ASSERT_TRUE(r.converged);
  const auto& tip = r.json["tip"]["position"];
  const Vec3 x_tip(tip[0].get<double>(), tip[1].get<double>(), tip[2].get<double>());
  const double radius = 0.001, I = M_PI * std::pow(radius, 4) / 4;
  const double sigma = x_tip.cross(F).norm() * radius / I;  // Pa
  const double reported = r.json["nodes"]["bending_stress"][0].get<double>();
  EXPECT_NEAR(reported, sigma, 1e-8 * sigma);
  EXPECT_EQ(r.json["bending"]["max_stress"].get<double>(), reported);
  EXPECT_EQ(r.json["bending"]["max_stress_s"].get<double>(), 0.0);
  EXPECT_NEAR(r.json["nodes"]["bending_stress"][problem.nodes - 1].get<double>(), 0.0, 1e-8 * sigma);
}

// A steel rod (r = 2 mm, 0.5 m, free-free) dropped flat from H = 5 cm onto a frictionless,
// undamped floor: all of it falls and lands at once, so energy conservation gives the deepest
// penetration, q (H + δ) = k δ²/2, q the weight per metre. At k = 1e4 N/m² δ = 3.24 mm, past
// the radius: the centreline goes beyond the floor, which the log must say; at k = 1e5,
// δ = 1.00 mm, half the radius, and it must not. (BDF2 at ω dt = 0.03 and 0.1 takes 5e-5 and
// 2e-3 of the bounce's energy, which only makes δ smaller; ε = 4 µm of smoothing shifts it by
// 2 µm.)
TEST(Run, ARodDroppedThroughASoftFloorIsWarnedOf) {
  const auto drop = [](const char* stiffness) {
    const io::ParseResult parsed = io::ParseProblem(std::string(R"({
      "format": "cosserat-problem/1", "analysis": "dynamics", "boundary": "free-free",
      "rod": {"length": 0.5, "nodes": 21, "section": {"shape": "circle", "radius": 0.002},
              "material": {"youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000}},
      "base": {"position": [0, 0, 0.052], "rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
      "loads": {"gravity": [0, 0, -9.81]},
      "dynamics": {"dt": 1e-4, "duration": 0.13, "output_interval": 1e-3,
                   "initial_loads": {"gravity": [0, 0, 0]}},
      "environment": {"contact": [{"shape": "plane", "point": [0, 0, 0], "normal": [0, 0, 1],
                                   "stiffness": )") + stiffness + "}]}}");
    EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : parsed.errors.front());
    return cosserat::run::Run(*parsed.problem);
  };
  const Result soft = drop("1e4"), firm = drop("1e5");
  EXPECT_TRUE(soft.converged) << soft.log;
  EXPECT_TRUE(firm.converged) << firm.log;
  EXPECT_NE(soft.log.find("went through environment.contact[0] (its centreline beyond the "
                          "surface"),
            std::string::npos)
      << soft.log;
  EXPECT_EQ(firm.log.find("went through"), std::string::npos) << firm.log;
}

// On the quaternion-FD path: a cantilever (0.5 m, r = 2 mm) released onto a sphere (r = 1 cm)
// below its tip goes through it at k = 1e3 N/m² and stays out at 1e5. The truth is the run's
// own geometry, recorded every 5 ms (the tip, falling under 1 m/s, takes over 10 ms to cross
// the core's 1 cm): the warning is given exactly when some frame has a node within half the
// sphere's radius of its centre.
TEST(Run, AQuaternionFdRodThroughASphereIsWarnedOfWhenItsFramesSayItWent) {
  for (const char* stiffness : {"1e3", "1e5"}) {
    const io::ParseResult parsed = io::ParseProblem(std::string(R"({
      "format": "cosserat-problem/1", "analysis": "dynamics", "formulation": "quaternion-fd",
      "rod": {"length": 0.5, "nodes": 51, "section": {"shape": "circle", "radius": 0.002},
              "material": {"youngs_modulus": 2e10, "shear_modulus": 8e9, "density": 8000}},
      "base": {"position": [0, 0, 0], "rotation": [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]},
      "loads": {"gravity": [0, 0, -9.81]},
      "dynamics": {"dt": 5e-4, "duration": 0.2, "output_interval": 5e-3,
                   "initial_loads": {"gravity": [0, 0, 0]}},
      "environment": {"contact": [{"shape": "sphere", "center": [0.4, 0, -0.03],
                                   "radius": 0.01, "stiffness": )") + stiffness + "}]}}");
    ASSERT_TRUE(parsed.ok()) << parsed.errors.front();
    RunOptions options;
    options.frames = true;
    const Result out = cosserat::run::Run(*parsed.problem, options);
    ASSERT_TRUE(out.converged) << out.log;
    double nearest = 1.0;  // m, any frame's node to the centre
    for (const io::VtkFrame& frame : out.frames)
      for (const Vec3& p : frame.rods[0].position_W)
        nearest = std::min(nearest, (p - Vec3(0.4, 0, -0.03)).norm());
    const bool went = nearest < 0.005;
    EXPECT_EQ(went, std::string(stiffness) == "1e3") << nearest;  // the premise of the case
    EXPECT_EQ(out.log.find("went through environment.contact[0]") != std::string::npos, went)
        << stiffness << '\n' << out.log;
  }
}

}  // namespace
}  // namespace cosserat::run
