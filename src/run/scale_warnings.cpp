#include "scale_warnings.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "cosserat/io/json_reader.hpp"
#include "cosserat/rod/filled_pipe_section.hpp"
#include "cosserat/rod/section_profile.hpp"
#include "cosserat/rod/stiffness_profiles.hpp"
#include "cosserat/state/solve_status.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"

namespace cosserat::run::detail {
namespace {

/// A rod shorter than this many outer diameters is not slender: rod theory does not hold.
constexpr double kSlenderness = 2.0;
/// The largest node-to-node stretch |Δx|/Δs − 1 (either way) a linear elastic rod is trusted
/// with; beyond it the answer is almost surely a unit slip.
constexpr double kLargestStretch = 0.5;
/// A stretch past which the linear law is the model's answer, not a material's: metals yield
/// near 0.2 %, and rubbers stiffen or soften away from a linear law by 10 %. A steel rope pulled
/// to an anchor beyond its reach stretched by 33 % (6.7 GPa) without a word.
constexpr double kLargeStretch = 0.1;

/// The bending curvature (1/m) of a "nodes" block's node i: |(κ₁, κ₂)| of its "curvature"
/// (body frame); 0 when the block has none.
double Bending(const nlohmann::ordered_json& nodes, size_t i) {
  if (!nodes.contains("curvature") || i >= nodes["curvature"].size()) return 0.0;
  const nlohmann::ordered_json& k = nodes["curvature"][i];
  return std::hypot(k[0].get<double>(), k[1].get<double>());
}

/// The largest |Δx/c − 1| between consecutive nodes of a "nodes" block ({"s", "position"},
/// "curvature" if given), and the s where it starts (m); 0 when the block has no such lists.
/// c is Δs, or for a shot the chord of an arc of length Δs at the two nodes' mean bending
/// curvature.
/// shot: the nodes come from an SE(3) shot, whose RK4 in s shrinks the frames it turns, and the
/// positions with them, where a segment turns by more than 0.5 rad (the grid check names such a
/// grid): there the nodes' spacing is not the rod's length, and the segment is left out (a tendon
/// robot coiled at 0.84 rad per segment has nodes 11 % closer than its length at a strain of
/// 0.09 %).
/// *everywhere: whether every segment is stretched within 10 % of it (a uniform stretch, with
/// no place to name).
double LargestStretch(const nlohmann::ordered_json& nodes, bool shot, double* at_s,
                      bool* everywhere) {
  if (!nodes.is_object() || !nodes.contains("s") || !nodes.contains("position")) return 0.0;
  const nlohmann::ordered_json& s = nodes["s"];
  const nlohmann::ordered_json& x = nodes["position"];
  double worst = 0.0, least = INFINITY;
  for (size_t i = 0; i + 1 < s.size() && i + 1 < x.size(); ++i) {
    const double ds = s[i + 1].get<double>() - s[i].get<double>();
    if (!(ds > 0)) continue;
    if (shot && std::max(Bending(nodes, i), Bending(nodes, i + 1)) * ds > 0.5) continue;
    double dx2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double d = x[i + 1][k].get<double>() - x[i][k].get<double>();
      dx2 += d * d;
    }
    // A shot's nodes lie on a curve, a chord apart, 2 sin(κh/2)/κ for an arc of curvature κ: 1 %
    // short of h at κh = 0.49 rad (a steel wire folded back by an end push read "compressed by
    // 1.08 %" at a strain of 1e-4). The chord of the segment's mean curvature is its reference.
    // Quaternion-FD vertices are joined by straight segments |Γ| h long: h is theirs.
    const double half_turn =
        shot ? 0.5 * ds * 0.5 * (Bending(nodes, i) + Bending(nodes, i + 1)) : 0.0;  // rad
    const double chord = half_turn > 1e-8 ? ds * std::sin(half_turn) / half_turn : ds;  // m
    const double stretch = std::abs(std::sqrt(dx2) / chord - 1.0);
    least = std::min(least, stretch);
    if (stretch > worst) {
      worst = stretch;
      *at_s = s[i].get<double>();
    }
  }
  // Within 10 % of the largest at every segment: a uniform stretch has no place to name.
  if (everywhere) *everywhere = least >= 0.9 * worst;
  return worst;
}

/// Loads past what any elastic rod carries: a force over ten times the axial stiffness EA (it
/// would stretch the rod tenfold), a moment turning the rod through 1e4 rad (M L/EI), or a drill
/// bit's static friction torque μ_s W R twisting it through 1e4 rad (τ L/GJ). A force of 1e30 N
/// on a steel wire stopped its load steps at once, and the hint spoke of the grid.
void ImpossibleLoadWarning(const io::Problem& problem, std::ostringstream* log) {
  if (problem.has_assembly || !problem.rod.section) return;
  const SectionProperties p = problem.rod.section->At(0.0, problem.robot.actuation);
  const double L = problem.rod.length, EA = p.stiffness(5, 5), EI = p.min_bending_stiffness();
  const double force = LoadForceBound(problem.rod, problem.loads);  // N
  const double turn = problem.loads.tip_moment.norm() * L / EI;     // rad
  if (force > 10.0 * EA)
    *log << "cosserat: warning: the loads add up to " << force << " N, over ten times the rod's "
         << "axial stiffness EA = " << EA << " N (they would stretch it tenfold): check the "
         << "units of the loads (N, N/m, m/s²) and of the material (Pa)\n";
  if (turn > 1e4)
    *log << "cosserat: warning: the tip moment would turn the rod through M L/EI = " << turn
         << " rad: check the units of loads.tip_moment (N·m) and of the material (Pa)\n";
  const BitFriction& bit = problem.loads.bit;
  const double torque = bit.static_coefficient * bit.weight_on_bit * bit.radius;  // N·m
  const double twist = bit.present() ? torque * L / p.stiffness(2, 2) : 0.0;        // rad
  if (twist > 1e4)
    *log << "cosserat: warning: the bit's static friction torque μ_s W R = " << torque
         << " N·m would twist the "
         << "string through τ L/GJ = " << twist << " rad: check the units of "
         << "loads.bit_friction.weight_on_bit (N) and radius (m)\n";
}

/// Values only a slip of units gives: gravity over 1000 m/s², a hundred Earths' (mm/s² for
/// m/s²), a commanded tendon path ten times the rod's length (mm for m). A robot's tendons
/// written in mm went slack, "converged", without a word.
void UnitSlipWarnings(const io::Problem& problem, std::ostringstream* log) {
  const double g = problem.loads.gravity_W.stableNorm();  // finite for components up to 1e308
  if (g > 1000.0)
    *log << "cosserat: warning: loads.gravity is " << g << " m/s², "
         << std::llround(std::min(g / 9.81, 1e18))
         << " times Earth's 9.81 (over 1000 m/s²): check its units (m/s²)\n";
  // An inflated tube below 100 Pa is a slip (vine robots run at 1–30 kPa: kPa typed as Pa), and
  // at 0 Pa it is an uninflated film, which the kink check reports collapsed.
  if (problem.robot.kind == io::RobotKind::kEversion) {
    const double p = problem.robot.actuation.pressure;  // Pa
    if (p == 0.0)
      *log << "cosserat: warning: the eversion robot's pressure is 0 Pa, an uninflated film tube: "
              "give robot.actuation.pressure or rod.stiffness_profile.pressure (Pa)\n";
    else if (p < 100.0)
      *log << "cosserat: warning: the eversion robot's pressure is " << p << " Pa (vine robots "
           << "run at 1e3–3e4 Pa): check its units (Pa, not kPa)\n";
  }
  if (!problem.robot.tendon_lengths) return;
  const double L = problem.rod.length;
  for (std::size_t i = 0; i < problem.rod.tendons.size(); ++i) {
    const double l = (*problem.robot.tendon_lengths)[i];
    if (l > 10.0 * L) {
      *log << "cosserat: warning: robot.actuation.length[" << i << "] is " << l << " m on a " << L
           << " m rod: check its units (m)\n";
      return;
    }
  }
}

/// A contact's smoothing ε is the depth over which the penalty ramps up (contact.hpp), by default
/// 1e-3 of the diameter d (m): past d the rod sinks into the surface by more than its width
/// before it is held (ε = 10 m on a 1 cm rod: a loop, "converged").
void ContactSmoothingWarning(const io::Problem& problem, double d, std::ostringstream* log) {
  for (int k = 0; k < problem.loads.contact.count; ++k) {
    const double eps = problem.loads.contact.surface[k].smoothing;
    if (d > 0 && eps > d)
      *log << "cosserat: warning: environment.contact[" << k << "].smoothing is " << eps
           << " m, more than the rod's width (" << d << " m): the penalty ramps up over that "
              "depth, so the rod sinks into the surface before it is held; the default, 1e-3 of "
              "the diameter, is a sharp contact\n";
  }
}

/// The profile a problem file describes, inside the fixed pressures the parser wraps it in.
const SectionProfile* FileProfile(const io::Problem& problem) {
  const SectionProfile* profile = problem.rod.section.get();
  if (const auto* fixed = dynamic_cast<const FixedActuationSection*>(profile))
    profile = fixed->inner().get();
  return profile;
}

/// The Young's modulus of a rod of one material along its length (Pa), looking through a pipe's
/// contents; 0 for other profiles (tapers, tubes, bands).
double UniformYoungsModulus(const SectionProfile* profile) {
  if (const auto* filled = dynamic_cast<const FilledPipeSection*>(profile))
    profile = &filled->pipe();
  const auto* uniform = dynamic_cast<const UniformSection*>(profile);
  return uniform ? uniform->material().youngs_modulus : 0.0;
}

/// A section whose radius of gyration √(I/A) (from EI/EA) is under 1e-4 of its width: its
/// rotation under shear, ω² ≈ κGA/ρI, then stands beyond 1e17 times a cable's sag modes. A
/// 0.006 m² stay cable (8.7 cm across) given I = 1e-16 m⁴ for "no bending" (1.5e-6 of its width)
/// failed its statics on 101 nodes and read unstable on 201, its lowest ω² lost to round-off;
/// 1e-15 m⁴ (4.7e-6) still solved. A flat strip 1000 times wider than thick is at 3e-4.
void TinyBendingStiffnessWarning(const io::Problem& problem, std::ostringstream* log) {
  const SectionProperties p = problem.rod.section->At(0.0, problem.robot.actuation);
  const double ea = p.stiffness(5, 5), ei = p.min_bending_stiffness(), d = p.outer_diameter;
  if (!(ea > 0 && ei > 0 && d > 0)) return;
  const double gyration = std::sqrt(ei / ea);  // m
  if (gyration >= 1e-4 * d) return;
  *log << "cosserat: warning: the section's radius of gyration sqrt(I/A) is " << gyration
       << " m, " << gyration / d << " of its width " << d << " m: a bending stiffness this "
       << "small leaves its sections' turning under shear (κGA/ρI) too stiff beside the rod's "
          "bending and sag for double precision, and statics or modes may fail or lose their "
          "lowest modes; check rod.section's units (m², m⁴: an area in mm² is 1e6 times too "
          "large), and for a rope or strand that hardly bends give its wires' own I (n π d⁴/64 "
          "for n wires of diameter d)\n";
}

/// A line held at both ends over a hundred times longer than their distance piles up between
/// them: a length in mm with anchors in m (a 200 m stay typed 199 320 ended under_resolved,
/// its notes on compression and self-contact, not on the length).
void LineLongerThanItsSpanWarning(const io::Problem& problem, std::ostringstream* log) {
  if (problem.boundary != io::Boundary::kAnchored) return;
  const double span = (problem.anchor.position - problem.base.p).norm();  // m
  if (!(span > 0.0 && problem.rod.length > 100.0 * span)) return;
  *log << "cosserat: warning: rod.length (" << problem.rod.length << " m) is "
       << problem.rod.length / span << " times the anchors' distance (" << span
       << " m): if it was meant in mm, it is in m here\n";
}

/// A pipe in a fluid without contents_density is sealed and empty: its bore's volume is buoyant.
/// Drill pipe and a flooded riser are open and full of the fluid: 1 000 m of 5 in drill pipe in
/// 1.2 SG mud hung 118 kN from its table taken sealed, 226 kN full.
void SealedPipeNote(const io::Problem& problem, std::ostringstream* log) {
  const double rho = problem.loads.fluid.density;  // kg/m³
  if (problem.bore_area <= 0.0 || problem.bore_filled || rho <= 0.0 ||
      problem.loads.gravity_W.isZero())
    return;
  const double lift = rho * problem.loads.gravity_W.norm() * problem.bore_area;  // N/m
  *log << "cosserat: note: rod.section is a pipe in a fluid without contents_density, so it is "
          "taken sealed and empty: its bore's volume lifts it by "
       << lift << " N/m; an open pipe (drill pipe, a flooded riser) is full of the fluid, "
       << "\"contents_density\": " << io::detail::ShortestNumber(rho) << "\n";
}

/// The stretch past which the linear law is the model's answer, not the material's: kLargeStretch,
/// or 1 % for a uniform rod as stiff as a metal (E over 20 GPa: steel, aluminium, glass and
/// carbon fibre; polymers stay under 5 GPa). A steel stay cable stretched 2.6 % carries 5 GPa,
/// where strand breaks below 2 GPa.
double StretchTrusted(const io::Problem& problem) {
  if (problem.has_assembly || !problem.rod.section) return kLargeStretch;
  return UniformYoungsModulus(FileProfile(problem)) > 20e9 ? 0.01 : kLargeStretch;
}

/// After a solve that did not converge, the slips of units that may be its cause: a Young's
/// modulus below 1e3 Pa (the softest hydrogels'; a steel rod typed in GPa, 200, ran out of load
/// steps and the hint spoke of the grid), and a rest curvature of over two turns along the rod
/// (degrees typed for 1/m: 90 on a 1 m rod is 14 turns, which 51 nodes cannot follow).
void FailedSolveUnitHints(const io::Problem& problem, std::ostringstream* log) {
  if (problem.has_assembly || !problem.rod.section) return;
  const double E = UniformYoungsModulus(FileProfile(problem));  // Pa; 0 where not uniform
  if (E > 0.0 && E < 1e3)
    *log << "cosserat: hint: rod.material.youngs_modulus is " << E << " Pa: if it was meant "
         << "in GPa or MPa, write it in Pa (" << E << "e9 or " << E << "e6)\n";
  const Vec3 k0 = problem.rod.RestStrainAt(0.0).head<3>();  // 1/m, body frame
  const double turns = k0.norm() * problem.rod.length / (2 * M_PI);
  if (turns > 2.0)
    *log << "cosserat: hint: rod.rest_curvature [" << k0.x() << ", " << k0.y() << ", " << k0.z()
         << "] turns the unloaded rod through " << turns
         << " full turns along its length: if it was meant in degrees, curvature is in rad/m "
            "(1/radius)\n";
}

}  // namespace

void AddScaleWarnings(const io::Problem& problem, Result* result) {
  std::ostringstream log;
  log << std::setprecision(3);
  ImpossibleLoadWarning(problem, &log);
  UnitSlipWarnings(problem, &log);
  LineLongerThanItsSpanWarning(problem, &log);
  if (!problem.has_assembly && problem.rod.section) {
    const double d = problem.rod.section->At(0.0, problem.robot.actuation).outer_diameter;
    if (d > 0 && problem.rod.length < kSlenderness * d)
      log << "cosserat: warning: the rod is " << problem.rod.length << " m long and " << d
          << " m across: not a slender rod, which rod theory assumes; check rod.length and the "
             "section's sizes (m)\n";
    ContactSmoothingWarning(problem, d, &log);
    TinyBendingStiffnessWarning(problem, &log);
    SealedPipeNote(problem, &log);
    // A length typed in mm makes a soft robot over 1e4 and a wire 1e5 widths long; drill
    // strings, risers and stay cables reach 4e4, but at 5 cm across or more. Said only after a
    // failed solve, where it may be the cause.
    if (d > 0 && d < 0.05 && problem.rod.length > 1e4 * d && !result->converged)
      log << "cosserat: hint: the rod is " << problem.rod.length << " m long and " << d
          << " m across, " << problem.rod.length / d << " times its width: if rod.length or "
             "the section's sizes were meant in mm, they are in m here\n";
  }
  // The inflated tube's thin-wall laws (I = π r³ t, a wrinkling moment of π p r³/2) drop terms of
  // order t/r: past a 10 % difference from the annulus's I, r the outer radius, it is noted.
  if (const auto* tube = dynamic_cast<const InflatedTubeSection*>(FileProfile(problem))) {
    const double r = tube->radius(), t = tube->wall_thickness();
    const double thin = r * r * r * t, annulus = 0.25 * (std::pow(r, 4) - std::pow(r - t, 4));
    if (thin > 1.1 * annulus)
      log << "cosserat: note: rod.stiffness_profile.wall_thickness is " << t / r
          << " of the tube's radius: its thin-wall bending stiffness (I = π r³ t) is "
          << thin / annulus << " times the annulus's π (r⁴ − (r − t)⁴)/4, and its wrinkling "
          << "moment π p r³/2 assumes a thin wall too\n";
  }
  if (problem.analysis == io::Analysis::kDynamics && problem.dynamics.initial_loads_without_gravity)
    log << "cosserat: warning: dynamics.initial_loads has no \"gravity\" while loads has: it "
           "replaces loads, so the run starts from the equilibrium without gravity; repeat "
           "loads.gravity there, or write \"gravity\": [0, 0, 0] if that start is meant\n";
  // A solve that did not converge leaves an iterate, whose stretch says nothing of the units
  // (an equilibrium on a grid too coarse for it is still one).
  // Its units warnings come right after the summary line, before the hints on grids and steps,
  // which the units may make moot.
  if (!result->converged && result->json.value("status", "") != ToString(SolveStatus::kUnderResolved)) {
    FailedSolveUnitHints(problem, &log);
    const size_t first_line = result->log.find('\n');
    result->log.insert(first_line == std::string::npos ? result->log.size() : first_line + 1,
                       log.str());
    return;
  }
  const nlohmann::ordered_json& j = result->json;
  double at_s = 0.0, worst = 0.0;
  bool everywhere = false;
  const bool shot = problem.formulation == io::Formulation::kSe3Shooting;
  if (j.contains("nodes")) worst = LargestStretch(j["nodes"], shot, &at_s, &everywhere);
  if (j.contains("assembly") && j["assembly"].contains("rods"))
    for (const nlohmann::ordered_json& rod : j["assembly"]["rods"])
      if (rod.contains("nodes")) {
        double s = 0.0;
        bool whole = false;
        const double w = LargestStretch(rod["nodes"], shot, &s, &whole);
        if (w > worst) worst = w, at_s = s, everywhere = whole;
      }
  std::ostringstream place;
  place << std::setprecision(3) << "near s = " << at_s << " m";
  const std::string where = everywhere ? "along the whole rod" : place.str();
  if (worst > kLargestStretch)
    log << "cosserat: warning: the rod is stretched or compressed by " << 100 * worst
        << " % of its length " << where
        << ", far beyond a linear elastic law; check the units of the material (Pa, kg/m³) "
           "and of the loads (N, m)\n";
  else if (worst > StretchTrusted(problem) && problem.rod.chambers.empty())  // chambers extend
    log << "cosserat: warning: the rod is stretched or compressed by " << 100 * worst
        << " % of its length " << where
        << ": the linear elastic law gives this answer, but few materials follow it so far "
           "(metals yield near 0.2 %, rubbers leave it by several per cent); check the loads and "
           "the geometry (an anchor farther than the rod reaches, a tendon length it cannot "
           "take)\n";
  result->log += log.str();
}

}  // namespace cosserat::run::detail
