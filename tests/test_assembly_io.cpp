// Assemblies in problem files ("assembly", docs/problem-format.md#assembly) and their runs
// (run::Run): robots/stewart_gough.json is the robot ContinuumStewartGough() builds; its inverse
// kinematics fed back as lengths returns the pose; the guided beam example deflects as
// P L³/(24 EI); the result's pose Jacobian matches central differences of forward runs; bad
// input names its JSON path.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cosserat/io/problem.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/robots/stewart_gough.hpp"
#include "cosserat/rod/section_profile.hpp"
#include "cosserat/run/run.hpp"

namespace cosserat {
namespace {

using json = nlohmann::json;

io::Problem Load(const std::string& relative_path) {
  const io::ParseResult r =
      io::LoadProblemFile(std::string(COSSERAT_SOURCE_DIR) + "/" + relative_path);
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors.front());
  EXPECT_TRUE(r.problem && io::UnsupportedFeatures(*r.problem).empty());
  return r.problem.value_or(io::Problem());
}

Vec3 ReadVec3(const nlohmann::ordered_json& a) {
  return Vec3(a[0].get<double>(), a[1].get<double>(), a[2].get<double>());
}

Mat3 ReadRows(const nlohmann::ordered_json& rows) {
  Mat3 R;
  for (int i = 0; i < 3; ++i) R.row(i) = ReadVec3(rows[i]).transpose();
  return R;
}

/// The pose of body 0 in a result.
lie::SE3 BodyPose(const run::Result& r) {
  const auto& body = r.json["assembly"]["bodies"][0];
  lie::SE3 pose;
  pose.p = ReadVec3(body["position"]);
  pose.R = ReadRows(body["rotation"]);
  return pose;
}

std::vector<double> Lengths(const run::Result& r) {
  std::vector<double> out;
  for (const auto& rod : r.json["assembly"]["rods"]) out.push_back(rod["length"].get<double>());
  return out;
}

/// The same problem solved forward at `lengths`.
io::Problem Forward(io::Problem p, const std::vector<double>& lengths) {
  p.assembly.inverse_poses.clear();
  p.assembly.lengths = lengths;
  return p;
}

// The file and the builder: the same rods, holes, joints and sections. The file's numbers are
// Python's shortest round-trip decimals of the builder's formula (scripts/make_stewart_gough.py),
// so the holes agree to the last bit or two (1e-16 m asked); the material is given by its Poisson
// ratio in both, so the stiffnesses agree to round-off.
TEST(AssemblyIo, StewartGoughFileIsTheRobotTheBuilderMakes) {
  const io::Problem p = Load("robots/stewart_gough.json");
  ASSERT_TRUE(p.has_assembly);
  const Assembly& file = p.assembly.assembly;
  const Assembly built = ContinuumStewartGough();
  ASSERT_EQ(file.rods.size(), built.rods.size());
  ASSERT_EQ(file.bodies.size(), 1u);
  EXPECT_EQ(file.bodies[0].name, built.bodies[0].name);
  EXPECT_EQ(file.bodies[0].mass, built.bodies[0].mass);
  EXPECT_LT((file.bodies[0].pose.p - built.bodies[0].pose.p).norm(), 1e-16);
  for (size_t i = 0; i < built.rods.size(); ++i) {
    const AssemblyRod &a = file.rods[i], &b = built.rods[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.nodes, b.nodes);
    EXPECT_EQ(a.model.length, b.model.length);
    EXPECT_EQ(a.base_joint, b.base_joint);
    EXPECT_EQ(a.tip_joint, b.tip_joint);
    EXPECT_EQ(a.body, b.body);
    EXPECT_LT((a.base.p - b.base.p).norm(), 1e-16) << a.name;
    EXPECT_LT((a.attachment.p - b.attachment.p).norm(), 1e-16) << a.name;
    EXPECT_TRUE(a.base.R.isIdentity() && a.attachment.R.isIdentity());
    const SectionProperties sa = a.model.section->At(0, {}), sb = b.model.section->At(0, {});
    EXPECT_LT((sa.stiffness - sb.stiffness).cwiseAbs().maxCoeff(),
              1e-14 * sb.stiffness.cwiseAbs().maxCoeff());
    EXPECT_NEAR(sa.mass(3, 3), sb.mass(3, 3), 1e-14 * sb.mass(3, 3));  // ρA, kg/m
  }
  const lie::SE3& target = p.assembly.inverse_poses.at(0);
  EXPECT_LT((target.p - Vec3(0, 0.02, 0.45)).norm(), 1e-16);
  EXPECT_NEAR(lie::SO3Log(target.R).z(), 0.1, 1e-15);
}

// Inverse kinematics from the file, its lengths fed back as a forward problem: the platform
// returns to the file's pose within 1e-6 m and 1e-6 rad (both solves converge to 1e-10 of their
// scales, so it returns to ~1e-10 m; the library test reaches 1e-10 m for another pose). The
// result's pose is the target itself (the inverse problem holds it).
TEST(AssemblyIo, StewartGoughInverseThenForwardReturnsThePose) {
  const io::Problem inverse = Load("robots/stewart_gough.json");
  const run::Result ri = run::Run(inverse);
  ASSERT_TRUE(ri.converged) << ri.log;
  const lie::SE3 target = inverse.assembly.inverse_poses.at(0);
  EXPECT_LT((BodyPose(ri).p - target.p).norm(), 1e-12);
  const std::vector<double> lengths = Lengths(ri);
  ASSERT_EQ(lengths.size(), 6u);

  const run::Result rf = run::Run(Forward(inverse, lengths));
  ASSERT_TRUE(rf.converged) << rf.log;
  const lie::SE3 pose = BodyPose(rf);
  const double dp = (pose.p - target.p).norm();
  const double dr = lie::SO3Log(Mat3(target.R.transpose() * pose.R)).norm();
  std::printf("Stewart-Gough file: %s  forward back within %.2e m, %.2e rad\n", ri.log.c_str(), dp,
              dr);
  EXPECT_LT(dp, 1e-6);
  EXPECT_LT(dr, 1e-6);
  EXPECT_EQ(rf.json["assembly"]["kind"], "forward");
  EXPECT_EQ(ri.json["assembly"]["kind"], "inverse");
}

// The result's pose Jacobian (inverse run: from the forward solve at its lengths) against
// central differences of forward runs at L ± h, h = 1e-5 m, for every rod. Truncation is
// O(h²) ≈ 1e-10 relative; each solve's pose error (~1e-11 m at its 1e-10 tolerance) over 2h adds
// ~1e-6: entries of order 1 must agree to 1e-5.
TEST(AssemblyIo, ResultPoseJacobianMatchesCentralDifferences) {
  const io::Problem inverse = Load("robots/stewart_gough.json");
  const run::Result ri = run::Run(inverse);
  ASSERT_TRUE(ri.converged) << ri.log;
  const auto& J = ri.json["assembly"]["pose_jacobian"];
  ASSERT_EQ(J.size(), 6u);
  const std::vector<double> lengths = Lengths(ri);
  const double h = 1e-5;
  double worst = 0.0;
  for (size_t c = 0; c < lengths.size(); ++c) {
    std::vector<double> plus = lengths, minus = lengths;
    plus[c] += h;
    minus[c] -= h;
    const lie::SE3 a = BodyPose(run::Run(Forward(inverse, plus)));
    const lie::SE3 b = BodyPose(run::Run(Forward(inverse, minus)));
    Vec6 fd;
    fd.head<3>() = (a.p - b.p) / (2 * h);
    fd.tail<3>() = lie::SO3Log(Mat3(b.R.transpose() * a.R)) / (2 * h);  // body frame
    for (int r = 0; r < 6; ++r) worst = std::max(worst, std::abs(J[r][c].get<double>() - fd(r)));
  }
  std::printf("pose Jacobian vs central differences: max difference %.2e\n", worst);
  EXPECT_LT(worst, 1e-5);
}

// examples/guided_beam.json: each wire a guided beam carrying P/2, δ = P L³/(24 EI). The plate's
// residual turn adds 3 r²/d² ≈ 3e-4 of δ, shear 3e-5, the geometric nonlinearity (δ/L)² ≈ 4e-7:
// within 1e-3.
TEST(AssemblyIo, GuidedBeamExampleDeflectsAsBeamTheory) {
  const io::Problem p = Load("examples/guided_beam.json");
  const run::Result r = run::Run(p);
  ASSERT_TRUE(r.converged) << r.log;
  const double EI = 200e9 * M_PI * std::pow(0.001, 4) / 4, P = 0.01, L = 0.5;
  const double expected = P * L * L * L / (24 * EI);
  const double delta = BodyPose(r).p.x();
  std::printf("guided beam example: plate moves %.6e m, P L^3/(24 EI) = %.6e m (%.1e)\n", delta,
              expected, delta / expected - 1);
  EXPECT_NEAR(delta, expected, 1e-3 * expected);
  // The two base reactions together carry the load (the rods are weightless here): to the
  // solve's tolerance, 1e-10 of EI/L² ≈ 0.63 N, i.e. 6e-11 N. (Each carries P/2 only to 0.4 %:
  // the axial forces N = ±P L/d that take the couple stiffen the wire in tension against
  // sideways motion and soften the other by N L²/(10 EI) = 0.8 %, shifting each share by half.)
  double sum = 0.0;
  for (int i = 0; i < 2; ++i)
    sum += r.json["assembly"]["rods"][i]["base_wrench"]["force"][0].get<double>();
  EXPECT_NEAR(sum, -P, 1e-7 * P);
}

// The L-frame's --csv table holds each node's numbers as the result JSON does: every number
// reads back to the same double, written as the shortest text that does, as a single rod's
// table writes them (17 digits would write s = 0.01 as 0.010000000000000000).
TEST(AssemblyIo, TheNodeTableWritesTheResultsNumbersShortest) {
  run::RunOptions options;
  options.nodes_csv = true;
  const run::Result r = run::Run(Load("examples/l_frame.json"), options);
  ASSERT_TRUE(r.converged) << r.log;
  std::istringstream table(r.nodes_csv);
  std::string line;
  std::getline(table, line);
  EXPECT_EQ(line, "rod,s,x,y,z");
  int rows = 0, rod = -1, n = 0;  // n: the node within its rod
  while (std::getline(table, line)) {
    std::vector<std::string> cell;
    std::istringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) cell.push_back(f);
    ASSERT_EQ(cell.size(), 5u) << line;
    n = std::stoi(cell[0]) == rod ? n + 1 : 0;
    rod = std::stoi(cell[0]);
    const auto& nodes = r.json["assembly"]["rods"][rod]["nodes"];
    // The same double, in no more characters than nlohmann's own shortest text (which adds
    // ".0" to a whole number).
    const auto same = [&](const std::string& text, const nlohmann::ordered_json& value) {
      EXPECT_EQ(std::stod(text), value.get<double>()) << line;
      EXPECT_LE(text.size(), value.dump().size()) << line;
    };
    same(cell[1], nodes["s"][n]);
    for (int k = 0; k < 3; ++k) same(cell[2 + k], nodes["position"][n][k]);
    ++rows;
  }
  EXPECT_GT(rows, 10);
}

// examples/l_frame.json: the members' internal forces against statics. P hangs from the beam's
// end, b = 0.3 m out: the column carries P in compression (force_body z = −P) and the constant
// bending moment P b; the beam's moment falls linearly from P b at the corner to 0 at its end, its
// shear is P. Tolerances: the sway (1.5e-4 m) moves the lever arms by 5e-4 of b and tilts the
// members by ~1e-3 rad; the solve's tolerance, 1e-10 of EI/L², is far below.
TEST(AssemblyIo, TheLFramesMembersCarryTheirStaticsInternalForces) {
  const io::Problem p = Load("examples/l_frame.json");
  const run::Result r = run::Run(p);
  ASSERT_TRUE(r.converged) << r.log;
  const double P = 0.00098175, b = 0.3;  // N, m: the file's load and beam
  const auto& column = r.json["assembly"]["rods"][0]["nodes"];
  const auto& beam = r.json["assembly"]["rods"][1]["nodes"];
  for (std::size_t i = 0; i < column["s"].size(); ++i) {
    const Vec3 m = ReadVec3(column["moment_body"][i]), n = ReadVec3(column["force_body"][i]);
    EXPECT_NEAR(m.norm(), P * b, 2e-3 * P * b) << "column node " << i;
    EXPECT_NEAR(n.z(), -P, 1e-5 * P) << "column node " << i;
  }
  const std::size_t last = beam["s"].size() - 1;
  for (std::size_t i = 0; i <= last; ++i) {
    const double s = beam["s"][i].get<double>();
    const Vec3 m = ReadVec3(beam["moment_body"][i]), n = ReadVec3(beam["force_body"][i]);
    EXPECT_NEAR(m.norm(), P * (b - s), 2e-3 * P * b) << "beam node " << i;
    EXPECT_NEAR(std::hypot(n.x(), n.y()), P, 2e-3 * P) << "beam node " << i;
  }
}

// ----- bad input ---------------------------------------------------------------------------------

/// The guided beam as JSON, to break in each test.
json GuidedBeam() {
  return json::parse(R"({
    "format": "cosserat-problem/1",
    "assembly": {
      "rods": [
        { "name": "left",
          "rod": { "length": 0.5, "nodes": 21, "section": { "shape": "circle", "radius": 0.001 },
                   "material": { "youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000 } },
          "base": { "position": [-0.05, 0, 0] },
          "tip": { "joint": "clamped", "body": "plate", "attachment": { "position": [-0.05, 0, 0] } } },
        { "name": "right",
          "rod": { "length": 0.5, "nodes": 21, "section": { "shape": "circle", "radius": 0.001 },
                   "material": { "youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000 } },
          "base": { "position": [0.05, 0, 0] },
          "tip": { "joint": "clamped", "body": "plate", "attachment": { "position": [0.05, 0, 0] } } }
      ],
      "bodies": [ { "name": "plate", "pose": { "position": [0, 0, 0.5] }, "force": [0.01, 0, 0] } ]
    }
  })");
}

std::string AllErrors(const io::ParseResult& r) {
  std::string out;
  for (const std::string& e : r.errors) out += "  " + e + "\n";
  return out;
}

bool HasError(const std::vector<std::string>& errors, std::initializer_list<std::string> parts) {
  for (const std::string& e : errors) {
    bool all = true;
    for (const std::string& p : parts) all = all && e.find(p) != std::string::npos;
    if (all) return true;
  }
  return false;
}

#define EXPECT_ERROR(result, ...) \
  EXPECT_TRUE(HasError(result.errors, {__VA_ARGS__})) << "errors were:\n" << AllErrors(result)

io::ParseResult Parse(const json& j) { return io::ParseProblem(j.dump(2)); }

TEST(AssemblyIo, TheValidBeamParses) {
  const io::ParseResult r = Parse(GuidedBeam());
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  EXPECT_TRUE(io::UnsupportedFeatures(*r.problem).empty());
  EXPECT_EQ(r.problem->assembly.assembly.rods[1].nodes, 21);
  EXPECT_FALSE(r.problem->assembly.inverse());
}

TEST(AssemblyIo, AJointNamingAMissingBodyNamesTheBodies) {
  json j = GuidedBeam();
  j["assembly"]["rods"][1]["tip"]["body"] = "plat";
  EXPECT_ERROR(Parse(j), "assembly.rods[1].tip.body: names \"plat\", but the bodies are \"plate\"");
}

TEST(AssemblyIo, NamesAreUnique) {
  json j = GuidedBeam();
  j["assembly"]["rods"][1]["name"] = "left";
  j["assembly"]["bodies"].push_back(j["assembly"]["bodies"][0]);
  const io::ParseResult r = Parse(j);
  EXPECT_ERROR(r, "assembly.rods[1].name: expected a name no other rod has",
               "\"left\", already the name of assembly.rods[0]");
  EXPECT_ERROR(r, "assembly.bodies[1].name: expected a name no other body has");
}

TEST(AssemblyIo, StaticsNeedsEveryBodyJoinedToTheWorld) {
  // The plate carries the right rod hanging from it (its base on the plate) and nothing holds
  // the plate: it floats. Statics under gravity ended load_stepping_failed, "reached 0"; it is
  // refused by name. Dynamics runs it (a free assembly), and a rod from the world to the plate
  // grounds it (and the hanging rod with it).
  json j = GuidedBeam();
  j["assembly"]["rods"][0]["tip"] = json::parse(R"({ "joint": "free" })");
  j["assembly"]["rods"][0]["base"] = json::parse(R"({ "position": [0, 0, 0.5], "body": "plate" })");
  j["assembly"]["rods"][1]["tip"] = json::parse(R"({ "joint": "free" })");
  j["assembly"]["rods"][1]["base"] = json::parse(R"({ "position": [0, 0, 0.5], "body": "plate" })");
  EXPECT_ERROR(Parse(j), "assembly.bodies[0]: no chain of rods joins \"plate\" to the world");
  j["analysis"] = "dynamics";
  EXPECT_FALSE(HasError(Parse(j).errors, {"no chain of rods"})) << AllErrors(Parse(j));
  j["analysis"] = "statics";
  j["assembly"]["rods"][0] = GuidedBeam()["assembly"]["rods"][0];
  EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
}

TEST(AssemblyIo, AFreeTipJoinsNoBodyAndAJoinedTipNamesOne) {
  json j = GuidedBeam();
  j["assembly"]["rods"][0]["tip"]["joint"] = "free";
  j["assembly"]["rods"][1]["tip"].erase("body");
  const io::ParseResult r = Parse(j);
  EXPECT_ERROR(r, "assembly.rods[0].tip.body: a \"free\" tip joins no body");
  EXPECT_ERROR(r, "assembly.rods[1].tip.body: expected the name of the body a \"clamped\" tip");
  EXPECT_ERROR(r, "assembly.bodies[0]: no rod holds \"plate\"");
}

TEST(AssemblyIo, ATorsionFreeBaseNeedsAClampedTip) {
  json j = GuidedBeam();
  j["assembly"]["rods"][0]["base"]["joint"] = "torsion_free";
  j["assembly"]["rods"][0]["tip"]["joint"] = "pinned";
  EXPECT_ERROR(Parse(j), "assembly.rods[0].base.joint: expected \"clamped\" unless the tip is",
               "got \"torsion_free\" with a \"pinned\" tip");
}

TEST(AssemblyIo, AnInverseProblemNeedsSixRodsPerBodyAndOnePosePerBody) {
  json j = GuidedBeam();
  j["assembly"]["inverse"] = json::parse(R"({"poses": [{"body": "plate", "position": [0, 0, 0.5]},
                                                       {"body": "plate"}]})");
  j["assembly"]["lengths"] = {0.5, 0.5};
  const io::ParseResult r = Parse(j);
  EXPECT_ERROR(r, "assembly.inverse: expected six rods joined to each body", "got 2 on \"plate\"");
  EXPECT_ERROR(r, "assembly.inverse.poses[1].body: expected one pose per body");
  EXPECT_ERROR(r, "assembly.lengths: not read with \"inverse\"");
}

TEST(AssemblyIo, LengthsAreOnePerRod) {
  json j = GuidedBeam();
  j["assembly"]["lengths"] = {0.5};
  EXPECT_ERROR(Parse(j), "assembly.lengths: expected an array of one length per rod (2 in");
  j["assembly"]["lengths"] = {0.5, -1};
  EXPECT_ERROR(Parse(j), "assembly.lengths[1]: expected a positive number, got -1");
}

TEST(AssemblyIo, TheSingleRodKeysAndTipLoadsAreRefused) {
  json j = GuidedBeam();
  j["rod"] = j["assembly"]["rods"][0]["rod"];
  j["boundary"] = "cantilever";
  j["buckling"] = json::object();
  j["loads"] = {{"gravity", {0, 0, -9.81}}, {"tip_force", {1, 0, 0}}};
  const io::ParseResult r = Parse(j);
  EXPECT_ERROR(r, "rod: not read with \"assembly\" (each rod of assembly.rods has its own");
  EXPECT_ERROR(r, "boundary: not read with \"assembly\" (assembly.rods[i].tip holds each");
  EXPECT_ERROR(r, "buckling: not read with \"assembly\": an assembly's buckling and modes");
  EXPECT_ERROR(r, "loads.tip_force: not read with \"assembly\" (load a body instead");
}

TEST(AssemblyIo, ARodIsReadByTheRodParser) {
  json j = GuidedBeam();
  j["assembly"]["rods"][0]["rod"]["section"]["radius"] = -1;
  j["assembly"]["rods"][1]["rod"]["lenght"] = 1;
  const io::ParseResult r = Parse(j);
  EXPECT_ERROR(r, "assembly.rods[0].rod.section.radius: expected a positive number, got -1");
  EXPECT_ERROR(r, "assembly.rods[1].rod.lenght: unknown key (did you mean \"length\"?)");
}

TEST(AssemblyIo, OnlyStaticsAndDynamicsOnSe3ShootingRun) {
  json j = GuidedBeam();
  j["analysis"] = "modes";
  j["formulation"] = "quaternion-fd";
  const io::ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const std::vector<std::string> unsupported = io::UnsupportedFeatures(*r.problem);
  EXPECT_TRUE(HasError(unsupported, {"analysis: \"modes\" of an \"assembly\" is not"}));
  EXPECT_TRUE(HasError(unsupported, {"formulation: \"quaternion-fd\" of an \"assembly\""}));
}

// What dynamics of an assembly cannot take is named: a single rod's dynamics keys, a body's
// negative inertia, an inverse problem, given lengths, a torsion-free base.
TEST(AssemblyIo, AssemblyDynamicsNamesWhatItCannotTake) {
  json j = GuidedBeam();
  j["analysis"] = "dynamics";
  j["dynamics"] = {{"dt", 0.01}, {"duration", 0.1}, {"tip_mass", 0.1}, {"base_spin", 1.0}};
  j["assembly"]["bodies"][0]["inertia"] = {1e-3, -1e-3, 1e-3};
  io::ParseResult r = Parse(j);
  EXPECT_ERROR(r, "dynamics.tip_mass: not read with \"assembly\"");
  EXPECT_ERROR(r, "dynamics.base_spin: not read with \"assembly\"");
  EXPECT_ERROR(r, "assembly.bodies[0].inertia[1]: expected a principal moment of inertia >= 0");

  j = GuidedBeam();
  j["analysis"] = "dynamics";
  j["assembly"]["lengths"] = {0.5, 0.5};
  j["assembly"]["rods"][1]["base"]["joint"] = "torsion_free";
  r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const std::vector<std::string> unsupported = io::UnsupportedFeatures(*r.problem);
  EXPECT_TRUE(HasError(unsupported, {"assembly.lengths: not read in dynamics"}));
  EXPECT_TRUE(HasError(unsupported, {"assembly.rods[1].base.joint: \"torsion_free\" is statics"}));
}

// examples/platform_release.json through run::Run: the plate on two light wires, released from
// a sideways offset, swings at the spring–mass frequency of the two guided beams (the library's
// test, AssemblyDynamics.APlatformOnTwoRodsOscillatesAtTheSpringMassFrequency, checks the same
// at three steps). The file's dt is about T/200, where BDF2's phase error is 4e-4
// (that test's measurement): 1e-3 on the period. The energy never grows (BDF2 dissipates).
TEST(AssemblyIo, PlatformReleaseExampleSwingsAtTheSpringMassFrequency) {
  const io::Problem p = Load("examples/platform_release.json");
  const run::Result r = run::Run(p);
  ASSERT_TRUE(r.converged) << r.log;
  const double EI = 200e9 * M_PI * std::pow(0.001, 4) / 4, L = 0.5, r_wire = 0.001, d = 0.1;
  const double rod_mass = 8000 * M_PI * r_wire * r_wire * L;
  const double M = p.assembly.assembly.bodies[0].mass;
  const double k = 24 * EI / (L * L * L) / (1 + 3 * (r_wire / d) * (r_wire / d));
  const double period = 2 * M_PI * std::sqrt((M + 2 * 13.0 / 35.0 * rod_mass) / k);
  const auto& traj = r.json["trajectory"];
  std::vector<double> crossings;
  double t0 = 0, x0 = 0;
  for (std::size_t i = 0; i < traj["t"].size(); ++i) {
    const double t = traj["t"][i].get<double>();
    const double x = traj["bodies"][0]["position"][i][0].get<double>();
    if (i > 0 && (x0 < 0) != (x < 0)) crossings.push_back(t0 + (t - t0) * x0 / (x0 - x));
    t0 = t;
    x0 = x;
  }
  ASSERT_GE(crossings.size(), 3u);
  const double measured = crossings[2] - crossings[0];
  std::printf("platform example: period %.6f s, spring-mass %.6f s\n", measured, period);
  EXPECT_NEAR(measured, period, 1e-3 * period);
  // BDF2 dissipates: at θ = 2π/200 the sway loses (θ⁴/4) 2 per step, 2e-4 of its energy over
  // the 400 steps; the release also sheds the wires' own modes, which BDF2 damps out at once
  // (1.3e-3 measured). The discrete energy of a frame wobbles within a period by O(θ²) of the
  // kinetic part's share, so only the run's end is compared: it kept more than 99 %.
  const double e0 = traj["energy"][0].get<double>(), e1 = traj["energy"].back().get<double>();
  EXPECT_LT(e1, e0);
  EXPECT_GT(e1, 0.99 * e0);
}

}  // namespace
}  // namespace cosserat
