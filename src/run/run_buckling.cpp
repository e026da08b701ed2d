#include "cosserat/run/run_buckling.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

#include "cosserat/analysis/buckling.hpp"
#include "cosserat/analysis/column_ends.hpp"
#include "cosserat/analysis/buckling_in_pieces.hpp"
#include "cosserat/analysis/quatfd_buckling.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/io/result_writer.hpp"
#include "cosserat/rod/stiffness_profiles.hpp"
#include "cosserat/run/solver_options.hpp"
#include "cosserat/strong/static_multiple_shooting.hpp"
#include "column_guide_note.hpp"
#include "frame_output.hpp"
#include "node_table.hpp"
#include "tendon_law_limit.hpp"

namespace cosserat::run {

namespace {

// loads(λ) = problem loads + λ · direction, for the load kind the "buckling" block names; or the
// tendon tensions + λ · weights ("tendon_tension"), or the pressure max − λ ("pressure").
LoadPath MakePath(const io::Problem& problem) {
  LoadPath path;
  path.fixed = problem.loads;
  path.fixed_actuation = problem.robot.actuation;
  path.per_unit.tip_force_frame = problem.loads.tip_force_frame;
  path.per_unit.tip_moment_frame = problem.loads.tip_moment_frame;
  const Vec3& d = problem.buckling.direction;
  using io::BucklingLoad;
  const BucklingLoad load = problem.buckling.load;
  if (load == BucklingLoad::kTipForce) {
    path.per_unit.tip_force = d;
  } else if (load == BucklingLoad::kTipMoment) {
    path.per_unit.tip_moment = d;
  } else if (load == BucklingLoad::kGravity) {
    path.per_unit.gravity_W = d;
  } else if (load == BucklingLoad::kDistributedForce) {
    path.per_unit.distributed_force_W = d;
  } else if (load == BucklingLoad::kTendonTension) {
    // λ is the tension added to the most-weighted tendon (the parser checked one weight per
    // tendon, >= 0, not all zero; none given: all alike).
    const std::vector<double>& w = problem.buckling.tendon_weights;
    const size_t n = problem.rod.tendons.size();
    const double w_max = w.empty() ? 1.0 : *std::max_element(w.begin(), w.end());
    for (size_t i = 0; i < n && i < static_cast<size_t>(Actuation::kMaxTendons); ++i)
      path.tension_per_unit[i] = w.empty() ? 1.0 : w[i] / w_max;
  } else {  // "pressure": p(λ) = max − λ, from the problem's other actuation
    const StaticLoads loads = problem.loads;
    const Actuation held = path.fixed_actuation;
    path = LoadPath::PressureDrop(problem.buckling.max, loads);
    path.fixed_actuation.tendon_tension = held.tendon_tension;
    path.fixed_actuation.jamming_pressure = held.jamming_pressure;
  }
  return path;
}

// The rod the analysis runs on. A pressure path drives the pressure itself: a profile the parser
// wrapped at the file's fixed pressures (no robot) is unwrapped, its other pressures kept.
RodModel MakeModel(const io::Problem& problem, LoadPath* path) {
  RodModel model = problem.rod;
  if (problem.buckling.load != io::BucklingLoad::kPressure) return model;
  if (const auto* fixed = dynamic_cast<const FixedActuationSection*>(model.section.get())) {
    path->fixed_actuation.jamming_pressure = fixed->actuation().jamming_pressure;
    model.section = fixed->inner();
  }
  return model;
}

// The load reported for λ: λ itself, or the pressure max − λ for a pressure drop.
double ReportedLoad(const io::Problem& problem, double lambda) {
  return problem.buckling.load == io::BucklingLoad::kPressure ? problem.buckling.max - lambda
                                                              : lambda;
}

nlohmann::ordered_json NumberOrNull(double x) {
  return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(nullptr);
}

/// The searched load is added to the file's own value of that load: say so when it is not zero
/// (a column under gravity searched in gravity reports the increment, not the total).
std::string OnTopOfTheFilesLoad(const io::Problem& problem) {
  const StaticLoads& l = problem.loads;
  const io::BucklingLoad k = problem.buckling.load;
  const bool own = (k == io::BucklingLoad::kTipForce && !l.tip_force.isZero()) ||
                   (k == io::BucklingLoad::kTipMoment && !l.tip_moment.isZero()) ||
                   (k == io::BucklingLoad::kGravity && !l.gravity_W.isZero()) ||
                   (k == io::BucklingLoad::kDistributedForce && !l.distributed_force_W.isZero());
  return own ? " on top of loads." + io::ToString(k) : "";
}

/// After a search that found no critical load along a path that is not conservative (a follower
/// load, a tip moment, drag): such a rod can also lose its stability by flutter, two frequencies
/// meeting (Beck's column), which no static search sees; the modes at a load do.
std::string FlutterNote(const io::Problem& problem, BucklingStatus status) {
  if (status != BucklingStatus::kNotFound) return "";
  const LoadPath path = MakePath(problem);
  if (LoadsAreConservative(path.fixed) && LoadsAreConservative(path.per_unit)) return "";
  const bool drag = HasDrag(path.fixed) || HasDrag(path.per_unit);
  return std::string("cosserat: note: the loads are not conservative (") +
         (drag ? "a flow's drag" : "a follower load or a tip moment") +
         "): the rod may also lose its stability by flutter, two of its frequencies meeting, "
         "which a static search does not see; \"analysis\": \"modes\" at a load reports it as "
         "unstable\n";
}

/// After a search that found no critical load: the file's loads push the rod across its axis
/// (an imperfection), so it bends smoothly along the path and has no bifurcation to find. A
/// column's tip guide takes a tip force across the axis whole: that one bends nothing.
std::string ImperfectionNote(const io::Problem& problem, ColumnEnds ends,
                             BucklingStatus status) {
  if (status != BucklingStatus::kNotFound && status != BucklingStatus::kPathFailed) return "";
  // On contact surfaces the loads across the axis press the rod onto them, which can leave a
  // plane of symmetry (a pipe on the low side of a bore buckles sideways): not an imperfection.
  if (problem.loads.contact.count > 0) return "";
  const StaticLoads& l = problem.loads;
  const Vec3 axis = problem.base.R.col(2);  // the rod's tangent at s = 0, world
  auto across = [&](const Vec3& f) { return f.cross(axis).norm() > 1e-12 * f.norm(); };
  const bool drag = l.fluid.present() && across(l.fluid.velocity_W);
  const bool tip = ends == ColumnEnds::kClampedFree && across(l.tip_force);
  if (!(tip || across(l.distributed_force_W) || across(l.gravity_W) || drag))
    return "";
  return "cosserat: note: the file's loads push the rod across its axis, an imperfection: it "
         "bends smoothly as the load grows, with no bifurcation to find (a limit point, if any, "
         "is what the search reports); \"analysis\": \"statics\" gives the deflection under a "
         "load\n";
}

/// After a search that found no critical load for a dead tip force that presses the rod along
/// its axis: buckling.max below the Euler load of its ends (EI the least along the rod), which
/// the search then never reaches. The file's other loads move the critical load, so this is a
/// pointer, not a bound.
std::string BelowEulerNote(const io::Problem& problem, ColumnEnds ends, BucklingStatus status) {
  if (status != BucklingStatus::kNotFound ||
      problem.buckling.load != io::BucklingLoad::kTipForce ||
      problem.loads.tip_force_frame == LoadFrame::kBody || !problem.rod.section)
    return "";
  const Vec3 axis = problem.base.R.col(2);
  if (problem.buckling.direction.normalized().dot(axis) > -0.5) return "";  // DirectionNote's
  const double L = problem.rod.length;
  double ei = INFINITY;  // N m², the least of five points along the rod
  for (int i = 0; i <= 4; ++i)
    ei = std::min(ei, problem.rod.section->At(0.25 * i * L, problem.robot.actuation)
                          .min_bending_stiffness());
  const double euler = EulerLoadCoefficient(ends) * ei / (L * L);
  if (!(problem.buckling.max < euler)) return "";
  std::ostringstream note;
  note << std::setprecision(4) << "cosserat: note: buckling.max (" << problem.buckling.max
       << " N) is below the Euler load of a uniform rod with these ends, " << euler << " N ("
       << EulerLoadCoefficient(ends) << " EI/L², EI the least along the rod, " << ei
       << " N m²): the search stops at buckling.max before any critical load of that size; "
          "raise it\n";
  return note.str();
}

/// After a search that found no critical load for a force along a fixed direction: that direction
/// is across the rod or pulls it along its axis (the default [0, 0, −1] on a rod clamped level
/// is across it), so the load never presses it and there is nothing to find. The axis is the
/// base frame's third column (a follower tip force's direction is in the tip's frame, whose
/// axis is e₃).
std::string DirectionNote(const io::Problem& problem, BucklingStatus status) {
  if (status != BucklingStatus::kNotFound && status != BucklingStatus::kPathFailed) return "";
  using io::BucklingLoad;
  const BucklingLoad k = problem.buckling.load;
  if (k != BucklingLoad::kTipForce && k != BucklingLoad::kGravity &&
      k != BucklingLoad::kDistributedForce)
    return "";
  const bool follower =
      k == BucklingLoad::kTipForce && problem.loads.tip_force_frame == LoadFrame::kBody;
  // Components below rounding print as 0 (a base turned by a rotation matrix of cosines).
  auto clean = [](const Vec3& v) {
    return Vec3(v.unaryExpr([](double x) { return std::abs(x) < 1e-12 ? 0.0 : x; }));
  };
  const Vec3 axis = follower ? Vec3::UnitZ() : Vec3(problem.base.R.col(2));
  const Vec3 shown = clean(axis);
  const Vec3 d = clean(problem.buckling.direction.normalized());
  const double along = d.dot(axis);  // −1: presses the rod along its axis
  if (along < -0.5) return "";
  std::ostringstream note;
  note << std::setprecision(3) << "cosserat: note: buckling.direction [" << d.x() << ", "
       << d.y() << ", " << d.z() << "] "
       << (along > 0.5 ? "pulls the rod along its axis, which does not buckle it"
                       : "is mostly across the rod, which bends it without a bifurcation")
       << " (the rod's axis at its base is [" << shown.x() << ", " << shown.y() << ", "
       << shown.z() << "]" << (follower ? ", in the tip's frame" : ", base.rotation's third column")
       << "); a direction of [" << 0.0 - shown.x() << ", " << 0.0 - shown.y() << ", "
       << 0.0 - shown.z() << "] presses it\n";
  return note.str();
}

/// How a buckling search's critical load errs with the grid: about coefficient (k h)^power,
/// k = sqrt(P/EI) where the pre-buckled rod is pressed by P; a note above `note_above`, asking
/// for the nodes that give k h = target_kh (an error below `target`).
struct BucklingGridLaw {
  double coefficient;
  int power;
  double note_above, target_kh;
  const char* target;
  const char* scheme;
  const char* size;  ///< "up to about" for an upper estimate, "about" for the measured law
};
/// SE(3), RK4 in s: about 1.5e-2 (k h)⁴ at most (measured on a pinned column: +5.1e-3 at
/// k h = 0.79, +1.3e-2 at 1.05, +2.8e-2 at π/2); from 1e-4 (k h = 0.29), to k h = 0.2 (2.4e-5).
constexpr BucklingGridLaw kShootingBucklingGrid{1.5e-2, 4,          1e-4,       0.2,
                                                "3e-5", "RK4 in s", "up to about"};
/// Quaternion FD, second order, low: −0.084 (k h)² on a steel cantilever (−5.0 % at k h = 0.77,
/// −1.28 % at 0.39, −0.081 % at 0.098); from 1e-3 (k h = 0.11), to k h = 0.03 (7.7e-5).
constexpr BucklingGridLaw kQuatFdBucklingGrid{0.085,  2,      1e-3,           0.03,
                                              "1e-4", "quaternion FD", "about"};

/// After a found search: the note on a grid coarse for the buckled shape, empty otherwise.
std::string CoarseGridNote(const io::Problem& problem, bool found, const RodState& state,
                           const BucklingGridLaw& law) {
  if (!found || state.size() < 2) return "";
  double worst = 0.0, worst_s = 0.0, worst_k = 0.0;  // k h, where (m), k (1/m)
  for (int i = 0; i + 1 < state.size(); ++i) {
    const double pressed = std::max(-state.wrench_B[i](5), -state.wrench_B[i + 1](5));  // N
    const double ei = problem.rod.section->At(state.s[i], problem.robot.actuation)
                          .min_bending_stiffness();
    const double k = pressed > 0 && ei > 0 ? std::sqrt(pressed / ei) : 0.0;
    const double kh = k * (state.s[i + 1] - state.s[i]);
    if (kh > worst) worst = kh, worst_s = state.s[i], worst_k = k;
  }
  const double error = law.coefficient * std::pow(worst, law.power);  // relative, an estimate
  if (!(error > law.note_above)) return "";
  std::ostringstream note;
  note << std::setprecision(3)
       << "cosserat: note: the grid is coarse for the buckled shape: at s = "
       << worst_s << " m the pressed rod bends by k h = " << worst
       << " per segment (k = sqrt(P/EI)), and the critical load's relative error grows as "
          "(k h)^" << law.power << " (" << law.scheme << "), " << law.size << " "
       << error << " here; \"rod\": {\"nodes\": "
       << static_cast<long>(std::ceil(problem.rod.length * worst_k / law.target_kh)) + 1
       << "} brings it below " << law.target << "\n";
  return note.str();
}

/// After an SE(3) buckling search that failed before any load, and could not be searched in
/// pieces (a tendon or pressure path, a robot): its statics shoot the rod in one piece, which a
/// stiff contact foundation or a high tension puts beyond double precision.
std::string SingleShotHint(const io::Problem& problem, const BucklingSummary& b) {
  if (b.status == BucklingStatus::kPathFailed && b.beyond_single_shot) {
    std::ostringstream hint;
    hint << "cosserat: hint: one shot from the base cannot resolve this rod's tension from a "
         << "load of " << std::setprecision(6) << ReportedLoad(problem, b.lambda_reached)
         << " on (the fields that count its stability grow past e^10 along it), and a search "
            "along an actuation (tendon tension, pressure) shoots the rod in one piece: this "
            "one is beyond this version's buckling search\n";
    return hint.str();
  }
  const double exponent = StaticShootingExponent(problem.rod, problem.loads);
  if (b.status != BucklingStatus::kPathFailed || b.lambda_reached > 0.0 || exponent <= 10.0)
    return "";
  std::ostringstream hint;
  hint << "cosserat: hint: a single SE(3) shot of this rod amplifies errors by about e^"
       << std::setprecision(3) << exponent
       << " (contact stiffness or tension; more than double precision holds from e^15 on), and "
          "a search along an actuation (tendon tension, pressure) shoots the rod in one piece: "
          "this one is beyond this version's buckling search (its statics, in pieces, still "
          "run)\n";
  return hint.str();
}

/// The one-line summary of an SE(3) search: what it found, or how far it got.
std::string SummaryLine(const io::Problem& problem, ColumnEnds ends, const BucklingSummary& b) {
  std::ostringstream line;
  line << "cosserat: buckling " << ToString(b.status) << " (" << ToString(ends) << ")";
  if (b.found())
    line << ", critical " << io::ToString(problem.buckling.load) << " " << std::setprecision(6)
         << ReportedLoad(problem, b.critical_load) << OnTopOfTheFilesLoad(problem)
         << ", mode bends most at s = " << b.mode.s_max_curvature << " m";
  else if (b.status == BucklingStatus::kPreloadPastCritical)
    line << ": the file's loads alone reach a critical point at " << std::setprecision(3)
         << b.preload_critical_fraction
         << " of them, so the equilibrium they load is past buckling and no load on top of them "
            "is its critical load (search from zero with them as the buckling load)";
  else
    line << ", " << (problem.buckling.load == io::BucklingLoad::kPressure ? "pressure" : "load")
         << " reached " << std::setprecision(6) << ReportedLoad(problem, b.lambda_reached);
  line << ", " << b.solves << " static solves, " << std::setprecision(3) << b.wall_time_s * 1e3
       << " ms";
  return line.str() + '\n';
}

/// A rod one shot cannot follow (a long pipe on a bore, a taut rod) whose single-shot search
/// failed: the search again, the rod shot in pieces, when its path is of loads only. Replaces
/// *b and *state (kept alive by *in_pieces) when that got further; returns the note that says
/// so, or that it failed too.
std::string SearchInPieces(const io::Problem& problem, const RodModel& model, ColumnEnds ends,
                           const LoadPath& path, const BucklingOptions& options,
                           BucklingSummary* b, const RodState** state,
                           std::unique_ptr<BucklingInPieces>* in_pieces) {
  const bool loads_only = !path.has_actuation() && model.tendons.empty() &&
                          model.chambers.empty() && !problem.has_robot;
  if (b->status != BucklingStatus::kPathFailed || !loads_only ||
      !(problem.loads.contact.count > 0 || b->beyond_single_shot ||
        StaticShootingExponent(problem.rod, problem.loads) > 10.0))
    return "";
  *in_pieces =
      std::make_unique<BucklingInPieces>(model, problem.nodes, ends, problem.base, path, options);
  const BucklingSummary split = (*in_pieces)->FindCriticalLoad();
  if (split.status == BucklingStatus::kPathFailed && split.lambda_reached <= b->lambda_reached)
    return "cosserat: note: the single-shot search could not follow this rod, nor could "
           "multiple shooting in " +
           std::to_string((*in_pieces)->pieces()) + " pieces\n";
  std::ostringstream note;
  const int pieces = (*in_pieces)->pieces();
  if (b->beyond_single_shot) {
    note << "cosserat: note: one shot from the base cannot resolve this rod's tension ";
    if (b->lambda_reached > 0.0)
      note << "from a load of " << std::setprecision(6) << ReportedLoad(problem, b->lambda_reached)
           << " on";
    else
      note << "under the file's loads";
    note << " (the fields that count its stability grow past e^10 along it)";
  } else {
    note << "cosserat: note: the single-shot search could not follow this rod (it failed at "
         << std::setprecision(6) << ReportedLoad(problem, b->lambda_reached) << ")";
  }
  note << "; it was searched again by multiple shooting, in " << pieces
       << (pieces == 1 ? " piece" : " pieces") << ", its stability counted piece by piece\n";
  if (split.found() && split.critical_load_bracket > 1e-6 * split.critical_load)
    note << "cosserat: note: the solves near the critical load failed before it was refined: it "
            "lies between "
         << std::setprecision(6)
         << ReportedLoad(problem, split.critical_load - split.critical_load_bracket) << " and "
         << ReportedLoad(problem, split.critical_load) << "\n";
  const int single_solves = b->solves;
  const double single_time_s = b->wall_time_s;
  *b = split;
  b->solves += single_solves;
  b->wall_time_s += single_time_s;
  *state = &(*in_pieces)->state();
  return note.str();
}

/// A tendon-tension path that stopped short of `max` with a tendon past half the tendon law's
/// limit (tendon_law_limit.hpp): tension alone buckles no rod, and a path on a thin backbone
/// (EI = 4.2e-3 N·m², tendons 8 mm out) stops at 38 N added, at 0.6 of it. Names how near the
/// tendon was; empty below half.
std::string TendonLimitHint(const io::Problem& problem, const LoadPath& path,
                            const BucklingSummary& b) {
  if (problem.buckling.load != io::BucklingLoad::kTendonTension ||
      b.status != BucklingStatus::kPathFailed)
    return "";
  const detail::TendonLawLoad worst =
      detail::LargestTendonLawLoad(problem, path.ActuationAt(b.lambda_reached));
  // Well below the limit (half of it) the tendons are not why the path stopped.
  if (worst.ratio < 0.5) return "";
  std::ostringstream hint;
  hint << std::setprecision(3) << "cosserat: hint: the tension path stopped at " << b.lambda_reached
       << " N added, where tendon \"" << worst.name << "\" pulls with tension x offset^2 / EI = "
       << worst.ratio << ", approaching the tendon strain law's limit (at 1 the inside of the "
       << "bend, where the tendon runs, shrinks to zero length; a helical tendon fails from about "
          "0.76). Tension alone buckles no rod: the path most likely ends at that limit, not at "
          "a buckle\n";
  return hint.str();
}

}  // namespace

Result RunBuckling(const io::Problem& problem, const RunOptions& run_options) {
  ColumnEnds ends = ColumnEnds::kClampedFree;
  ToColumnEnds(problem.boundary, &ends);  // UnsupportedFeatures let only these through
  BucklingOptions options;
  options.lambda_max = problem.buckling.max;
  options.solver = StaticOptions(problem);
  options.progress = run_options.progress;  // the load reached, of the search's maximum
  LoadPath path = MakePath(problem);
  const RodModel model = MakeModel(problem, &path);
  BucklingAnalysis analysis(model, problem.nodes, ends, problem.base, path, options);
  BucklingSummary b = analysis.FindCriticalLoad();
  const RodState* state = &analysis.state();
  std::unique_ptr<BucklingInPieces> in_pieces;
  const std::string pieces_note =
      SearchInPieces(problem, model, ends, path, options, &b, &state, &in_pieces);
  const double critical = ReportedLoad(problem, b.critical_load);
  const double reached = ReportedLoad(problem, b.lambda_reached);
  const bool actuation_load = path.has_actuation();
  const bool ok = b.status != BucklingStatus::kPathFailed;

  StaticShootingSummary statics;
  statics.status = ok ? SolveStatus::kConverged : SolveStatus::kLoadSteppingFailed;
  // A search that failed before any load has no equilibrium to measure (null, not 0).
  if (!ok && b.lambda_reached <= 0.0) statics.residual = NAN;
  statics.iterations = b.solves;  // the search's static solves
  statics.wall_time_s = b.wall_time_s;
  Result result;
  result.json = io::StaticResultToJson(statics, *state);
  detail::KeepStaticFrame(problem, *state, run_options, &result);
  nlohmann::ordered_json block;
  block["critical_load"] = NumberOrNull(critical);
  block["mode_s_max"] =
      b.found() ? nlohmann::ordered_json(b.mode.s_max_curvature) : nlohmann::ordered_json(nullptr);
  block["status"] = ToString(b.status);
  block["load"] = io::ToString(problem.buckling.load);
  if (actuation_load)
    block["direction"] = nullptr;
  else
    block["direction"] = {problem.buckling.direction.x(), problem.buckling.direction.y(),
                          problem.buckling.direction.z()};
  if (problem.buckling.load == io::BucklingLoad::kTendonTension) {
    nlohmann::ordered_json w = nlohmann::ordered_json::array();
    for (size_t i = 0; i < problem.rod.tendons.size(); ++i) w.push_back(path.tension_per_unit[i]);
    block["tension_per_unit"] = w;
  }
  block["boundary"] = ToString(ends);
  block["load_reached"] = reached;
  block["static_solves"] = b.solves;
  if (b.status == BucklingStatus::kPreloadPastCritical)
    block["preload_critical_fraction"] = b.preload_critical_fraction;
  if (b.found()) {
    nlohmann::ordered_json mode;
    mode["double"] = b.mode.double_root;
    mode["s"] = b.mode.s;
    auto rows = [](const std::vector<Vec3>& v) {
      nlohmann::ordered_json a = nlohmann::ordered_json::array();
      for (const Vec3& x : v) a.push_back({x.x(), x.y(), x.z()});
      return a;
    };
    mode["displacement"] = rows(b.mode.displacement_W);
    mode["curvature"] = rows(b.mode.curvature_B);
    block["mode"] = mode;
  }
  result.json["buckling"] = block;
  if (run_options.nodes_csv) result.nodes_csv = detail::NodesCsv(*state);

  result.log = SummaryLine(problem, ends, b) + pieces_note +
               (in_pieces ? "" : SingleShotHint(problem, b)) +
               detail::GuideTakesTipForceNote(problem, ends) +
               ImperfectionNote(problem, ends, b.status) +
               DirectionNote(problem, b.status) +
               BelowEulerNote(problem, ends, b.status) + FlutterNote(problem, b.status) +
               TendonLimitHint(problem, path, b) +
               CoarseGridNote(problem, b.found(), *state, kShootingBucklingGrid);
  result.converged = ok;
  return result;
}

Result RunQuatFdBuckling(const io::Problem& problem, const RunOptions& run_options) {
  quatfd::QuatFdOptions model_options;
  model_options.segments = problem.nodes - 1;
  model_options.base_end = quatfd::EndCondition::kClamped;
  QuatFdBucklingOptions options;
  options.lambda_max = problem.buckling.max;
  options.statics = QuatFdStaticOptions(problem);
  QuatFdBuckling analysis(problem.rod, problem.base, MakePath(problem), model_options, options);
  const QuatFdBucklingSummary b = analysis.FindCriticalLoad();
  const bool ok = b.status != BucklingStatus::kPathFailed;

  RodState state;
  analysis.model().ToRodState(analysis.q(), Eigen::VectorXd::Zero(analysis.model().size()), &state);
  StaticShootingSummary statics;
  statics.status = ok ? SolveStatus::kConverged : SolveStatus::kLoadSteppingFailed;
  statics.iterations = b.solves;  // the search's static solves
  statics.wall_time_s = b.wall_time_s;
  Result result;
  result.json = io::StaticResultToJson(statics, state);
  detail::KeepStaticFrame(problem, state, run_options, &result);
  nlohmann::ordered_json block;
  block["critical_load"] = NumberOrNull(b.critical_load);
  block["mode_s_max"] = NumberOrNull(b.mode_s_max);
  block["status"] = ToString(b.status);
  block["load"] = io::ToString(problem.buckling.load);
  block["direction"] = {problem.buckling.direction.x(), problem.buckling.direction.y(),
                        problem.buckling.direction.z()};
  block["boundary"] = "cantilever";
  block["formulation"] = "quaternion-fd";
  block["load_reached"] = b.lambda_reached;
  block["static_solves"] = b.solves;
  block["multiplicity"] = b.multiplicity;
  if (b.status == BucklingStatus::kPreloadPastCritical)
    block["preload_unstable_directions"] = b.preload_unstable_directions;
  result.json["buckling"] = block;
  if (run_options.nodes_csv) result.nodes_csv = detail::NodesCsv(state);

  std::ostringstream line;
  line << "cosserat: buckling " << ToString(b.status) << " (cantilever, quaternion-fd)";
  if (b.found())
    line << ", critical " << io::ToString(problem.buckling.load) << " " << std::setprecision(6)
         << b.critical_load << OnTopOfTheFilesLoad(problem) << ", mode bends most at s = "
         << b.mode_s_max << " m";
  else if (b.status == BucklingStatus::kPreloadPastCritical)
    line << ": the file's loads alone leave the equilibrium unstable ("
         << b.preload_unstable_directions
         << " unstable directions), so no load on top of them is its critical load (search from "
            "zero with them as the buckling load)";
  else
    line << ", load reached " << std::setprecision(6) << b.lambda_reached;
  line << ", " << b.solves << " static solves, " << std::setprecision(3) << b.wall_time_s * 1e3
       << " ms";
  result.log = line.str() + '\n' +
               ImperfectionNote(problem, ColumnEnds::kClampedFree, b.status) +
               DirectionNote(problem, b.status) +
               BelowEulerNote(problem, ColumnEnds::kClampedFree, b.status) +
               FlutterNote(problem, b.status) +
               CoarseGridNote(problem, b.found(), state, kQuatFdBucklingGrid);
  result.converged = ok;
  return result;
}

}  // namespace cosserat::run
