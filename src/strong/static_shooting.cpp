#include "cosserat/strong/static_shooting.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>

#include "cosserat/lie/so3.hpp"
#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/constitutive/tendon_law.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/rod/grid.hpp"
#include "frame_tangent.hpp"

namespace cosserat {

namespace {

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

// ξ = ξ* + C W, C = K⁻¹ (diagonal: sections are principal-axes, constitutive/section_law.hpp).
COSSERAT_HOT Vec6 Compliance(const Sample& smp, const Vec6& W) {
  return smp.rest_strain + smp.compliance_diagonal.cwiseProduct(W);
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
  // Compliance written out: this is the innermost loop of every solve.
  const double* c = smp.compliance_diagonal.data();
  const double* r = smp.rest_strain.data();
  (*xi)(0) = r[0] + c[0] * y.m(0);
  (*xi)(1) = r[1] + c[1] * y.m(1);
  (*xi)(2) = r[2] + c[2] * y.m(2);
  (*xi)(3) = r[3] + c[3] * y.n(0);
  (*xi)(4) = r[4] + c[4] * y.n(1);
  (*xi)(5) = r[5] + c[5] * y.n(2);
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
  const Mat6 dxi = H ? Mat6(H->partialPivLu().solve(dW))
                     : Mat6(smp.compliance_diagonal.asDiagonal() * dW);
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
  return (W_tip_B - TipWrenchInBody(TotalTipWrench(loads), R_tip)).cwiseQuotient(scale);
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
    return TotalDistributedForce_W(loads, {smp.s, 1.0, smp.mass_per_length});
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
    // d(Rᵀ w_dead) for the dead part of the tip wrench; the follower part does not turn.
    const SplitWrench tip = TotalTipWrench(loads);
    J->topRows<3>() -= TransposeTimesFixed(dy.R, Vec3(tip.dead_W.head<3>()));
    J->bottomRows<3>() -= TransposeTimesFixed(dy.R, Vec3(tip.dead_W.tail<3>()));
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
    const SectionLaw law = SectionLaw::At(model_, s, actuation_);
    Sample& smp = samples_[q];
    smp.compliance_diagonal = law.stiffness.cwiseInverse();
    smp.rest_strain = law.rest_strain;
    smp.mass_per_length = law.mass_per_length();
    smp.s = s;
    if (!tendon_stages_.empty()) tendon_stages_[q].stiffness = law.stiffness.asDiagonal();
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

Vec6 StaticShootingSolver::StoredShotResidual(const StaticLoads& loads) const {
  return TipResidual(state_.rotation_WB.back(), state_.wrench_B.back(), loads, scale_);
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

}  // namespace cosserat
