#pragma once
/// \file
/// Problem files ("cosserat-problem/1", see docs/problem-format.md): parsing into the library's
/// types, with every input error reported as one line `<json.path>: expected <what>, got <found>`.

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cosserat/assembly/assembly.hpp"
#include "cosserat/io/problem_kinds.hpp"
#include "cosserat/lie/se3.hpp"
#include "cosserat/lie/types.hpp"
#include "cosserat/robots/rotary_table.hpp"
#include "cosserat/loads/static_loads.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"

namespace cosserat::io {

/// How far from the world origin a base or an anchor may lie, in rod lengths: where a double
/// still resolves the rod's shape (at 1e9 lengths it keeps 2e-7 of one; at 1e16 m a metre rod's
/// deflection is lost whole).
inline constexpr double kFarthestPointInRodLengths = 1e9;

/// The most grid nodes `rod.nodes` takes.
inline constexpr int kMaxRodNodes = 1000000;

/// The only value of the required top-level "format" key this version reads.
inline constexpr const char* kProblemFormat = "cosserat-problem/1";

/// A validated problem. Every field holds a value from the file or its documented default.
struct Problem {
  Analysis analysis = Analysis::kStatics;
  bool analysis_given = false;  ///< the file names "analysis" (else statics, the default)
  Formulation formulation = Formulation::kSe3Shooting;
  RodModel rod;    ///< length, section profile, rest strain
  int nodes = 41;  ///< grid points along s, ends included
  /// An "annulus" rod.section's bore π r_i² (m²; 0 for other sections), and whether the file
  /// fills it ("contents_density"); without, the pipe is sealed and empty.
  double bore_area = 0.0;
  bool bore_filled = false;
  lie::SE3 base;   ///< clamp pose: R_WB (body z = rod tangent), p_W
  Boundary boundary = Boundary::kCantilever;
  /// "anchor", for the boundary "anchored": the tip is pinned at `position`; the base is held at
  /// base.position, pinned (rotation free) or clamped (base.rotation kept).
  struct Anchor {
    Vec3 position = Vec3::Zero();  ///< where the tip is held, world, m
    bool base_clamped = false;
    bool tip_clamped = false;
    /// A clamped tip's rotation R_WB (world; its third column the tangent at s = L); "rotation",
    /// by default base.rotation.
    Mat3 rotation = Mat3::Identity();
    /// "motion": in dynamics the anchor moves as position + amplitude (1 − cos(2π t / period)),
    /// from rest (a vessel's heave and surge; world, m and s). Zero amplitude: held still.
    Vec3 motion_amplitude = Vec3::Zero();
    double motion_period = 0.0;
  } anchor;
  StaticLoads loads;
  /// "environment.fluid.gust": the flow's gusting in dynamics (loads/fluid.hpp).
  FluidGust gust;
  /// "solver": the static solves' convergence test, read by every formulation (run/ turns it
  /// into each solver's options).
  struct Solver {
    /// Dimensionless residual norm below which a static solve has converged
    /// (StaticShootingOptions::tolerance).
    double tolerance = 1e-10;
    int max_iterations = 50;  ///< Levenberg–Marquardt or Newton iterations per solve
  } solver;

  /// "dynamics": run by the `cosserat` command (SE(3) path: BDF2 shooting, cantilever or
  /// free-free; quaternion-FD path: the Radau integrator, cantilever).
  struct Dynamics {
    double dt = 0.002;      ///< s
    double duration = 1.0;  ///< s
    /// s; how often the trajectory is recorded (a whole number of steps, at least 1). The
    /// parser sets it to dt when the file leaves it out.
    double output_interval = 0.002;
    std::string initial = "static";
    std::optional<StaticLoads> initial_loads;  ///< empty: start from equilibrium under `loads`
    /// initial_loads is given without a "gravity" key while `loads` has gravity: it replaces
    /// `loads`, so the start is without gravity (the run's log says so; often a slip).
    bool initial_loads_without_gravity = false;
    double tip_mass = 0.0;                     ///< kg, a rigid body at the tip (dynamics only)
    Vec3 tip_inertia = Vec3::Zero();           ///< kg·m², its principal moments, tip body frame
    /// rad/s: the clamp turns about its own axis (base body z) at this rate from t = 0 (a
    /// drill string's rotary table); SE(3) path, cantilever.
    double base_spin = 0.0;
    /// The file gives base_spin (0 too: a string twisted and let go): the trajectory reports the
    /// tip's spin and the string's torque on the clamp.
    bool base_spin_given = false;
    /// "rotary_table": the clamp turned by a motor with inertia instead (robots/rotary_table.hpp;
    /// SE(3) path, cantilever); absent: inertia 0.
    RotaryTable rotary_table;
    /// Bdf2Options::shooting_segments (SE(3) path); 0: chosen by the stepper.
    int shooting_segments = 0;
    /// Bdf2Options::spatial_scheme (SE(3) path).
    ShotScheme spatial_scheme = ShotScheme::kRk4Pairs;
    /// Quaternion-FD path: the Radau integrator's rel_tol = abs_tol (IntegratorOptions; rotations
    /// in rad), in (0, 0.1].
    double integrator_tolerance = 1e-6;
    /// Quaternion-FD path: the most Radau steps (accepted + rejected) between two output frames
    /// before the run stops with status max_iterations (IntegratorOptions::max_steps). A run
    /// whose step collapses (an exploding rod) ends in about a minute at ~11 nodes instead of
    /// the hours the integrator's own cap of 5e7 allows.
    int integrator_max_steps = 1000000;
  } dynamics;
  bool has_dynamics = false;

  /// "buckling": the load path searched (docs/problem-format.md, section "buckling").
  struct Buckling {
    BucklingLoad load = BucklingLoad::kTipForce;
    Vec3 direction{0, 0, -1};  ///< unit vector (normalised on input); unused by the last two
    /// Largest load magnitude searched. "tendon_tension": the largest added tension, N (the
    /// most-weighted tendon's); "pressure": the pressure the drop starts from, Pa.
    double max = 0;
    /// "tendon_tension": one weight >= 0 per tendon of robot.tendons (not all zero), as given;
    /// empty = every tendon alike. Tension added to tendon i is λ · w_i / max_j w_j.
    std::vector<double> tendon_weights;
  } buckling;
  bool has_buckling = false;

  struct Modes {
    int count = 4;
  } modes;
  bool has_modes = false;

  /// "robot": the robot kind and its actuation; its tendons are in rod.tendons.
  struct Robot {
    RobotKind kind = RobotKind::kNone;  ///< kNone exactly when !has_robot
    Actuation actuation;                ///< statics; dynamics for t > 0
    Actuation initial_actuation;        ///< dynamics: the equilibrium the run starts from
    /// Displacement control: commanded tendon path lengths (m) instead of tensions.
    std::optional<std::array<double, Actuation::kMaxTendons>> tendon_lengths;
    /// Eversion: grow from this length to rod.length in `growth_steps` quasi-static steps.
    std::optional<double> growth_initial_length;
    int growth_steps = 20;
    /// Eversion: the tension of the tail pulled back through the body to the base, N.
    double tail_tension = 0.0;
  } robot;
  bool has_robot = false;

  /// "assembly": rods and rigid bodies solved together (docs/assemblies.md), in place of "rod",
  /// "base" and "boundary"; statics on the SE(3) path. `rod` and `base` keep their defaults.
  struct AssemblyProblem {
    Assembly assembly;  ///< rods (their models at rod.length) and bodies (pose: the start guess)
    /// Forward kinematics: one length per rod, m; empty: each rod's rod.length.
    std::vector<double> lengths;
    /// "inverse": one pose per body, in the bodies' order (world); the rods' lengths are solved.
    /// Empty: the forward problem.
    std::vector<lie::SE3> inverse_poses;
    bool inverse() const { return !inverse_poses.empty(); }
    /// Dynamics: each body's applied force and moment in the equilibrium the run starts from
    /// (bodies[j].initial_force, .initial_moment; default: its force and moment), world.
    std::vector<Vec3> initial_force, initial_moment;
  } assembly;
  bool has_assembly = false;
};

struct ParseResult {
  std::optional<Problem> problem;   ///< set exactly when there are no errors
  std::vector<std::string> errors;  ///< one line per problem found, in document order
  bool ok() const { return errors.empty(); }
};

/// Parses and validates a problem given as JSON text, collecting every error. `source_name`
/// prefixes the message for malformed JSON (e.g. the file name).
ParseResult ParseProblem(const std::string& json_text, const std::string& source_name = "<input>");

/// The same for a document already parsed (a study's point: no text to read again).
ParseResult ParseProblemDocument(const nlohmann::json& document);

/// Reads a file and parses it; an unreadable file gives one error naming the path.
ParseResult LoadProblemFile(const std::string& path);

/// An actuation given as a JSON object with the keys of a problem file's robot.actuation
/// ("tension", "pressure", "chamber_pressure", "jamming_pressure"; not "length"), checked by the
/// file's rules against `problem`'s tendons, chambers and jamming segments: a controller's input
/// for one step. Left out, the pressures the section reads ("pressure", "jamming_pressure") stay
/// the problem's, and tensions and chamber pressures are zero. Errors name their field under
/// `path`.
struct ActuationParse {
  std::optional<Actuation> actuation;  ///< set exactly when there are no errors
  std::vector<std::string> errors;
};
ActuationParse ParseActuationObject(const nlohmann::json& object, const Problem& problem,
                                    const std::string& path = "actuation");

/// The most time steps (round(duration / dt)) a dynamics problem may ask for.
inline constexpr int kMaxDynamicsSteps = 10000000;
/// The most frames a quaternion-FD run may record (round(duration / output_interval)): each is
/// at least one Radau step and a stored state, ~35 µs and ~300 bytes, so 10⁶ frames take about
/// half a minute and 300 MB.
inline constexpr int kMaxQuatFdFrames = 1000000;
/// The most nodes for modes: the quaternion-FD modes of a stable undamped rod come from its
/// banded factorisation (0.05 s at 801 nodes, linear in the nodes), others from a dense spectrum
/// the run refuses beyond 801 nodes (~5 min and 1.6 GB there, growing as nodes³); the SE(3)
/// frequency search keeps ~8 kB a node (a million nodes took 7 GB).
inline constexpr int kMaxQuatFdModeNodes = 100001;
inline constexpr int kMaxSe3ModeNodes = 100001;

/// Things the contract names but this version cannot run yet: an analysis other than "statics",
/// "dynamics", "buckling" or "modes", a boundary other than "cantilever" (se3-shooting dynamics
/// also runs "free-free", buckling the column ends "pinned-pinned", "clamped-clamped",
/// "clamped-pinned"; quaternion-fd runs only "cantilever", and no buckling).
/// One line each.
std::vector<std::string> UnsupportedFeatures(const Problem& problem);

/// The loads a column's guided tip cannot take in dynamics ("clamped-clamped",
/// "clamped-pinned"): a follower tip force, a moment at a pinned tip. One line each; none for
/// other ends. Part of UnsupportedFeatures, for loads that change from step to step.
void GuidedTipLoadFeatures(const StaticLoads& loads, Boundary boundary,
                           std::vector<std::string>* out);

}  // namespace cosserat::io
