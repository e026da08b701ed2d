#include "cosserat/run/run_modes.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "cosserat/analysis/modes.hpp"
#include "cosserat/io/result_writer.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/run/initial_equilibrium.hpp"
#include "cosserat/run/run_quatfd.hpp"
#include "cosserat/run/solver_options.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "column_guide_note.hpp"
#include "frame_output.hpp"
#include "mode_planes.hpp"
#include "node_table.hpp"

namespace cosserat::run {
namespace {

/// The most reduced coordinates (six per segment, twice that for damped modes) the quaternion-FD
/// modes take a dense spectrum on: about 801 nodes (401 damped), ~5 min and 1.6 GB
/// (ModalOptions::max_dense). A stable undamped rod on a
/// finer grid takes the banded path instead.
constexpr int kMaxDenseModeCoordinates = 4800;

nlohmann::ordered_json Vectors(const std::vector<Vec3>& v) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Vec3& x : v) out.push_back({x.x(), x.y(), x.z()});
  return out;
}

/// SE(3) modes shoot the rod in one piece from the clamp, statics and frequency scan alike: a
/// tension or a foundation beyond what one shot resolves is the other formulation's.
std::string SingleShotHint(const io::Problem& problem, const ModalResult& r) {
  if (problem.formulation == io::Formulation::kQuaternionFd ||
      r.status != ModalStatus::kStaticsFailed)
    return "";
  const double exponent = StaticShootingExponent(problem.rod, problem.loads);
  if (!(exponent > 10.0)) return "";
  std::ostringstream hint;
  hint << std::setprecision(3)
       << "cosserat: hint: SE(3) modes shoot the rod in one piece from the clamp (statics and "
          "frequency scan), and its loads give L sqrt(T/EI) (or L (k/4EI)^(1/4) for a "
          "foundation) = "
       << exponent << ", beyond the ~10 one shot resolves: use \"formulation\": "
                      "\"quaternion-fd\"\n";
  return hint.str();
}

/// SE(3) modes found fewer frequencies than asked: past ModalResult::shot_limit_hz one shot
/// amplifies round-off beyond what separates a pair's roots (frequency_shot_limit.hpp), and the
/// scan lists none there. Says where that begins.
std::string HighModesHint(const io::Problem& problem, const ModalResult& r) {
  if (problem.formulation == io::Formulation::kQuaternionFd ||
      r.status != ModalStatus::kTooFewModes || !problem.rod.section)
    return "";
  const double limit = r.shot_limit_hz;
  if (limit == 0.0)  // the tension alone passes the limit at any frequency
    return "cosserat: hint: SE(3) modes shoot the rod in one piece, and its tension alone makes a "
           "perturbation grow by more than e^28 along it (L sqrt(T/EI) past 28), beyond what "
           "one shot resolves: use \"formulation\": \"quaternion-fd\"\n";
  // Fewer for another reason (the scan's band or budget) when the last found is far below it.
  const double last = r.modes.empty() ? limit : r.modes.back().frequency_hz;
  if (!std::isfinite(limit) || last < 0.5 * limit) return "";
  std::ostringstream hint;
  hint << std::setprecision(3) << "cosserat: hint: SE(3) modes shoot the rod in one piece, "
       << "which resolves frequencies up to about " << limit
       << " Hz here (where a perturbation grows by e^28 along the rod, ∫ μ ds = 28 with "
          "μ² = (T + sqrt(T² + 4 EI ρA ω²))/(2 EI)); above it the roots blur and none is listed: "
          "ask for fewer modes, or use \"formulation\": \"quaternion-fd\"\n";
  return hint.str();
}

/// How well the grid resolves the modes found. A mode's wave number k along the rod, from its
/// frequency ω: bending, the tensioned beam's EI k⁴ + T k² = ρA ω² at the least tension T of
/// the equilibrium (compression counts against it); axial ω sqrt(ρA/EA); torsion
/// ω sqrt(ρJ/GJ); the stiffest k over the rod. The frequency error on a grid of spacing h,
/// measured on a steel cantilever's bending modes (3–33 nodes): SE(3), RK4 in s, about
/// 0.011 (k h)⁴ (1.8 % at k h = 1.17, 0.17 % at 0.59); quaternion FD about 0.2 (k h)² (6.2 % at
/// 0.59, 0.42 % at 0.15). A string's central second difference is off by (k h)²/24 (0.41 % at
/// k h = 0.31 on a taut stay cable; a torsion mode 0.103 % at 0.157), and so are the axial and
/// torsional wave equations': on the quaternion-FD grid those take (k h)²/24, and a bending
/// mode's coefficient is the two weighted by their shares of ρA ω² (EI k⁴ and T k²). Above 1 % a
/// warning; status under_resolved above 10 % on the quaternion-FD grid (12 % measured at
/// k h = 0.98) and above k h = 2 in RK4 (est. 18 %): its error changes sign near there (−1.1 % at
/// k h = 1.96, −19.5 % at 2.35, −44 % at 2.93; on the imaginary axis RK4 is stable up to 2.83).
struct ModesGrid {
  bool under_resolved = false;
  std::string log;
};
ModesGrid CheckModesGrid(const io::Problem& problem, const ModalResult& r) {
  ModesGrid out;
  if (r.modes.empty() || !problem.rod.section || problem.nodes < 2) return out;
  const bool quatfd = problem.formulation == io::Formulation::kQuaternionFd;
  const double L = problem.rod.length, h = L / (problem.nodes - 1);
  double tension = r.equilibrium.wrench_B.empty() ? 0.0 : INFINITY;  // N, the least along it
  for (const Vec6& w : r.equilibrium.wrench_B) tension = std::min(tension, w(5));
  // The error coefficients above: RK4's of (k h)⁴, the quaternion-FD grid's of (k h)².
  constexpr double kRk4 = 0.011, kQuatFdBending = 0.2, kString = 1.0 / 24.0;
  double worst = 0.0, worst_k = 0.0, worst_hz = 0.0, nodes_needed = 0.0;
  int worst_mode = 0;
  std::vector<SectionProperties> sections;  // at 0, L/4, … L: the stiffest wave number of these
  for (int i = 0; i <= 4; ++i)
    sections.push_back(problem.rod.section->At(0.25 * i * L, problem.robot.actuation));
  for (size_t m = 0; m < r.modes.size(); ++m) {
    const double omega = 2 * M_PI * r.modes[m].frequency_hz;
    if (!(omega > 0.0)) continue;
    for (const SectionProperties& p : sections) {
      const double rhoA = p.mass(5, 5), EI = p.min_bending_stiffness();
      double k = 0.0, quatfd_coefficient = kQuatFdBending;  // 1/m; error / (k h)²
      switch (r.modes[m].kind) {
        case ModeKind::kBending: {
          k = std::sqrt((-tension + std::sqrt(tension * tension + 4 * EI * rhoA * omega * omega)) /
                        (2 * EI));
          // Each term's error weighted by its size: under compression the two nearly cancel
          // in ρA ω² at a low mode (a bow swinging slowly about a tilted chord), where their
          // difference would blow the weight up (272 % for a swing no grid changes), so by
          // their magnitudes.
          const double bending = EI * std::pow(k, 4), stretched = tension * k * k;  // N/m
          if (bending + std::abs(stretched) > 0.0)
            quatfd_coefficient = (kQuatFdBending * bending + kString * std::abs(stretched)) /
                                 (bending + std::abs(stretched));
          break;
        }
        case ModeKind::kAxial:  // wave equations: the string's central difference
          k = omega * std::sqrt(rhoA / p.stiffness(5, 5));
          quatfd_coefficient = kString;
          break;
        case ModeKind::kTorsion:
          k = omega * std::sqrt(p.mass(2, 2) / p.stiffness(2, 2));
          quatfd_coefficient = kString;
          break;
      }
      // The quaternion-FD frequency is low by its error, so the k it gives is too: once more
      // from k / (1 − error) (a string's 11-node estimate 5.7 % becomes 6.5 %, as measured).
      if (quatfd) k /= std::max(0.5, 1.0 - quatfd_coefficient * k * h * k * h);
      const double kh = k * h;
      const double error = quatfd ? quatfd_coefficient * kh * kh : kRk4 * std::pow(kh, 4);
      const double kh_one_percent = quatfd ? std::sqrt(0.01 / quatfd_coefficient)
                                           : std::pow(0.01 / kRk4, 0.25);
      nodes_needed = std::max(nodes_needed, std::ceil(k * L / kh_one_percent) + 1);
      if (error > worst)
        worst = error, worst_k = k, worst_hz = r.modes[m].frequency_hz,
        worst_mode = static_cast<int>(m) + 1;
    }
  }
  if (!(worst > 0.01)) return out;
  out.under_resolved = worst > (quatfd ? 0.1 : kRk4 * 16.0);  // RK4: k h > 2
  std::ostringstream log;
  log << std::setprecision(3)
      << (!out.under_resolved ? "cosserat: warning: the grid resolves the modes coarsely: "
          : r.converged()       ? "cosserat: the grid is too coarse for these modes (status "
                                  "under_resolved): "
                                : "cosserat: the grid is also too coarse for these modes: ")
      << "mode " << worst_mode << " (" << worst_hz << " Hz) has k h = " << worst_k * h
      << " (k its wave number along the rod), where its frequency is off by "
      << (quatfd ? "about " : "up to about ") << 100 * worst << " % ("
      << (quatfd ? "quaternion FD, second order in k h"
                 : "RK4 in s, fourth order in k h, an upper estimate: its error turns sign near "
                   "k h = 2")
      << "); rod.nodes ≥ " << static_cast<long>(nodes_needed)
      << " keeps every mode found within about 1 %\n";
  out.log = log.str();
  return out;
}

/// Whether the section has Kelvin–Voigt damping anywhere: every sixteenth of the rod, and both
/// sides of each jump in the section (a damped band).
bool HasSectionDamping(const io::Problem& problem) {
  if (!problem.rod.section) return false;
  std::vector<double> at;
  for (int i = 0; i <= 16; ++i) at.push_back(problem.rod.length * i / 16);
  for (const double b : problem.rod.Breakpoints())
    for (const double side : {-1e-9, 1e-9}) at.push_back(b + side * problem.rod.length);
  for (const double s : at)
    if (s >= 0 && s <= problem.rod.length &&
        problem.rod.section->At(s, problem.robot.actuation).damping.cwiseAbs().maxCoeff() > 0)
      return true;
  return false;
}

/// Why no modes came from a converged equilibrium (ModalResult::declined), and what to do: a
/// coarser grid; for damped modes of a damped section, the undamped ones, which the banded path
/// takes at any grid; the SE(3) path where it runs the rod (not an "anchored" line, which it
/// refuses: the note once sent such a stay cable there).
std::string DeclinedNote(const io::Problem& problem, const ModalResult& r) {
  if (r.declined.empty()) return "";
  // The dense size grows with the segments: the nodes that keep it within the limit.
  const long segments = static_cast<long>(r.s.size()) - 1;
  const long nodes = r.declined_dense_size > 0
                         ? segments * kMaxDenseModeCoordinates / r.declined_dense_size + 1
                         : kMaxDenseModeCoordinates / 6 + 1;
  std::string note = "cosserat: no modes on this grid: " + r.declined + "; rod.nodes <= " +
                     std::to_string(nodes) + " takes the dense spectrum";
  // A flow's drag damps as well (at rest in still water its linearised drag is zero).
  const bool flow_damps = HasDrag(problem.loads) && !problem.loads.fluid.velocity_W.isZero();
  if (r.declined.find("damped") != std::string::npos && HasSectionDamping(problem) && !flow_damps)
    note += ", or without rod.material.damping the undamped modes come from the banded "
            "factorisation on any grid";
  if (problem.boundary != io::Boundary::kAnchored) note += ", or \"formulation\": \"se3-shooting\"";
  return note + "\n";
}

/// The modes of the problem in its formulation; `progress` follows the SE(3) scan (modes found,
/// modes asked).
ModalResult ModesOf(const io::Problem& problem,
                    const std::function<void(double, double)>& progress) {
  ModalOptions mo;
  mo.count = problem.modes.count;
  mo.max_dense = kMaxDenseModeCoordinates;
  if (problem.formulation == io::Formulation::kQuaternionFd) {
    quatfd::QuatFdModel model(problem.rod, problem.base, QuatFdModelOptions(problem),
                              problem.robot.actuation);
    model.set_loads(problem.loads);  // the start of a held rod's statics sags along gravity
    return ComputeModes(&model, problem.loads, mo, nullptr, nullptr,
                        QuatFdStaticOptions(problem));
  }
  ShootingModalOptions so;
  so.modal = mo;
  so.statics = StaticOptions(problem);
  so.progress = progress;
  so.tip_mass = problem.dynamics.tip_mass;  // a body at a cantilever's tip (a drill string's BHA)
  so.tip_inertia = problem.dynamics.tip_inertia;
  ColumnEnds ends = ColumnEnds::kClampedFree;
  ToColumnEnds(problem.boundary, &ends);  // a column's; UnsupportedFeatures let only these through
  return ComputeModesShooting(problem.rod, problem.nodes, problem.base,
                              WithTipMassWeight(problem, problem.loads), so,
                              problem.robot.actuation, ends);
}

/// The SE(3) modes leave the section's Kelvin–Voigt damping out: said when the rod has some.
std::string UndampedShootingNote(const io::Problem& problem) {
  if (problem.formulation != io::Formulation::kSe3Shooting || !HasSectionDamping(problem))
    return "";
  return std::string("cosserat: note: the se3-shooting modes are undamped "
                     "(rod.material.damping is left out)") +
         (problem.boundary == io::Boundary::kCantilever ||
                  problem.boundary == io::Boundary::kAnchored
              ? "; \"formulation\": \"quaternion-fd\" also gives each mode's damped "
                "frequency and damping ratio"
              : "; the quaternion-FD path, which gives damped modes, runs a cantilever or an "
                "\"anchored\" line") +
         "\n";
}

/// Which modes are neutral (Mode::neutral), and what that means.
std::string NeutralNote(const ModalResult& r) {
  std::ostringstream which, computed;
  computed << std::setprecision(3);
  int count = 0;
  for (size_t m = 0; m < r.modes.size(); ++m) {
    if (!r.modes[m].neutral) continue;
    which << (count ? ", " : " ") << m + 1;
    computed << (count++ ? ", " : "") << r.modes[m].computed_omega_squared;
  }
  if (count == 0) return "";
  return std::string("cosserat: note: mode") + (count > 1 ? "s" : "") + which.str() +
         (count > 1 ? " are" : " is") +
         " neutral, listed at 0 Hz: a motion that costs no energy, whose computed ω² (" +
         computed.str() +
         " rad²/s²) is round-off of zero (such as a bowed line turning about a chord that "
         "gravity runs along, or an equilibrium at its critical load); neither the stability "
         "nor the grid is judged by it\n";
}

/// "cosserat: converged (modes, ...), 4 modes: f... Hz, damping ratios ζ..., t ms".
std::string SummaryLine(const io::Problem& problem, const ModalResult& r) {
  std::ostringstream log;
  log << "cosserat: " << ToString(r.status) << " (modes, " << io::ToString(problem.formulation)
      << "), " << r.modes.size() << " modes" << (r.modes.empty() ? "" : ":");
  for (const Mode& m : r.modes) log << ' ' << std::setprecision(6) << m.frequency_hz;
  if (!r.modes.empty()) log << " Hz";
  if (!r.damped.empty()) {  // each mode's ζ, or "overdamped" where it has no pair
    log << ", damping ratios";
    for (size_t m = 0; m < r.damped.size(); ++m) {
      const DampedMode& d = r.damped[m];
      if (m < r.modes.size() && r.modes[m].neutral)
        log << " neutral";
      else if (std::isnan(d.damping_ratio))
        log << " overdamped";
      else
        log << ' ' << std::setprecision(4) << d.damping_ratio;
    }
  }
  log << ", " << std::setprecision(3) << r.wall_time_s * 1e3 << " ms\n";
  return log.str();
}

}  // namespace

Result RunModes(const io::Problem& problem, const RunOptions& options) {
  const ModalResult r = ModesOf(problem, options.progress);

  // The contract's fields of every result (status, iterations, residual, tip, base_wrench,
  // nodes) describe the equilibrium the modes are about; "modes" and the statics' own status
  // ("equilibrium") follow.
  StaticShootingSummary eq;
  eq.status = r.statics_status;
  eq.iterations = r.statics_iterations;
  eq.residual = r.statics_residual;
  const nlohmann::ordered_json statics = io::StaticResultToJson(eq, r.equilibrium);
  Result result;
  detail::KeepStaticFrame(problem, r.equilibrium, options, &result);
  result.json["status"] = ToString(r.status);
  for (const char* key : {"iterations", "residual"}) result.json[key] = statics[key];
  result.json["wall_time_s"] = r.wall_time_s;
  for (const char* key : {"tip", "base_wrench", "nodes"})
    if (statics.contains(key)) result.json[key] = statics[key];
  if (problem.boundary == io::Boundary::kAnchored && r.equilibrium.size() > 0) {
    // As the statics report it: the force the tip's anchor exerts on the rod (N, world).
    const Vec3 f = r.equilibrium.rotation_WB.back() * r.equilibrium.wrench_B.back().tail<3>();
    result.json["anchor_force"] = {f.x(), f.y(), f.z()};
  }
  nlohmann::ordered_json modes;
  modes["formulation"] = io::ToString(problem.formulation);
  modes["frequencies_hz"] = r.frequencies_hz();
  std::vector<std::string> kinds;
  for (const Mode& m : r.modes) kinds.push_back(ToString(m.kind));
  modes["kinds"] = kinds;
  std::vector<bool> neutral;
  for (const Mode& m : r.modes) neutral.push_back(m.neutral);
  modes["neutral"] = neutral;
  if (problem.boundary == io::Boundary::kAnchored) {  // a cable's in-plane and sideways modes
    const std::vector<std::string> planes =
        detail::ModePlanes(r.equilibrium, r.modes, problem.loads.gravity_W);
    if (!planes.empty()) modes["planes"] = planes;
  }
  if (!r.damped.empty()) {
    // One entry per mode: null where the mode has no damped pair (overdamped, or unstable).
    nlohmann::ordered_json fd = nlohmann::ordered_json::array(),
                           zeta = nlohmann::ordered_json::array();
    for (const DampedMode& d : r.damped) {
      const bool paired = std::isfinite(d.damping_ratio);
      fd.push_back(paired ? nlohmann::ordered_json(d.damped_frequency_hz) : nullptr);
      zeta.push_back(paired ? nlohmann::ordered_json(d.damping_ratio) : nullptr);
    }
    modes["damped_frequencies_hz"] = fd;
    modes["damping_ratios"] = zeta;
  }
  modes["s"] = r.s;
  nlohmann::ordered_json shapes = nlohmann::ordered_json::array();
  for (const Mode& m : r.modes)
    shapes.push_back(
        {{"displacement", Vectors(m.displacement_W)}, {"rotation", Vectors(m.rotation_W)}});
  modes["shapes"] = shapes;
  result.json["modes"] = modes;
  result.json["equilibrium"] = {{"status", ToString(r.statics_status)}};
  if (options.nodes_csv) result.nodes_csv = detail::NodesCsv(r.equilibrium);

  std::ostringstream log;
  log << SummaryLine(problem, r);
  if (r.status == ModalStatus::kUnstable && !r.instability.empty())
    log << "cosserat: unstable: " << r.instability << "\n";
  log << DeclinedNote(problem, r) << UndampedShootingNote(problem) << NeutralNote(r);
  ColumnEnds ends = ColumnEnds::kClampedFree;
  if (problem.formulation == io::Formulation::kSe3Shooting && ToColumnEnds(problem.boundary, &ends))
    log << detail::GuideTakesTipForceNote(problem, ends);
  const ModesGrid grid = CheckModesGrid(problem, r);
  if (problem.formulation == io::Formulation::kQuaternionFd && r.equilibrium.size() > 0)
    log << ClampedEndGridWarning(problem, r.equilibrium);  // the statics' own warning
  result.log = log.str() + grid.log + SingleShotHint(problem, r) + HighModesHint(problem, r);
  result.converged = r.converged() && !grid.under_resolved;
  if (r.converged() && grid.under_resolved)
    result.json["status"] = ToString(SolveStatus::kUnderResolved);
  return result;
}

}  // namespace cosserat::run
