// Problem files: parsing, mapping onto the library types, and the error messages for bad input.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cosserat/io/problem.hpp"
#include "cosserat/io/result_writer.hpp"
#include "cosserat/rod/grid.hpp"
#include "cosserat/rod/section_profile.hpp"
#include "cosserat/rod/stiffness_profiles.hpp"
#include "support/source_json.hpp"

namespace cosserat::io {
namespace {

using json = nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

std::string SourceDir() {
#ifdef COSSERAT_SOURCE_DIR
  return COSSERAT_SOURCE_DIR;
#else
  const std::string file = __FILE__;
  return file.substr(0, file.rfind("/tests/"));
#endif
}

/// A small valid problem to break in each test.
json ValidProblem() {
  return json::parse(R"({
    "format": "cosserat-problem/1",
    "rod": {
      "length": 0.5,
      "nodes": 21,
      "section": { "shape": "circle", "radius": 0.001 },
      "material": { "youngs_modulus": 200e9, "shear_modulus": 80e9, "density": 8000 }
    }
  })");
}

ParseResult Parse(const json& j) { return ParseProblem(j.dump(2)); }

std::string AllErrors(const ParseResult& r) {
  std::string out;
  for (const std::string& e : r.errors) out += "  " + e + "\n";
  return out;
}

/// True if one error line contains every part.
bool HasError(const ParseResult& r, std::initializer_list<std::string> parts) {
  for (const std::string& e : r.errors) {
    bool all = true;
    for (const std::string& p : parts) all = all && e.find(p) != std::string::npos;
    if (all) return true;
  }
  return false;
}

#define EXPECT_ERROR(result, ...) \
  EXPECT_TRUE(HasError(result, {__VA_ARGS__})) << "errors were:\n" << AllErrors(result)

// ----- valid input ---------------------------------------------------------------------------

TEST(ProblemIo, DefaultExampleParsesAndMapsValues) {
  const ParseResult r = LoadProblemFile(SourceDir() + "/examples/cantilever.json");
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  ASSERT_TRUE(r.problem.has_value());
  const Problem& p = *r.problem;
  EXPECT_EQ(p.analysis, Analysis::kStatics);
  EXPECT_EQ(p.formulation, Formulation::kSe3Shooting);
  EXPECT_EQ(p.boundary, Boundary::kCantilever);
  EXPECT_DOUBLE_EQ(p.rod.length, 0.5);
  EXPECT_EQ(p.nodes, 41);

  const auto uniform = std::dynamic_pointer_cast<const UniformSection>(p.rod.section);
  ASSERT_TRUE(uniform);
  const double I = kPi * std::pow(0.001, 4) / 4.0;
  EXPECT_NEAR(uniform->section().I1, I, 1e-12 * I);
  EXPECT_DOUBLE_EQ(uniform->material().youngs_modulus, 200e9);
  EXPECT_DOUBLE_EQ(uniform->material().shear_modulus, 80e9);
  EXPECT_DOUBLE_EQ(uniform->material().density, 8000);
  const SectionProperties props = p.rod.section->At(0.25, Actuation{});
  EXPECT_NEAR(props.stiffness(0, 0), 200e9 * I, 1e-9 * 200e9 * I);    // EI
  EXPECT_NEAR(props.stiffness(2, 2), 80e9 * 2 * I, 1e-9 * 80e9 * I);  // GJ

  EXPECT_TRUE(p.loads.gravity_W.isApprox(Vec3(-9.81, 0, 0)));
  EXPECT_TRUE(p.loads.tip_force.isApprox(Vec3(-0.2, 0, 0)));
  EXPECT_EQ(p.loads.tip_force_frame, LoadFrame::kWorld);
  EXPECT_TRUE(p.loads.tip_moment.isZero());
  EXPECT_TRUE(p.base.R.isIdentity());
  EXPECT_TRUE(p.base.p.isZero());
  EXPECT_DOUBLE_EQ(p.solver.tolerance, 1e-10);
  EXPECT_EQ(p.solver.max_iterations, 50);
  EXPECT_TRUE(UnsupportedFeatures(p).empty());
}

TEST(ProblemIo, OptionalBlocksTakeTheirDefaults) {
  const ParseResult r = Parse(ValidProblem());
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const Problem& p = *r.problem;
  EXPECT_EQ(p.analysis, Analysis::kStatics);
  EXPECT_EQ(p.boundary, Boundary::kCantilever);
  EXPECT_TRUE(p.loads.gravity_W.isZero());
  EXPECT_TRUE(p.base.R.isIdentity());
  EXPECT_DOUBLE_EQ(p.solver.tolerance, 1e-10);
  EXPECT_EQ(p.solver.max_iterations, 50);
  EXPECT_FALSE(p.has_dynamics || p.has_buckling || p.has_modes);
  EXPECT_TRUE(p.rod.RestStrainAt(0.1).isApprox(StraightRestStrain()));
}

TEST(ProblemIo, ChoicesAreReadIntoTheirEnums) {
  json j = ValidProblem();
  j["analysis"] = "dynamics";
  j["boundary"] = "free-free";
  j["dynamics"] = {{"dt", 0.01}, {"duration", 0.1}, {"spatial_scheme", "heun"}};
  const ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  EXPECT_EQ(r.problem->analysis, Analysis::kDynamics);
  EXPECT_EQ(r.problem->boundary, Boundary::kFreeFree);
  EXPECT_EQ(r.problem->dynamics.spatial_scheme, ShotScheme::kHeun);
  j["dynamics"]["spatial_scheme"] = "rk4-pairs";
  EXPECT_EQ(Parse(j).problem->dynamics.spatial_scheme, ShotScheme::kRk4Pairs);
  EXPECT_EQ(r.problem->robot.kind, RobotKind::kNone);
  const ParseResult robot = LoadProblemFile(SourceDir() + "/robots/eversion_banded_vine.json");
  ASSERT_TRUE(robot.ok()) << AllErrors(robot);
  EXPECT_EQ(robot.problem->robot.kind, RobotKind::kEversion);
}

TEST(ProblemIo, ChoiceNamesRoundTrip) {
  for (const std::string& name : Names<Boundary>()) {
    Boundary b = Boundary::kCantilever;
    ASSERT_TRUE(FromString(name, &b)) << name;
    EXPECT_EQ(ToString(b), name);
  }
  EXPECT_EQ(ToString(Formulation::kQuaternionFd), "quaternion-fd");
  EXPECT_EQ(ToString(BucklingLoad::kDistributedForce), "distributed_force");
  Analysis a = Analysis::kModes;
  EXPECT_FALSE(FromString("static", &a));
  EXPECT_EQ(a, Analysis::kModes);  // unchanged
}

TEST(ProblemIo, PoissonRatioGivesTheShearModulus) {
  json j = ValidProblem();
  j["rod"]["material"].erase("shear_modulus");
  j["rod"]["material"]["poisson_ratio"] = 0.3;
  const ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const auto uniform = std::dynamic_pointer_cast<const UniformSection>(r.problem->rod.section);
  ASSERT_TRUE(uniform);
  EXPECT_NEAR(uniform->material().shear_modulus, 200e9 / 2.6, 1.0);
}

TEST(ProblemIo, SectionsRestCurvatureDampingAndBase) {
  json j = ValidProblem();
  j["rod"]["section"] = {{"shape", "rectangle"}, {"width", 0.004}, {"height", 0.002}};
  j["rod"]["rest_curvature"] = {1.0, 0.0, 0.5};
  j["rod"]["material"]["damping"] = {{"bending", 1e-4}, {"shear", 0.1}};
  j["base"] = {{"position", {1, 2, 3}}, {"rotation", {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}}};
  j["loads"] = {{"tip_moment", {0, 0, 0.01}}, {"tip_moment_frame", "body"}};
  const ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const Problem& p = *r.problem;
  const auto uniform = std::dynamic_pointer_cast<const UniformSection>(p.rod.section);
  ASSERT_TRUE(uniform);
  EXPECT_NEAR(uniform->section().I1, 0.004 * std::pow(0.002, 3) / 12, 1e-20);
  EXPECT_DOUBLE_EQ(uniform->material().damping.bending, 1e-4);
  EXPECT_DOUBLE_EQ(uniform->material().damping.shear, 0.1);
  EXPECT_DOUBLE_EQ(uniform->material().damping.torsion, 0.0);
  EXPECT_TRUE(p.rod.RestStrainAt(0.2).head<3>().isApprox(Vec3(1.0, 0.0, 0.5)));
  EXPECT_DOUBLE_EQ(p.rod.RestStrainAt(0.2)(5), 1.0);
  EXPECT_TRUE(p.base.p.isApprox(Vec3(1, 2, 3)));
  EXPECT_DOUBLE_EQ(p.base.R(0, 1), -1.0);  // row-major in the file
  EXPECT_DOUBLE_EQ(p.base.R(1, 0), 1.0);
  EXPECT_EQ(p.loads.tip_moment_frame, LoadFrame::kBody);
}

TEST(ProblemIo, ExplicitSectionWithoutShape) {
  json j = ValidProblem();
  j["rod"]["section"] = {{"area", 1e-6}, {"I1", 1e-13}, {"I2", 2e-13}, {"J", 3e-13}};
  const ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const auto uniform = std::dynamic_pointer_cast<const UniformSection>(r.problem->rod.section);
  ASSERT_TRUE(uniform);
  EXPECT_EQ(uniform->section().shape, SectionShape::kExplicit);
  EXPECT_DOUBLE_EQ(uniform->section().I2, 2e-13);
}

TEST(ProblemIo, StiffnessProfileBuildsBands) {
  json j = ValidProblem();
  j["rod"]["stiffness_profile"] = json::parse(R"([{"start": 0.1, "end": 0.2, "factor": 0.36}])");
  const ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const auto& section = r.problem->rod.section;
  ASSERT_TRUE(std::dynamic_pointer_cast<const BandedSection>(section));
  EXPECT_EQ(section->Breakpoints().size(), 2u);
  const double ei_out = section->At(0.05, Actuation{}).stiffness(0, 0);
  const double ei_in = section->At(0.15, Actuation{}).stiffness(0, 0);
  EXPECT_NEAR(ei_in / ei_out, 0.36, 1e-12);
}

// ----- rod.stiffness_profile, object form ----------------------------------------------------

/// The profile inside the FixedActuationSection the parser wraps actuation-dependent kinds in.
template <typename T>
std::shared_ptr<const T> Inner(const ParseResult& r, Actuation* state = nullptr) {
  const auto fixed = std::dynamic_pointer_cast<const FixedActuationSection>(r.problem->rod.section);
  if (!fixed) return nullptr;
  if (state) *state = fixed->actuation();
  return std::dynamic_pointer_cast<const T>(fixed->inner());
}

TEST(ProblemIo, StiffnessProfileObjectBands) {
  json j = ValidProblem();
  j["rod"]["stiffness_profile"] =
      json::parse(R"({"kind": "bands", "bands": [{"start": 0.1, "end": 0.2, "factor": 0.36}]})");
  const ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const auto& section = r.problem->rod.section;
  ASSERT_TRUE(std::dynamic_pointer_cast<const BandedSection>(section));
  EXPECT_NEAR(section->At(0.15, {}).stiffness(0, 0) / section->At(0.05, {}).stiffness(0, 0), 0.36,
              1e-12);
}

TEST(ProblemIo, StiffnessProfileTaperTipAndTable) {
  json j = ValidProblem();
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "taper", "tip": {"radius": 0.0005}})");
  ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  auto taper = std::dynamic_pointer_cast<const TaperedSection>(r.problem->rod.section);
  ASSERT_TRUE(taper);
  EXPECT_DOUBLE_EQ(taper->SectionAt(0.25).outer_radius, 0.00075);

  j["rod"]["section"] = {{"shape", "annulus"}, {"outer_radius", 0.002}, {"inner_radius", 0.001}};
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "taper", "table": [
      {"s": 0.2, "outer_radius": 0.0015, "inner_radius": 0.001},
      {"s": 0.5, "outer_radius": 0.001, "inner_radius": 0.0005}],
      "bands": [{"start": 0.3, "end": 0.35, "factor": 0.5}]})");
  r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const auto banded = std::dynamic_pointer_cast<const BandedSection>(r.problem->rod.section);
  ASSERT_TRUE(banded);
  EXPECT_EQ(r.problem->rod.section->Breakpoints().size(), 3u + 3u + 2u);  // 2 × knots, band
  const auto grid = ModelGrid(r.problem->rod, r.problem->nodes);
  EXPECT_NE(std::find(grid.begin(), grid.end(), 0.2), grid.end());
  const double ro = 0.00175, ri = 0.001;  // at s = 0.1, halfway to the first row
  EXPECT_NEAR(r.problem->rod.section->At(0.1, {}).stiffness(0, 0),
              200e9 * kPi * (std::pow(ro, 4) - std::pow(ri, 4)) / 4, 1e-9);
}

TEST(ProblemIo, StiffnessProfilePressureModulusAtTheFilesPressure) {
  json j = ValidProblem();
  j["rod"]["material"] = {{"youngs_modulus", 1e6}, {"poisson_ratio", 0.45}, {"density", 1100}};
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "pressure_modulus", "pressure": 15e3,
      "modulus": {"table": [[0, 1e6], [10e3, 2e6], [20e3, 2.5e6]]}})");
  ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  Actuation state;
  const auto inner = Inner<PressureModulusSection>(r, &state);
  ASSERT_TRUE(inner);
  EXPECT_EQ(state.pressure, 15e3);
  EXPECT_DOUBLE_EQ(inner->ModulusAt(15e3), 2.25e6);
  const double I = kPi * std::pow(0.001, 4) / 4;
  EXPECT_DOUBLE_EQ(r.problem->rod.section->At(0.1, {}).stiffness(0, 0), 2.25e6 * I);

  j["rod"]["stiffness_profile"] =
      json::parse(R"({"kind": "pressure_modulus", "pressure": 1e4, "modulus": {"slope": 30}})");
  r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  EXPECT_DOUBLE_EQ(Inner<PressureModulusSection>(r)->ModulusAt(1e4), 1e6 + 3e5);  // E0: material
}

TEST(ProblemIo, StiffnessProfileJammingSegmentsAndStates) {
  json j = ValidProblem();
  j["rod"]["nodes"] = 31;
  j["rod"]["section"] = {{"shape", "annulus"}, {"outer_radius", 0.01}, {"inner_radius", 0.009}};
  j["rod"]["material"] = {{"youngs_modulus", 1e6}, {"poisson_ratio", 0.45}, {"density", 1100}};
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "jamming", "pressure": 30e3,
      "tube_modulus": {"slope": 20}, "layer_I": 2e-9, "layer_modulus": {"slope": 1000},
      "segments": [{"start": 0, "end": 0.2}, {"start": 0.2, "end": 0.4, "pressure": 80e3}]})");
  const ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  Actuation state;
  const auto jam = Inner<JammingSection>(r, &state);
  ASSERT_TRUE(jam);
  EXPECT_EQ(state.pressure, 30e3);
  EXPECT_EQ(state.jamming_pressure[0], 0.0);
  EXPECT_EQ(state.jamming_pressure[1], 80e3);
  const double EI_tube = 1.6e6 * kPi * (1e-8 - std::pow(0.009, 4)) / 4;
  EXPECT_NEAR(jam->StiffnessRatio(1, 0, state), (EI_tube + 0.16) / EI_tube, 1e-9);
}

TEST(ProblemIo, StiffnessProfileInflatedWithConstrictions) {
  json j = ValidProblem();
  j["rod"]["section"] = {{"shape", "circle"}, {"radius", 0.025}};
  j["rod"]["material"] = {{"youngs_modulus", 0.2e9}, {"poisson_ratio", 0.4}, {"density", 950}};
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "inflated", "wall_thickness": 1e-4,
      "pressure": 20e3, "modulus": {"slope": 5000},
      "constrictions": [{"start": 0.3, "end": 0.32, "diameter_ratio": 0.5, "factor": 0.36}]})");
  const ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  Actuation state;
  const auto tube = Inner<InflatedTubeSection>(r, &state);
  ASSERT_TRUE(tube);
  EXPECT_EQ(tube->radius(), 0.025);
  EXPECT_DOUBLE_EQ(tube->WrinklingMomentAt(0.1, state), kPi * 20e3 * std::pow(0.025, 3) / 2);
  EXPECT_NEAR(tube->BendingStiffnessAt(0.1, state),
              (0.2e9 + 5000 * 20e3) * kPi * std::pow(0.025, 3) * 1e-4, 1e-9);
}

TEST(ProblemIo, StiffnessProfileDrivesTheSolver) {
  // A band of α = 0.36 softens the whole cantilever: the tip deflects more than without.
  json j = ValidProblem();
  j["loads"] = {{"tip_force", {1e-3, 0, 0}}};
  ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  StaticShootingSolver plain(r.problem->rod, r.problem->nodes);
  ASSERT_TRUE(plain.Solve(r.problem->base, r.problem->loads).converged());
  j["rod"]["stiffness_profile"] =
      json::parse(R"({"kind": "bands", "bands": [{"start": 0, "end": 0.25, "factor": 0.36}]})");
  r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  StaticShootingSolver banded(r.problem->rod, r.problem->nodes);
  ASSERT_TRUE(banded.Solve(r.problem->base, r.problem->loads).converged());
  EXPECT_GT(banded.state().tip_position_W().x(), 1.5 * plain.state().tip_position_W().x());
}

TEST(ProblemIo, NearlyOrthonormalRotationIsAcceptedAndCleaned) {
  json j = ValidProblem();
  j["base"]["rotation"] = {{1, 1e-8, 0}, {0, 1, 0}, {0, 0, 1}};
  const ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const Mat3& R = r.problem->base.R;
  EXPECT_LT((R.transpose() * R - Mat3::Identity()).norm(), 1e-14);
}

TEST(ProblemIo, LaterAnalysesParseButAreGated) {
  json j = ValidProblem();
  j["analysis"] = "buckling";
  j["formulation"] = "quaternion-fd";
  j["boundary"] = "pinned-pinned";
  j["buckling"] = {{"load", "tip_force"}, {"direction", {0, 0, -2}}, {"max", 10.0}};
  j["dynamics"] = {
      {"dt", 0.001}, {"duration", 0.5}, {"initial_loads", {{"gravity", {0, 0, -9.81}}}}};
  j["modes"] = {{"count", 6}};
  const ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const Problem& p = *r.problem;
  EXPECT_TRUE(p.has_buckling && p.has_dynamics && p.has_modes);
  EXPECT_TRUE(p.buckling.direction.isApprox(Vec3(0, 0, -1)));
  EXPECT_DOUBLE_EQ(p.buckling.max, 10.0);
  EXPECT_DOUBLE_EQ(p.dynamics.dt, 0.001);
  ASSERT_TRUE(p.dynamics.initial_loads.has_value());
  EXPECT_DOUBLE_EQ(p.dynamics.initial_loads->gravity_W.z(), -9.81);
  EXPECT_EQ(p.modes.count, 6);

  const std::vector<std::string> gated = UnsupportedFeatures(p);
  // quaternion-fd runs statics, dynamics and buckling, with a cantilever only, and
  // buckling there only under conservative (world-frame) tip loads.
  ASSERT_EQ(gated.size(), 1u);
  EXPECT_EQ(gated[0], R"(boundary: "pinned-pinned" is not implemented in this version )"
                      R"((supported: "cantilever") for "analysis": "buckling" on "quaternion-fd"; )"
                      R"("pinned-pinned" runs statics, buckling and modes on "se3-shooting")");
  j["loads"]["tip_force_frame"] = "body";
  const std::vector<std::string> follower = UnsupportedFeatures(*Parse(j).problem);
  ASSERT_EQ(follower.size(), 2u);
  EXPECT_EQ(follower[1].rfind("loads.tip_force_frame: ", 0), 0u) << follower[1];
  j["loads"].erase("tip_force_frame");
  // A moment of fixed direction is not conservative in 3-D (Ziegler 1977): refused as the load
  // searched for and as a preload.
  j["buckling"]["load"] = "tip_moment";
  const std::vector<std::string> moment = UnsupportedFeatures(*Parse(j).problem);
  ASSERT_EQ(moment.size(), 2u);
  EXPECT_EQ(moment[1].rfind("buckling.load: \"tip_moment\"", 0), 0u) << moment[1];
  j["buckling"]["load"] = "tip_force";
  j["loads"]["tip_moment"] = {0, 0, 0.01};
  const std::vector<std::string> preload = UnsupportedFeatures(*Parse(j).problem);
  ASSERT_EQ(preload.size(), 2u);
  EXPECT_EQ(preload[1].rfind("loads.tip_moment: ", 0), 0u) << preload[1];
  j["loads"].erase("tip_moment");
  // Buckling runs on se3-shooting, with the column end conditions.
  j["formulation"] = "se3-shooting";
  EXPECT_TRUE(UnsupportedFeatures(*Parse(j).problem).empty());
  j["boundary"] = "free-free";
  const std::vector<std::string> free = UnsupportedFeatures(*Parse(j).problem);
  ASSERT_EQ(free.size(), 1u);
  EXPECT_EQ(free[0], R"(boundary: "free-free" is not implemented in this version (supported: )"
                     R"("cantilever", "pinned-pinned", "clamped-clamped", "clamped-pinned") )"
                     R"(for "analysis": "buckling" on "se3-shooting"; "free-free" runs dynamics )"
                     R"(on "se3-shooting")");
}

// Dimensions that pass their own checks but underflow together are named where they were given:
// a radius of 1e-300 m has an area of 0, E = 1e-300 Pa against G = 8e10 Pa a Poisson ratio that
// rounds to −1, and E = 5e-324 Pa with a Poisson ratio a shear modulus of 0 (which was named as
// if the file had given it).
TEST(ProblemIo, DegenerateSectionsAndMaterialsAreNamed) {
  json j = ValidProblem();
  j["rod"]["section"]["radius"] = 1e-300;
  ParseResult r = Parse(j);
  EXPECT_TRUE(HasError(r, {"rod.section: area must be a finite positive number"})) << AllErrors(r);
  j = ValidProblem();
  j["rod"]["material"]["youngs_modulus"] = 1e-300;
  r = Parse(j);
  EXPECT_TRUE(HasError(r, {"rod.material: expected youngs_modulus and shear_modulus whose Poisson "
                           "ratio E/(2G) − 1 is above −1"}))
      << AllErrors(r);
  j = ValidProblem();
  j["rod"]["material"].erase("shear_modulus");
  j["rod"]["material"]["poisson_ratio"] = 0.45;
  j["rod"]["material"]["youngs_modulus"] = 5e-324;
  r = Parse(j);
  EXPECT_TRUE(HasError(r, {"rod.material.youngs_modulus: expected a modulus whose shear modulus "
                           "E/(2(1 + ν)) is a normal double"}))
      << AllErrors(r);
}

// Jamming pressures are one per switchable segment of the rod's jamming profile, as chamber
// pressures are one per chamber: a wrong count, or a robot with no jamming profile, would run
// with the extra values ignored.
TEST(ProblemIo, JammingPressuresMatchTheProfilesSegments) {
  json j = json::parse(std::ifstream(SourceDir() + "/robots/jamming_virtual_joints.json"));
  ASSERT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
  j["robot"]["actuation"]["jamming_pressure"] = {80000, 0};
  EXPECT_ERROR(Parse(j), "robot.actuation.jamming_pressure: expected one value per segment of the "
                         "jamming profile (3 in rod.stiffness_profile.segments)");
  j = json::parse(std::ifstream(SourceDir() + "/robots/tendon_three_tendon.json"));
  j["robot"]["actuation"]["jamming_pressure"] = {1000};
  EXPECT_ERROR(Parse(j), "robot.actuation.jamming_pressure: expected a rod.stiffness_profile of "
                         "kind \"jamming\"");
}

// One bad coordinate of a tendon is named at its index, and it is the only error: the
// per-tendon lists still count the tendon the file lists (before: "offset: expected 2 finite
// numbers, got an array of 2 items", then "actuation.tension: expected one value per tendon
// (0 in robot.tendons)"). A profile kind that is not a string is a field error, not the JSON
// library's exception.
TEST(ProblemIo, ABadTendonCoordinateIsNamedAndAloneInItsErrors) {
  json j = json::parse(std::ifstream(SourceDir() + "/robots/tendon_three_tendon.json"));
  j["robot"]["tendons"][0]["offset"][1] = "x";
  const ParseResult r = Parse(j);
  EXPECT_ERROR(r, "robot.tendons[0].offset[1]: expected a finite number", "got a string");
  EXPECT_EQ(r.errors.size(), 1u) << AllErrors(r);
  j = json::parse(std::ifstream(SourceDir() + "/robots/tendon_three_tendon.json"));
  j["rod"]["stiffness_profile"] = {{"kind", 1}};
  EXPECT_ERROR(Parse(j), "rod.stiffness_profile.kind: expected one of");
}

// Errors in the right place: a misspelt "shape" of a contact entry is named with its fix; an axis
// with an entry near 1e300 is a direction (it overflowed to "a zero vector"); a smoothing of 0 is
// refused; an anchored rod with an error of its own gets no error about the anchor's reach from a
// length of 0.
TEST(ProblemIo, ErrorsNameWhatIsWrong) {
  json j = ValidProblem();
  j["environment"]["contact"] = json::array({{{"shaep", "plane"}, {"stiffness", 1e5}}});
  EXPECT_ERROR(Parse(j), "environment.contact[0].shaep: unknown key (did you mean \"shape\"?)");
  j = ValidProblem();
  j["environment"]["contact"] = json::array(
      {{{"shape", "cylinder"}, {"axis", {1e300, 0, 1}}, {"radius", 0.01}, {"side", "outside"},
        {"point", {1, 1, 0}}, {"stiffness", 1e5}}});
  const ParseResult r = Parse(j);
  EXPECT_TRUE(r.ok()) << AllErrors(r);
  if (r.ok()) EXPECT_NEAR(r.problem->loads.contact.surface[0].direction_W.x(), 1.0, 1e-15);
  // A smoothing of 0 silently meant the default width; a sharp contact is refused instead.
  j["environment"]["contact"][0]["smoothing"] = 0.0;
  EXPECT_ERROR(Parse(j), "environment.contact[0].smoothing: expected a positive width (m)");
  j = ValidProblem();
  j["boundary"] = "anchored";
  j["anchor"] = {{"position", {0, 0, 0.4}}};
  j["rod"]["section"] = {{"shape", "circle"}, {"raduis", 0.001}};
  const ParseResult bad_rod = Parse(j);
  EXPECT_ERROR(bad_rod, "rod.section.raduis: unknown key");
  for (const std::string& e : bad_rod.errors)
    EXPECT_EQ(e.find("anchor.position"), std::string::npos) << e;
}

// validate passes exactly what solve runs: an explicit section of area 1e300 m² (E A overflows)
// is a parse error at rod.section, where solve stopped with a message about off-diagonal
// entries of the stiffness.
TEST(ProblemIo, ASectionThatOverflowsIsAnErrorAtTheSection) {
  json j = ValidProblem();
  j["rod"]["section"] = {{"shape", "explicit"}, {"area", 1e300}, {"I1", 1e-12}, {"I2", 1e-12},
                         {"J", 2e-12}};
  EXPECT_ERROR(Parse(j),
               "rod.section: its stiffness or mass per length at s = 0 m is not a finite");
}

// The inflation pressure given twice, differently (the profile's 3 kPa, the actuation's 6 kPa):
// the actuation's silently won. Refused; the same value twice is fine.
TEST(ProblemIo, AnEversionRobotHasOnePressure) {
  json j = json::parse(std::ifstream(SourceDir() + "/robots/eversion_banded_vine.json"));
  ASSERT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
  j["robot"]["actuation"]["pressure"] = 6000;
  EXPECT_ERROR(Parse(j), "robot.actuation.pressure: expected the pressure "
                         "rod.stiffness_profile.pressure sets (3000 Pa)");
}

// A tolerance above 1e-3 of the dimensionless residual can pass the rigid-body guess itself as
// converged (tolerance 1: the example cantilever's tip 1.4 % off): refused. So is one below what
// double precision resolves (1e-20 stalled and threw a 2.8e-17 iterate away).
TEST(ProblemIo, ASolverToleranceOutsideWhatTheResidualResolvesIsRefused) {
  json j = ValidProblem();
  for (double ok : {1e-3, 1e-15}) {
    j["solver"] = {{"tolerance", ok}};
    EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
  }
  for (double bad : {1.0, 1e-20}) {
    j["solver"] = {{"tolerance", bad}};
    EXPECT_ERROR(Parse(j), "solver.tolerance: expected a number in [1e-15, 1e-3]");
  }
}

// One error in an eversion robot's inflated profile is one line: the robot's checks of its
// profile kind and of its growth against rod.length must not add false ones ("expected a
// robot whose rod.stiffness_profile is of kind \"inflated\"", "<= rod.length (0 m)").
TEST(ProblemIo, ABadInflatedProfileIsOneError) {
  json j = json::parse(std::ifstream(SourceDir() + "/robots/eversion_banded_vine.json"));
  j["rod"]["stiffness_profile"]["wall_thickness"] = j["rod"]["section"]["radius"];
  const ParseResult r = Parse(j);
  ASSERT_EQ(r.errors.size(), 1u) << AllErrors(r);
  EXPECT_ERROR(r, "rod.stiffness_profile.wall_thickness: expected a number smaller than");
}

// An eversion robot's tail tension is a force in newtons, >= 0; no other robot has a tail.
TEST(ProblemIo, ATailTensionIsAnEversionRobotsAndNotNegative) {
  json j = json::parse(std::ifstream(SourceDir() + "/robots/eversion_banded_vine.json"));
  j["robot"]["tail_tension"] = 2.5;
  const ParseResult ok = Parse(j);
  ASSERT_TRUE(ok.ok()) << AllErrors(ok);
  EXPECT_EQ(ok.problem->robot.tail_tension, 2.5);
  j["robot"]["tail_tension"] = -1;
  EXPECT_ERROR(Parse(j), "robot.tail_tension: expected a number >= 0");
  j["robot"]["tail_tension"] = "2 N";
  EXPECT_ERROR(Parse(j), "robot.tail_tension");
  json tendon = json::parse(std::ifstream(SourceDir() + "/robots/tendon_two_segment.json"));
  tendon["robot"]["tail_tension"] = 1.0;
  EXPECT_ERROR(Parse(tendon), "robot.tail_tension: only an \"eversion\" robot has a tail");
}

// A massless rod (density 0) is a statics case the SE(3) solvers take; the quaternion-FD model
// divides forces by the vertex masses, so it is refused there, naming the density, instead of
// failing or writing NaN frequencies. Modes it has none: refused on SE(3) too (it passed
// validation and ended in "0 modes, up to about inf Hz").
TEST(ProblemIo, AMasslessRodIsRefusedOnlyWhereTheModelNeedsMass) {
  json j = ValidProblem();
  j["rod"]["material"]["density"] = 0;
  j["loads"] = {{"tip_force", {0.01, 0, 0}}};
  for (const char* analysis : {"statics", "modes", "dynamics"}) {
    j["analysis"] = analysis;
    j["formulation"] = "quaternion-fd";
    ParseResult r = Parse(j);
    ASSERT_TRUE(r.ok()) << AllErrors(r);
    const std::vector<std::string> gated = UnsupportedFeatures(*r.problem);
    ASSERT_EQ(gated.size(), 1u) << analysis;
    EXPECT_EQ(gated[0].rfind("rod.material.density: a massless rod", 0), 0u) << gated[0];
    j["formulation"] = "se3-shooting";
    r = Parse(j);
    const std::vector<std::string> se3 = UnsupportedFeatures(*r.problem);
    if (std::string(analysis) == "modes") {
      ASSERT_EQ(se3.size(), 1u);
      EXPECT_EQ(se3[0].rfind("rod.material.density: a massless rod (density 0) has no natural",
                             0),
                0u)
          << se3[0];
    } else {
      EXPECT_TRUE(se3.empty()) << analysis;
    }
  }
}

// A bore (a cylinder the rod stays inside) no wider than the rod cannot hold it: refused,
// naming its radius (it was accepted, and the solve ended non_finite).
TEST(ProblemIo, ABoreNarrowerThanTheRodIsRefused) {
  json j = ValidProblem();
  j["environment"] = {{"contact", {{{"shape", "cylinder"}, {"point", {0, 0, 0}},
                                    {"axis", {0, 0, 1}}, {"radius", 0.0005},
                                    {"side", "inside"}, {"stiffness", 1e5}}}}};
  EXPECT_ERROR(Parse(j), "environment.contact[0].radius: a bore of radius 0.0005 m",
               "outer radius 0.001 m");
  j["environment"]["contact"][0]["radius"] = 0.002;
  EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
  // A bore along x about a rod along z: the rod leaves it at once, outside the bore (it read
  // "inside this surface", backwards for a bore).
  j["environment"]["contact"][0]["axis"] = {1, 0, 0};
  EXPECT_ERROR(Parse(j), "environment.contact[0]: the rod starts outside this bore: at s = ");
}

// An anchor's motion sweeps position + amplitude (1 − cos): its far end must be within the rod's
// reach, as the anchor itself (an amplitude of 1e5 m would run Radau into its step cap).
TEST(ProblemIo, AnAnchorMotionOutOfReachIsRefused) {
  json j = ValidProblem();
  j["analysis"] = "dynamics";
  j["formulation"] = "quaternion-fd";
  j["boundary"] = "anchored";
  j["anchor"] = {{"position", {0.4, 0, 0}},
                 {"motion", {{"amplitude", {0.1, 0, 0}}, {"period", 2.0}}}};
  EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));  // reaches 0.6 m ≤ 1.5 L = 0.75 m
  j["anchor"]["motion"]["amplitude"] = {0.2, 0, 0};   // 0.8 m
  const ParseResult r = Parse(j);
  EXPECT_TRUE(HasError(r, {"anchor.motion.amplitude: expected a motion that keeps the anchor "
                           "within 1.5 × rod.length (0.75 m)",
                           "got 0.8 m away"}))
      << AllErrors(r);
}

// A forcing period must be one the run can follow: on the SE(3) path at least two steps of dt (a
// gust of 1e-300 s sampled an aliased load and converged on it); on the quaternion-FD path at
// most 1e4 periods over the run (1 µs over 1 s ran for minutes). Both are named by field.
TEST(ProblemIo, AForcingPeriodTheStepsCannotFollowIsRefused) {
  json j = ValidProblem();
  j["analysis"] = "dynamics";
  j["formulation"] = "quaternion-fd";
  j["boundary"] = "anchored";
  j["anchor"] = {{"position", {0.4, 0, 0}},
                 {"motion", {{"amplitude", {0.1, 0, 0}}, {"period", 1e-6}}}};
  j["dynamics"] = {{"dt", 0.001}, {"duration", 1.0}};
  ParseResult r = Parse(j);
  EXPECT_TRUE(HasError(r, {"anchor.motion.period: expected a period giving at most 1e4 periods "
                           "over dynamics.duration (1 s), got 1e-06"}))
      << AllErrors(r);
  j["anchor"]["motion"]["period"] = 2e-4;  // 5 000 periods: followed
  EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
  j = ValidProblem();
  j["analysis"] = "dynamics";
  j["environment"] = {{"fluid", {{"density", 1000}, {"velocity", {0.1, 0, 0}},
                                 {"gust", {{"amplitude", 0.2}, {"period", 1e-300}}}}}};
  j["dynamics"] = {{"dt", 0.005}, {"duration", 1.0}};
  r = Parse(j);
  EXPECT_TRUE(HasError(r, {"environment.fluid.gust.period: expected a period of at least two "
                           "steps (2 dynamics.dt = 0.01 s)"}))
      << AllErrors(r);
  j["environment"]["fluid"]["gust"]["period"] = 0.01;
  EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
}

// Modes on a grid past what the spectrum can hold are refused at rod.nodes (a million nodes ran
// out of memory after 48 s on the quaternion-FD path and took 7 GB on the SE(3) one). Both take
// 100 001 (the quaternion-FD path's banded spectrum; its dense one is refused by the run past
// 801).
TEST(ProblemIo, ModesOnAGridTooFineForTheSpectrumAreRefused) {
  json j = ValidProblem();
  j["analysis"] = "modes";
  j["modes"] = {{"count", 4}};
  for (const char* formulation : {"quaternion-fd", "se3-shooting"}) {
    j["formulation"] = formulation;
    j["rod"]["nodes"] = 801;
    EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
    j["rod"]["nodes"] = 1000000;
    const ParseResult r = Parse(j);
    EXPECT_TRUE(HasError(r, {"rod.nodes: expected at most 100001 nodes for modes"}))
        << AllErrors(r);
  }
}

// initial_loads replaces loads: given with a preload alone it drops gravity from the start, which
// a user rarely means; the parse marks it (the run's log warns). An explicit "gravity", even
// zero (a release into gravity), or loads without gravity leave it unmarked.
TEST(ProblemIo, InitialLoadsWithoutGravityAreMarked) {
  json j = ValidProblem();
  j["analysis"] = "dynamics";
  j["loads"] = {{"gravity", {0, 0, -9.81}}};
  j["dynamics"] = {{"dt", 0.002}, {"duration", 0.1},
                   {"initial_loads", {{"tip_force", {-0.2, 0, 0}}}}};
  EXPECT_TRUE(Parse(j).problem->dynamics.initial_loads_without_gravity);
  j["dynamics"]["initial_loads"]["gravity"] = {0, 0, 0};
  EXPECT_FALSE(Parse(j).problem->dynamics.initial_loads_without_gravity);
  j["dynamics"]["initial_loads"].erase("gravity");
  j["loads"] = json::object();
  EXPECT_FALSE(Parse(j).problem->dynamics.initial_loads_without_gravity);
}

TEST(ProblemIo, DynamicsParsesAndRuns) {
  json j = ValidProblem();
  j["analysis"] = "dynamics";
  j["dynamics"] = {{"dt", 0.001},
                   {"duration", 0.5},
                   {"output_interval", 0.01},
                   {"initial_loads", {{"tip_force", {-0.1, 0, 0}}}}};
  ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  EXPECT_TRUE(r.problem->has_dynamics);
  EXPECT_DOUBLE_EQ(r.problem->dynamics.output_interval, 0.01);
  EXPECT_DOUBLE_EQ(r.problem->dynamics.initial_loads->tip_force.x(), -0.1);
  EXPECT_TRUE(UnsupportedFeatures(*r.problem).empty());

  j["dynamics"].erase("output_interval");  // defaults to dt
  r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  EXPECT_DOUBLE_EQ(r.problem->dynamics.output_interval, 0.001);

  j.erase("dynamics");  // the defaults of the whole block
  r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  EXPECT_DOUBLE_EQ(r.problem->dynamics.output_interval, r.problem->dynamics.dt);
  EXPECT_TRUE(UnsupportedFeatures(*r.problem).empty());
}

TEST(ProblemIo, DynamicsTipBody) {
  json j = ValidProblem();
  j["analysis"] = "dynamics";
  j["dynamics"] = {
      {"dt", 0.002}, {"duration", 0.1}, {"tip_mass", 0.02}, {"tip_inertia", {1e-6, 1e-6, 2e-7}}};
  ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  EXPECT_DOUBLE_EQ(r.problem->dynamics.tip_mass, 0.02);
  EXPECT_DOUBLE_EQ(r.problem->dynamics.tip_inertia.z(), 2e-7);
  j["dynamics"]["tip_mass"] = -1;
  j["dynamics"]["tip_inertia"] = {1e-6, -1e-6, 0};
  r = Parse(j);
  EXPECT_ERROR(r, "dynamics.tip_mass: expected", "got -1");
  EXPECT_ERROR(r, "dynamics.tip_inertia[1]: expected a moment of inertia >= 0", "got -1e-06");
}

TEST(ProblemIo, DynamicsRunsForCantileverFreeFreeAndClampedColumns) {
  json j = ValidProblem();
  j["analysis"] = "dynamics";
  for (const char* ends : {"free-free", "clamped-clamped", "clamped-pinned"}) {
    j["boundary"] = ends;
    const ParseResult r = Parse(j);
    ASSERT_TRUE(r.ok()) << AllErrors(r);
    EXPECT_TRUE(UnsupportedFeatures(*r.problem).empty()) << ends;
  }
  j["boundary"] = "pinned-pinned";
  ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const std::vector<std::string> gated = UnsupportedFeatures(*r.problem);
  ASSERT_EQ(gated.size(), 1u);
  EXPECT_EQ(gated[0], R"(boundary: "pinned-pinned" is not implemented in this version )"
                      R"((supported: "cantilever", "free-free", "clamped-clamped", )"
                      R"("clamped-pinned") for "analysis": "dynamics" on "se3-shooting"; )"
                      R"("pinned-pinned" runs statics, buckling and modes on "se3-shooting")");
  // A column's guided tip takes a dead tip force only.
  j["boundary"] = "clamped-pinned";
  j["loads"]["tip_force_frame"] = "body";
  j["loads"]["tip_force"] = json::array({0, 0, -1});
  r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const std::vector<std::string> follower = UnsupportedFeatures(*r.problem);
  ASSERT_EQ(follower.size(), 1u);
  EXPECT_EQ(follower[0].rfind("loads.tip_force_frame: a column's guided tip", 0), 0u)
      << follower[0];
  j.erase("loads");
  // Statics is still cantilever only.
  j["analysis"] = "statics";
  j["boundary"] = "free-free";
  r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  EXPECT_EQ(UnsupportedFeatures(*r.problem).size(), 1u);
}

// ----- bad input: one test per class --------------------------------------------------------

TEST(ProblemIoErrors, MalformedJsonGivesOneLineWithPosition) {
  const ParseResult r =
      ParseProblem("{\n  \"format\": \"cosserat-problem/1\",\n  rod: {}\n}", "bad.json");
  ASSERT_EQ(r.errors.size(), 1u) << AllErrors(r);
  EXPECT_FALSE(r.problem.has_value());
  EXPECT_ERROR(r, "bad.json: invalid JSON at line 3, column");
  EXPECT_EQ(r.errors[0].find("comments"), std::string::npos);  // no comment there
  // A comment, as one writes in C++ or a JSON5 file, is named (JSON has none).
  for (const char* comment : {"// the rod", "/* the rod */"}) {
    const ParseResult c = ParseProblem(
        std::string("{\n  \"format\": \"cosserat-problem/1\",\n  ") + comment + "\n}", "c.json");
    EXPECT_ERROR(c, "c.json: invalid JSON at line 3", "JSON has no comments");
  }
}

TEST(ProblemIoErrors, EmptyInputAndTrailingGarbage) {
  EXPECT_ERROR(ParseProblem(""), "invalid JSON", "line 1");
  EXPECT_ERROR(ParseProblem("{} x"), "invalid JSON");
  EXPECT_ERROR(ParseProblem("[1, 2]"), "(top level): expected an object, got an array");
}

TEST(ProblemIoErrors, UnreadableFileNamesThePath) {
  const ParseResult r = LoadProblemFile("/nonexistent/dir/problem.json");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_ERROR(r, "/nonexistent/dir/problem.json", "cannot read");
}

TEST(ProblemIoErrors, WrongTypes) {
  json j = ValidProblem();
  j["rod"]["length"] = "0.5";
  j["rod"]["nodes"] = 20.5;
  j["rod"]["section"] = 3;
  j["solver"] = {{"max_iterations", true}};
  const ParseResult r = Parse(j);
  EXPECT_FALSE(r.problem.has_value());
  EXPECT_ERROR(r, "rod.length: expected a positive number, got a string (\"0.5\")");
  EXPECT_ERROR(r, "rod.nodes: expected an integer", "got 20.5");
  EXPECT_ERROR(r, "rod.section: expected an object, got 3");
  EXPECT_ERROR(r, "solver.max_iterations: expected an integer", "got true");
}

TEST(ProblemIoErrors, NegativeAndZeroSizes) {
  json j = ValidProblem();
  j["rod"]["length"] = -0.5;
  j["rod"]["nodes"] = 2;
  j["rod"]["section"]["radius"] = 0;
  j["rod"]["material"]["youngs_modulus"] = 0;
  j["rod"]["material"]["density"] = -1;
  const ParseResult r = Parse(j);
  EXPECT_ERROR(r, "rod.length: expected a positive number, got -0.5");
  EXPECT_ERROR(r, "rod.nodes: expected an integer between 3 and", "got 2");
  EXPECT_ERROR(r, "rod.section.radius: expected a positive number, got 0");
  EXPECT_ERROR(r, "rod.material.youngs_modulus: expected a positive number, got 0");
  EXPECT_ERROR(r, "rod.material.density: expected a number >= 0, got -1");
}

TEST(ProblemIoErrors, AnnulusAndBandRanges) {
  json j = ValidProblem();
  j["rod"]["section"] = {{"shape", "annulus"}, {"outer_radius", 0.002}, {"inner_radius", 0.003}};
  j["rod"]["stiffness_profile"] =
      json::parse(R"([{"start": 0.3, "end": 0.2, "factor": 1}, {"start": 0, "end": 0.6,
                      "factor": -1}, 5])");
  j["rod"]["material"]["poisson_ratio"] = 0.7;
  j["rod"]["material"].erase("shear_modulus");
  const ParseResult r = Parse(j);
  EXPECT_ERROR(r, "rod.section.inner_radius: expected a number smaller than outer_radius");
  EXPECT_ERROR(r, "rod.stiffness_profile[0].end: expected a number greater than start");
  EXPECT_ERROR(r, "rod.stiffness_profile[1].factor: expected a positive number, got -1");
  EXPECT_ERROR(r, "rod.stiffness_profile[2]: expected a band", "got 5");
  EXPECT_ERROR(r, "rod.material.poisson_ratio: expected a number in (-1, 0.5], got 0.7");
}

// A wrong rod (a negative radius, a negative modulus) is named once: the robot's tendon anchors,
// tendon offsets and chambers checked against it said the rod was 0 m long or -1 m wide.
TEST(ProblemIoErrors, AWrongRodIsNamedWithoutFollowOnErrorsInItsRobot) {
  for (const char* file : {"robots/tendon_two_segment.json", "robots/pneumatic_finger.json"}) {
    for (const char* wrong : {"radius", "youngs_modulus"}) {
      json j = testing::SourceJson(file);
      if (std::string(wrong) == "radius")
        j["rod"]["section"]["radius"] = -1;
      else
        j["rod"]["material"]["youngs_modulus"] = -5;
      const ParseResult r = Parse(j);
      ASSERT_EQ(r.errors.size(), 1u) << file << " " << wrong << ": " << r.errors.front() << " / "
                                     << r.errors.back();
      EXPECT_NE(r.errors.front().find(wrong), std::string::npos) << r.errors.front();
    }
  }
}

TEST(ProblemIoErrors, BandEndBeyondLengthAndTooFewNodes) {
  json j = ValidProblem();
  j["rod"]["nodes"] = 3;
  j["rod"]["stiffness_profile"] = json::parse(R"([{"start": 0.1, "end": 0.2, "factor": 2},
                                                  {"start": 0.3, "end": 0.7, "factor": 2}])");
  ParseResult r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile[1].end: expected a number <= rod.length (0.5), got 0.7");
  j["rod"]["stiffness_profile"][1]["end"] = 0.4;
  r = Parse(j);
  EXPECT_ERROR(r, "rod.nodes: expected at least 6", "got 3");
}

TEST(ProblemIoErrors, OverlappingBandsNameTheLaterBand) {
  json j = ValidProblem();
  j["rod"]["stiffness_profile"] = json::parse(R"([{"start": 0.3, "end": 0.4, "factor": 0.5},
                                                  {"start": 0.1, "end": 0.35, "factor": 0.5}])");
  ParseResult r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile[0].start: expected a number >= 0.35",
               "the end of rod.stiffness_profile[1]; bands must not overlap", "got 0.3");
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "bands", "bands":
      [{"start": 0.1, "end": 0.2, "factor": 0.5}, {"start": 0.15, "end": 0.3, "factor": 0.5}]})");
  r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile.bands[1].start: expected a number >= 0.2", "got 0.15");
}

TEST(ProblemIoErrors, StiffnessProfileObjectKeysAndKinds) {
  json j = ValidProblem();
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "tapper", "tip": {"radius": 1e-4}})");
  ParseResult r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile.kind: expected one of", "did you mean \"taper\"?");
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "jamming", "layer_i": 1e-9,
      "layer_modulus": {"slope": 10}, "presure": 5, "segments": [{"start": 0, "end": 0.1}]})");
  r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile.layer_i: unknown key for a \"jamming\" profile",
               "did you mean \"layer_I\"?");
  EXPECT_ERROR(r, "rod.stiffness_profile.presure: unknown key", "did you mean \"pressure\"?");
  EXPECT_ERROR(r, "rod.stiffness_profile.layer_I: expected a positive number, got nothing");
  j["rod"]["stiffness_profile"] = 5;
  r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile: expected an array of bands", "or a profile", "got 5");
}

TEST(ProblemIoErrors, StiffnessProfileBadPressuresAndTables) {
  json j = ValidProblem();
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "pressure_modulus", "pressure": -5,
      "modulus": {"table": [[0, 1e6], [2e4, 2e6], [1e4, 3e6], [3e4, 1e6], [-1, 1e6], [4e4]]}})");
  ParseResult r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile.pressure: expected a number >= 0, got -5");
  EXPECT_ERROR(r, "rod.stiffness_profile.modulus.table[2][0]: expected a pressure greater than",
               "got 10000");
  EXPECT_ERROR(r, "rod.stiffness_profile.modulus.table[3][1]: expected a modulus >= the previous",
               "may not fall with pressure", "got 1000000");
  EXPECT_ERROR(r, "rod.stiffness_profile.modulus.table[4][0]: expected a number >= 0, got -1");
  EXPECT_ERROR(r, "rod.stiffness_profile.modulus.table[5]: expected a [pressure (Pa), modulus");
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "pressure_modulus",
      "modulus": {"E0": 1e6, "slope": -3, "table": [[0, 1]]}})");
  r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile.modulus: expected either \"table\" or \"E0\"/\"slope\"",
               "got both");
  j["rod"]["stiffness_profile"] =
      json::parse(R"({"kind": "pressure_modulus", "modulus": {"E0": 0, "slope": -3}})");
  r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile.modulus.E0: expected a positive number, got 0");
  EXPECT_ERROR(r, "rod.stiffness_profile.modulus.slope: expected a number >= 0, got -3");
}

TEST(ProblemIoErrors, StiffnessProfileBadRadiiSegmentsAndShapes) {
  json j = ValidProblem();
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "taper", "tip": {"radius": 0}})");
  ParseResult r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile.tip.radius: expected a positive number, got 0");
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "taper", "table": [
      {"s": 0.3, "radius": 1e-3}, {"s": 0.2, "radius": 1e-3}, {"s": 0.6, "radius": -1}]})");
  r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile.table[1].s: expected a number greater than the previous",
               "got 0.2");
  EXPECT_ERROR(r, "rod.stiffness_profile.table[2].s: expected a number <= rod.length (0.5)");
  EXPECT_ERROR(r, "rod.stiffness_profile.table[2].radius: expected a positive number, got -1");
  j["rod"]["section"] = {{"shape", "rectangle"}, {"width", 0.01}, {"height", 0.002}};
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "taper", "tip": {"radius": 1e-4}})");
  r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile.kind: expected a \"circle\" or \"annulus\" rod.section",
               "got \"rectangle\"");
  j = ValidProblem();
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "jamming", "layer_I": 1e-9,
      "layer_modulus": {"slope": 10}, "segments": [{"start": 0, "end": 0.2},
      {"start": 0.1, "end": 0.3, "pressure": -2}]})");
  r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile.segments[1].pressure: expected a number >= 0, got -2");
  j["rod"]["stiffness_profile"]["segments"][1]["pressure"] = 1e4;
  r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile.segments[1].start: expected a number >= 0.2",
               "listed in order along the rod", "got 0.1");
  j["rod"]["stiffness_profile"]["segments"] = json::array();
  for (int k = 0; k < 17; ++k)
    j["rod"]["stiffness_profile"]["segments"].push_back(
        {{"start", 0.01 * k}, {"end", 0.01 * (k + 1)}});
  r = Parse(j);
  EXPECT_ERROR(r, "rod.stiffness_profile.segments: expected 1 to 16 segments",
               "got an array of 17");
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "inflated", "wall_thickness": 0.002,
      "constrictions": [{"start": 0.1, "end": 0.2, "diameter_ratio": 1.5, "factor": 0.36}]})");
  r = Parse(j);
  EXPECT_ERROR(r,
               "rod.stiffness_profile.wall_thickness: expected a number smaller than "
               "rod.section.radius (0.001), got 0.002");
  EXPECT_ERROR(r,
               "rod.stiffness_profile.constrictions[0].diameter_ratio: expected a number in "
               "(0, 1], got 1.5");
}

TEST(ProblemIoErrors, TooFewNodesForProfileBreakpoints) {
  json j = ValidProblem();
  j["rod"]["nodes"] = 4;
  j["rod"]["stiffness_profile"] = json::parse(R"({"kind": "jamming", "layer_I": 1e-9,
      "layer_modulus": {"slope": 10}, "segments": [{"start": 0, "end": 0.1},
      {"start": 0.1, "end": 0.2}, {"start": 0.2, "end": 0.3}]})");
  const ParseResult r = Parse(j);
  EXPECT_ERROR(r, "rod.nodes: expected at least 5", "breakpoint", "got 4");
}

TEST(ProblemIoErrors, NonFiniteNumbersFromOverflow) {
  const std::string text = R"({
    "format": "cosserat-problem/1",
    "rod": {
      "length": 1e999,
      "nodes": 21,
      "section": { "shape": "circle", "radius": 0.001 },
      "material": { "youngs_modulus": 200e9, "shear_modulus": 80e9, "density": -1e999 }
    }
  })";
  const ParseResult r = ParseProblem(text);
  EXPECT_EQ(r.errors.size(), 2u) << AllErrors(r);
  EXPECT_FALSE(r.problem.has_value());
  EXPECT_ERROR(r, "rod.length: expected a positive number", "overflow");
  EXPECT_ERROR(r, "rod.material.density: expected a number >= 0", "overflow");
}

TEST(ProblemIoErrors, OverflowInsideAnArrayNamesTheElement) {
  json j = ValidProblem();
  j["loads"]["gravity"] = {0, 0, 1};
  std::string text = j.dump();
  text.replace(text.find("[0,0,1]"), 7, "[0,0,1e400]");
  EXPECT_ERROR(ParseProblem(text), "loads.gravity[2]: expected a finite number", "overflow");
}

TEST(ProblemIoErrors, UnknownKeysWithSuggestions) {
  json j = ValidProblem();
  j["rod"]["lenght"] = j["rod"]["length"];
  j["rod"].erase("length");
  j["loads"] = {{"Gravity", {0, 0, -9.81}}, {"wind", {1, 0, 0}}};
  j["rod"]["section"]["width"] = 0.01;
  const ParseResult r = Parse(j);
  EXPECT_ERROR(r, "rod.lenght: unknown key (did you mean \"length\"?)");
  EXPECT_ERROR(r, "rod.length: expected a positive number, got nothing");
  EXPECT_ERROR(r, "loads.Gravity: unknown key (did you mean \"gravity\"?)");
  EXPECT_ERROR(r, "loads.wind: unknown key (allowed: \"gravity\"");
  EXPECT_ERROR(r, "rod.section.width: unknown key for a \"circle\" section");
}

// Textbooks name end conditions "fixed" (clamped) and "simply supported" (pinned): those names
// are pointed to ours, which no edit distance would find ("fixed-free" is 8 edits from
// "cantilever").
TEST(ProblemIoErrors, TextbookEndConditionsPointToOurs) {
  const std::pair<const char*, const char*> cases[] = {{"fixed-free", "cantilever"},
                                                       {"Simply supported", "pinned-pinned"},
                                                       {"fixed_fixed", "clamped-clamped"},
                                                       {"propped-cantilever", "clamped-pinned"}};
  for (const auto& [typed, ours] : cases) {
    json j = ValidProblem();
    j["boundary"] = typed;
    EXPECT_ERROR(Parse(j), "boundary: expected one of",
                 std::string("did you mean \"") + ours + "\"?");
  }
}

TEST(ProblemIoErrors, MissingRequiredKeys) {
  json j = ValidProblem();
  j.erase("format");
  j["rod"].erase("material");
  j["rod"]["section"].erase("radius");
  const ParseResult r = Parse(j);
  EXPECT_ERROR(r, "format: expected \"cosserat-problem/1\", got nothing (required key is missing)");
  EXPECT_ERROR(r, "rod.material: expected an object, got nothing (required key is missing)");
  EXPECT_ERROR(r, "rod.section.radius: expected a positive number, got nothing");
  EXPECT_ERROR(Parse(json::object({{"format", "cosserat-problem/1"}})), "rod: expected an object",
               "missing");
}

TEST(ProblemIoErrors, WrongFormatVersion) {
  json j = ValidProblem();
  j["format"] = "cosserat-problem/2";
  EXPECT_ERROR(Parse(j),
               "format: expected \"cosserat-problem/1\", got a string (\"cosserat-problem/2\")");
}

TEST(ProblemIoErrors, BadEnumerationsListTheChoices) {
  json j = ValidProblem();
  j["analysis"] = "static";
  j["boundary"] = "fixed";
  j["rod"]["section"]["shape"] = "cirlce";
  j["loads"] = {{"tip_force_frame", "local"}};
  const ParseResult r = Parse(j);
  EXPECT_ERROR(r, "analysis: expected one of \"statics\", \"dynamics\", \"buckling\", \"modes\"",
               "got \"static\" (did you mean \"statics\"?)");
  EXPECT_ERROR(r, "boundary: expected one of \"cantilever\"", "got \"fixed\"");
  EXPECT_ERROR(r, "rod.section.shape: expected one of \"circle\"", "did you mean \"circle\"?");
  EXPECT_ERROR(r, "loads.tip_force_frame: expected one of \"world\", \"body\", got \"local\"");
}

TEST(ProblemIoErrors, RotationMustBeOrthonormalWithPositiveDeterminant) {
  json j = ValidProblem();
  j["base"]["rotation"] = {{1, 0, 0}, {0, 2, 0}, {0, 0, 1}};
  EXPECT_ERROR(Parse(j), "base.rotation: expected a rotation matrix", "1e-6",
               "got max |R^T R - I| = 3");
  j["base"]["rotation"] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};  // a reflection
  EXPECT_ERROR(Parse(j), "base.rotation: expected a rotation matrix", "determinant -1");
  // 45° about x typed to five digits: |RᵀR − I| = 2 · 0.70711² − 1 ≈ 9.1e-6, past 1e-6.
  j["base"]["rotation"] = {{1, 0, 0}, {0, 0.70711, -0.70711}, {0, 0.70711, 0.70711}};
  EXPECT_ERROR(Parse(j), "base.rotation: expected a rotation matrix",
               "got max |R^T R - I| = 9.1", "give them to 7 significant digits or more");
  j["base"]["rotation"] = {{1, 0, 0}, {0, "a", 0}, {0, 0}};
  const ParseResult r = Parse(j);
  EXPECT_ERROR(r, "base.rotation[1][1]: expected a finite number, got a string (\"a\")");
  EXPECT_ERROR(r, "base.rotation[2]: expected a row of 3 numbers, got an array of 2 items");
}

TEST(ProblemIoErrors, ShearModulusAndPoissonRatioExclusive) {
  json j = ValidProblem();
  j["rod"]["material"]["poisson_ratio"] = 0.3;
  EXPECT_ERROR(Parse(j),
               "rod.material: expected exactly one of \"shear_modulus\" and "
               "\"poisson_ratio\", got both");
  j["rod"]["material"].erase("poisson_ratio");
  j["rod"]["material"].erase("shear_modulus");
  EXPECT_ERROR(Parse(j), "rod.material: expected exactly one of", "got neither");
  j["rod"]["material"]["shear_modulus"] = 50e9;  // nu = 1
  EXPECT_ERROR(Parse(j), "rod.material.shear_modulus: expected at least youngs_modulus / 3");
}

TEST(ProblemIoErrors, DuplicateKeys) {
  const std::string text =
      R"({"format": "cosserat-problem/1", "rod": {"length": 0.5, "length": 0.6, "nodes": 21,
          "section": {"shape": "circle", "radius": 0.001},
          "material": {"youngs_modulus": 2e11, "shear_modulus": 8e10, "density": 8000}}})";
  EXPECT_ERROR(ParseProblem(text), "rod.length: expected each key once", "duplicate");
}

TEST(ProblemIoErrors, LaterAnalysisBlocksAreValidatedToo) {
  json j = ValidProblem();
  j["analysis"] = "buckling";
  j["dynamics"] = {{"dt", 2.0}, {"duration", 1.0}, {"initial", "rest"}};
  j["modes"] = {{"count", 0}};
  const ParseResult r = Parse(j);
  EXPECT_ERROR(r, "buckling: expected an object", "required key is missing");
  EXPECT_ERROR(r, "dynamics.dt: expected a time step no longer than duration", "got 2");
  EXPECT_ERROR(r, "dynamics.initial: expected one of \"static\", got \"rest\"");
  EXPECT_ERROR(r, "modes.count: expected an integer between 1 and", "got 0");
  j["buckling"] = {{"direction", {0, 0, 0}}};
  EXPECT_ERROR(Parse(j), "buckling.direction: expected a non-zero vector");
  EXPECT_ERROR(Parse(j), "buckling.max: expected a positive number, got nothing");
}

// A searched load that cannot act is refused before the search, which ran to its max and said
// "not found": a tip force across a column's axis (the tip's guide takes it whole; here the
// default direction, −z, on a column along +x) and gravity on a rod with no mass and no fluid.
TEST(ProblemIoErrors, ABucklingLoadThatCannotActIsNamed) {
  json j = ValidProblem();
  j["analysis"] = "buckling";
  j["boundary"] = "pinned-pinned";
  j["base"] = {{"position", {0, 0, 0}}, {"rotation", {{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}}}};
  j["buckling"] = {{"load", "tip_force"}, {"max", 10.0}};
  EXPECT_ERROR(Parse(j), "buckling.direction: expected a direction with a part along the column's "
                         "axis, base.rotation's third column [1, 0, 0]",
               "got [0, 0, -1] (the default)");
  j["buckling"]["direction"] = {-1, 0, 0};
  EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
  j["boundary"] = "cantilever";  // a free tip: a force across the axis bends it, and is searched
  j["buckling"]["direction"] = {0, 0, -1};
  EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
  j["buckling"] = {{"load", "gravity"}, {"max", 10.0}};
  EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
  j["rod"]["material"]["density"] = 0.0;
  EXPECT_ERROR(Parse(j), "buckling.load: expected a load this problem has (\"gravity\" acts on "
                         "the rod's mass, or through a fluid's buoyancy)");
  j["environment"] = {{"fluid", {{"density", 1000.0}}}};  // buoyancy lifts it
  EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
}

// Buckling along actuation paths: "tendon_tension" needs a tendon robot (optional weights, one per
// tendon), "pressure" a pressure-dependent section; neither takes a direction.
TEST(ProblemIo, BucklingActuationLoadsParse) {
  json j = ValidProblem();
  j["analysis"] = "buckling";
  j["robot"] = json::parse(R"({"kind": "tendon", "tendons": [
      {"route": "parallel", "offset": [0.0005, 0]}, {"route": "parallel", "offset": [0, 0.0005]}]})");
  j["buckling"] = {{"load", "tendon_tension"}, {"tendons", {2, 0}}, {"max", 50.0}};
  ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  EXPECT_EQ(r.problem->buckling.load, BucklingLoad::kTendonTension);
  EXPECT_EQ(r.problem->buckling.tendon_weights, (std::vector<double>{2, 0}));
  j["buckling"].erase("tendons");  // default: every tendon alike
  r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  EXPECT_TRUE(r.problem->buckling.tendon_weights.empty());

  json q = ValidProblem();
  q["analysis"] = "buckling";
  q["rod"]["stiffness_profile"] = json::parse(
      R"({"kind": "pressure_modulus", "pressure": 5000, "modulus": {"E0": 1e6, "slope": 100}})");
  q["buckling"] = {{"load", "pressure"}, {"max", 30000.0}};
  r = Parse(q);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  EXPECT_EQ(r.problem->buckling.load, BucklingLoad::kPressure);
  EXPECT_DOUBLE_EQ(r.problem->buckling.max, 30000.0);
  EXPECT_TRUE(UnsupportedFeatures(*r.problem).empty());
  q["formulation"] = "quaternion-fd";
  r = Parse(q);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const auto unsupported = UnsupportedFeatures(*r.problem);
  ASSERT_EQ(unsupported.size(), 1u);
  EXPECT_NE(unsupported[0].find("buckling.load: \"pressure\" runs on the \"se3-shooting\""),
            std::string::npos)
      << unsupported[0];
}

TEST(ProblemIoErrors, BucklingActuationLoads) {
  json j = ValidProblem();
  j["analysis"] = "buckling";
  j["buckling"] = {{"load", "tendon_tension"}, {"max", 10.0}};
  EXPECT_ERROR(Parse(j), "buckling.load: expected a load this problem has",
               "needs a robot of robot.kind \"tendon\"", "got \"tendon_tension\" with no robot");
  j["robot"] = {{"kind", "jamming"}};
  EXPECT_ERROR(Parse(j), "buckling.load:", "got \"tendon_tension\" with robot.kind \"jamming\"");

  j["robot"] = {{"kind", "tendon"}, {"tendons", json::array()}};
  EXPECT_ERROR(Parse(j), "buckling.load:", "with an empty robot.tendons");

  j["robot"] = json::parse(R"({"kind": "tendon", "tendons": [
      {"route": "parallel", "offset": [0.0005, 0]}, {"route": "parallel", "offset": [0, 0.0005]}]})");
  j["buckling"]["tendons"] = {1, 1, 1};
  EXPECT_ERROR(Parse(j), "buckling.tendons: expected one weight per tendon (2 in robot.tendons)",
               "got 3 weights");
  j["buckling"]["tendons"] = {0, 0};
  EXPECT_ERROR(Parse(j), "buckling.tendons: expected at least one weight > 0, got all zero");
  j["buckling"]["tendons"] = {1, -0.5};
  EXPECT_ERROR(Parse(j), "buckling.tendons[1]: expected a weight >= 0, got -0.5");
  j["buckling"]["tendons"] = "all";
  EXPECT_ERROR(Parse(j), "buckling.tendons: expected an array of 1 to 8 weights >= 0");
  j["buckling"]["tendons"] = {1, 1};
  j["buckling"]["direction"] = {0, 0, -1};
  EXPECT_ERROR(Parse(j), "buckling.direction: not used by a \"tendon_tension\" load");
  j["buckling"] = {{"load", "tip_force"}, {"tendons", {1, 1}}, {"max", 10.0}};
  EXPECT_ERROR(Parse(j), "buckling.tendons: only a \"tendon_tension\" load has tendon weights");

  json q = ValidProblem();
  q["analysis"] = "buckling";
  q["buckling"] = {{"load", "pressure"}, {"max", 1e4}};
  EXPECT_ERROR(Parse(q), "buckling.load: expected a load this problem has",
               "needs a pressure-dependent section", "got \"pressure\" with no such profile");
  q["rod"]["stiffness_profile"] = {{"kind", "bands"}, {"bands", json::array()}};
  EXPECT_ERROR(Parse(q), "buckling.load:", "got \"pressure\" with a \"bands\" profile");
}

TEST(ProblemIoErrors, DynamicsTimes) {
  json j = ValidProblem();
  j["analysis"] = "dynamics";
  j["dynamics"] = {{"dt", 0}, {"duration", -1.0}, {"output_interval", -0.5}};
  ParseResult r = Parse(j);
  EXPECT_ERROR(r, "dynamics.dt: expected a positive number, got 0");
  EXPECT_ERROR(r, "dynamics.duration: expected a positive number, got -1");
  EXPECT_ERROR(r, "dynamics.output_interval: expected a positive number, got -0.5");
  EXPECT_EQ(r.errors.size(), 3u) << AllErrors(r);

  r = ParseProblem(R"({"format": "cosserat-problem/1", "analysis": "dynamics",
      "rod": {"length": 0.5, "nodes": 21, "section": {"shape": "circle", "radius": 0.001},
              "material": {"youngs_modulus": 2e11, "shear_modulus": 8e10, "density": 8000}},
      "dynamics": {"output_interval": "10 ms", "dt": null, "duration": 1e999}})");
  EXPECT_ERROR(r, "dynamics.output_interval: expected a positive number, got a string");
  EXPECT_ERROR(r, "dynamics.dt: expected a positive number, got null");
  EXPECT_ERROR(r, "dynamics.duration: expected a positive number", "overflow");

  j["dynamics"] = {{"duration", 0.001}};  // shorter than the default dt
  EXPECT_ERROR(Parse(j), "dynamics.dt: expected a time step no longer than duration (0.001 s)",
               "got 0.002 (the default)");
  j["dynamics"] = {{"dt", 1e-9}, {"duration", 100.0}};
  EXPECT_ERROR(Parse(j), "dynamics.dt: expected a time step giving at most 10000000 steps",
               "got 1e-09");
  // A duration far too long for its step is named, not the step the file also gave.
  j["dynamics"] = {{"dt", 0.002}, {"duration", 1e300}};
  EXPECT_ERROR(Parse(j), "dynamics.duration: expected a duration giving at most 10000000 steps "
               "of dt (0.002 s)", "got 1e+300, 5e+302 steps");
  j["dynamics"] = {{"dt", 0.01}, {"duration", 0.1}, {"output_intervall", 0.02}};
  EXPECT_ERROR(Parse(j),
               "dynamics.output_intervall: unknown key (did you mean \"output_interval\"?)");
}

TEST(ProblemIoErrors, EveryErrorIsReported) {
  json j = ValidProblem();
  j.erase("format");
  j["rod"]["length"] = 0;
  j["rod"]["nodes"] = "many";
  j["rod"]["section"]["radius"] = -1;
  j["rod"]["material"]["poisson_ratio"] = 0.3;
  j["loads"] = {{"gravity", {0, "down", 0}}, {"tip_forse", {1, 0, 0}}};
  j["solver"] = {{"tolerance", -1}};
  j["extra"] = 1;
  const ParseResult r = Parse(j);
  EXPECT_FALSE(r.problem.has_value());
  EXPECT_EQ(r.errors.size(), 9u) << AllErrors(r);
  for (const char* path :
       {"format:", "rod.length:", "rod.nodes:", "rod.section.radius:", "rod.material:",
        "loads.gravity[1]:", "loads.tip_forse:", "solver.tolerance:", "extra:"})
    EXPECT_ERROR(r, path);
}

// ----- result writer ------------------------------------------------------------------------

RodState TwoNodeState() {
  RodState state;
  state.Resize(2);
  state.s = {0.0, 0.5};
  state.position_W = {Vec3::Zero(), Vec3(0.1, 0.0, 0.4)};
  Mat3 tip;
  tip << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  state.rotation_WB = {Mat3::Identity(), tip};
  Vec6 xi0, xi1;
  xi0 << 1, 2, 3, 0, 0, 1;
  xi1 << 4, 5, 6, 0, 0, 1;
  state.strain = {xi0, xi1};
  Vec6 w0;
  w0 << 0.1, 0.2, 0.3, 1, 2, 3;
  state.wrench_B = {w0, Vec6::Zero()};
  return state;
}

TEST(ResultWriter, JsonHasTheContractKeys) {
  StaticShootingSummary summary;
  summary.status = SolveStatus::kConverged;
  summary.iterations = 7;
  summary.residual = 3e-13;
  const RodState state = TwoNodeState();
  const nlohmann::ordered_json out = StaticResultToJson(summary, state);
  EXPECT_EQ(out["status"], "converged");
  EXPECT_EQ(out["iterations"], 7);
  EXPECT_DOUBLE_EQ(out["residual"].get<double>(), 3e-13);
  EXPECT_TRUE(out.contains("wall_time_s"));
  EXPECT_DOUBLE_EQ(out["tip"]["position"][2].get<double>(), 0.4);
  EXPECT_DOUBLE_EQ(out["tip"]["rotation"][0][1].get<double>(), -1.0);  // row-major
  EXPECT_DOUBLE_EQ(out["tip"]["rotation"][1][0].get<double>(), 1.0);
  const Vec6 reaction = state.BaseReaction_W();
  EXPECT_DOUBLE_EQ(out["base_wrench"]["moment"][2].get<double>(), reaction(2));
  EXPECT_DOUBLE_EQ(out["base_wrench"]["force"][0].get<double>(), reaction(3));
  EXPECT_EQ(out["nodes"]["s"].size(), 2u);
  EXPECT_DOUBLE_EQ(out["nodes"]["curvature"][1][2].get<double>(), 6.0);
  EXPECT_DOUBLE_EQ(out["nodes"]["position"][1][0].get<double>(), 0.1);
}

DynamicRun TwoFrameRun() {
  DynamicRun run;
  run.status = SolveStatus::kConverged;
  run.initial_state_ok = true;
  run.steps = 4;
  run.iterations = 9;
  run.shots = 13;
  run.wall_time_s = 0.5;
  run.stepping_wall_time_s = 0.4;
  run.simulated_time_s = 0.008;
  run.step_time_s = {4e-6, 1e-6, 3e-6, 2e-6};
  run.energy.kinetic = 1.5;
  run.frame_t = {0.0, 0.008};
  run.frame_tip = {Vec3(0, 0, 0.5), Vec3(0.1, 0, 0.4)};
  run.frame_positions = {Vec3::Zero(), Vec3(0, 0, 0.5), Vec3::Zero(), Vec3(0.1, 0, 0.4)};
  return run;
}

TEST(ResultWriter, DynamicJsonHasTheContractKeys) {
  const RodState state = TwoNodeState();
  DynamicRun run = TwoFrameRun();
  nlohmann::ordered_json out = DynamicResultToJson(run, state);
  EXPECT_EQ(out.begin().key(), "status");
  EXPECT_EQ(out["status"], "converged");
  EXPECT_FALSE(out.contains("failed_at_t"));
  EXPECT_EQ(out["steps"], 4);
  EXPECT_EQ(out["iterations"], 9);
  EXPECT_EQ(out["shots"], 13);
  EXPECT_DOUBLE_EQ(out["real_time_ratio"].get<double>(), 0.008 / 0.4);
  EXPECT_DOUBLE_EQ(out["step_time_us"]["median"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(out["step_time_us"]["p99"].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(out["step_time_us"]["max"].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(out["tip"]["position"][0].get<double>(), 0.1);
  EXPECT_TRUE(out.contains("base_wrench"));
  EXPECT_TRUE(out.contains("nodes"));
  EXPECT_DOUBLE_EQ(out["energy"]["kinetic"].get<double>(), 1.5);
  EXPECT_EQ(out["trajectory"]["t"].size(), 2u);
  EXPECT_DOUBLE_EQ(out["trajectory"]["tip_position"][1][2].get<double>(), 0.4);

  run.status = SolveStatus::kMaxIterations;  // failed before any state: no state keys
  run.initial_state_ok = false;
  run.failed_at_t = 0.0;
  out = DynamicResultToJson(run, state);
  EXPECT_EQ(out["status"], "max_iterations");
  EXPECT_DOUBLE_EQ(out["failed_at_t"].get<double>(), 0.0);
  EXPECT_FALSE(out.contains("tip") || out.contains("trajectory") || out.contains("nodes"));
}

TEST(ResultWriter, TrajectoryCsvIsLongFormat) {
  std::ostringstream csv;
  WriteTrajectoryCsv(csv, TwoFrameRun(), {0.0, 0.5});
  EXPECT_EQ(csv.str(),
            "t,node,s,x,y,z\n"
            "0,0,0,0,0,0\n"
            "0,1,0.5,0,0,0.5\n"
            "0.008,0,0,0,0,0\n"
            "0.008,1,0.5,0.1,0,0.4\n");
}

// Numbers are written as the shortest text that reads back to the same double.
TEST(ResultWriter, CsvNumbersReadBackExactly) {
  RodState state = TwoNodeState();
  const double values[] = {1.0 / 3, -6.6164789470187966e-05, 1e-300, 123456789.123456789};
  state.position_W[1] = Vec3(values[0], values[1], values[2]);
  state.strain[1](0) = values[3];
  std::ostringstream csv;
  WriteNodesCsv(csv, state);
  std::istringstream lines(csv.str());
  std::string row;
  std::getline(lines, row);
  std::getline(lines, row);
  std::getline(lines, row);
  std::vector<double> read;
  std::istringstream fields(row);
  for (std::string f; std::getline(fields, f, ',');)
    read.push_back(std::strtod(f.c_str(), nullptr));
  ASSERT_EQ(read.size(), 7u);
  EXPECT_EQ(read[1], values[0]);
  EXPECT_EQ(read[2], values[1]);
  EXPECT_EQ(read[3], values[2]);
  EXPECT_EQ(read[4], values[3]);
}

TEST(ResultWriter, CsvHasHeaderAndOneRowPerNode) {
  std::ostringstream csv;
  WriteNodesCsv(csv, TwoNodeState());
  std::istringstream lines(csv.str());
  std::string header, row0, row1, extra;
  std::getline(lines, header);
  std::getline(lines, row0);
  std::getline(lines, row1);
  EXPECT_EQ(header, "s,x,y,z,k1,k2,k3");
  EXPECT_EQ(row0, "0,0,0,0,1,2,3");
  EXPECT_EQ(row1, "0.5,0.1,0,0.4,4,5,6");
  EXPECT_FALSE(std::getline(lines, extra));
}

// ----- robot section ---------------------------------------------------------------------------

TEST(ProblemIoRobot, TendonRoutesAndTensionsMapToTheModel) {
  json j = ValidProblem();
  j["robot"] = json::parse(R"({
    "kind": "tendon", "disk_radius": 0.01,
    "tendons": [ { "name": "a", "route": "parallel", "offset": [0.008, 0] },
                 { "route": "converging", "offset_base": [0, 0.008], "offset_tip": [0, 0.004] },
                 { "route": "helical", "radius": 0.005, "pitch": -0.25, "phase": 0.5 } ],
    "actuation": { "tension": [1.5, 0, 2] },
    "initial_actuation": { "tension": [0.5, 0, 0] } })");
  const ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const Problem& p = *r.problem;
  ASSERT_EQ(p.rod.tendons.size(), 3u);
  EXPECT_EQ(p.rod.tendons[0].name, "a");
  EXPECT_EQ(p.rod.tendons[0].route.OffsetAt(0.3, 0.5), Vec3(0.008, 0, 0));
  EXPECT_EQ(p.rod.tendons[1].route.OffsetAt(0.5, 0.5), Vec3(0, 0.004, 0));  // at the tip
  EXPECT_EQ(p.rod.tendons[2].route.kind, TendonRoute::Kind::kHelical);
  EXPECT_EQ(p.rod.tendons[2].route.pitch, -0.25);
  EXPECT_EQ(p.robot.actuation.tendon_tension[2], 2.0);
  EXPECT_EQ(p.robot.initial_actuation.tendon_tension[0], 0.5);
  EXPECT_FALSE(p.robot.tendon_lengths.has_value());
}

TEST(ProblemIoRobot, LengthControlAndItsErrors) {
  json j = ValidProblem();
  j["robot"] = json::parse(R"({ "kind": "tendon",
    "tendons": [ { "route": "parallel", "offset": [0.0005, 0] } ],
    "actuation": { "length": [0.499] } })");
  ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  EXPECT_EQ((*r.problem->robot.tendon_lengths)[0], 0.499);

  j["robot"]["actuation"] = json::parse(R"({ "length": [0.499, 0.4], "tension": [1] })");
  r = Parse(j);
  EXPECT_ERROR(r, "robot.actuation", "either \"tension\"");
  EXPECT_ERROR(r, "robot.actuation.length", "one value per tendon (1 in robot.tendons)");
  j["robot"]["actuation"] = json::parse(R"({ "tension": [1] })");
  j["robot"]["tendons"][0]["offset"] = json::array({0.002, 0});  // outside the 1 mm rod
  r = Parse(j);
  EXPECT_ERROR(r, "robot.tendons[0].offset", "within the section", "0.002");
  j["robot"].erase("tendons");
  r = Parse(j);
  EXPECT_ERROR(r, "robot.tendons", "required key is missing");
}

TEST(ProblemIoRobot, ChambersAndTheirPressuresMapToTheModel) {
  json j = ValidProblem();
  j["robot"] = json::parse(R"({ "kind": "pneumatic",
    "chambers": [ { "name": "a", "offset": [0.0005, 0], "area": 2.8e-7 },
                  { "offset": [0, -0.0005], "area": 2.8e-7, "from": 0.1, "to": 0.3 } ],
    "actuation": { "chamber_pressure": [1e5, -5e4] },
    "initial_actuation": { "chamber_pressure": [2e4, 0] } })");
  const ParseResult r = Parse(j);
  ASSERT_TRUE(r.ok()) << AllErrors(r);
  const Problem& p = *r.problem;
  EXPECT_EQ(p.robot.kind, RobotKind::kPneumatic);
  ASSERT_EQ(p.rod.chambers.size(), 2u);
  EXPECT_EQ(p.rod.chambers[0].name, "a");
  EXPECT_EQ(p.rod.chambers[0].start, 0.0);  // the whole rod by default
  EXPECT_EQ(p.rod.chambers[0].end, 0.5);
  EXPECT_EQ(p.rod.chambers[1].offset, Vec2(0, -0.0005));
  EXPECT_EQ(p.rod.chambers[1].start, 0.1);
  EXPECT_EQ(p.rod.chambers[1].end, 0.3);
  EXPECT_EQ(p.robot.actuation.chamber_pressure[1], -5e4);  // a partial vacuum
  EXPECT_EQ(p.robot.initial_actuation.chamber_pressure[0], 2e4);
  // Both formulations run a pneumatic robot's statics.
  j["formulation"] = "quaternion-fd";
  EXPECT_TRUE(UnsupportedFeatures(*Parse(j).problem).empty());
}

TEST(ProblemIoRobot, BadChambersAreNamedByTheirPath) {
  json j = ValidProblem();  // L = 0.5 m, radius 1 mm
  j["robot"] = json::parse(R"({ "kind": "pneumatic",
    "chambers": [ { "offset": [0.0004, 0], "area": -1e-7 },
                  { "offset": [0.0008, 0], "area": 2.8e-7 },
                  { "offset": [0, 0], "area": 1e-7, "from": 0.3, "to": 0.2 },
                  { "offset": [0, 0], "area": 1e-7, "to": 0.6 },
                  { "offset": [0, 12345.5], "area": 1e-7 },
                  { "offset": [0, 0], "area": 1e-7, "from": -0.1 } ],
    "actuation": { "chamber_pressure": [1e5, 0, 0] } })");
  std::string text = j.dump(2);  // an overflowing number, which nlohmann::json cannot hold
  text.replace(text.find("12345.5"), 7, "1e999");
  const ParseResult r = ParseProblem(text);
  EXPECT_ERROR(r, "robot.chambers[0].area: expected a positive number", "-1e-07");
  EXPECT_ERROR(r, "robot.chambers[1].offset: expected a chamber within the section",
               "outer radius 0.001 m");
  EXPECT_ERROR(r, "robot.chambers[2].to: expected from < to", "from = 0.3, to = 0.2");
  EXPECT_ERROR(r, "robot.chambers[3].to: expected a number within [0, rod.length]", "0.6");
  EXPECT_ERROR(r, "robot.chambers[4].offset", "finite");
  EXPECT_ERROR(r, "robot.chambers[5].from: expected a number within [0, rod.length]");
  EXPECT_ERROR(r,
               "robot.actuation.chamber_pressure: expected one value per chamber (6 in "
               "robot.chambers)");

  // A rectangle: the chamber's disc must fit in both directions.
  j = ValidProblem();
  j["rod"]["section"] = json::parse(R"({ "shape": "rectangle", "width": 0.004, "height": 0.002 })");
  j["robot"] = json::parse(R"({ "kind": "pneumatic",
    "chambers": [ { "offset": [0.0015, 0], "area": 1e-6 } ] })");
  EXPECT_ERROR(Parse(j), "robot.chambers[0].offset: expected a chamber within the rectangle");
  j["robot"]["chambers"][0]["offset"] = json::array({0.0, 0.0});
  EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));

  // A pneumatic robot needs chambers; a pressure below vacuum is refused; chamber ends need nodes.
  j = ValidProblem();
  j["robot"] = json::parse(R"({ "kind": "pneumatic" })");
  EXPECT_ERROR(Parse(j), "robot.chambers", "required key is missing");
  j["robot"] = json::parse(R"({ "kind": "pneumatic",
    "chambers": [ { "offset": [0, 0], "area": 1e-7 } ],
    "actuation": { "chamber_pressure": [-2e5] } })");
  EXPECT_ERROR(Parse(j),
               "robot.actuation.chamber_pressure[0]: expected a gauge pressure >= -101325");
  j["rod"]["nodes"] = 3;
  j["robot"] = json::parse(R"({ "kind": "pneumatic",
    "chambers": [ { "offset": [0, 0], "area": 1e-7, "from": 0.1, "to": 0.2 } ] })");
  EXPECT_ERROR(Parse(j), "rod.nodes: expected at least 4");

  // An inflation "pressure" on a rod whose section does not depend on it did nothing, silently
  // (a pneumatic finger given "pressure" for "chamber_pressure"); 0 is harmless.
  j = ValidProblem();
  j["robot"] = json::parse(R"({ "kind": "pneumatic",
    "chambers": [ { "offset": [0, 0], "area": 1e-7 } ], "actuation": { "pressure": 1e5 } })");
  EXPECT_ERROR(Parse(j), "robot.actuation.pressure: expected a rod.stiffness_profile that "
                         "depends on it", "\"chamber_pressure\"");
  j["robot"]["actuation"]["pressure"] = 0;
  EXPECT_TRUE(Parse(j).ok()) << AllErrors(Parse(j));
}

}  // namespace
}  // namespace cosserat::io
