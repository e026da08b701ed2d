#include "cosserat/robots/eversion_robot.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "cosserat/loads/total_load.hpp"
#include "cosserat/rod/grid.hpp"
#include "cosserat/state/resampled_state.hpp"

namespace cosserat {
namespace {

constexpr double kPi = 3.14159265358979323846;

bool Finite(double x) { return std::isfinite(x); }

[[noreturn]] void Throw(const std::string& field, const std::string& what) {
  throw std::invalid_argument(field + ": " + what);
}

std::string Interval(const EversionBand& b) {
  std::ostringstream out;
  out << "[" << b.start << ", " << b.end << ")";
  return out.str();
}

}  // namespace

const char* ToString(KinkStatus status) {
  switch (status) {
    case KinkStatus::kNone:
      return "none";
    case KinkStatus::kWrinkled:
      return "wrinkled";
    case KinkStatus::kCollapsed:
      return "collapsed";
  }
  return "unknown";
}

void EversionRobotDesign::Validate() const {
  if (!(Finite(radius) && radius > 0)) Throw("radius", "must be finite and > 0 (m)");
  if (!(Finite(wall_thickness) && wall_thickness > 0))
    Throw("wall_thickness", "must be finite and > 0 (m)");
  if (!(wall_thickness < radius))
    Throw("wall_thickness", "must be smaller than the radius (thin-walled tube)");
  std::string why;
  if (!wall_modulus.IsValid(&why)) Throw("wall_modulus", why);
  if (!(wall_modulus.MinValue() > 0))
    Throw("wall_modulus", "E_eff(p) must be > 0 for every p >= 0");
  if (!(poisson_ratio > -1 && poisson_ratio <= 0.5))
    Throw("poisson_ratio", "must lie in (-1, 0.5]");
  if (!(Finite(wall_density) && wall_density >= 0))
    Throw("wall_density", "must be finite and >= 0 (kg/m^3)");
  for (double d : {damping.bending, damping.torsion, damping.shear, damping.extension})
    if (!(Finite(d) && d >= 0)) Throw("damping", "coefficients must be finite and >= 0");
  if (!(Finite(max_length) && max_length > 0)) Throw("max_length", "must be finite and > 0 (m)");
  if (!jamming.empty()) {
    const JammingSection probe(
        std::make_shared<InflatedTubeSection>(radius, wall_thickness, wall_modulus, poisson_ratio,
                                              wall_density),
        jamming);
    if (!probe.IsValid(max_length, &why)) Throw("jamming", why);
    for (std::size_t k = 0; k < jamming.size(); ++k)
      for (const EversionBand& b : bands)
        if (b.start < jamming[k].end && jamming[k].start < b.end)
          Throw("jamming[" + std::to_string(k) + "]", "overlaps a band");
  }
  if (!(base.R.allFinite() && base.p.allFinite() &&
        (base.R.transpose() * base.R - Mat3::Identity()).norm() < 1e-9 && base.R.determinant() > 0))
    Throw("base", "must be a finite pose with a proper rotation matrix");
  for (std::size_t k = 0; k < bands.size(); ++k) {
    const EversionBand& b = bands[k];
    const std::string field = "bands[" + std::to_string(k) + "]";
    if (!(Finite(b.start) && Finite(b.end) && b.start >= 0 && b.start < b.end &&
          b.end <= max_length))
      Throw(field, "must lie within [0, max_length] = [0, " + std::to_string(max_length) +
                       "] m with start < end, got " + Interval(b));
    if (!(b.diameter_ratio > 0 && b.diameter_ratio <= 1))
      Throw(field, "diameter_ratio must lie in (0, 1]");
    if (!(Finite(b.factor) && b.factor > 0)) Throw(field, "factor (alpha) must be > 0");
  }
  std::vector<std::size_t> order(bands.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return bands[a].start < bands[b].start; });
  for (std::size_t i = 1; i < order.size(); ++i) {
    const EversionBand& a = bands[order[i - 1]];
    const EversionBand& b = bands[order[i]];
    if (b.start < a.end)
      Throw("bands[" + std::to_string(order[i]) + "]",
            "overlaps bands[" + std::to_string(order[i - 1]) + "] (" + Interval(b) + " and " +
                Interval(a) + ")");
  }
  const InflatedTubeSection profile(radius, wall_thickness, wall_modulus, poisson_ratio,
                                    wall_density, bands, damping);
  if (!profile.IsValid(max_length, &why)) Throw("design", why);  // anything missed above
}

EversionRobot::EversionRobot(EversionRobotDesign design, double initial_length, double pressure,
                             EversionOptions options)
    : design_(std::move(design)), options_(std::move(options)) {
  design_.Validate();
  std::string why;
  if (!options_.solver.IsValid(&why)) Throw("options.solver", why);
  if (!(Finite(options_.nodes_per_metre) && options_.nodes_per_metre > 0))
    Throw("options.nodes_per_metre", "must be finite and > 0");
  if (options_.min_nodes < 3) Throw("options.min_nodes", "must be >= 3");
  // Before any grid is built: the node count of a longer robot need not even fit an int.
  if (design_.max_length > options_.MaxLength()) {
    std::ostringstream why_long;
    why_long << "a grid of " << options_.nodes_per_metre << " nodes per metre over "
             << design_.max_length << " m would exceed " << EversionOptions::kMaxNodes << " nodes";
    Throw("max_length", why_long.str());
  }
  if (!(Finite(initial_length) && initial_length > 0 && initial_length <= design_.max_length))
    Throw("length", "initial length must lie in (0, max_length]");
  full_profile_ = std::make_shared<InflatedTubeSection>(
      design_.radius, design_.wall_thickness, design_.wall_modulus, design_.poisson_ratio,
      design_.wall_density, design_.bands, design_.damping);
  length_ = initial_length;
  SetPressure(pressure);
}

void EversionRobot::SetPressure(double pressure) {
  if (!(Finite(pressure) && pressure >= 0))
    Throw("pressure", "must be finite and >= 0 (gauge, Pa)");
  if (pressure != pressure_) solver_stale_ = true;
  pressure_ = pressure;
}

void EversionRobot::SetTailTension(double tension) {
  if (!(Finite(tension) && tension >= 0)) Throw("tail_tension", "must be finite and >= 0 (N)");
  if (tension > 0 && design_.pressure_load != PressureLoadModel::kClosedVessel)
    Throw("tail_tension", "is modelled in the closed vessel (PressureLoadModel::kClosedVessel)");
  if (tension != tail_tension_) solver_stale_ = true;
  tail_tension_ = tension;
}

Actuation EversionRobot::actuation() const {
  Actuation a;
  a.pressure = pressure_;
  a.jamming_pressure = jamming_pressure_;
  return a;
}

void EversionRobot::SetJammingPressure(int k, double pressure) {
  const std::string field = "jamming_pressure[" + std::to_string(k) + "]";
  if (k < 0 || k >= static_cast<int>(design_.jamming.size()))
    Throw(field, "no such jamming segment (the design has " +
                     std::to_string(design_.jamming.size()) + ")");
  if (!(Finite(pressure) && pressure >= 0)) Throw(field, "must be finite and >= 0 (Pa)");
  if (pressure != jamming_pressure_[k]) solver_stale_ = true;
  jamming_pressure_[k] = pressure;
}

int EversionRobot::NodesAt(double length) const {
  int bands = 0;
  for (const EversionBand& b : design_.bands)
    if (b.start < length * (1.0 - 1e-12)) ++bands;
  for (const JammingSegment& j : design_.jamming)
    if (j.start < length * (1.0 - 1e-12)) ++bands;  // its ends are nodes too
  const int base = std::max(options_.min_nodes,
                            static_cast<int>(std::ceil(length * options_.nodes_per_metre)) + 1);
  return base + 2 * bands;
}

EversionRobotDesign DesignFromTube(const InflatedTubeSection& tube, double max_length,
                                   const lie::SE3& base) {
  EversionRobotDesign design;
  design.radius = tube.radius();
  design.wall_thickness = tube.wall_thickness();
  design.wall_modulus = tube.wall_modulus();
  design.poisson_ratio = tube.poisson_ratio();
  design.wall_density = tube.density();
  design.damping = tube.damping();
  design.bands = tube.constrictions();
  design.max_length = max_length;
  design.base = base;
  return design;
}

RodModel EversionRobot::ModelAt(double length) const {
  if (!(Finite(length) && length > 0 && length <= design_.max_length))
    Throw("length",
          "must lie in (0, max_length] = (0, " + std::to_string(design_.max_length) + "] m");
  std::vector<EversionBand> everted;
  for (const EversionBand& b : design_.bands) {
    if (!(b.start < length * (1.0 - 1e-12))) continue;  // not everted yet
    EversionBand c = b;
    c.end = std::min(b.end, length);
    everted.push_back(c);
  }
  auto profile = std::make_shared<InflatedTubeSection>(
      design_.radius, design_.wall_thickness, design_.wall_modulus, design_.poisson_ratio,
      design_.wall_density, std::move(everted), design_.damping);
  RodModel model;
  model.length = length;
  model.section = profile;
  std::vector<JammingSegment> jammed;  // the everted prefix of the (sorted) list keeps its indices
  for (const JammingSegment& j : design_.jamming) {
    if (!(j.start < length * (1.0 - 1e-12))) break;
    JammingSegment c = j;
    c.end = std::min(j.end, length);
    jammed.push_back(c);
  }
  if (!jammed.empty()) model.section = std::make_shared<JammingSection>(profile, std::move(jammed));
  if (design_.pressure_load == PressureLoadModel::kClosedVessel &&
      (pressure_ > 0 || tail_tension_ > 0)) {
    // The wall carries the tension p A(s) of the closed vessel less the tail's T (which runs
    // along the axis and bends nothing), and its hoop stress p r/t shortens it by ν p r/(E t)
    // (thin isotropic wall): N_wall = EA ε + 2ν p A, so the rest stretch
    // ((1 − 2ν) p A − T) / EA on top of the straight rest strain makes the solver's wrench the
    // net wrench of wall, air and tail.
    const Actuation act = actuation();
    const double p = pressure_, nu = profile->poisson_ratio(), tail = tail_tension_;
    model.rest_strain = [profile, act, p, nu, tail](double s) {
      Vec6 xi = StraightRestStrain();
      const double r = profile->RadiusAt(s);
      xi(5) += ((1.0 - 2.0 * nu) * p * kPi * r * r - tail) / profile->At(s, act).stiffness(5, 5);
      return xi;
    };
  }
  return model;
}

StaticLoads EversionRobot::SolverLoads(const StaticLoads& external, double length) const {
  StaticLoads loads = external;
  if (design_.pressure_load != PressureLoadModel::kTipFollowerOnly) return loads;
  if (loads.tip_force_frame == LoadFrame::kWorld) {
    if (loads.tip_force.squaredNorm() != 0.0)
      Throw("loads.tip_force",
            "the kTipFollowerOnly pressure model adds a body-frame follower force; give the "
            "external tip force in the body frame too");
    loads.tip_force_frame = LoadFrame::kBody;
  }
  const double r = full_profile_->RadiusAt(std::max(0.0, length * (1.0 - 1e-12)));
  loads.tip_force.z() += pressure_ * kPi * r * r;
  return loads;
}

Vec6 EversionRobot::PredictBaseWrench(double length, const StaticLoads& loads) const {
  // W(0) in the world frame is the resultant of the loads on the body, moment about p(0).
  const RodState& st = state();
  const Vec3& p0 = st.position_W.front();
  const Mat3& R0 = st.rotation_WB.front();
  const Vec3& tip = st.tip_position_W();
  const Mat3& R_tip = st.tip_rotation_WB();
  const double dL = length - solver_length_;
  const Vec3 step = R_tip.col(2) * dL;  // the new (or removed) material along the tip tangent
  const double s_mid = std::min(std::max(0.0, solver_length_ + 0.5 * dL), design_.max_length);
  const SectionProperties grown = full_profile_->At(s_mid, actuation());
  const Vec3 dF =
      TotalDistributedForce_W(loads, {s_mid, 1.0, grown.mass(5, 5), grown.outer_diameter}) * dL;
  const SplitWrench tip_wrench = TotalTipWrench(loads);
  const Vec3 tip_force_W = tip_wrench.dead_W.tail<3>() + R_tip * tip_wrench.follower_B.tail<3>();
  Vec6 W;
  W.head<3>() = R0 * last_base_wrench_.head<3>() + (tip + 0.5 * step - p0).cross(dF) +
                step.cross(tip_force_W);
  W.tail<3>() = R0 * last_base_wrench_.tail<3>() + dF;
  Vec6 W_B;
  W_B.head<3>() = R0.transpose() * W.head<3>();
  W_B.tail<3>() = R0.transpose() * W.tail<3>();
  return W_B;
}

void EversionRobot::RebuildSolver(double length) {
  solver_ = std::make_unique<StaticShootingSolver>(ModelAt(length), NodesAt(length),
                                                   options_.solver, actuation());
  solver_length_ = length;
  solver_stale_ = false;
}

EversionSolveSummary EversionRobot::Solve(double length, const StaticLoads& loads) {
  if (!(Finite(length) && length > 0 && length <= design_.max_length))
    Throw("length",
          "must lie in (0, max_length] = (0, " + std::to_string(design_.max_length) + "] m");
  std::string why;
  if (!loads.IsValid(&why)) Throw("loads", why);
  const StaticLoads solver_loads = SolverLoads(loads, length);
  // Pressed on a surface at the last solve: the contact threshold for pieces (a vine beside a
  // wall it does not touch keeps the single shot and its stability index).
  bool pressed = false;
  for (int k = 0; have_solution_ && k < solver_loads.contact.count; ++k)
    pressed = pressed || PressesOn(solver_loads.contact.surface[k], state(),
                                   [this](double s) { return RadiusAt(s); });

  bool seeded = false;
  if (solver_stale_ || length != solver_length_) {
    // Guess: the previous equilibrium (another length or pressure), plus, for a new length, the
    // base wrench of the material added (or removed) at the tip, laid along the old tip tangent.
    Vec6 seed = last_base_wrench_;
    if (have_solution_ && solver_ && length != solver_length_)
      seed = PredictBaseWrench(length, solver_loads);
    RebuildSolver(length);
    if (have_solution_) {
      solver_->WarmStartFrom(design_.base, solver_loads, seed);
      seeded = true;
    }
  }
  length_ = length;
  solved_pressure_ = pressure_;
  solved_tail_tension_ = tail_tension_;

  EversionSolveSummary out;
  out.length = length;
  // Pieces first where the last solve needed them (the body a little longer needs them too),
  // from its shape, and where a single shot's exponent passes options.pieces_above_exponent (10,
  // as for a plain rod; 6 where the last solve pressed on a surface): a 1.2 m tube on a floor
  // (βL = 10.9) took 1 300 Newton iterations in one shot per growth step, 2 m 10 000.
  const bool last_in_pieces = in_pieces_;
  const double pieces_above =
      pressed ? options_.pieces_on_contact_above_exponent : options_.pieces_above_exponent;
  const bool beyond_one_shot =
      StaticShootingExponent(ModelAt(length), solver_loads, actuation()) > pieces_above;
  in_pieces_ = false;
  if (last_in_pieces) SolveInPieces(length, solver_loads, true, &out.solve);  // from the last
  if (!in_pieces_ && beyond_one_shot) SolveInPieces(length, solver_loads, false, &out.solve);
  if (!in_pieces_) {
    const StaticShootingSummary failed_in_pieces = out.solve;  // the work of pieces that failed
    out.solve = solver_->Solve(design_.base, solver_loads);
    out.solve.CountWorkOf(failed_in_pieces);
    if (!out.solve.converged() && (seeded || out.solve.warm_started)) {
      const StaticShootingSummary warm = out.solve;
      solver_->ResetWarmStart();
      out.solve = solver_->Solve(design_.base, solver_loads);
      out.solve.iterations += warm.iterations;
      out.solve.shots += warm.shots;
      out.solve.wall_time_s += warm.wall_time_s;
    }
    out.solve.warm_started = out.solve.warm_started || seeded;
    if (!out.solve.converged() && !beyond_one_shot)  // else tried from the unloaded body already
      SolveInPieces(length, solver_loads, false, &out.solve);
  }
  if (out.solve.converged()) {
    have_solution_ = true;
    last_base_wrench_ = in_pieces_ ? state().wrench_B.front() : solver_->base_wrench_B();
    out.kink = CheckKink();
  }
  return out;
}

void EversionRobot::SolveInPieces(double length, const StaticLoads& solver_loads, bool from_last,
                                  StaticShootingSummary* summary) {
  // One shot amplifies the error of its base unknowns by e^{βL} along a floor's foundation
  // (β = (k/4EI)^¼; a 2 m tube on k = 1e4 N/m² failed its load steps), which multiple shooting
  // cuts into pieces chosen from that exponent, as for a plain rod. No stability index there.
  StaticMultipleShootingOptions options;
  options.tolerance = options_.solver.tolerance;
  const RodModel model = ModelAt(length);
  const int nodes = NodesAt(length);
  // A body a growth step longer (or at another pressure) lies close to the last one: Newton from
  // that shape, grown straight along its tip tangent, rather than the loads followed again from
  // the unloaded body at every step.
  if (from_last && pieces_) {
    const RodState guess = ResampledState(pieces_->state(), ModelGrid(model, nodes));
    pieces_ = std::make_unique<StaticMultipleShootingSolver>(model, nodes, options, actuation());
    StaticShootingSummary warm = pieces_->SolveFrom(design_.base, solver_loads, guess);
    warm.warm_started = true;
    *summary = warm;
    in_pieces_ = warm.converged();
    return;  // else pieces from the unloaded body, and the single shot
  }
  pieces_ = std::make_unique<StaticMultipleShootingSolver>(model, nodes, options, actuation());
  StaticShootingSummary in_pieces = pieces_->Solve(design_.base, solver_loads);
  if (!in_pieces.converged()) {  // the single shot's summary says why; the work counts
    summary->CountWorkOf(in_pieces);
    return;
  }
  in_pieces.CountWorkOf(*summary);
  *summary = in_pieces;
  in_pieces_ = true;
}

GrowthSummary EversionRobot::Grow(double target_length, int steps, const StaticLoads& loads,
                                  const StepCallback& on_step) {
  if (!(Finite(target_length) && target_length > 0 && target_length <= design_.max_length))
    Throw("target_length", "must lie in (0, max_length]");
  if (steps < 1) Throw("steps", "must be >= 1");
  GrowthSummary out;
  const double L0 = length_;
  for (int k = 1; k <= steps; ++k) {
    const double L = k == steps ? target_length : L0 + (target_length - L0) * k / steps;
    const EversionSolveSummary step = Solve(L, loads);
    StaticShootingSummary last = step.solve;
    last.CountWorkOf(out.last_solve);
    out.last_solve = last;
    if (!step.solve.converged()) {
      out.status = step.solve.status;
      return out;
    }
    out.steps = k;
    out.length = L;
    if (step.kink.kinked() && out.first_kink_step < 0) {
      out.first_kink_step = k;
      out.first_kink_length = L;
    }
    if (step.kink.max_ratio > out.worst_kink.max_ratio) out.worst_kink = step.kink;
    if (on_step) on_step(k, step, *this);
  }
  out.status = SolveStatus::kConverged;
  return out;
}

const RodState& EversionRobot::state() const {
  if (!solver_) throw std::logic_error("EversionRobot::state(): no solve has been run");
  return in_pieces_ ? pieces_->state() : solver_->state();
}

KinkReport EversionRobot::CheckKink() const {
  const RodState& st = state();
  KinkReport rep;
  const double L = solver_length_;
  const double delta = 1e-9 * L;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // The membrane stays taut while its least principal stress resultant is positive everywhere
  // round the section: N_x N_θ > N_xθ² with, on the compressed side, N_x = N/(2πr) − M/(πr²)
  // (N the wall's axial force, WallTension; M the bending moment), the hoop N_θ = p r and the
  // shear N_xθ = T/(2πr²) of the torque T. Scaling M and T by 1/ρ to the onset gives
  // a ρ² − b ρ − c = 0, a = N p/(2π), b = M p/(π r), c = T²/(4π² r⁴): without torque
  // ρ = M/M_w, M_w = N r/2 (π p r³/2 from inflation alone: Comer & Levy 1963); without bending
  // ρ = T/T_w, T_w = √2 π p r³ at N = pπr². A wall with no axial tension left (pushed slack,
  // or uninflated and not pulled: N ≤ 0) carries no compression and is collapsed (ρ = ∞), and
  // so is an uninflated one (p = 0, no hoop tension) under a torque; an uninflated wall pulled
  // taut keeps M_w = N r/2, the limit of p → 0.
  auto ratio_at = [&](int i, double r, double* mw) {
    const double N = WallTensionAt(i, r), p = solved_pressure_;
    const double M = st.wrench_B[i].head<2>().norm(), T = std::abs(st.wrench_B[i](2));
    *mw = std::max(0.0, 0.5 * N * r);
    if (!(N > 0.0)) return kInf;
    if (T == 0.0) return M / *mw;
    if (!(p > 0.0)) return kInf;
    const double a = N * p / (2 * kPi), b = M * p / (kPi * r);
    const double c = T * T / (4 * kPi * kPi * std::pow(r, 4));
    return (b + std::sqrt(b * b + 4 * a * c)) / (2 * a);
  };
  for (int i = 0; i < st.size(); ++i) {
    const double s = st.s[i];
    // At a band end the radius jumps: the side nearer wrinkling governs.
    double ratio = -1.0, mw = kInf;
    for (const int side : {-1, 1}) {
      if (side < 0 ? !(s > 0) : !(s < L)) continue;  // the sides on the body
      double side_mw = 0.0;
      const double side_ratio = ratio_at(i, RadiusAt(std::max(0.0, s + side * delta)), &side_mw);
      if (side_ratio > ratio) ratio = side_ratio, mw = side_mw;
    }
    ratio = std::max(ratio, 0.0);
    if (ratio >= 1.0 && rep.first_kink_s < 0) rep.first_kink_s = s;
    if (ratio > rep.max_ratio || i == 0) {
      rep.max_ratio = ratio;
      rep.s_max = s;
      rep.moment = st.wrench_B[i].head<2>().norm();
      rep.torque = std::abs(st.wrench_B[i](2));
      rep.wrinkling_moment = mw;
    }
  }
  // M_c = 2 M_w at the same radius (Comer & Levy), so the ratio classifies both limits.
  rep.status = rep.max_ratio >= 2.0   ? KinkStatus::kCollapsed
               : rep.max_ratio >= 1.0 ? KinkStatus::kWrinkled
                                      : KinkStatus::kNone;
  return rep;
}

double EversionRobot::BendingStiffnessAt(double s) const {
  double EI = full_profile_->BendingStiffnessAt(s, actuation());
  for (std::size_t k = 0; k < design_.jamming.size(); ++k) {
    const JammingSegment& j = design_.jamming[k];
    if (s >= j.start && s < j.end) EI += j.layer_modulus(jamming_pressure_[k]) * j.layer_I;
  }
  return EI;
}

double EversionRobot::AxialStiffness() const {
  return design_.wall_modulus(pressure_) * 2.0 * kPi * design_.radius * design_.wall_thickness;
}

double EversionRobot::WrinklingMomentAt(double s) const {
  return InflatedWrinklingMoment(pressure_, RadiusAt(s));
}

double EversionRobot::TipForce() const {
  const double r = RadiusAt(std::max(0.0, length_ * (1.0 - 1e-12)));
  return pressure_ * kPi * r * r;
}

double EversionRobot::FreeAxialStrain() const {
  // The closed vessel's hoop stress shortens the wall by ν p r/(E t); a tip force alone does not.
  const double hoop = design_.pressure_load == PressureLoadModel::kClosedVessel
                          ? 2.0 * full_profile_->poisson_ratio()
                          : 0.0;
  return ((1.0 - hoop) * pressure_ * kPi * design_.radius * design_.radius - tail_tension_) /
         AxialStiffness();
}

double EversionRobot::WallTension(int node) const {
  const RodState& st = state();
  if (node < 0 || node >= st.size()) throw std::out_of_range("WallTension: node out of range");
  const double s = st.s[node];
  return WallTensionAt(node, RadiusAt(s < solver_length_ ? s : std::max(0.0, s * (1.0 - 1e-12))));
}

double EversionRobot::WallTensionAt(int node, double r) const {
  double n3 = state().wrench_B[node](5);  // N
  if (design_.pressure_load == PressureLoadModel::kClosedVessel)
    n3 += solved_pressure_ * kPi * r * r - solved_tail_tension_;
  return n3;
}

}  // namespace cosserat
