#include "cosserat/analysis/buckling_in_pieces.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "cosserat/strong/load_parameter.hpp"

namespace cosserat {

namespace {

StaticMultipleShootingOptions PiecesOptions(ColumnEnds ends, const BucklingOptions& options) {
  StaticMultipleShootingOptions o = MultipleShootingOptionsFor(ends);
  o.tolerance = options.solver.tolerance;
  o.max_load_increment = options.solver.max_load_increment;
  return o;
}

}  // namespace

BucklingInPieces::BucklingInPieces(const RodModel& model, int num_nodes, ColumnEnds ends,
                                   const lie::SE3& base, const LoadPath& path,
                                   const BucklingOptions& options)
    : model_(model),
      base_(base),
      path_(path),
      options_(options),
      column_(model, num_nodes, ends, options.solver),
      solver_(model, num_nodes, PiecesOptions(ends, options)) {
  std::string why;
  if (!options_.IsValid(&why)) throw std::invalid_argument("BucklingOptions: " + why);
  if (path_.has_actuation())
    throw std::invalid_argument(
        "BucklingInPieces: a tendon or pressure path varies the actuation, which multiple "
        "shooting does not take (BucklingAnalysis searches it)");
}

bool BucklingInPieces::SolveAt(const StaticLoads& loads, int* index, BucklingSummary* out) {
  ++out->solves;
  if (!solver_.Solve(base_, loads).converged()) return false;
  *index = column_.StabilityIndexInPieces(base_, loads, solver_.state(), solver_.pieces());
  return true;
}

template <class LoadsAt>
bool BucklingInPieces::Scan(const LoadsAt& loads_at, double t_max, double first_step,
                            double tolerance, int index0, double* lo, double* hi, bool* failed,
                            BucklingSummary* out) {
  // As BucklingAnalysis's scan: short first steps that double up to t_max / scan_steps, a failed
  // step halved up to 10 times in a row.
  const double h_nominal = t_max / options_.scan_steps;
  double t = 0.0, h = std::min(first_step, h_nominal);
  int halvings = 0;
  *failed = false;
  while (t < t_max) {
    const double next = std::min(t_max, t + h);
    if (!(next > t)) break;
    int index = -1;
    if (!SolveAt(loads_at(next), &index, out)) {
      if (++halvings > 10) break;
      h *= 0.5;
      continue;
    }
    if (index < 0) break;  // not defined here: nothing to scan on
    halvings = 0;
    out->scan_lambda.push_back(next);
    out->scan_sigma_min.push_back(NAN);
    if (options_.progress) options_.progress(next, t_max);
    if (index > index0) {
      // Bisection on whether the index has risen: the first critical point of [t, next]. Near
      // it the pieces' Jacobian turns singular, and a solve may fail: the bracket reached is
      // then the answer. The state at its upper end is kept (the pre-buckled equilibrium).
      double a = t, b = next;
      hi_state_ = solver_.state();
      hi_index_ = index;
      while (b - a > tolerance * b) {
        // The midpoint, or, where its solve fails (the root's singular Jacobian nearby), a
        // quarter of the way from either end.
        double m = 0.5 * (a + b);
        int im = -1;
        bool solved = SolveAt(loads_at(m), &im, out) && im >= 0;
        for (double share : {0.25, 0.75}) {
          if (solved) break;
          m = a + share * (b - a);
          solved = SolveAt(loads_at(m), &im, out) && im >= 0;
        }
        if (!solved) break;
        if (im > index0) {
          b = m;
          hi_state_ = solver_.state();
          hi_index_ = im;
        } else {
          a = m;
        }
      }
      *lo = a;
      *hi = b;
      return true;
    }
    t = next;
    h = std::min(h_nominal, 2 * h);
  }
  *failed = t < t_max;
  *lo = t;
  return false;
}

BucklingMode BucklingInPieces::ModeAt(const StaticLoads& loads, const RodState& state,
                                      bool double_root) const {
  const ColumnSolver::PiecewiseFields f =
      column_.FieldsInPieces(base_, loads, state, solver_.pieces());
  Mat6 J;
  column_.TipResidual(base_, loads, f.record, f.tangents.back(), &J);
  const Eigen::JacobiSVD<Mat6> svd(J, Eigen::ComputeFullV);
  // The null vector in the last piece's basis, carried back piece by piece to the unknowns.
  Vec6 c = svd.matrixV().col(5);
  const int n = static_cast<int>(f.tangents.size());
  std::vector<Eigen::Matrix<double, 18, 1>> t(n);
  for (int k = static_cast<int>(f.first_node.size()) - 1; k >= 0; --k) {
    const int first = f.first_node[k];
    const int end = k + 1 < static_cast<int>(f.first_node.size()) ? f.first_node[k + 1] : n;
    for (int i = first; i < end; ++i) t[i] = f.tangents[i] * c;
    c = f.basis_change[k] * c;
  }
  return ModeFromPerturbation(model_, Actuation{}, f.record, t, c.normalized(), double_root);
}

BucklingSummary BucklingInPieces::FindCriticalLoad() {
  const auto t0 = std::chrono::steady_clock::now();
  BucklingSummary out;
  found_ = false;
  auto finish = [&](BucklingStatus status) { return FinishSearch(status, t0, &out); };
  // The unloaded rod is stable (index 0); the preload, followed from it, must stay so.
  double lo = 0.0, hi = 0.0;
  bool failed = false;
  int index0 = 0;
  const StaticLoads none = path_.fixed.Scaled(0.0);
  if (!SolveAt(none, &index0, &out) || index0 != 0) return finish(BucklingStatus::kPathFailed);
  if (path_.fixed != none) {
    auto share = [&](double mu) { return path_.fixed.Scaled(mu); };
    if (Scan(share, 1.0, 1.0 / 64, 1e-6, 0, &lo, &hi, &failed, &out)) {
      out.preload_critical_fraction = 0.5 * (lo + hi);
      return finish(BucklingStatus::kPreloadPastCritical);
    }
    if (failed) return finish(BucklingStatus::kPathFailed);
    out.scan_lambda.clear();
    out.scan_sigma_min.clear();
    if (!SolveAt(path_.LoadsAt(0.0), &index0, &out) || index0 < 0)
      return finish(BucklingStatus::kPathFailed);
  }
  auto loads_at = [&](double lambda) { return path_.LoadsAt(lambda); };
  // The first step as BucklingAnalysis's: 1/64 of a scan step, and no more than 1e-4 in the
  // dimensionless load.
  const double unit = StaticLoadParameter(model_, path_.per_unit, path_.fixed_actuation);
  double first = options_.lambda_max / options_.scan_steps / 64;
  if (unit > 0) first = std::min(first, 1e-4 / unit);
  if (!Scan(loads_at, options_.lambda_max, first, options_.lambda_tolerance, index0, &lo, &hi,
            &failed, &out)) {
    out.lambda_reached = lo;
    return finish(failed ? BucklingStatus::kPathFailed : BucklingStatus::kNotFound);
  }
  // The pre-buckled equilibrium at λ_cr (the bracket's upper end: its index has risen by the
  // root's multiplicity), and the mode there.
  found_ = true;
  out.critical_load = hi;
  out.critical_load_bracket = hi - lo;
  out.lambda_reached = hi;
  out.mode = ModeAt(loads_at(hi), hi_state_, hi_index_ - index0 >= 2);
  return finish(BucklingStatus::kFound);
}

}  // namespace cosserat
