#include "cosserat/strong/static_shooting.hpp"

#include <ceres/tiny_solver.h>

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include "cosserat/lie/so3.hpp"
#include "cosserat/loads/tendons.hpp"
#include "cosserat/rod/grid.hpp"
#include "frame_tangent.hpp"

namespace cosserat {

const char* ToString(SolveStatus status) {
  switch (status) {
    case SolveStatus::kNotRun:
      return "not_run";
    case SolveStatus::kConverged:
      return "converged";
    case SolveStatus::kMaxIterations:
      return "max_iterations";
    case SolveStatus::kLoadSteppingFailed:
      return "load_stepping_failed";
    case SolveStatus::kNonFinite:
      return "non_finite";
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

#if defined(__GNUC__)
#define COSSERAT_HOT inline __attribute__((always_inline))
#else
#define COSSERAT_HOT inline
#endif

using Sample = StaticShootingSolver::Sample;
using namespace internal;

// State of the integration in s: centreline and frame in the world, internal wrench in the body
// frame. Keeping W in the body frame keeps the chain of dependent operations per stage short,
// which is what bounds the speed of a shot.
struct ShotState {
  Vec3 p;  // p_W, m
  Mat3 R;  // R_WB
  Vec3 m;  // m_B, N·m
  Vec3 n;  // n_B, N
};

// Derivative of ShotState with respect to the 6 unknowns (one column each), in the same
// coordinates, so RK4 applied to (state, tangent) gives the exact derivative of the discrete map.
struct ShotTangent {
  Mat36 p;
  RotationTangent R;  // d(R e_j)
  Mat36 m;
  Mat36 n;
};

// ShotState is 18 contiguous doubles; the hot loops below treat it as a flat array.
static_assert(sizeof(ShotState) == 18 * sizeof(double), "ShotState must be 18 packed doubles");
inline double* Flat(ShotState& y) { return y.p.data(); }
inline const double* Flat(const ShotState& y) { return y.p.data(); }

COSSERAT_HOT ShotState Axpy(const ShotState& y, double a, const ShotState& d) {
  ShotState out;
  double* o = Flat(out);
  const double* py = Flat(y);
  const double* pd = Flat(d);
  for (int i = 0; i < 18; ++i) o[i] = py[i] + a * pd[i];
  return out;
}

ShotTangent Axpy(const ShotTangent& y, double a, const ShotTangent& d) {
  return {y.p + a * d.p,
          {y.R[0] + a * d.R[0], y.R[1] + a * d.R[1], y.R[2] + a * d.R[2]},
          y.m + a * d.m,
          y.n + a * d.n};
}

// RK4 combination y += h/6 (k1 + 2 k2 + 2 k3 + k4), for states and tangents.
COSSERAT_HOT void Rk4Update(double h, const ShotState& k1, const ShotState& k2, const ShotState& k3,
                            const ShotState& k4, ShotState* y) {
  const double a = h / 6, b = h / 3;
  double* o = Flat(*y);
  const double *p1 = Flat(k1), *p2 = Flat(k2), *p3 = Flat(k3), *p4 = Flat(k4);
  for (int i = 0; i < 18; ++i) o[i] += a * (p1[i] + p4[i]) + b * (p2[i] + p3[i]);
}

void Rk4Update(double h, const ShotTangent& k1, const ShotTangent& k2, const ShotTangent& k3,
               const ShotTangent& k4, ShotTangent* y) {
  const double a = h / 6, b = h / 3;
  y->p += a * (k1.p + k4.p) + b * (k2.p + k3.p);
  for (int j = 0; j < 3; ++j) y->R[j] += a * (k1.R[j] + k4.R[j]) + b * (k2.R[j] + k3.R[j]);
  y->m += a * (k1.m + k4.m) + b * (k2.m + k3.m);
  y->n += a * (k1.n + k4.n) + b * (k2.n + k3.n);
}

// ξ = ξ* + C W (C = K⁻¹; diagonal for principal-axes sections, which gets the cheap path).
COSSERAT_HOT Vec6 Compliance(const Sample& smp, const Vec6& W) {
  if (smp.diagonal) return smp.rest_strain + smp.compliance_diagonal.cwiseProduct(W);
  return smp.rest_strain + smp.compliance * W;
}

COSSERAT_HOT Vec6 BodyWrench(const ShotState& y) {
  Vec6 W;
  W.head<3>() = y.m;
  W.tail<3>() = y.n;
  return W;
}

// d/ds of the state (FD notes 2025, eqs. 14, 16 with V = 0; W = [m; n] = −Λ) given the strain:
//   p' = R Γ,  R' = R K̂,  m' = −K × m − Γ × n,  n' = −K × n − Rᵀ f_W.
COSSERAT_HOT ShotState Rates(const Vec6& xi, const Vec3& f_W, const ShotState& y) {
  const double k0 = xi(0), k1 = xi(1), k2 = xi(2);
  const double g0 = xi(3), g1 = xi(4), g2 = xi(5);
  const double m0 = y.m(0), m1 = y.m(1), m2 = y.m(2);
  const double n0 = y.n(0), n1 = y.n(1), n2 = y.n(2);
  const Mat3& R = y.R;
  ShotState d;
  for (int i = 0; i < 3; ++i) {
    d.p(i) = R(i, 0) * g0 + R(i, 1) * g1 + R(i, 2) * g2;
    // (R K̂) row i = (row i of R) × K
    d.R(i, 0) = R(i, 1) * k2 - R(i, 2) * k1;
    d.R(i, 1) = R(i, 2) * k0 - R(i, 0) * k2;
    d.R(i, 2) = R(i, 0) * k1 - R(i, 1) * k0;
  }
  // m' = m × K + n × Γ,  n' = n × K − Rᵀ f
  d.m(0) = m1 * k2 - m2 * k1 + n1 * g2 - n2 * g1;
  d.m(1) = m2 * k0 - m0 * k2 + n2 * g0 - n0 * g2;
  d.m(2) = m0 * k1 - m1 * k0 + n0 * g1 - n1 * g0;
  const double f0 = f_W(0), f1 = f_W(1), f2 = f_W(2);
  d.n(0) = n1 * k2 - n2 * k1 - (R(0, 0) * f0 + R(1, 0) * f1 + R(2, 0) * f2);
  d.n(1) = n2 * k0 - n0 * k2 - (R(0, 1) * f0 + R(1, 1) * f1 + R(2, 1) * f2);
  d.n(2) = n0 * k1 - n1 * k0 - (R(0, 2) * f0 + R(1, 2) * f1 + R(2, 2) * f2);
  return d;
}

// The plain rod's derivative: strain from the linear law, then the rates. Writes the strain.
COSSERAT_HOT ShotState Derivative(const Sample& smp, const Vec3& f_W, const ShotState& y,
                                  Vec6* xi) {
  if (smp.diagonal) {  // written out: this is the innermost loop of every solve
    const double* c = smp.compliance_diagonal.data();
    const double* r = smp.rest_strain.data();
    (*xi)(0) = r[0] + c[0] * y.m(0);
    (*xi)(1) = r[1] + c[1] * y.m(1);
    (*xi)(2) = r[2] + c[2] * y.m(2);
    (*xi)(3) = r[3] + c[3] * y.n(0);
    (*xi)(4) = r[4] + c[4] * y.n(1);
    (*xi)(5) = r[5] + c[5] * y.n(2);
  } else {
    *xi = Compliance(smp, BodyWrench(y));
  }
  return Rates(*xi, f_W, y);
}

// With tendons, the strain solves K (ξ − ξ*) + Σ τ a(ξ) = W (tendons.hpp), starting from the
// guess in *xi; H = K + ∂(Σ τ a)/∂ξ is written for the tangent. A failed solve gives NaN rates.
ShotState TendonDerivative(const Sample& smp, const StaticShootingSolver::TendonStage& ts,
                           const double* tension, const Vec3& f_W, const ShotState& y, Vec6* xi,
                           Mat6* H) {
  if (!SolveTendonStrain(ts.stiffness, smp.rest_strain, ts.tendons, tension, BodyWrench(y), xi, H))
    xi->setConstant(NAN);
  return Rates(*xi, f_W, y);
}

// The linearisation of Derivative along the tangent dy, given the primal strain.
// With tendons (H given), dξ = H⁻¹ (dW − source), the source being ∂(Σ τ a)/∂(direction).
ShotTangent TangentDerivative(const Sample& smp, const Vec3& f_W, const ShotState& y,
                              const ShotTangent& dy, const Vec6& xi, const Mat6* H = nullptr,
                              const Mat6* source = nullptr) {
  Mat6 dW;
  dW << dy.m, dy.n;
  if (source) dW -= *source;
  const Mat6 dxi = H              ? Mat6(H->partialPivLu().solve(dW))
                   : smp.diagonal ? Mat6(smp.compliance_diagonal.asDiagonal() * dW)
                                  : Mat6(smp.compliance * dW);
  const Mat36 dK = dxi.topRows<3>(), dG = dxi.bottomRows<3>();
  const Vec3 K = xi.head<3>(), G = xi.tail<3>();
  ShotTangent dd;
  dd.p = RotateTangent(y.R, dy.R, G, dG);
  dd.R = RotationRateTangent(y.R, dy.R, K, dK);
  // d(m × K + n × Γ) and d(n × K − Rᵀ f)
  dd.m = Cross(y.m, dK) + Cross(dy.m, K) + Cross(y.n, dG) + Cross(dy.n, G);
  dd.n = Cross(y.n, dK) + Cross(dy.n, K) - TransposeTimesFixed(dy.R, f_W);
  return dd;
}

// Tip condition W(L) = W_tip in the tip body frame, made dimensionless by scale.
Vec6 TipResidual(const Mat3& R_tip, const Vec6& W_tip_B, const StaticLoads& loads,
                 const Vec6& scale) {
  const Mat3 Rt = R_tip.transpose();
  Vec6 target;
  target << (loads.tip_moment_frame == LoadFrame::kWorld ? Vec3(Rt * loads.tip_moment)
                                                         : loads.tip_moment),
      (loads.tip_force_frame == LoadFrame::kWorld ? Vec3(Rt * loads.tip_force) : loads.tip_force);
  return (W_tip_B - target).cwiseQuotient(scale);
}

// Integrates from s = 0 to L with RK4 on the grid and returns the dimensionless tip residual.
// With record, writes the node values; with J, propagates the tangent and writes d r / d x.
// With tendons (tc not null): the tendon strain law at every stage, and the tendon path lengths
// by the same RK4 quadrature.
struct TendonContext {
  const std::vector<StaticShootingSolver::TendonStage>* stages;  // parallel to the samples
  const double* tension;
  double* length;  // out: Σ over stages of the quadrature weight × |q_i|
  // The tangent's 6 directions: the unknowns x (−1), or the tensions of tendons k0 … k0 + 5.
  int tension_block = -1;
  Mat36* tip_dp = nullptr;            // out if set: d p(L) along the directions
  RotationTangent* tip_dR = nullptr;  // out if set: d R(L) e_j along the directions
};

// ∂(Σ τ a)/∂τ_k for k = k0 … k0 + 5 (zero columns past the last tendon): the source of the
// tension tangent, dξ = H⁻¹ (dW − this).
Mat6 TensionSource(const StaticShootingSolver::TendonStage& ts, const double* tension,
                   const Vec6& xi, int k0) {
  std::array<Vec6, Actuation::kMaxTendons> a;
  TendonWrench(ts.tendons, tension, xi, nullptr, &a);
  Mat6 out = Mat6::Zero();
  for (int j = 0; j < 6 && k0 + j < ts.tendons.count; ++j) out.col(j) = a[k0 + j];
  return out;
}

// Rows of StateTangent: p (0–2), R e₀ (3–5), R e₁ (6–8), R e₂ (9–11), m (12–14), n (15–17).
ShotTangent FromRows(const StaticShootingSolver::StateTangent& T) {
  ShotTangent t;
  t.p = T.middleRows<3>(0);
  for (int j = 0; j < 3; ++j) t.R[j] = T.middleRows<3>(3 + 3 * j);
  t.m = T.middleRows<3>(12);
  t.n = T.middleRows<3>(15);
  return t;
}

StaticShootingSolver::StateTangent ToRows(const ShotTangent& t) {
  StaticShootingSolver::StateTangent T;
  T.middleRows<3>(0) = t.p;
  for (int j = 0; j < 3; ++j) T.middleRows<3>(3 + 3 * j) = t.R[j];
  T.middleRows<3>(12) = t.m;
  T.middleRows<3>(15) = t.n;
  return T;
}

// For other boundary conditions (ShootTangent): the tangent's start value instead of the
// unknowns' directions, and where to write it at every node and at the tip. node_rows: the same
// node tangents in the public row layout (an array sized to the grid), for the stability check.
struct TangentSeed {
  const ShotTangent* start = nullptr;
  std::vector<ShotTangent>* nodes = nullptr;  // sized to the grid
  ShotTangent* tip = nullptr;
  StaticShootingSolver::StateTangent* node_rows = nullptr;
};

Vec6 Shoot(const std::vector<double>& grid, const std::vector<Sample>& samples, const Vec6& scale,
           const lie::SE3& base, const StaticLoads& loads, const Vec6& x, RodState* record, Mat6* J,
           const TendonContext* tc = nullptr, const TangentSeed* seed = nullptr) {
  const int n = static_cast<int>(grid.size());
  const Vec6 W0 = scale.cwiseProduct(x);
  ShotState y{base.p, base.R, W0.head<3>(), W0.tail<3>()};
  ShotTangent dy;
  if (J) {
    dy.p.setZero();
    for (auto& c : dy.R) c.setZero();
    dy.m.setZero();
    dy.n.setZero();
    if (!(tc && tc->tension_block >= 0)) {  // directions: the unknowns, W(0) = scale ⊙ x
      dy.m.leftCols<3>() = scale.head<3>().asDiagonal();
      dy.n.rightCols<3>() = scale.tail<3>().asDiagonal();
    }
    if (seed && seed->start) dy = *seed->start;
  }
  auto f_at = [&](const Sample& smp) -> Vec3 {
    return smp.mass_per_length * loads.gravity_W + loads.distributed_force_W;
  };
  auto record_node = [&](int i, const Vec6& xi) {
    record->position_W[i] = y.p;
    record->rotation_WB[i] = y.R;
    record->wrench_B[i] = BodyWrench(y);
    record->strain[i] = xi;
  };

  Vec6 xi1, xi2, xi3, xi4;
  Mat6 H1, H2, H3, H4;
  Vec6 guess = samples.front().rest_strain;  // tendon strain solves start from the last stage
  int count = 0;
  if (tc) {
    count = (*tc->stages)[0].tendons.count;
    for (int k = 0; k < count; ++k) tc->length[k] = 0.0;
  }
  // One stage: the plain law, or the tendon law from the running guess.
  auto derivative = [&](int q, const Vec3& f, const ShotState& ys, Vec6* xi, Mat6* H) {
    if (!tc) return Derivative(samples[q], f, ys, xi);
    *xi = guess;
    const ShotState d =
        TendonDerivative(samples[q], (*tc->stages)[q], tc->tension, f, ys, xi, J ? H : nullptr);
    guess = *xi;
    return d;
  };
  for (int i = 0; i + 1 < n; ++i) {
    const double h = grid[i + 1] - grid[i];
    const int q0 = 3 * i, qm = 3 * i + 1, q1 = 3 * i + 2;
    const Sample& s0 = samples[q0];
    const Sample& sm = samples[qm];
    const Sample& s1 = samples[q1];
    const Vec3 f0 = f_at(s0), fm = f_at(sm), f1 = f_at(s1);
    const ShotState k1 = derivative(q0, f0, y, &xi1, &H1);
    if (record) record_node(i, xi1);
    const ShotState y2 = Axpy(y, 0.5 * h, k1);
    const ShotState k2 = derivative(qm, fm, y2, &xi2, &H2);
    const ShotState y3 = Axpy(y, 0.5 * h, k2);
    const ShotState k3 = derivative(qm, fm, y3, &xi3, &H3);
    const ShotState y4 = Axpy(y, h, k3);
    const ShotState k4 = derivative(q1, f1, y4, &xi4, &H4);
    if (J) {
      if (seed && seed->nodes) (*seed->nodes)[i] = dy;
      if (seed && seed->node_rows) seed->node_rows[i] = ToRows(dy);
      const Mat6* h1 = tc ? &H1 : nullptr;
      const Mat6* h2 = tc ? &H2 : nullptr;
      const Mat6* h3 = tc ? &H3 : nullptr;
      const Mat6* h4 = tc ? &H4 : nullptr;
      Mat6 src[4];
      const bool tension = tc && tc->tension_block >= 0;
      if (tension) {
        const auto& ts = *tc->stages;
        const int k0 = tc->tension_block;
        src[0] = TensionSource(ts[q0], tc->tension, xi1, k0);
        src[1] = TensionSource(ts[qm], tc->tension, xi2, k0);
        src[2] = TensionSource(ts[qm], tc->tension, xi3, k0);
        src[3] = TensionSource(ts[q1], tc->tension, xi4, k0);
      }
      auto source = [&](int j) { return tension ? &src[j] : nullptr; };
      const ShotTangent t1 = TangentDerivative(s0, f0, y, dy, xi1, h1, source(0));
      const ShotTangent t2 =
          TangentDerivative(sm, fm, y2, Axpy(dy, 0.5 * h, t1), xi2, h2, source(1));
      const ShotTangent t3 =
          TangentDerivative(sm, fm, y3, Axpy(dy, 0.5 * h, t2), xi3, h3, source(2));
      const ShotTangent t4 = TangentDerivative(s1, f1, y4, Axpy(dy, h, t3), xi4, h4, source(3));
      Rk4Update(h, t1, t2, t3, t4, &dy);
    }
    for (int k = 0; k < count; ++k) {
      const auto& ts = *tc->stages;
      tc->length[k] +=
          h / 6 *
          (TendonPathRate(ts[q0].tendons, k, xi1) + 2 * TendonPathRate(ts[qm].tendons, k, xi2) +
           2 * TendonPathRate(ts[qm].tendons, k, xi3) + TendonPathRate(ts[q1].tendons, k, xi4));
    }
    Rk4Update(h, k1, k2, k3, k4, &y);
  }
  if (record) {
    const int q_tip = 3 * (n - 2) + 2;
    Vec6 xi_tip = Compliance(samples[q_tip], BodyWrench(y));
    if (tc) {
      xi_tip = guess;
      if (!SolveTendonStrain((*tc->stages)[q_tip].stiffness, samples[q_tip].rest_strain,
                             (*tc->stages)[q_tip].tendons, tc->tension, BodyWrench(y), &xi_tip,
                             nullptr))
        xi_tip.setConstant(NAN);
    }
    record_node(n - 1, xi_tip);
  }

  if (J && seed) {
    if (seed->nodes) seed->nodes->back() = dy;
    if (seed->node_rows) seed->node_rows[n - 1] = ToRows(dy);
    if (seed->tip) *seed->tip = dy;
  }
  if (J) {
    J->topRows<3>() = dy.m;
    J->bottomRows<3>() = dy.n;
    if (loads.tip_moment_frame == LoadFrame::kWorld)
      J->topRows<3>() -= TransposeTimesFixed(dy.R, loads.tip_moment);
    if (loads.tip_force_frame == LoadFrame::kWorld)
      J->bottomRows<3>() -= TransposeTimesFixed(dy.R, loads.tip_force);
    *J = scale.cwiseInverse().asDiagonal() * *J;
    if (tc && tc->tip_dp) *tc->tip_dp = dy.p;
    if (tc && tc->tip_dR) *tc->tip_dR = dy.R;
  }
  return TipResidual(y.R, BodyWrench(y), loads, scale);
}

}  // namespace

StaticShootingSolver::StaticShootingSolver(const RodModel& model, int num_nodes,
                                           const StaticShootingOptions& options,
                                           const Actuation& actuation)
    : model_(model), options_(options), actuation_(actuation) {
  std::string why;
  if (!options_.IsValid(&why)) throw std::invalid_argument("StaticShootingOptions: " + why);
  if (!model_.IsValid(&why)) throw std::invalid_argument("RodModel: " + why);
  grid_ = ModelGrid(model_, num_nodes);
  const int n = static_cast<int>(grid_.size());
  const std::vector<double> points = SegmentSamplePoints(grid_);
  samples_.resize(points.size());
  if (!model_.tendons.empty()) {
    tendon_stages_.resize(points.size());
    for (size_t q = 0; q < points.size(); ++q)
      tendon_stages_[q].tendons = SampleTendons(model_.tendons, points[q], model_.length);
  }
  SampleSections();

  const SectionProperties base_section = model_.section->At(0.0, actuation);
  const double EI = std::max(base_section.stiffness(0, 0), base_section.stiffness(1, 1));
  const double L = model_.length;
  scale_ << EI / L, EI / L, EI / L, EI / (L * L), EI / (L * L), EI / (L * L);
  state_.Resize(n);
  for (int i = 0; i < n; ++i) state_.s[i] = grid_[i];
  kept_record_.Resize(n);
  for (int i = 0; i < n; ++i) kept_record_.s[i] = grid_[i];
  kept_tangents_.assign(n, StateTangent::Zero());

  // Rest shape in the base body frame (zero wrench, no tendon tension), for the rigid-body
  // initial guess.
  RodState rest;
  rest.Resize(n);
  Shoot(grid_, samples_, scale_, lie::SE3{}, StaticLoads{}, Vec6::Zero(), &rest, nullptr);
  rest_position_B_ = rest.position_W;
  rest_rotation_B_ = rest.rotation_WB;
}

void StaticShootingSolver::SampleSections() {
  const std::vector<double> points = SegmentSamplePoints(grid_);
  for (size_t q = 0; q < points.size(); ++q) {
    const double s = points[q];
    const SectionProperties p = model_.section->At(s, actuation_);
    Sample& smp = samples_[q];
    smp.compliance = p.stiffness.inverse();
    smp.diagonal = true;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if (i != j && smp.compliance(i, j) != 0.0) smp.diagonal = false;
    smp.compliance_diagonal = smp.compliance.diagonal();
    smp.rest_strain = model_.RestStrainAt(s);
    smp.mass_per_length = p.mass(5, 5);
    if (!tendon_stages_.empty()) tendon_stages_[q].stiffness = p.stiffness;
  }
}

void StaticShootingSolver::SetActuation(const Actuation& actuation) {
  actuation_ = actuation;
  SampleSections();
  state_is_solution_ = false;  // the stored shot belongs to the old actuation
}

void StaticShootingSolver::WarmStartFrom(const lie::SE3& base, const StaticLoads& loads,
                                         const Vec6& base_wrench_B) {
  x_ = base_wrench_B.cwiseQuotient(scale_);
  solved_base_ = base;
  solved_loads_ = loads;
  has_solution_ = true;
  has_jacobian_ = false;       // the Jacobian of another model is no use here
  state_is_solution_ = false;  // the state is not the shot of this guess
}

Vec6 StaticShootingSolver::Residual(const lie::SE3& base, const StaticLoads& loads, const Vec6& x) {
  state_is_solution_ = false;
  if (tendon_stages_.empty())
    return Shoot(grid_, samples_, scale_, base, loads, x, &state_, nullptr);
  const TendonContext tc{&tendon_stages_, actuation_.tendon_tension.data(), tendon_length_.data()};
  return Shoot(grid_, samples_, scale_, base, loads, x, &state_, nullptr, &tc);
}

Mat6 StaticShootingSolver::ResidualJacobian(const lie::SE3& base, const StaticLoads& loads,
                                            const Vec6& x, Vec6* residual) const {
  Mat6 J;
  std::array<double, Actuation::kMaxTendons> lengths{};
  const TendonContext tc{&tendon_stages_, actuation_.tendon_tension.data(), lengths.data()};
  const Vec6 r = Shoot(grid_, samples_, scale_, base, loads, x, nullptr, &J,
                       tendon_stages_.empty() ? nullptr : &tc);
  if (residual) *residual = r;
  return J;
}

Mat6 StaticShootingSolver::ResidualJacobianKeepingTangents(const lie::SE3& base,
                                                           const StaticLoads& loads,
                                                           const Vec6& x, Vec6* residual) {
  Mat6 J;
  std::array<double, Actuation::kMaxTendons> lengths{};
  const TendonContext tc{&tendon_stages_, actuation_.tendon_tension.data(), lengths.data()};
  TangentSeed seed;
  seed.node_rows = kept_tangents_.data();
  const Vec6 r = Shoot(grid_, samples_, scale_, base, loads, x, &kept_record_, &J,
                       tendon_stages_.empty() ? nullptr : &tc, &seed);
  kept_x_ = x;
  kept_base_ = base;
  kept_loads_ = loads;
  has_kept_ = true;
  if (residual) *residual = r;
  return J;
}

bool StaticShootingSolver::TipJacobianWrtTensions(const lie::SE3& base, const StaticLoads& loads,
                                                  TensionJacobian* J) const {
  const int count = static_cast<int>(model_.tendons.size());
  J->setZero();
  if (!state_is_solution_ || count == 0) return false;
  std::array<double, Actuation::kMaxTendons> lengths{};
  Mat36 dp_x, dp_t;
  RotationTangent dR_x, dR_t;
  // d r/d x and the tip pose along x …
  TendonContext tc{
      &tendon_stages_, actuation_.tendon_tension.data(), lengths.data(), -1, &dp_x, &dR_x};
  Mat6 Jx, Jt;
  Shoot(grid_, samples_, scale_, base, loads, x_, nullptr, &Jx, &tc);
  const Eigen::PartialPivLU<Mat6> lu(Jx);
  const Mat3& R = state_.rotation_WB.back();
  // Body-frame rotation: R⁻¹ dR = (δθ)^, δθ read off the skew part.
  auto angle = [&](const RotationTangent& dR, int k) {
    Mat3 M;
    for (int j = 0; j < 3; ++j) M.col(j) = R.transpose() * dR[j].col(k);
    return Vec3(0.5 * (M(2, 1) - M(1, 2)), 0.5 * (M(0, 2) - M(2, 0)), 0.5 * (M(1, 0) - M(0, 1)));
  };
  // … then, six tendons at a time, d r/d τ and the tip pose along τ at fixed x; implicit
  // function theorem: dx/dτ = −Jx⁻¹ Jτ, d tip/dτ = T_x dx/dτ + T_τ.
  for (int k0 = 0; k0 < count; k0 += 6) {
    tc.tension_block = k0;
    tc.tip_dp = &dp_t;
    tc.tip_dR = &dR_t;
    Shoot(grid_, samples_, scale_, base, loads, x_, nullptr, &Jt, &tc);
    const Mat6 dx = -lu.solve(Jt);
    for (int j = 0; j < 6 && k0 + j < count; ++j) {
      Vec3 dp = dp_t.col(j), dth = angle(dR_t, j);
      for (int k = 0; k < 6; ++k) {
        dp += dp_x.col(k) * dx(k, j);
        dth += angle(dR_x, k) * dx(k, j);
      }
      J->col(k0 + j) << dp, dth;
    }
  }
  return J->allFinite();
}

StaticShootingSolver::StateTangent StaticShootingSolver::ShootTangent(
    const lie::SE3& base, const StaticLoads& loads, const Vec6& base_wrench_B,
    const StateTangent& start, RodState* record, std::vector<StateTangent>* node_tangents) const {
  const ShotTangent start_t = FromRows(start);
  ShotTangent tip_t;
  std::vector<ShotTangent> nodes;
  if (node_tangents) nodes.resize(grid_.size());
  const TangentSeed seed{&start_t, node_tangents ? &nodes : nullptr, &tip_t};
  if (record && record->size() != static_cast<int>(grid_.size())) {
    record->Resize(static_cast<int>(grid_.size()));
    for (size_t i = 0; i < grid_.size(); ++i) record->s[i] = grid_[i];
  }
  Mat6 J;
  std::array<double, Actuation::kMaxTendons> lengths{};
  const TendonContext tc{&tendon_stages_, actuation_.tendon_tension.data(), lengths.data()};
  Shoot(grid_, samples_, scale_, base, loads, base_wrench_B.cwiseQuotient(scale_), record, &J,
        tendon_stages_.empty() ? nullptr : &tc, &seed);
  if (node_tangents) {
    node_tangents->resize(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i) (*node_tangents)[i] = ToRows(nodes[i]);
  }
  return ToRows(tip_t);
}

namespace {
bool SameLoads(const StaticLoads& a, const StaticLoads& b) {
  return a.gravity_W == b.gravity_W && a.distributed_force_W == b.distributed_force_W &&
         a.tip_force == b.tip_force && a.tip_moment == b.tip_moment &&
         a.tip_force_frame == b.tip_force_frame && a.tip_moment_frame == b.tip_moment_frame;
}
}  // namespace

int StaticShootingSolver::IndexAfterSolve(const lie::SE3& base, const StaticLoads& loads,
                                          const Vec6& x) const {
  // Levenberg–Marquardt's last Jacobian shot is at its solution: its node states and tangents
  // are the Jacobi fields the count needs, with no shot of its own.
  if (has_kept_ && kept_x_ == x && kept_base_.R == base.R && kept_base_.p == base.p &&
      SameLoads(kept_loads_, loads))
    return StabilityIndexFromShot(loads, kept_record_, kept_tangents_);
  return StabilityIndex(base, loads, scale_.cwiseProduct(x));
}

bool StaticShootingSolver::FollowStablePath(const lie::SE3& base, const StaticLoads& loads,
                                            double max_fraction, Vec6* x_out,
                                            StaticShootingSummary* summary) {
  // Natural-parameter continuation from the unloaded rod (W ≡ 0: stable, the energy is a
  // positive definite quadratic about the rest shape) along loads(μ) = μ · loads, with a secant
  // predictor; a step is accepted only if it converges on an equilibrium without unstable
  // directions, otherwise halved. Along an imperfect path (no bifurcation) the stable branch is
  // connected to μ = 0, and small enough steps follow it through its sharp turn near P_cr.
  const StaticLoads zero = loads.Scaled(0.0);
  Vec6 x_a = Vec6::Zero(), x_prev = Vec6::Zero();
  double mu = 0.0, mu_prev = 0.0, dmu = max_fraction;
  int steps = 0;
  while (summary->load_steps + steps < options_.max_load_steps) {
    const double mu_try = std::min(1.0, mu + dmu);
    const StaticLoads target = mu_try == 1.0 ? loads : StaticLoads::Blend(zero, loads, mu_try);
    Vec6 guess = x_a;
    if (mu > mu_prev) guess += (x_a - x_prev) * ((mu_try - mu) / (mu - mu_prev));
    ++steps;
    const double tol =
        mu_try == 1.0 ? options_.tolerance : std::max(options_.tolerance, kIntermediateTolerance);
    if (TryLevenbergMarquardt(base, target, tol, &guess, summary) &&
        IndexAfterSolve(base, target, guess) == 0) {
      x_prev = x_a;
      mu_prev = mu;
      x_a = guess;
      mu = mu_try;
      if (mu == 1.0) {
        *x_out = x_a;
        summary->stable_path_steps = steps;
        return true;
      }
      dmu = std::min({2.0 * dmu, max_fraction, 1.0 - mu});
    } else {
      dmu *= 0.5;
      if (dmu < options_.min_load_step) break;
    }
  }
  summary->stable_path_steps = steps;
  return false;
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
      J = solver->ResidualJacobianKeepingTangents(*base, *loads, x, &r_value);
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
  lm.options.max_num_iterations = options_.max_iterations + 1;  // TinySolver runs n − 1 steps
  lm.options.cost_threshold = 0.5 * tolerance * tolerance;
  lm.options.gradient_tolerance = 0.0;  // stop on the residual only
  lm.options.parameter_tolerance = 1e-15;
  lm.options.function_tolerance = 0.0;
  Vec6 xt = *x;
  const auto& s = lm.Solve(cost, &xt);
  summary->iterations += s.iterations;
  // Decide on a residual evaluated here: TinySolver's final cost is not set when the first
  // evaluation is not finite.
  const double res = xt.allFinite() ? Residual(base, loads, xt).norm() : NAN;
  ++summary->shots;
  if (!std::isfinite(res)) {
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
  Vec6 r;
  if (state_is_solution_ && loads.gravity_W == solved_loads_.gravity_W &&
      loads.distributed_force_W == solved_loads_.distributed_force_W) {
    // Only the tip load changed: the stored shot of the previous solution is the shot at x, and
    // only its tip condition differs. No integration needed.
    r = TipResidual(state_.rotation_WB.back(), state_.wrench_B.back(), loads, scale_);
  } else {
    r = Residual(base, loads, x);
    ++summary->shots;
  }
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
  if (!loads.IsValid(nullptr) || !base.R.allFinite() || !base.p.allFinite()) {
    summary.status = SolveStatus::kNonFinite;  // NaN or Inf in the input: nothing to solve
    summary.residual = NAN;
    return summary;
  }

  // Start from a known solution: the previous one at the same base, else the unloaded rod
  // (W ≡ 0 is exact at zero load, whatever the rest shape).
  // (Continuation blends loads, so their tip-load frames must match too.)
  const bool from_previous = has_solution_ && (solved_base_.R - base.R).norm() == 0.0 &&
                             (solved_base_.p - base.p).norm() == 0.0 &&
                             solved_loads_.tip_force_frame == loads.tip_force_frame &&
                             solved_loads_.tip_moment_frame == loads.tip_moment_frame;
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
  bool via_quasi_newton = false;
  if (max_fraction == 1.0) {
    if (from_previous && has_jacobian_ && options_.reuse_jacobian) {
      ok = TryQuasiNewton(base, loads, &x, &summary);
      state_current = ok;
      via_quasi_newton = ok;
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
      summary.status =
          options_.load_stepping ? SolveStatus::kLoadSteppingFailed : SolveStatus::kMaxIterations;
  }

  // Stability (options_.stable_branch): a Newton-type solve converges to whichever equilibrium
  // is nearest its start, and past a critical load the nearest one can be unstable (a column at
  // 1.15 P_cr with a small imperfection: the near-straight state beside the start, deflected
  // against the imperfection). Step control on the size of the correction does not see this —
  // the unstable root is the one near the predictor — so the converged equilibrium is checked
  // instead, from Levenberg–Marquardt's last Jacobian shot (taken at the solution). A
  // quasi-Newton warm re-solve is not checked: it continues the previous solution by steps that
  // halve the residual, and takes no tangent shot (17 µs; a check would add one, ≈ 53 µs).
  if (ok && options_.stable_branch && !via_quasi_newton) {
    summary.stability_index = IndexAfterSolve(base, loads, x);
    if (summary.stability_index > 0) {
      Vec6 x_stable = x;
      const Mat6 J_first = jacobian_;  // d r/d x at x, for the next warm start if we keep x
      if (FollowStablePath(base, loads, max_fraction, &x_stable, &summary)) {
        x = x_stable;
        summary.stability_index = 0;
      } else {
        jacobian_ = J_first;
      }
      state_current = false;
    }
  }

  if (!state_current) {
    const Vec6 r = Residual(base, loads, x);
    ++summary.shots;
    summary.residual = r.norm();
    if (!r.allFinite()) ok = false;
    if (!r.allFinite()) summary.status = SolveStatus::kNonFinite;
  }
  if (ok) {
    state_is_solution_ = true;
    summary.status = SolveStatus::kConverged;
    x_ = x;
    solved_base_ = base;
    solved_loads_ = loads;
    has_solution_ = true;
  }
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

}  // namespace cosserat
