#include "cosserat/analysis/quatfd_buckling.hpp"

#include "banded_inertia.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace cosserat {

namespace {

using Layout = quatfd::QuatFdLayout;

bool IsFollower(const StaticLoads& loads) {
  return (loads.tip_force_frame == LoadFrame::kBody && loads.tip_force.any()) ||
         (loads.tip_moment_frame == LoadFrame::kBody && loads.tip_moment.any());
}

}  // namespace

bool QuatFdBucklingOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (!(std::isfinite(lambda_max) && lambda_max > 0)) return fail("lambda_max: expected > 0");
  if (scan_steps < 2) return fail("scan_steps: expected at least 2");
  if (!(lambda_tolerance > 0 && lambda_tolerance < 0.1))
    return fail("lambda_tolerance: expected in (0, 0.1)");
  if (!(fd_step > 0 && fd_step <= 1e-2)) return fail("fd_step: expected in (0, 1e-2]");
  if (!(max_turn > 0)) return fail("max_turn: expected > 0");
  return statics.IsValid(why);
}

QuatFdBuckling::QuatFdBuckling(const RodModel& rod, const lie::SE3& base, const LoadPath& path,
                               const quatfd::QuatFdOptions& model_options,
                               const QuatFdBucklingOptions& options)
    : model_(rod, base, model_options, path.fixed_actuation), path_(path), options_(options) {
  std::string why;
  if (!options_.IsValid(&why)) throw std::invalid_argument("QuatFdBucklingOptions: " + why);
  if (model_options.base_end != quatfd::EndCondition::kClamped)
    throw std::invalid_argument(
        "base_end: quaternion-FD buckling needs a clamped base (the model's tip is free, and a "
        "pinned-free rod is a mechanism)");
  // Added mass is inertia: it scales accelerations, not the static stiffness, which the model's
  // ∂(acceleration)/∂q times the structural mass alone recovers.
  path_.fixed.fluid.added_mass = 0.0;
  path_.per_unit.fluid.added_mass = 0.0;
  const StaticLoads probe = path_.LoadsAt(1.0);
  if (IsFollower(probe) || IsFollower(path_.fixed))
    throw std::invalid_argument(
        std::string(probe.tip_force_frame == LoadFrame::kBody ? "tip_force_frame"
                                                              : "tip_moment_frame") +
        ": follower (body-frame) tip loads are not conservative; the static stiffness says "
        "nothing about their stability (flutter)");
  if (path_.has_actuation())
    throw std::invalid_argument(
        "load path: tendon tension and pressure paths are not supported on the quaternion-FD "
        "model (use the SE(3) shooting analysis)");
  const int N = model_.layout().segments;
  for (int n = 0; n <= N; ++n)
    if (!model_.IsFixed(Layout::X(n))) free_vertices_.push_back(n);
  zero_v_ = Eigen::VectorXd::Zero(model_.size());
  forces_plus_.resize(model_.size());
  forces_minus_.resize(model_.size());
  q_.resize(model_.size());
  Eigen::VectorXd v(model_.size());
  model_.RestState(q_, v);
}

bool QuatFdBuckling::SolveAt(double lambda, const Eigen::VectorXd& start, Eigen::VectorXd* q,
                             bool on_path) {
  *q = start;
  ++solves_;
  if (!quatfd::SolveStatics(&model_, path_.LoadsAt(lambda), *q, options_.statics).converged())
    return false;
  if (!on_path) return true;
  // An equilibrium that no segment turns to by less than max_turn from the start is another
  // branch, not the next point of the path (a rod bent by a lateral preload, jumping to its
  // mirror image near the Euler load): refused, so that the step is halved.
  double turn = 0.0;
  for (int seg = 0; seg < model_.layout().segments; ++seg) {
    const Vec4 a = start.segment<4>(Layout::P(seg)), b = q->segment<4>(Layout::P(seg));
    const double c = std::min(1.0, std::abs(a.dot(b)) / (a.norm() * b.norm()));
    turn = std::max(turn, 2.0 * std::acos(c));
  }
  return turn <= options_.max_turn;
}


Eigen::MatrixXd QuatFdBuckling::StiffnessFiniteDifference(const Eigen::VectorXd& q) {
  const int N = model_.layout().segments;
  const int nv = static_cast<int>(free_vertices_.size());
  const int m = 3 * nv + 3 * N;
  const double L = model_.length(), h = options_.fd_step;
  // G' = [L F(free vertices); τ(segments)], paired with [δx/L; δθ].
  auto gather = [&](const Eigen::VectorXd& f, Eigen::Ref<Eigen::VectorXd> g) {
    for (int a = 0; a < nv; ++a)
      g.segment<3>(3 * a) = L * f.segment<3>(Layout::X(free_vertices_[a]));
    for (int s = 0; s < N; ++s) g.segment<3>(3 * nv + 3 * s) = f.segment<3>(Layout::P(s) + 1);
  };
  // The retraction of q along tangent coordinate j by t.
  Eigen::VectorXd qt(q.size());
  auto retract = [&](int j, double t) {
    qt = q;
    if (j < 3 * nv) {
      qt[Layout::X(free_vertices_[j / 3]) + j % 3] += t * L;
    } else {
      const int s = (j - 3 * nv) / 3, k = (j - 3 * nv) % 3;
      Vec4 d(std::cos(0.5 * t), 0, 0, 0);
      d[1 + k] = std::sin(0.5 * t);
      const Vec4 p = q.segment<4>(Layout::P(s));
      qt.segment<4>(Layout::P(s)) = lie::QuatMultiply<double>(p, d);
    }
  };
  Eigen::MatrixXd H(m, m);
  Eigen::VectorXd gp(m), gm(m);
  for (int j = 0; j < m; ++j) {
    retract(j, h);
    model_.Forces(qt, zero_v_, forces_plus_);
    retract(j, -h);
    model_.Forces(qt, zero_v_, forces_minus_);
    gather(forces_plus_, gp);
    gather(forces_minus_, gm);
    H.col(j) = -(gp - gm) / (2 * h * model_.moment_scale());
  }
  return H;
}

Eigen::MatrixXd QuatFdBuckling::StiffnessAnalytic(const Eigen::VectorXd& q) {
  return Eigen::MatrixXd(StiffnessAnalyticSparse(q));
}

Eigen::MatrixXd QuatFdBuckling::Stiffness(double lambda, const Eigen::VectorXd& q,
                                          bool finite_difference) {
  model_.set_loads(path_.LoadsAt(lambda));
  return finite_difference ? StiffnessFiniteDifference(q) : StiffnessAnalytic(q);
}

Eigen::VectorXd QuatFdBuckling::StiffnessEigenvalues(double lambda, const Eigen::VectorXd& q,
                                                     Eigen::MatrixXd* vectors) {
  const Eigen::MatrixXd H = Stiffness(lambda, q, options_.finite_difference_stiffness);
  const double size = H.cwiseAbs().maxCoeff();
  asymmetry_ = size > 0 ? (H - H.transpose()).cwiseAbs().maxCoeff() / size : 0.0;
  const Eigen::MatrixXd Hs = 0.5 * (H + H.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(
      Hs, vectors ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly);
  if (vectors) *vectors = eig.eigenvectors();
  return eig.eigenvalues();
}

int QuatFdBuckling::StiffnessEigenvaluesBelow(double lambda, const Eigen::VectorXd& q,
                                              double below) {
  if (options_.finite_difference_stiffness) {  // the cross-check: dense by construction
    const Eigen::VectorXd e = StiffnessEigenvalues(lambda, q);
    return static_cast<int>((e.array() < -below).count());
  }
  model_.set_loads(path_.LoadsAt(lambda));
  const Eigen::SparseMatrix<double> H = StiffnessAnalyticSparse(q);
  const int m = static_cast<int>(H.rows());
  // The tangent coordinates (free vertices' first, then segments') along the rod, where the
  // stiffness is banded.
  const int N = model_.layout().segments, nv = static_cast<int>(free_vertices_.size());
  std::vector<int> vertex_column(N + 1, -1), segment_column(N);
  for (int a = 0; a < nv; ++a) vertex_column[free_vertices_[a]] = 3 * a;
  for (int s = 0; s < N; ++s) segment_column[s] = 3 * nv + 3 * s;
  const std::vector<int> order = detail::AlongTheRod(vertex_column, segment_column, m);
  // The symmetric part ½ (H + Hᵀ) in that order, and |H − Hᵀ| / |H|.
  const Eigen::SparseMatrix<double> Ht = H.transpose();
  const Eigen::SparseMatrix<double> sym = 0.5 * (H + Ht), skew = H - Ht;
  double size = 0.0, asymmetry = 0.0;
  for (int j = 0; j < m; ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(H, j); it; ++it)
      size = std::max(size, std::abs(it.value()));
    for (Eigen::SparseMatrix<double>::InnerIterator it(skew, j); it; ++it)
      asymmetry = std::max(asymmetry, std::abs(it.value()));
  }
  asymmetry_ = size > 0 ? asymmetry / size : 0.0;
  const detail::SymmetricBand band = detail::BandInOrder(sym, order);
  const int count = detail::CountEigenvaluesBelow(band, below);
  if (count >= 0 || m > kMaxDenseStiffness) return count;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Eigen::MatrixXd(sym),
                                                           Eigen::EigenvaluesOnly);
  return static_cast<int>((eig.eigenvalues().array() < -below).count());
}

/// The last stable and the first unstable point of the path: λ, the least eigenvalue μ of the
/// stiffness there, the equilibrium on the stable side and how many eigenvalues are near zero on
/// the unstable side (|μ| < 1e-4 |μ(0)|).
struct QuatFdBuckling::Bracket {
  double lo = 0, mu_lo = NAN, hi = NAN, mu_hi = NAN;
  int multiplicity = 0;
  double mu0 = NAN;  ///< μ at λ = 0
  Eigen::VectorXd q_lo;
  int NearZero(const Eigen::VectorXd& e) const {
    return static_cast<int>((e.array().abs() < 1e-4 * std::abs(mu0)).count());
  }
};

void QuatFdBuckling::RefineBracket(Bracket* b) {
  // Illinois regula falsi on μ(λ), from the stable side (every solve starts at the last stable
  // equilibrium, so it stays on the pre-buckled branch).
  Eigen::VectorXd q_try(model_.size());
  int side = 0;
  for (int it = 0; it < 100 && b->hi - b->lo > options_.lambda_tolerance * b->hi; ++it) {
    double c = (b->lo * b->mu_hi - b->hi * b->mu_lo) / (b->mu_hi - b->mu_lo);
    if (!(c > b->lo && c < b->hi)) c = 0.5 * (b->lo + b->hi);
    if (!SolveAt(c, b->q_lo, &q_try)) {
      c = 0.5 * (b->lo + b->hi);
      if (!SolveAt(c, b->q_lo, &q_try)) break;
    }
    const Eigen::VectorXd e = StiffnessEigenvalues(c, q_try);
    if (e(0) > 0) {
      b->lo = c;
      b->mu_lo = e(0);
      b->q_lo = q_try;
      if (side == 1) b->mu_hi *= 0.5;
      side = 1;
    } else {
      b->hi = c;
      b->mu_hi = e(0);
      b->multiplicity = b->NearZero(e);
      if (side == -1) b->mu_lo *= 0.5;
      side = -1;
    }
  }
}

double QuatFdBuckling::ModeMaxCurvatureS(double lambda, const Eigen::VectorXd& q) {
  // The mode: the vertex where its curvature change (the difference of neighbouring segment
  // rotations over the distance of their midpoints) is largest.
  Eigen::MatrixXd V;
  StiffnessEigenvalues(lambda, q, &V);
  const int N = model_.layout().segments;
  const int nv = static_cast<int>(free_vertices_.size());
  const std::vector<double>& s = model_.grid();
  auto theta = [&](int seg) { return Vec3(V.col(0).segment<3>(3 * nv + 3 * seg)); };
  double best = -1, s_max = NAN;
  for (int n = 0; n < N; ++n) {  // the free tip carries no bending element
    const double mid_b = 0.5 * (s[n] + s[n + 1]);
    const double mid_a = n == 0 ? 0.0 : 0.5 * (s[n - 1] + s[n]);
    const Vec3 dK = (theta(n) - (n == 0 ? Vec3::Zero() : theta(n - 1))) / (mid_b - mid_a);
    const double k = dK.head<2>().norm();
    if (k > best * (1 + 1e-9)) {
      best = k;
      s_max = s[n];
    }
  }
  return s_max;
}

QuatFdBucklingSummary QuatFdBuckling::FindCriticalLoad() {
  const auto t0 = std::chrono::steady_clock::now();
  QuatFdBucklingSummary out;
  solves_ = 0;
  auto finish = [&](BucklingStatus status) {
    out.status = status;
    out.solves = solves_;
    out.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
  Bracket b;
  Eigen::VectorXd v(model_.size()), q_try(model_.size());
  b.q_lo.resize(model_.size());
  model_.RestState(b.q_lo, v);
  if (!SolveAt(0.0, b.q_lo, &b.q_lo, /*on_path=*/false)) {  // from the rest shape
    q_ = b.q_lo;
    return finish(BucklingStatus::kPathFailed);
  }
  const Eigen::VectorXd e0 = StiffnessEigenvalues(0.0, b.q_lo);
  b.mu_lo = e0(0);
  b.mu0 = b.mu_lo;
  if (b.mu_lo <= 0) {
    // The fixed loads alone leave the equilibrium unstable: a critical load on top of them
    // would be a higher one (a cantilever pressed by 5 Euler loads gave "found" at 0).
    q_ = b.q_lo;
    out.preload_unstable_directions = static_cast<int>((e0.array() <= 0).count());
    return finish(BucklingStatus::kPreloadPastCritical);
  }
  out.scan_lambda.push_back(b.lo);
  out.scan_min_eigenvalue.push_back(b.mu_lo);
  // The scan: steps of λ_max/scan_steps, halved after a failed solve (up to 10 times in a row;
  // one that quatfd::TurnsBack jumped branches) and grown back after a success, until μ <= 0.
  const double h_nominal = options_.lambda_max / options_.scan_steps;
  double h = h_nominal;
  int halvings = 0;
  Eigen::VectorXd q_before = b.q_lo;  // the path's point before b.q_lo
  while (b.lo < options_.lambda_max) {
    const double lambda = std::min(options_.lambda_max, b.lo + h);
    // (A step below λ's resolution fails as well: 11 of them are a failed path.)
    if (!(lambda > b.lo) || !SolveAt(lambda, b.q_lo, &q_try) ||
        quatfd::TurnsBack(model_, q_before, b.q_lo, q_try)) {
      if (++halvings > 10) {
        q_ = b.q_lo;
        out.lambda_reached = b.lo;
        return finish(BucklingStatus::kPathFailed);
      }
      h *= 0.5;
      continue;
    }
    const Eigen::VectorXd e = StiffnessEigenvalues(lambda, q_try);
    out.scan_lambda.push_back(lambda);
    out.scan_min_eigenvalue.push_back(e(0));
    if (e(0) <= 0) {
      b.hi = lambda;
      b.mu_hi = e(0);
      b.multiplicity = b.NearZero(e);
      break;
    }
    q_before = b.q_lo;
    b.lo = lambda;
    b.mu_lo = e(0);
    b.q_lo = q_try;
    h = std::min(h_nominal, 2 * h);
    halvings = 0;
  }
  out.lambda_reached = b.lo;
  if (std::isnan(b.hi)) {
    q_ = b.q_lo;
    return finish(BucklingStatus::kNotFound);
  }
  RefineBracket(&b);
  q_ = b.q_lo;
  out.mode_s_max = ModeMaxCurvatureS(b.lo, b.q_lo);
  const double lo = b.lo, hi = b.hi, mu_lo = b.mu_lo, mu_hi = b.mu_hi;
  out.critical_load = mu_lo == mu_hi ? lo : (lo * mu_hi - hi * mu_lo) / (mu_hi - mu_lo);
  out.critical_load = std::clamp(out.critical_load, lo, hi);
  out.lambda_reached = lo;
  out.multiplicity = b.multiplicity;
  return finish(BucklingStatus::kFound);
}

}  // namespace cosserat
