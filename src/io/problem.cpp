#include "cosserat/io/problem.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <utility>

#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/io/json_document.hpp"
#include "cosserat/io/json_reader.hpp"
#include "cosserat/io/text_file.hpp"
#include "cosserat/rod/grid.hpp"
#include "cosserat/rod/rest_shape.hpp"
#include "problem_assembly.hpp"
#include "problem_buckling.hpp"
#include "problem_environment.hpp"
#include "problem_robot.hpp"
#include "problem_rod.hpp"
#include "read_enum.hpp"
#include "read_pose.hpp"

namespace cosserat::io {
namespace detail {
namespace {

using json = nlohmann::json;

constexpr int kMaxIterations = 1000000;
constexpr int kMaxModes = 1000;

// --- base, loads, solver -----------------------------------------------------------------------

void ParseBase(const ObjectReader& base, lie::SE3* pose) {
  base.AllowOnly({"position", "rotation"});
  *pose = ReadPose(base);
}

/// "anchor": {"position": [x, y, z], "base": "pinned" | "clamped", "tip": "pinned" | "clamped",
///            "rotation": [[..]] (a clamped tip's), "motion": {"amplitude": [..], "period": T}}.
void ParseAnchor(const ObjectReader& o, Problem::Anchor* anchor) {
  o.AllowOnly({"position", "base", "tip", "motion", "rotation"});
  if (const auto motion = ReadObject(o, "motion", Presence::kOptional)) {
    motion->AllowOnly({"amplitude", "period"});
    anchor->motion_amplitude =
        ReadVec3(*motion, "amplitude", Presence::kRequired).value_or(Vec3::Zero());
    anchor->motion_period =
        ReadNumber(*motion, "period", PositiveNumber(), Presence::kRequired).value_or(0.0);
  }
  anchor->position = ReadVec3(o, "position", Presence::kRequired).value_or(Vec3::Zero());
  anchor->base_clamped =
      ReadChoice(o, "base", {"pinned", "clamped"}, Presence::kOptional) == std::string("clamped");
  anchor->tip_clamped =
      ReadChoice(o, "tip", {"pinned", "clamped"}, Presence::kOptional) == std::string("clamped");
  if (const auto R = ReadRotation(o, "rotation")) anchor->rotation = *R;
  if (o.Has("rotation") && !anchor->tip_clamped)
    o.report().Add(o.PathOf("rotation"), "is read only with \"tip\": \"clamped\"");
}

/// The anchors must be apart, and no farther than the rod can reach by a stretch the linear law
/// describes (50 %).
void CheckAnchor(const ObjectReader& top, const Problem& p) {
  const bool anchored = p.boundary == Boundary::kAnchored;
  if (anchored != (top.Find("anchor") != nullptr)) {
    if (anchored)
      top.report().Missing("anchor", "the tip's anchor for \"boundary\": \"anchored\"");
    else
      top.report().Add("anchor", "is read only with \"boundary\": \"anchored\" (got \"" +
                                     ToString(p.boundary) + "\")");
    return;
  }
  // Without a valid rod (its errors are reported) there is no length to reach with; without a
  // position (its error is reported) no point to reach.
  if (!anchored || !p.rod.section || !(p.rod.length > 0)) return;
  const nlohmann::json* anchor = top.Find("anchor");
  if (!anchor || !anchor->is_object() || !anchor->contains("position")) return;
  const double distance = (p.anchor.position - p.base.p).norm(), L = p.rod.length;
  if (distance > 1.5 * L)
    top.report().Expected("anchor.position",
                          "at most 1.5 × rod.length (" + FormatNumber(1.5 * L) +
                              " m) from base.position: the rod cannot reach farther",
                          FormatNumber(distance) + " m away");
  else if (distance < 1e-6 * L)
    top.report().Expected("anchor.position",
                          "a point at least 1e-6 × rod.length (" + FormatNumber(1e-6 * L) +
                              " m) from base.position",
                          FormatNumber(distance) + " m away");
  // A moving anchor sweeps position + amplitude (1 − cos): its farthest point, + 2 amplitude,
  // must be in reach too.
  const double farthest = (p.anchor.position + 2 * p.anchor.motion_amplitude - p.base.p).norm();
  if (distance <= 1.5 * L && farthest > 1.5 * L)
    top.report().Expected("anchor.motion.amplitude",
                          "a motion that keeps the anchor within 1.5 × rod.length (" +
                              FormatNumber(1.5 * L) +
                              " m) of base.position (it reaches position + 2 amplitude)",
                          FormatNumber(farthest) + " m away");
}

/// A load at a held tip goes straight into its anchor: a tip force on an anchored rod (and a
/// tip moment at a clamped anchor) would load nothing and be silently lost.
void CheckHeldTipLoads(const ObjectReader& top, const Problem& p) {
  if (p.boundary != Boundary::kAnchored) return;
  if (p.dynamics.initial_loads && !p.dynamics.initial_loads->tip_force.isZero(0.0))
    top.report().Add("dynamics.initial_loads.tip_force",
                     "acts at the anchored tip, which the anchor holds in place: the anchor takes "
                     "it whole and the rod carries none of it");
  if (!p.loads.tip_force.isZero(0.0))
    top.report().Add("loads.tip_force",
                     "acts at the anchored tip, which the anchor holds in place: the anchor takes "
                     "it whole and the rod carries none of it (a point load along the line is not "
                     "supported; see anchor_force for the anchor's reaction)");
  if (p.anchor.tip_clamped && !p.loads.tip_moment.isZero(0.0))
    top.report().Add("loads.tip_moment",
                     "acts at the tip, which \"anchor.tip\": \"clamped\" holds: the clamp takes it "
                     "whole and the rod carries none of it");
}

LoadFrame ReadFrame(const ObjectReader& o, const std::string& key) {
  const auto frame = ReadChoice(o, key, {"world", "body"}, Presence::kOptional);
  return frame == std::optional<std::string>("body") ? LoadFrame::kBody : LoadFrame::kWorld;
}

/// "bit_friction": a drill bit's friction torque at the tip (loads/bit_friction.hpp).
BitFriction ParseBitFriction(const ObjectReader& o) {
  o.AllowOnly({"weight_on_bit", "radius", "static_coefficient", "kinetic_coefficient",
               "stribeck_velocity", "regularisation", "viscous"});
  BitFriction b;
  const auto number = [&](const char* key, const NumberRule& rule, Presence presence,
                          double fallback) {
    return ReadNumber(o, key, rule, presence).value_or(fallback);
  };
  b.weight_on_bit = number("weight_on_bit", PositiveNumber(), Presence::kRequired, 0.0);
  b.radius = number("radius", PositiveNumber(), Presence::kRequired, 0.0);
  b.kinetic_coefficient =
      number("kinetic_coefficient", NonNegativeNumber(), Presence::kRequired, 0.0);
  b.static_coefficient =
      number("static_coefficient", NonNegativeNumber(), Presence::kRequired, 0.0);
  b.stribeck_velocity =
      number("stribeck_velocity", PositiveNumber(), Presence::kOptional, b.stribeck_velocity);
  b.regularisation =
      number("regularisation", PositiveNumber(), Presence::kOptional, b.regularisation);
  b.viscous = number("viscous", NonNegativeNumber(), Presence::kOptional, b.viscous);
  if (b.static_coefficient < b.kinetic_coefficient)
    o.report().Expected(o.PathOf("static_coefficient"),
                        "a number >= kinetic_coefficient (" +
                            FormatNumber(b.kinetic_coefficient) + ")",
                        FormatNumber(b.static_coefficient));
  return b;
}

StaticLoads ParseLoads(const ObjectReader& o) {
  o.AllowOnly({"gravity", "tip_force", "tip_force_frame", "tip_moment", "tip_moment_frame",
               "distributed_force", "bit_friction"});
  const auto vector_or_zero = [&](const char* key) {
    return ReadVec3(o, key, Presence::kOptional).value_or(Vec3::Zero());
  };
  StaticLoads loads;
  loads.gravity_W = vector_or_zero("gravity");
  loads.tip_force = vector_or_zero("tip_force");
  loads.tip_force_frame = ReadFrame(o, "tip_force_frame");
  loads.tip_moment = vector_or_zero("tip_moment");
  loads.tip_moment_frame = ReadFrame(o, "tip_moment_frame");
  loads.distributed_force_W = vector_or_zero("distributed_force");
  if (const auto bit = ReadObject(o, "bit_friction", Presence::kOptional))
    loads.bit = ParseBitFriction(*bit);
  return loads;
}

void ParseSolver(const ObjectReader& o, Problem::Solver* options) {
  o.AllowOnly({"tolerance", "max_iterations"});
  // The residual is dimensionless (moments over EI/L, forces over EI/L²): above 1e-3 a
  // "converged" solve may be the rigid-body guess itself (at 1, 1.4 % of the tip's deflection
  // off on the example cantilever). Below 1e-15 double precision cannot resolve it: a solve at
  // 1e-20 stalled, threw away an iterate at 2.8e-17 and reported load_stepping_failed.
  const NumberRule tolerance{"a number in [1e-15, 1e-3] (below 1e-15 double precision cannot "
                             "resolve the residual)",
                             [](double x) { return x >= 1e-15 && x <= 1e-3; }};
  options->tolerance = ReadNumber(o, "tolerance", tolerance, Presence::kOptional)
                           .value_or(options->tolerance);
  options->max_iterations = ReadInteger(o, "max_iterations", 1, kMaxIterations, Presence::kOptional)
                                .value_or(options->max_iterations);
}

// --- dynamics, buckling, modes ------------------------------------------------------------------

void ParseDynamics(const ObjectReader& o, int nodes, Problem::Dynamics* d) {
  o.AllowOnly({"dt", "duration", "output_interval", "initial", "initial_loads", "tip_mass",
               "tip_inertia", "base_spin", "rotary_table", "shooting_segments", "spatial_scheme",
               "integrator_tolerance", "integrator_max_steps"});
  if (const auto t = ReadObject(o, "rotary_table", Presence::kOptional)) {
    t->AllowOnly({"inertia", "torque", "no_load_speed"});
    RotaryTable& table = d->rotary_table;
    table.inertia = ReadNumber(*t, "inertia", PositiveNumber(), Presence::kRequired).value_or(0.0);
    table.torque = ReadNumber(*t, "torque", AnyFiniteNumber(), Presence::kOptional).value_or(0.0);
    table.no_load_speed =
        ReadNumber(*t, "no_load_speed", PositiveNumber(), Presence::kOptional).value_or(0.0);
    if (o.Has("base_spin"))
      o.report().Add(o.PathOf("base_spin"),
                     "is not read with \"rotary_table\" (the table's motor sets its speed)");
  }
  d->base_spin =
      ReadNumber(o, "base_spin", AnyFiniteNumber(), Presence::kOptional).value_or(d->base_spin);
  d->base_spin_given = o.Has("base_spin") && !d->rotary_table.present();
  const auto dt = ReadNumber(o, "dt", PositiveNumber(), Presence::kOptional);
  const auto duration = ReadNumber(o, "duration", PositiveNumber(), Presence::kOptional);
  const auto interval = ReadNumber(o, "output_interval", PositiveNumber(), Presence::kOptional);
  d->dt = dt.value_or(d->dt);
  d->duration = duration.value_or(d->duration);
  d->output_interval = interval.value_or(d->dt);
  const bool both_usable = (dt || !o.Has("dt")) && (duration || !o.Has("duration"));
  const std::string got_dt = dt ? Describe(*o.Find("dt")) : FormatNumber(d->dt) + " (the default)";
  if (both_usable && d->dt > d->duration) {
    o.report().Expected(o.PathOf("dt"),
                        "a time step no longer than duration (" + FormatNumber(d->duration) + " s)",
                        got_dt);
  } else if (both_usable && std::round(d->duration / d->dt) > kMaxDynamicsSteps) {
    const std::string steps = FormatNumber(std::round(d->duration / d->dt)) + " steps";
    // The value the file gave is named; given both, the duration, unless the step is below a
    // nanosecond (no rod's dynamics needs one).
    if (o.Has("duration") && (!o.Has("dt") || d->dt > 1e-9))
      o.report().Expected(o.PathOf("duration"),
                          "a duration giving at most " + std::to_string(kMaxDynamicsSteps) +
                              " steps of dt (" + FormatNumber(d->dt) +
                              (o.Has("dt") ? " s)" : " s, the default)"),
                          Describe(*o.Find("duration")) + ", " + steps);
    else
      o.report().Expected(o.PathOf("dt"),
                          "a time step giving at most " + std::to_string(kMaxDynamicsSteps) +
                              " steps over duration (" + FormatNumber(d->duration) + " s)",
                          got_dt + ", " + steps);
  }
  d->tip_mass =
      ReadNumber(o, "tip_mass", NonNegativeNumber(), Presence::kOptional).value_or(d->tip_mass);
  const NumberRule moment{"a moment of inertia >= 0 (kg·m²)", [](double x) { return x >= 0; }};
  if (const auto inertia = ReadVec3(o, "tip_inertia", Presence::kOptional, moment))
    d->tip_inertia = *inertia;
  d->initial = ReadChoice(o, "initial", {"static"}, Presence::kOptional).value_or(d->initial);
  // One piece per grid segment at most (rod.nodes − 1).
  d->shooting_segments =
      ReadInteger(o, "shooting_segments", 1, std::max(1, nodes - 1), Presence::kOptional)
          .value_or(d->shooting_segments);
  d->spatial_scheme =
      ReadEnum<ShotScheme>(o, "spatial_scheme", Presence::kOptional).value_or(d->spatial_scheme);
  // Above 0.1 the error control no longer means anything (errors of 10 % of a metre or a
  // radian are accepted).
  const NumberRule tolerance_rule{"a number in (0, 0.1]",
                                  [](double x) { return x > 0 && x <= 0.1; }};
  d->integrator_tolerance =
      ReadNumber(o, "integrator_tolerance", tolerance_rule, Presence::kOptional)
          .value_or(d->integrator_tolerance);
  d->integrator_max_steps =
      ReadInteger(o, "integrator_max_steps", 1, 1000000000, Presence::kOptional)
          .value_or(d->integrator_max_steps);
  if (const auto loads = ReadObject(o, "initial_loads", Presence::kOptional))
    d->initial_loads = ParseLoads(*loads);
}

/// Dynamics settings that only the other formulation's integrator reads would be ignored
/// without a word: refused, naming who reads them. (A dynamics block kept in a file run for
/// another analysis is only checked: its base drive is noted by the run, run.cpp.)
void CheckFormulationSettings(const ObjectReader& o, const Problem& p) {
  if (p.analysis != Analysis::kDynamics) return;
  const bool quatfd = p.formulation == Formulation::kQuaternionFd;
  const std::initializer_list<const char*> se3_only = {"shooting_segments", "spatial_scheme"};
  const std::initializer_list<const char*> quatfd_only = {"integrator_tolerance",
                                                          "integrator_max_steps"};
  for (const char* key : quatfd ? se3_only : quatfd_only)
    if (o.Has(key))
      o.report().Add(o.PathOf(key), std::string("is read by the ") +
                                        (quatfd ? "\"se3-shooting\"" : "\"quaternion-fd\"") +
                                        " formulation only (this problem runs " +
                                        Quote(ToString(p.formulation)) + ")");
}

void ParseModes(const ObjectReader& o, Problem::Modes* m) {
  o.AllowOnly({"count"});
  m->count = ReadInteger(o, "count", 1, kMaxModes, Presence::kOptional).value_or(m->count);
}

// --- The whole problem -------------------------------------------------------------------------

void CheckFormat(const ObjectReader& top) {
  const std::string expected = Quote(kProblemFormat);
  const json* v = top.Find("format");
  if (!v)
    top.report().Missing("format", expected);
  else if (!v->is_string() || v->get<std::string>() != kProblemFormat)
    top.report().Expected("format", expected, Describe(*v));
}

/// A problem of rods and bodies: "assembly" in place of the single rod's keys.
void ParseAssemblyTopLevel(const ObjectReader& top, Problem* p) {
  for (const std::string& key : SingleRodKeys()) {
    if (!top.Has(key)) continue;
    const std::string why =
        key == "environment"
            ? ": fluid loads and contact act on single rods only in this version "
              "(loads.distributed_force and gravity act on every rod)"
        : key == "buckling" || key == "modes"
            ? ": an assembly's buckling and modes are not computed in this version (its statics "
              "report the bodies' stability_index)"
        : key == "boundary" || key == "anchor"
            ? " (assembly.rods[i].tip holds each rod's tip: its joint and body)"
            : " (each rod of assembly.rods has its own \"rod\" and \"base\")";
    top.report().Add(key, "not read with \"assembly\"" + why);
  }
  if (const auto loads = ReadObject(top, "loads", Presence::kOptional)) {
    p->loads = ParseLoads(*loads);
    CheckAssemblyLoads(*loads);
  }
  if (const auto o = ReadObject(top, "solver", Presence::kOptional)) ParseSolver(*o, &p->solver);
  if (const auto o = ReadObject(top, "dynamics", Presence::kOptional)) {
    p->has_dynamics = true;
    ParseDynamics(*o, kMaxDynamicsSteps, &p->dynamics);
    CheckAssemblyDynamics(*o);
  }
  if (const auto o = ReadObject(top, "assembly", Presence::kRequired)) ParseAssembly(*o, p);
}

void ParseTopLevel(const ObjectReader& top, Problem* p) {
  top.AllowOnly({"format", "description", "analysis", "formulation", "rod", "base", "boundary",
                 "anchor", "loads", "environment", "dynamics", "buckling", "modes", "solver",
                 "robot", "assembly"});
  CheckFormat(top);
  ReadString(top, "description", Presence::kOptional);
  p->analysis = ReadEnum<Analysis>(top, "analysis", Presence::kOptional).value_or(p->analysis);
  p->analysis_given = top.Has("analysis");
  p->formulation =
      ReadEnum<Formulation>(top, "formulation", Presence::kOptional).value_or(p->formulation);
  if (top.Has("assembly")) return ParseAssemblyTopLevel(top, p);
  if (const auto rod = ReadObject(top, "rod", Presence::kRequired)) ParseRod(*rod, p);
  if (const auto base = ReadObject(top, "base", Presence::kOptional)) ParseBase(*base, &p->base);
  p->boundary = ReadEnum<Boundary>(top, "boundary", Presence::kOptional).value_or(p->boundary);
  p->anchor.rotation = p->base.R;  // a clamped tip's default: as the base
  if (const auto anchor = ReadObject(top, "anchor", Presence::kOptional))
    ParseAnchor(*anchor, &p->anchor);
  CheckAnchor(top, *p);
  if (const auto loads = ReadObject(top, "loads", Presence::kOptional))
    p->loads = ParseLoads(*loads);
  if (const auto env = ReadObject(top, "environment", Presence::kOptional))
    ParseEnvironment(*env, &p->loads.fluid, &p->gust, &p->loads.contact);
  if (const auto o = ReadObject(top, "dynamics", Presence::kOptional)) {
    p->has_dynamics = true;
    ParseDynamics(*o, p->nodes, &p->dynamics);
    CheckFormulationSettings(*o, *p);
    // The quaternion-FD path records a frame every output_interval, each at least a Radau step
    // (the SE(3) path rounds it to whole steps of dt, which are capped above): cap the frames.
    const Problem::Dynamics& d = p->dynamics;
    const double frames = std::round(d.duration / d.output_interval);
    const std::string most = "at most " + std::to_string(kMaxQuatFdFrames) + " frames";
    const std::string got = ", " + FormatNumber(frames) + " frames";
    if (p->formulation == Formulation::kQuaternionFd && d.output_interval > 0 &&
        frames > kMaxQuatFdFrames) {
      // The value the file gave is named, as for dt above.
      if (o->Has("duration") && (!o->Has("output_interval") || d.output_interval > 1e-9))
        o->report().Expected(o->PathOf("duration"),
                             "a duration giving " + most + " of output_interval (" +
                                 FormatNumber(d.output_interval) + " s)",
                             FormatNumber(d.duration) + got);
      else
        o->report().Expected(o->PathOf("output_interval"),
                             "an interval giving " + most + " over duration (" +
                                 FormatNumber(d.duration) + " s)",
                             FormatNumber(d.output_interval) + got);
    }
  }
  CheckHeldTipLoads(top, *p);
  const auto buckling =
      ReadObject(top, "buckling",
                 p->analysis == Analysis::kBuckling ? Presence::kRequired : Presence::kOptional,
                 R"(an object {"load", "direction", "max"})");
  if (buckling) {
    p->has_buckling = true;
    ParseBuckling(*buckling, &p->buckling);
  }
  if (const auto o = ReadObject(top, "modes", Presence::kOptional)) {
    p->has_modes = true;
    ParseModes(*o, &p->modes);
  }
  if (const auto o = ReadObject(top, "solver", Presence::kOptional)) ParseSolver(*o, &p->solver);
  if (const auto o = ReadObject(top, "robot", Presence::kOptional)) ParseRobot(*o, top.value(), p);
  if (buckling) CheckBucklingActuation(top, *p);
  if (buckling && p->rod.section) CheckBucklingLoadActs(top, *p);
  // The environment is the world: it acts under the initial loads of a dynamics run too.
  if (p->dynamics.initial_loads) {
    const json* given = top.Find("dynamics");
    p->dynamics.initial_loads_without_gravity =
        given && given->is_object() && given->contains("initial_loads") &&
        (*given)["initial_loads"].is_object() && !(*given)["initial_loads"].contains("gravity") &&
        !p->loads.gravity_W.isZero(0.0);
    p->dynamics.initial_loads->fluid = p->loads.fluid;
    p->dynamics.initial_loads->contact = p->loads.contact;
  }
}

/// The section at every node as the solvers will take it: finite stiffness and mass (an area
/// of 1e300 m² overflows E A), and principal axes. `validate` then passes only what runs.
void CheckSectionsAtNodes(const Problem& p, ErrorReport* report) {
  // The solvers' own grid: its nodes include every band's ends, where a short band lies.
  for (const double s : ModelGrid(p.rod, std::max(p.nodes, 2))) {
    const SectionProperties sp = p.rod.section->At(s, p.robot.actuation);
    if (!sp.stiffness.allFinite() || !sp.mass.allFinite()) {
      // Finite at rest, overflowed under the actuation (a jamming or inflation pressure of
      // 1e308 Pa): the actuation is what to fix.
      const SectionProperties rest = p.rod.section->At(s, Actuation{});
      const bool actuated = rest.stiffness.allFinite() && rest.mass.allFinite();
      report->Add(actuated ? "robot.actuation" : "rod.section",
                  std::string(actuated ? "under it the section's" : "its") +
                      " stiffness or mass per length at s = " + FormatNumber(s) +
                      " m is not a finite number (" +
                      (actuated ? "the pressures' products with the section overflow a double)"
                                : "the section's products with the material overflow a "
                                  "double)"));
      return;
    }
    try {
      PrincipalAxesSectionAt(p.rod, s, p.robot.actuation);
    } catch (const std::exception& e) {
      report->Add("rod.section", e.what());
      return;
    }
  }
}

/// The library's own checks; they should never fire after the ones above.
/// A forcing period in dynamics (a gust, an anchor's motion): at least two steps of dt, which
/// the SE(3) steps need to see it at all (below, they sample an aliased load and converge on
/// it); on the quaternion-FD path, whose steps adapt, at most 1e4 periods over the run (a period
/// of 1 µs over 1 s ran for minutes).
void CheckForcingPeriod(const Problem& p, const std::string& where, double period,
                        ErrorReport* report) {
  const Problem::Dynamics& d = p.dynamics;
  constexpr double kMaxPeriods = 1e4;
  if (p.formulation == Formulation::kQuaternionFd) {
    if (d.duration / period > kMaxPeriods)
      report->Expected(where,
                       "a period giving at most 1e4 periods over dynamics.duration (" +
                           FormatNumber(d.duration) + " s)",
                       FormatNumber(period));
  } else if (period < 2 * d.dt) {
    report->Expected(where,
                     "a period of at least two steps (2 dynamics.dt = " + FormatNumber(2 * d.dt) +
                         " s), which the steps can resolve",
                     FormatNumber(period));
  }
}

void CheckWithLibrary(const Problem& p, ErrorReport* report) {
  std::string why;
  if (p.has_assembly) {
    if (!p.assembly.assembly.IsValid(&why)) report->Add("assembly", why);
    if (!p.loads.IsValid(&why)) report->Add("loads", why);
    return;
  }
  if (!p.rod.IsValid(&why)) report->Add("rod", why);
  if (report->empty()) CheckSectionsAtNodes(p, report);
  const double far = kFarthestPointInRodLengths * p.rod.length;
  for (const auto& [where, point] :
       {std::pair<const char*, Vec3>{"base.position", p.base.p},
        std::pair<const char*, Vec3>{"anchor.position", p.anchor.position}})
    if (point.cwiseAbs().maxCoeff() > far)
      report->Expected(where,
                       "a point within 1e9 rod lengths (" + FormatNumber(far) +
                           " m) of the origin, where a double still resolves the rod's shape",
                       FormatNumber(point.cwiseAbs().maxCoeff()) + " m away");
  if (!p.loads.IsValid(&why)) report->Add("loads", why);
  const int tendons = static_cast<int>(p.rod.tendons.size());
  const int chambers = static_cast<int>(p.rod.chambers.size());
  if (!p.robot.actuation.IsValid(&why, tendons, chambers)) report->Add("robot.actuation", why);
  if (!p.robot.initial_actuation.IsValid(&why, tendons, chambers))
    report->Add("robot.initial_actuation", why);
  if (report->empty()) CheckStartsOutsideSurfaces(p, report);
  if (p.analysis == Analysis::kModes) {
    const bool qfd = p.formulation == Formulation::kQuaternionFd;
    const int most = qfd ? kMaxQuatFdModeNodes : kMaxSe3ModeNodes;
    if (p.nodes > most)
      report->Expected("rod.nodes",
                       std::string("at most ") + std::to_string(most) + " nodes for modes on the " +
                           (qfd ? "quaternion-fd formulation"
                                : "se3-shooting formulation"),
                       std::to_string(p.nodes));
  }
  if (p.analysis == Analysis::kDynamics && p.gust.amplitude != 0.0)
    CheckForcingPeriod(p, "environment.fluid.gust.period", p.gust.period, report);
  if (p.analysis == Analysis::kDynamics && !p.anchor.motion_amplitude.isZero())
    CheckForcingPeriod(p, "anchor.motion.period", p.anchor.motion_period, report);
}

}  // namespace
}  // namespace detail

namespace {

/// The checks of a parsed document, after `errors` (those of the text) were found.
ParseResult ParseValue(const nlohmann::json& value, std::vector<std::string> errors) {
  ParseResult result;
  result.errors = std::move(errors);
  detail::ErrorReport report;
  if (!value.is_object()) {
    report.Expected("", "an object", detail::Describe(value));
  } else {
    Problem problem;
    detail::ParseTopLevel(detail::ObjectReader(value, "", &report), &problem);
    if (report.empty() && result.errors.empty()) detail::CheckWithLibrary(problem, &report);
    if (report.empty() && result.errors.empty()) result.problem = std::move(problem);
  }
  for (std::string& line : report.TakeLines()) result.errors.push_back(std::move(line));
  return result;
}

}  // namespace

ParseResult ParseProblem(const std::string& json_text, const std::string& source_name) {
  detail::JsonDocument doc = detail::ParseJsonDocument(json_text, source_name);
  if (!doc.value) {
    ParseResult result;
    result.errors = std::move(doc.errors);  // malformed JSON
    return result;
  }
  return ParseValue(*doc.value, std::move(doc.errors));  // errors: duplicate keys
}

ParseResult ParseProblemDocument(const nlohmann::json& document) { return ParseValue(document, {}); }

ParseResult LoadProblemFile(const std::string& path) {
  auto unreadable = [&](const std::string& why) {
    ParseResult r;
    r.errors.push_back(path + ": cannot read the file (" + why + ")");
    return r;
  };
  std::string text, why;
  if (!ReadTextFile(path, &text, &why)) return unreadable(why);
  return ParseProblem(text, path);
}

}  // namespace cosserat::io
