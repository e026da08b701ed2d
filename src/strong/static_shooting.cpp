#include "cosserat/strong/static_shooting.hpp"

#include <ceres/jet.h>
#include <ceres/tiny_solver.h>

#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "cosserat/lie/so3.hpp"
#include "cosserat/rod/grid.hpp"

namespace cosserat {

const char* ToString(SolveStatus status) {
  switch (status) {
    case SolveStatus::kNotRun: return "not_run";
    case SolveStatus::kConverged: return "converged";
    case SolveStatus::kMaxIterations: return "max_iterations";
    case SolveStatus::kLoadSteppingFailed: return "load_stepping_failed";
    case SolveStatus::kNonFinite: return "non_finite";
  }
  return "unknown";
}

bool StaticShootingOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (!(std::isfinite(tolerance) && tolerance > 0)) return fail("tolerance must be positive");
  if (max_iterations < 1) return fail("max_iterations must be at least 1");
  if (!(min_load_step > 0 && min_load_step <= 1)) return fail("min_load_step must be in (0, 1]");
  if (max_load_steps < 1) return fail("max_load_steps must be at least 1");
  if (!(std::isfinite(max_load_increment) && max_load_increment > 0))
    return fail("max_load_increment must be positive");
  return true;
}

namespace {

constexpr double kIntermediateTolerance = 1e-6;

using Sample = StaticShootingSolver::Sample;
using Jet6 = ceres::Jet<double, 6>;

// State of the spatial integration: centreline, frame and the internal wrench in world frame.
template <typename T>
struct ShotState {
  Vector3<T> p;  // p_W, m
  Matrix3<T> R;  // R_WB
  Vector3<T> n;  // n_W, N
  Vector3<T> m;  // m_W about p(s), N·m
};

template <typename T>
ShotState<T> Axpy(const ShotState<T>& y, double a, const ShotState<T>& d) {
  return {y.p + a * d.p, y.R + a * d.R, y.n + a * d.n, y.m + a * d.m};
}

// Body-frame wrench W = [Rᵀ m_W; Rᵀ n_W] and strain ξ = ξ* + C W (C = K⁻¹; diagonal for
// principal-axes sections, which gets the cheap path).
template <typename T>
void Strain(const Sample& smp, const ShotState<T>& y, Vector6<T>* W, Vector6<T>* xi) {
  W->template head<3>() = y.R.transpose() * y.m;
  W->template tail<3>() = y.R.transpose() * y.n;
  if (smp.diagonal) {
    for (int i = 0; i < 6; ++i) (*xi)(i) = smp.rest_strain(i) + smp.compliance(i, i) * (*W)(i);
    return;
  }
  for (int i = 0; i < 6; ++i) {
    T acc = T(smp.rest_strain(i));
    for (int j = 0; j < 6; ++j) acc += smp.compliance(i, j) * (*W)(j);
    (*xi)(i) = acc;
  }
}

// d/ds of the state (seed 002 eqs. 14 and 16 with V = 0, written with world-frame wrenches).
// Also returns the body wrench and strain it computed, for recording.
template <typename T>
ShotState<T> Derivative(const Sample& smp, const Vec3& f_W, const ShotState<T>& y,
                        Vector6<T>* W_out = nullptr, Vector6<T>* xi_out = nullptr) {
  Vector6<T> W, xi;
  Strain(smp, y, &W, &xi);
  ShotState<T> d;
  const Vector3<T> K = xi.template head<3>();
  d.p = y.R * xi.template tail<3>();
  // (R K̂) row i = (row i of R) × K.
  for (int i = 0; i < 3; ++i) d.R.row(i) = y.R.row(i).cross(K.transpose());
  d.n = -f_W.template cast<T>();
  d.m = y.n.cross(d.p);
  if (W_out) *W_out = W;
  if (xi_out) *xi_out = xi;
  return d;
}

}  // namespace

StaticShootingSolver::StaticShootingSolver(const RodModel& model, int num_nodes,
                                           const StaticShootingOptions& options,
                                           const Actuation& actuation)
    : model_(model), options_(options) {
  std::string why;
  if (!model_.IsValid(&why)) throw std::invalid_argument("RodModel: " + why);
  if (!options_.IsValid(&why)) throw std::invalid_argument("StaticShootingOptions: " + why);
  if (num_nodes < 2) throw std::invalid_argument("num_nodes must be at least 2");
  grid_ = MakeGrid(model_.length, num_nodes, model_.section->Breakpoints());
  const int n = static_cast<int>(grid_.size());

  // Properties at nodes and midpoints. A node on a breakpoint belongs to the piece on its right
  // for the step leaving it; the step arriving at it must use the left piece, so the sample for
  // the step end is taken a hair inside the step (the profile is smooth within a step).
  samples_.resize(3 * (n - 1));
  auto make = [&](double s) {
    const SectionProperties p = model_.section->At(s, actuation);
    Sample smp;
    smp.compliance = p.stiffness.inverse();
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if (i != j && smp.compliance(i, j) != 0.0) smp.diagonal = false;
    smp.rest_strain = model_.RestStrainAt(s);
    smp.mass_per_length = p.mass(5, 5);
    return smp;
  };
  for (int i = 0; i + 1 < n; ++i) {
    const double a = grid_[i], b = grid_[i + 1], h = b - a;
    samples_[3 * i + 0] = make(a);
    samples_[3 * i + 1] = make(a + 0.5 * h);
    samples_[3 * i + 2] = make(b - 1e-9 * h);
  }

  const double EI = std::max(1.0 / samples_[0].compliance(0, 0), 1.0 / samples_[0].compliance(1, 1));
  const double L = model_.length;
  scale_ << EI / L, EI / L, EI / L, EI / (L * L), EI / (L * L), EI / (L * L);
  state_.Resize(n);
  for (int i = 0; i < n; ++i) state_.s[i] = grid_[i];

  // Rest shape in the base body frame (zero wrench), for the rigid-body initial guess.
  rest_position_B_.assign(n, Vec3::Zero());
  rest_rotation_B_.assign(n, Mat3::Identity());
  ShotState<double> y{Vec3::Zero(), Mat3::Identity(), Vec3::Zero(), Vec3::Zero()};
  for (int i = 0; i + 1 < n; ++i) {
    const double h = grid_[i + 1] - grid_[i];
    const Vec3 zero = Vec3::Zero();
    const auto k1 = Derivative(samples_[3 * i], zero, y);
    const auto k2 = Derivative(samples_[3 * i + 1], zero, Axpy(y, 0.5 * h, k1));
    const auto k3 = Derivative(samples_[3 * i + 1], zero, Axpy(y, 0.5 * h, k2));
    const auto k4 = Derivative(samples_[3 * i + 2], zero, Axpy(y, h, k3));
    y = Axpy(Axpy(Axpy(Axpy(y, h / 6, k1), h / 3, k2), h / 3, k3), h / 6, k4);
    rest_position_B_[i + 1] = y.p;
    rest_rotation_B_[i + 1] = y.R;
  }
}

namespace {

// Integrates from s = 0 to L with RK4 on the grid and returns the dimensionless tip residual.
// When record is non-null, the node values are written to it (T = double only).
template <typename T>
Vector6<T> Shoot(const std::vector<double>& grid, const std::vector<Sample>& samples,
                 const Vec6& scale, const lie::SE3& base, const StaticLoads& loads,
                 const Vector6<T>& x, RodState* record) {
  const int n = static_cast<int>(grid.size());
  Vector6<T> W0;
  for (int i = 0; i < 6; ++i) W0(i) = scale(i) * x(i);
  ShotState<T> y;
  y.p = base.p.cast<T>();
  y.R = base.R.cast<T>();
  y.m = y.R * W0.template head<3>();
  y.n = y.R * W0.template tail<3>();

  auto f_at = [&](const Sample& smp) -> Vec3 {
    return smp.mass_per_length * loads.gravity_W + loads.distributed_force_W;
  };
  auto record_node = [&](int i, const Vector6<T>& W, const Vector6<T>& xi) {
    if constexpr (std::is_same_v<T, double>) {
      if (!record) return;
      record->position_W[i] = y.p;
      record->rotation_WB[i] = y.R;
      record->wrench_B[i] = W;
      record->strain[i] = xi;
    }
  };

  Vector6<T> W, xi;
  for (int i = 0; i + 1 < n; ++i) {
    const double h = grid[i + 1] - grid[i];
    const Sample& s0 = samples[3 * i];
    const Sample& sm = samples[3 * i + 1];
    const Sample& s1 = samples[3 * i + 2];
    const Vec3 f0 = f_at(s0), fm = f_at(sm), f1 = f_at(s1);
    const auto k1 = Derivative(s0, f0, y, &W, &xi);
    record_node(i, W, xi);
    const auto k2 = Derivative(sm, fm, Axpy(y, 0.5 * h, k1));
    const auto k3 = Derivative(sm, fm, Axpy(y, 0.5 * h, k2));
    const auto k4 = Derivative(s1, f1, Axpy(y, h, k3));
    const double a = h / 6, b = h / 3;
    y.p += a * (k1.p + k4.p) + b * (k2.p + k3.p);
    y.R += a * (k1.R + k4.R) + b * (k2.R + k3.R);
    y.n += a * (k1.n + k4.n) + b * (k2.n + k3.n);
    y.m += a * (k1.m + k4.m) + b * (k2.m + k3.m);
  }
  if constexpr (std::is_same_v<T, double>) {
    if (record) {
      Strain(samples[3 * (n - 2) + 2], y, &W, &xi);
      record_node(n - 1, W, xi);
    }
  }

  // Tip condition W(L) = W_tip, both in the tip body frame.
  const Matrix3<T> Rt = y.R.transpose();
  const Vector3<T> F_B = loads.tip_force_frame == LoadFrame::kWorld
                             ? Vector3<T>(Rt * loads.tip_force.cast<T>())
                             : Vector3<T>(loads.tip_force.cast<T>());
  const Vector3<T> M_B = loads.tip_moment_frame == LoadFrame::kWorld
                             ? Vector3<T>(Rt * loads.tip_moment.cast<T>())
                             : Vector3<T>(loads.tip_moment.cast<T>());
  Vector6<T> r;
  r.template head<3>() = Rt * y.m - M_B;
  r.template tail<3>() = Rt * y.n - F_B;
  for (int i = 0; i < 6; ++i) r(i) /= scale(i);
  return r;
}


}  // namespace

Vec6 StaticShootingSolver::Residual(const lie::SE3& base, const StaticLoads& loads,
                                    const Vec6& x) {
  return Shoot<double>(grid_, samples_, scale_, base, loads, x, &state_);
}

Mat6 StaticShootingSolver::ResidualJacobian(const lie::SE3& base, const StaticLoads& loads,
                                            const Vec6& x, Vec6* residual) const {
  Vector6<Jet6> xj;
  for (int i = 0; i < 6; ++i) xj(i) = Jet6(x(i), i);
  const Vector6<Jet6> r = Shoot<Jet6>(grid_, samples_, scale_, base, loads, xj, nullptr);
  Mat6 J;
  for (int i = 0; i < 6; ++i) {
    J.row(i) = r(i).v.transpose();
    if (residual) (*residual)(i) = r(i).a;
  }
  return J;
}

Vec6 StaticShootingSolver::base_wrench_B() const { return scale_.cwiseProduct(x_); }

Vec6 StaticShootingSolver::RigidGuess(const lie::SE3& base, const StaticLoads& loads) const {
  // Base wrench that balances the loads on the undeformed (rest) shape: a good start for small
  // loads and exact in the limit of zero load.
  const int n = static_cast<int>(grid_.size());
  Vec3 n_W = Vec3::Zero(), m_W = Vec3::Zero();
  auto add_force = [&](const Vec3& r_B, const Vec3& F_W) {
    n_W += F_W;
    m_W += (base.R * r_B).cross(F_W);
  };
  for (int i = 0; i + 1 < n; ++i) {
    const double h = grid_[i + 1] - grid_[i];
    const Sample& sm = samples_[3 * i + 1];
    const Vec3 f = sm.mass_per_length * loads.gravity_W + loads.distributed_force_W;
    add_force(0.5 * (rest_position_B_[i] + rest_position_B_[i + 1]), h * f);
  }
  const Mat3 R_tip = base.R * rest_rotation_B_.back();
  add_force(rest_position_B_.back(), loads.tip_force_frame == LoadFrame::kWorld
                                         ? loads.tip_force
                                         : Vec3(R_tip * loads.tip_force));
  m_W += loads.tip_moment_frame == LoadFrame::kWorld ? loads.tip_moment
                                                     : Vec3(R_tip * loads.tip_moment);
  Vec6 W_B;
  W_B << base.R.transpose() * m_W, base.R.transpose() * n_W;
  return W_B.cwiseQuotient(scale_);
}

namespace {

// The 6 × 6 shooting problem in the form ceres::TinySolver expects.
struct ShootingCost {
  using Scalar = double;
  enum { NUM_RESIDUALS = 6, NUM_PARAMETERS = 6 };
  StaticShootingSolver* solver;
  const lie::SE3* base;
  const StaticLoads* loads;
  int* shots;
  Mat6* last_jacobian;

  bool operator()(const double* x_ptr, double* r_ptr, double* J_ptr) const {
    const Eigen::Map<const Vec6> x(x_ptr);
    Eigen::Map<Vec6> r(r_ptr);
    ++*shots;
    if (J_ptr) {
      Eigen::Map<Mat6> J(J_ptr);
      Vec6 r_value;
      J = solver->ResidualJacobian(*base, *loads, x, &r_value);
      r = r_value;
      *last_jacobian = J;
    } else {
      r = solver->Residual(*base, *loads, x);
    }
    return r.allFinite();
  }
};

}  // namespace

bool StaticShootingSolver::TryLevenbergMarquardt(const lie::SE3& base, const StaticLoads& loads,
                                                 double tolerance, Vec6* x,
                                                 StaticShootingSummary* summary) {
  Mat6 J = Mat6::Identity();
  ShootingCost cost{this, &base, &loads, &summary->shots, &J};
  ceres::TinySolver<ShootingCost> lm;
  lm.options.max_num_iterations = options_.max_iterations;
  lm.options.cost_threshold = 0.5 * tolerance * tolerance;
  lm.options.gradient_tolerance = 0.0;  // stop on the residual only
  lm.options.parameter_tolerance = 1e-15;
  lm.options.function_tolerance = 0.0;
  Vec6 xt = *x;
  const auto& s = lm.Solve(cost, &xt);
  summary->iterations += s.iterations;
  const double res = std::sqrt(2.0 * std::max(0.0, s.final_cost));
  if (!(std::isfinite(res) && xt.allFinite())) {
    summary->status = SolveStatus::kNonFinite;
    return false;
  }
  summary->residual = res;
  *x = xt;
  if (res < tolerance) {
    // TinySolver evaluated the Jacobian at the accepted x last; keep it for the next solve.
    jacobian_ = J;
    has_jacobian_ = true;
    return true;
  }
  summary->status = SolveStatus::kMaxIterations;
  return false;
}

bool StaticShootingSolver::TryQuasiNewton(const lie::SE3& base, const StaticLoads& loads,
                                          Vec6* x_io, StaticShootingSummary* summary) {
  // Newton with the last solution's Jacobian, kept current by Broyden's rank-one update. Gives
  // up (and lets LM take over) as soon as a step fails to halve the residual.
  Vec6 x = *x_io;
  Vec6 r = Residual(base, loads, x);
  ++summary->shots;
  Mat6 J = jacobian_;
  Eigen::PartialPivLU<Mat6> lu(J);
  for (int it = 0; it <= options_.max_iterations; ++it) {
    const double norm = r.norm();
    if (!std::isfinite(norm)) return false;
    if (norm < options_.tolerance) {
      summary->residual = norm;
      *x_io = x;
      jacobian_ = J;
      return true;
    }
    if (it == options_.max_iterations) return false;
    const Vec6 dx = -lu.solve(r);
    const Vec6 r_new = Residual(base, loads, x + dx);
    ++summary->shots;
    ++summary->iterations;
    if (!(r_new.allFinite() && r_new.norm() < 0.5 * norm)) return false;
    J += (r_new - r - J * dx) * dx.transpose() / dx.squaredNorm();
    lu.compute(J);
    x += dx;
    r = r_new;
  }
  return false;
}

StaticShootingSummary StaticShootingSolver::Solve(const lie::SE3& base, const StaticLoads& loads) {
  const auto t0 = std::chrono::steady_clock::now();
  StaticShootingSummary summary;

  // Start from a known solution: the previous one at the same base, else the unloaded rod
  // (W ≡ 0 is exact at zero load, whatever the rest shape).
  const bool from_previous = has_solution_ && (solved_base_.R - base.R).norm() == 0.0 &&
                             (solved_base_.p - base.p).norm() == 0.0;
  summary.warm_started = from_previous;
  const StaticLoads start = from_previous ? solved_loads_ : loads.Scaled(0.0);
  const Vec6 x_start = from_previous ? x_ : Vec6::Zero();

  // How far the load moves, as the change of the rigid-body base wrench in units of EI/L and
  // EI/L² (≈ the load parameter PL²/EI, or the linear-theory rotation in rad). Newton-type
  // iterations jump between equilibrium branches when this is large, so the load is applied in
  // increments of at most options_.max_load_increment.
  const double load_change =
      (RigidGuess(base, loads) - RigidGuess(base, start)).lpNorm<Eigen::Infinity>();
  const double max_fraction =
      load_change > options_.max_load_increment ? options_.max_load_increment / load_change : 1.0;

  Vec6 x = x_start;
  bool ok = false;
  bool state_current = false;
  if (max_fraction == 1.0) {
    if (from_previous && has_jacobian_ && options_.reuse_jacobian) {
      ok = TryQuasiNewton(base, loads, &x, &summary);
      state_current = ok;
    }
    if (!ok) {
      x = from_previous ? x_ : RigidGuess(base, loads);
      ok = TryLevenbergMarquardt(base, loads, options_.tolerance, &x, &summary);
    }
  }

  if (!ok && (options_.load_stepping || max_fraction < 1.0)) {
    // Continuation along loads(μ) = start + μ (loads − start), μ: 0 → 1, with a secant predictor,
    // step halving on failure and doubling on success, never above max_fraction.
    Vec6 x_a = x_start, x_prev = x_start;
    double mu = 0.0, mu_prev = 0.0, dmu = max_fraction;
    int steps = 0;
    state_current = false;
    while (steps < options_.max_load_steps) {
      const double mu_try = std::min(1.0, mu + dmu);
      const StaticLoads target = mu_try == 1.0 ? loads : StaticLoads::Blend(start, loads, mu_try);
      Vec6 guess = x_a;
      if (mu > mu_prev) guess += (x_a - x_prev) * ((mu_try - mu) / (mu - mu_prev));
      ++steps;
      // Intermediate equilibria only seed the next step: a looser tolerance is enough.
      const double tol =
          mu_try == 1.0 ? options_.tolerance : std::max(options_.tolerance, kIntermediateTolerance);
      if (TryLevenbergMarquardt(base, target, tol, &guess, &summary)) {
        x_prev = x_a;
        mu_prev = mu;
        x_a = guess;
        mu = mu_try;
        if (mu == 1.0) {
          ok = true;
          break;
        }
        dmu = std::min({2.0 * dmu, max_fraction, 1.0 - mu});
      } else {
        if (!options_.load_stepping) break;
        dmu *= 0.5;
        if (dmu < options_.min_load_step) break;
      }
    }
    summary.load_steps = steps;
    x = x_a;
    if (!ok && summary.status != SolveStatus::kNonFinite)
      summary.status = options_.load_stepping ? SolveStatus::kLoadSteppingFailed
                                              : SolveStatus::kMaxIterations;
  }

  if (ok) {
    summary.status = SolveStatus::kConverged;
    x_ = x;
    solved_base_ = base;
    solved_loads_ = loads;
    has_solution_ = true;
  }
  if (!state_current) {
    const Vec6 r = Residual(base, loads, x);
    ++summary.shots;
    summary.residual = r.norm();
    if (!r.allFinite() && summary.status != SolveStatus::kConverged)
      summary.status = SolveStatus::kNonFinite;
  }
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

}  // namespace cosserat
