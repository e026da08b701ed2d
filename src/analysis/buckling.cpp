#include "cosserat/analysis/buckling.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "cosserat/strong/load_parameter.hpp"
#include "cosserat/strong/shooting_exponent.hpp"

namespace cosserat {

LoadPath LoadPath::TipForce(const Vec3& direction, LoadFrame frame) {
  LoadPath path;
  path.per_unit.tip_force = direction.normalized();
  path.per_unit.tip_force_frame = frame;
  path.fixed.tip_force_frame = frame;
  return path;
}

StaticLoads LoadPath::LoadsAt(double lambda) const {
  StaticLoads out = fixed;
  out.gravity_W += lambda * per_unit.gravity_W;
  out.distributed_force_W += lambda * per_unit.distributed_force_W;
  out.tip_force += lambda * per_unit.tip_force;
  out.tip_moment += lambda * per_unit.tip_moment;
  out.tip_force_frame = per_unit.tip_force_frame;
  out.tip_moment_frame = per_unit.tip_moment_frame;
  return out;
}

LoadPath LoadPath::PressureDrop(double initial_pressure, const StaticLoads& loads) {
  LoadPath path;
  path.fixed = loads;
  path.per_unit.tip_force_frame = loads.tip_force_frame;
  path.per_unit.tip_moment_frame = loads.tip_moment_frame;
  path.fixed_actuation.pressure = initial_pressure;
  path.pressure_per_unit = -1.0;
  return path;
}

Actuation LoadPath::ActuationAt(double lambda) const {
  Actuation out = fixed_actuation;
  for (int i = 0; i < Actuation::kMaxTendons; ++i)
    out.tendon_tension[i] += lambda * tension_per_unit[i];
  out.pressure += lambda * pressure_per_unit;
  return out;
}

bool LoadPath::has_actuation() const {
  if (pressure_per_unit != 0.0) return true;
  for (double t : tension_per_unit)
    if (t != 0.0) return true;
  return false;
}

bool BucklingOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (!(std::isfinite(lambda_max) && lambda_max > 0)) return fail("lambda_max must be positive");
  if (scan_steps < 2) return fail("scan_steps must be at least 2");
  if (!(lambda_tolerance > 0 && lambda_tolerance < 0.1))
    return fail("lambda_tolerance must be in (0, 0.1)");
  if (!(singular_threshold > 0 && singular_threshold < 1))
    return fail("singular_threshold must be in (0, 1)");
  if (!(max_shot_exponent > 0)) return fail("max_shot_exponent must be positive");
  return solver.IsValid(why);
}

const char* ToString(BucklingStatus status) {
  switch (status) {
    case BucklingStatus::kNotRun:
      return "not_run";
    case BucklingStatus::kFound:
      return "found";
    case BucklingStatus::kNotFound:
      return "not_found";
    case BucklingStatus::kPathFailed:
      return "path_failed";
    case BucklingStatus::kPreloadPastCritical:
      return "preload_past_critical";
  }
  return "unknown";
}

BucklingSummary FinishSearch(BucklingStatus status, std::chrono::steady_clock::time_point t0,
                             BucklingSummary* out) {
  out->status = status;
  out->wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return *out;
}

BucklingAnalysis::BucklingAnalysis(const RodModel& model, int num_nodes, ColumnEnds ends,
                                   const lie::SE3& base, const LoadPath& path,
                                   const BucklingOptions& options)
    : column_(model, num_nodes, ends, options.solver, path.ActuationAt(0.0)),
      model_(model),
      base_(base),
      path_(path),
      options_(options) {
  std::string why;
  if (!options_.IsValid(&why)) throw std::invalid_argument("BucklingOptions: " + why);
  // A falling pressure must stay >= 0 (the modulus laws are defined for p >= 0).
  const double p_end =
      path_.fixed_actuation.pressure + options_.lambda_max * path_.pressure_per_unit;
  if (!std::isfinite(path_.pressure_per_unit) || p_end < 0)
    throw std::invalid_argument(
        "BucklingOptions: lambda_max must keep the pressure >= 0 along the path (it reaches " +
        std::to_string(p_end) + " Pa)");
}

Vec6 BucklingAnalysis::ResidualAt(double lambda, const Vec6& u, Mat6* J, RodState* record,
                                   std::vector<ColumnSolver::StateTangent>* tangents) {
  if (path_.has_actuation() && lambda != applied_lambda_) {
    column_.SetActuation(path_.ActuationAt(lambda));
    applied_lambda_ = lambda;
  }
  return column_.Residual(base_, path_.LoadsAt(lambda), u, J, record, tangents);
}

ColumnSummary BucklingAnalysis::SolveAt(double lambda) {
  if (path_.has_actuation() && lambda != applied_lambda_) {
    column_.SetActuation(path_.ActuationAt(lambda));
    applied_lambda_ = lambda;
  }
  const Vec6 before = column_.unknowns();
  const RodState state_before = column_.state();  // a refused solve leaves the last one's
  ColumnSummary s = column_.Solve(base_, path_.LoadsAt(lambda));
  // Under tension the shot's Jacobi fields grow like exp(∫ sqrt(T/EI) ds): past the limit the
  // σ_min, det J and index read from them are rounding (a 300 m string hanging in mud, exponent
  // 47, "reached a critical point" under its own weight), so the solve counts as failed there.
  if (s.converged() &&
      SingleShootingExponent(model_, std::numeric_limits<double>::infinity(),
                             path_.ActuationAt(lambda), column_.state()) >
          options_.max_shot_exponent) {
    column_.set_unknowns(before);
    column_.set_state(state_before);
    beyond_single_shot_ = true;
    s.status = SolveStatus::kNonFinite;
  }
  return s;
}

namespace {

struct PathPoint {
  double lambda;
  Vec6 u;
  double sigma;
  double det_sign;
  int index = -1;  ///< unstable directions of the equilibrium (−1: not defined)
};

// The index rose from a to b: between them the path crossed at least one critical point, however
// many (two roots within a step leave det J's sign alone) and however multiple.
bool IndexRose(const PathPoint& a, const PathPoint& b) {
  return a.index >= 0 && b.index > a.index;
}

// Linear inter- or extrapolation of the unknowns to lambda.
Vec6 Interpolate(const PathPoint& a, const PathPoint& b, double lambda) {
  if (b.lambda == a.lambda) return b.u;
  return a.u + (b.u - a.u) * ((lambda - a.lambda) / (b.lambda - a.lambda));
}

/// How the scan along λ ended.
enum class ScanEnd {
  kIndexRise,   ///< the stability index rose between two path points
  kSignChange,  ///< det J changed sign between two path points
  kDip,         ///< σ_min dipped below singular_threshold σ_min(0)
  kNotFound,    ///< λ_max reached without either
  kPathFailed,  ///< a solve failed after 10 halvings of the step, or inside a dip
};

/// Golden-section search for the minimum of σ_min between the path points *a and *b. Returns
/// false when a solve fails; else [*a, *b] brackets the minimum to lambda_tolerance and *least
/// is the least point evaluated. evaluate(λ, guess, &point) solves at λ from a guess.
template <class Evaluate>
bool RefineDip(const Evaluate& evaluate, double lambda_tolerance, PathPoint* a, PathPoint* b,
               PathPoint* least) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  PathPoint c, d;
  bool fine = evaluate(b->lambda - g * (b->lambda - a->lambda),
                       Interpolate(*a, *b, b->lambda - g * (b->lambda - a->lambda)), &c) &&
              evaluate(a->lambda + g * (b->lambda - a->lambda),
                       Interpolate(*a, *b, a->lambda + g * (b->lambda - a->lambda)), &d);
  while (fine && b->lambda - a->lambda > lambda_tolerance * b->lambda) {
    if (c.sigma < d.sigma) {
      *b = d;
      d = c;
      const double l = b->lambda - g * (b->lambda - a->lambda);
      fine = evaluate(l, Interpolate(*a, *b, l), &c);
    } else {
      *a = c;
      c = d;
      const double l = a->lambda + g * (b->lambda - a->lambda);
      fine = evaluate(l, Interpolate(*a, *b, l), &d);
    }
  }
  if (fine) *least = c.sigma < d.sigma ? c : d;
  return fine;
}

/// The scan from pts (the path point at λ = 0) in steps of λ_max/scan_steps, each step halved
/// after a failed solve (up to 10 times in a row), the guess extrapolated from the last two
/// points; every point is recorded in out's scan. Stops at a sign change of det J ([*lo, *hi])
/// or at a local minimum of σ_min, refined by RefineDip, below singular_threshold sigma0 ([*lo,
/// *hi] and its least point *mid).
template <class Evaluate>
ScanEnd ScanPath(const Evaluate& evaluate, const BucklingOptions& options, double load_parameter,
                 double sigma0, std::vector<PathPoint>* pts, BucklingSummary* out,
                 PathPoint* lo, PathPoint* hi, PathPoint* mid) {
  // The first steps start short and double: a critical load inside the first step shows no dip
  // of σ_min, and a double root there no sign change of det J, so the scan found a later one (a
  // 5 m cantilever's 0.0155 N searched to 5 N in steps of 0.125 N; a cantilever searched to
  // 1e4 N from a first step of 3.9 N, 2.5 P_cr). So the first step is 64 times shorter than
  // λ_max/scan_steps, and no longer than λ of 1e-4 in StaticLoadParameter (load_parameter per
  // unit λ: P L²/EI for a tip force), far below any first critical load of the bare rod (2.47
  // for a tip force, 7.84 for gravity).
  const double h_nominal = options.lambda_max / options.scan_steps;
  double h = h_nominal / 64;
  if (load_parameter > 0) h = std::min(h, 1e-4 / load_parameter);
  int halvings = 0;
  while (pts->back().lambda < options.lambda_max) {
    const PathPoint& last = pts->back();
    const double lambda = std::min(options.lambda_max, last.lambda + h);
    if (!(lambda > last.lambda)) return ScanEnd::kPathFailed;  // a step below λ's resolution
    const Vec6 guess =
        pts->size() >= 2 ? Interpolate((*pts)[pts->size() - 2], last, lambda) : Vec6(last.u);
    PathPoint p;
    if (!evaluate(lambda, guess, &p)) {
      if (++halvings > 10) return ScanEnd::kPathFailed;
      h *= 0.5;
      continue;
    }
    halvings = 0;
    h = std::min(h_nominal, 2 * h);
    out->scan_lambda.push_back(p.lambda);
    out->scan_sigma_min.push_back(p.sigma);
    pts->push_back(p);
    if (options.progress) options.progress(p.lambda, options.lambda_max);
    const std::vector<PathPoint>& q = *pts;
    const size_t k = q.size() - 1;
    if (IndexRose(q[k - 1], q[k])) {
      *lo = q[k - 1];
      *hi = q[k];
      return ScanEnd::kIndexRise;
    }
    if (q[k].det_sign * q[k - 1].det_sign < 0) {
      *lo = q[k - 1];
      *hi = q[k];
      return ScanEnd::kSignChange;
    }
    if (k >= 2 && q[k - 1].sigma < q[k - 2].sigma && q[k - 1].sigma < q[k].sigma) {
      // A dip of σ_min: refine it by golden section and keep it if J is singular there.
      PathPoint a = q[k - 2], b = q[k];
      const double flanks = std::min(a.sigma, b.sigma);
      if (!RefineDip(evaluate, options.lambda_tolerance, &a, &b, mid)) return ScanEnd::kPathFailed;
      // Singular to rounding, or a V 100× below both its scan neighbours: an axial torque
      // couples the two bending planes into one complex condition (Greenhill's), whose root the
      // grid moves just off the real λ axis (σ_min 2.7e-6 σ_min(0) at 41 nodes, 8.6e-8 at 81:
      // O(h⁵)), where no regular equilibrium dips that far within one scan step.
      if (mid->sigma < options.singular_threshold * sigma0 || mid->sigma < 1e-2 * flanks) {
        *lo = a;
        *hi = b;
        return ScanEnd::kDip;
      }
    }
  }
  return ScanEnd::kNotFound;
}

/// Bisection of [*lo, *hi] down to lambda_tolerance on the sign of det J, or with by_index on
/// whether the index has risen above *lo's (the first critical point of the bracket, where det J
/// may keep its sign); false when a solve fails (*lo is then the last point below).
template <class Evaluate>
bool Bisect(const Evaluate& evaluate, double lambda_tolerance, bool by_index, PathPoint* lo,
            PathPoint* hi) {
  while (hi->lambda - lo->lambda > lambda_tolerance * hi->lambda) {
    const double l = 0.5 * (lo->lambda + hi->lambda);
    PathPoint p;
    if (!evaluate(l, Interpolate(*lo, *hi, l), &p)) return false;
    const bool past = by_index ? IndexRose(*lo, p) : p.det_sign * lo->det_sign < 0;
    (past ? *hi : *lo) = p;
  }
  return true;
}

/// The null vector of J from its SVD. For a double root any vector of the 2-D null space is a
/// mode; the one nearest a coordinate axis of the unknowns is taken, so the answer does not
/// depend on rounding.
Vec6 NullVector(const Eigen::JacobiSVD<Mat6>& svd, bool double_root) {
  Vec6 v = svd.matrixV().col(5);
  if (!double_root) return v;
  const Eigen::Matrix<double, 6, 2> N = svd.matrixV().rightCols<2>();
  int best = 0;
  for (int k = 1; k < 6; ++k)
    if (N.row(k).norm() > N.row(best).norm()) best = k;
  v = N * N.row(best).transpose();
  v.normalize();
  return v;
}

}  // namespace

void BucklingAnalysis::Singularity(double lambda, double* sigma_min, double* det_sign,
                                   int* index) {
  Mat6 J;
  RodState record;
  std::vector<ColumnSolver::StateTangent> tangents;
  ResidualAt(lambda, column_.unknowns(), &J, &record, &tangents);
  *index = column_.StabilityIndexFromShot(base_, path_.LoadsAt(lambda), column_.unknowns(),
                                          record, tangents);
  *sigma_min = Eigen::JacobiSVD<Mat6>(J).singularValues()(5);
  const double det = Eigen::PartialPivLU<Mat6>(J).determinant();
  *det_sign = det > 0 ? 1.0 : (det < 0 ? -1.0 : 0.0);
}

bool BucklingAnalysis::SolveFixedLoads(bool require_stable, int* solves) {
  // From the unloaded rod, with the fixed loads applied in 1, 4, 16 or 64 equal steps. A step too
  // large can land on another equilibrium (a pipe lying in a bore, loaded by its weight at once,
  // converged on an unstable one), which the stability index tells.
  bool ok = false;
  std::optional<Vec6> unstable;  // the first equilibrium reached that was not stable
  const LoadPath saved = path_;
  for (int pieces = 1; pieces <= 64 && !ok; pieces *= 4) {
    column_.set_unknowns(Vec6::Zero());
    ok = true;
    for (int k = 1; k <= pieces && ok; ++k) {
      path_.fixed = saved.fixed.Scaled(static_cast<double>(k) / pieces);  // frames kept
      ++*solves;
      ok = SolveAt(0.0).converged();
    }
    if (ok && require_stable) {
      double sigma, det_sign;
      int index;
      Singularity(0.0, &sigma, &det_sign, &index);
      if (index > 0 && !unstable) unstable = column_.unknowns();
      ok = index <= 0;  // stable, or not defined
    }
  }
  path_ = saved;
  if (ok || !unstable) return ok;
  column_.set_unknowns(*unstable);  // none stable: the first that converged, as without the check
  ++*solves;
  return SolveAt(0.0).converged();
}

void BucklingAnalysis::SetCriticalPoint(double lambda, const Vec6& guess, double sigma0,
                                        BucklingSummary* out) {
  lambda_cr_ = lambda;
  column_.set_unknowns(guess);
  ++out->solves;
  SolveAt(lambda_cr_);
  u_cr_ = column_.unknowns();
  Mat6 J;
  ResidualAt(lambda_cr_, u_cr_, &J);
  const Eigen::JacobiSVD<Mat6> svd(J, Eigen::ComputeFullV);
  const Vec6 sv = svd.singularValues();
  const bool double_root = sv(4) < std::sqrt(options_.singular_threshold) * sigma0;
  out->mode = ExtractMode(lambda_cr_, NullVector(svd, double_root), double_root);
  v_cr_ = out->mode.unknowns;
  out->critical_load = lambda_cr_;
  out->lambda_reached = lambda_cr_;
  out->sigma_min_ratio = sv(5) / sigma0;
  found_ = true;
}

BucklingSummary BucklingAnalysis::FindCriticalLoad() {
  const auto t0 = std::chrono::steady_clock::now();
  BucklingSummary out;
  found_ = false;
  beyond_single_shot_ = false;
  auto finish = [&](BucklingStatus status) {
    out.beyond_single_shot = status == BucklingStatus::kPathFailed && beyond_single_shot_;
    return FinishSearch(status, t0, &out);
  };

  if (path_.fixed != path_.fixed.Scaled(0.0)) {
    // A preload: the straight path under it may already have passed a critical point (a
    // column pressed by 8 Euler loads has; a scan on top of it found the third).
    const double fraction = PreloadCriticalFraction(&out);
    beyond_single_shot_ = false;  // the scan past the preload's own share says nothing of the path
    if (fraction < 1.0) {
      out.preload_critical_fraction = fraction;
      out.scan_lambda.clear();
      out.scan_sigma_min.clear();
      column_.set_unknowns(Vec6::Zero());
      SolveFixedLoads(false, &out.solves);  // state(): the (unstable) preloaded equilibrium
      return finish(BucklingStatus::kPreloadPastCritical);
    }
    out.scan_lambda.clear();
    out.scan_sigma_min.clear();
    column_.ForgetState();  // a failing solve below must not report the scan's last state
  }
  column_.set_unknowns(Vec6::Zero());
  if (!SolveFixedLoads(true, &out.solves)) return finish(BucklingStatus::kPathFailed);
  PathPoint cur{0.0, column_.unknowns(), 0, 0};
  Singularity(0.0, &cur.sigma, &cur.det_sign, &cur.index);
  const double sigma0 = cur.sigma;
  out.scan_lambda.push_back(0.0);
  out.scan_sigma_min.push_back(cur.sigma);
  std::vector<PathPoint> pts{cur};

  // Evaluates the path at lambda from a guess: solve, then σ_min, det sign and index.
  auto evaluate = [&](double lambda, const Vec6& guess, PathPoint* p) {
    column_.set_unknowns(guess);
    ++out.solves;
    if (!SolveAt(lambda).converged()) return false;
    p->lambda = lambda;
    p->u = column_.unknowns();
    Singularity(lambda, &p->sigma, &p->det_sign, &p->index);
    return true;
  };
  PathPoint lo{}, hi{}, mid{};
  const double unit = StaticLoadParameter(model_, path_.per_unit, path_.fixed_actuation);
  const ScanEnd end = ScanPath(evaluate, options_, unit, sigma0, &pts, &out, &lo, &hi, &mid);
  if (end == ScanEnd::kPathFailed || end == ScanEnd::kNotFound) {
    out.lambda_reached = pts.back().lambda;
    return finish(end == ScanEnd::kNotFound ? BucklingStatus::kNotFound
                                            : BucklingStatus::kPathFailed);
  }
  if (end == ScanEnd::kSignChange || end == ScanEnd::kIndexRise) {
    if (!Bisect(evaluate, options_.lambda_tolerance, end == ScanEnd::kIndexRise, &lo, &hi)) {
      out.lambda_reached = lo.lambda;
      return finish(BucklingStatus::kPathFailed);
    }
    mid = std::abs(lo.sigma) < std::abs(hi.sigma) ? lo : hi;
  }
  // The pre-buckled equilibrium at λ_cr, its null vector and the mode.
  SetCriticalPoint(mid.lambda, mid.u, sigma0, &out);
  return finish(BucklingStatus::kFound);
}

double BucklingAnalysis::PreloadCriticalFraction(BucklingSummary* out) {
  // The scan runs over μ, the fixed loads' share (Scaled keeps their frames), from the unloaded
  // rod.
  const LoadPath saved = path_;
  auto evaluate = [&](double mu, const Vec6& guess, PathPoint* p) {
    path_.fixed = saved.fixed.Scaled(mu);
    column_.set_unknowns(guess);
    ++out->solves;
    const bool ok = SolveAt(0.0).converged();
    if (ok) {
      p->lambda = mu;
      p->u = column_.unknowns();
      Singularity(0.0, &p->sigma, &p->det_sign, &p->index);
    }
    return ok;
  };
  // Scanned a quarter past the whole preload, so that a critical point just below it (1.01 P_E
  // pressing a column) has points on both sides to show as a dip.
  BucklingOptions shares = options_;
  shares.lambda_max = 1.25;
  shares.progress = nullptr;
  PathPoint start{};
  if (!evaluate(0.0, Vec6::Zero(), &start)) {
    path_ = saved;
    return NAN;
  }
  std::vector<PathPoint> pts{start};
  PathPoint lo{}, hi{}, mid{};
  const double unit = StaticLoadParameter(model_, saved.fixed, saved.fixed_actuation);
  const ScanEnd end = ScanPath(evaluate, shares, unit, start.sigma, &pts, out, &lo, &hi, &mid);
  double fraction = NAN;
  if (end == ScanEnd::kDip) fraction = mid.lambda;
  if (end == ScanEnd::kSignChange || end == ScanEnd::kIndexRise) {
    // Refined (to 1e-6 of the preload) only to tell a bracket that straddles the whole preload.
    if (Bisect(evaluate, 1e-6, end == ScanEnd::kIndexRise, &lo, &hi))
      fraction = 0.5 * (lo.lambda + hi.lambda);
  }
  path_ = saved;
  return fraction;
}

BucklingMode ModeFromPerturbation(const RodModel& model, const Actuation& act, const RodState& st,
                                  const std::vector<Eigen::Matrix<double, 18, 1>>& t,
                                  const Vec6& v, bool double_root) {
  BucklingMode mode;
  mode.double_root = double_root;
  const int n = static_cast<int>(t.size());
  mode.s = st.s;
  mode.displacement_W.resize(n);
  mode.rotation_B.resize(n);
  mode.curvature_B.resize(n);
  const double L = model.length;
  for (int i = 0; i < n; ++i) {
    const auto& ti = t[i];
    mode.displacement_W[i] = ti.segment<3>(0);
    Mat3 dR;
    for (int j = 0; j < 3; ++j) dR.col(j) = ti.segment<3>(3 + 3 * j);
    const Mat3 M = st.rotation_WB[i].transpose() * dR;  // (δθ)^ up to rounding
    mode.rotation_B[i] = 0.5 * Vec3(M(2, 1) - M(1, 2), M(0, 2) - M(2, 0), M(1, 0) - M(0, 1));
    Vec6 dW;
    dW << ti.segment<3>(12), ti.segment<3>(15);
    // Curvature from the compliance on either side of the node (a stiffness jump at a node
    // gives two values; the larger is kept).
    Vec3 best = Vec3::Zero();
    for (double side : {-1.0, 1.0}) {
      const double s = std::clamp(mode.s[i] + side * 1e-9 * L, 0.0, L);
      const Mat6 K = model.section->At(s, act).stiffness;
      const Vec3 dK = K.partialPivLu().solve(dW).head<3>();
      if (dK.head<2>().norm() >= best.head<2>().norm()) best = dK;
    }
    mode.curvature_B[i] = best;
  }
  // Scale: max |δp| = 1, the largest displacement component positive.
  double max_norm = 0, max_comp = 0;
  for (const Vec3& d : mode.displacement_W) {
    max_norm = std::max(max_norm, d.norm());
    for (int k = 0; k < 3; ++k)
      if (std::abs(d(k)) > std::abs(max_comp)) max_comp = d(k);
  }
  const double f = (max_comp < 0 ? -1.0 : 1.0) / (max_norm > 0 ? max_norm : 1.0);
  for (int i = 0; i < n; ++i) {
    mode.displacement_W[i] *= f;
    mode.rotation_B[i] *= f;
    mode.curvature_B[i] *= f;
  }
  mode.unknowns = (max_comp < 0 ? -1.0 : 1.0) * v;
  double kmax = 0;
  for (int i = 0; i < n; ++i) kmax = std::max(kmax, mode.curvature_B[i].head<2>().norm());
  for (int i = 0; i < n; ++i) {
    if (mode.curvature_B[i].head<2>().norm() >= (1 - 1e-6) * kmax) {
      mode.s_max_curvature = mode.s[i];
      break;
    }
  }
  return mode;
}

BucklingMode BucklingAnalysis::ExtractMode(double lambda, const Vec6& v, bool double_root) const {
  const StaticLoads loads = path_.LoadsAt(lambda);
  return ModeFromPerturbation(model_, path_.ActuationAt(lambda), column_.state(),
                              column_.Perturbation(base_, loads, u_cr_, v), v, double_root);
}

}  // namespace cosserat
