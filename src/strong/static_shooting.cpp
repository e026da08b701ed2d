#include "cosserat/strong/static_shooting.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/constitutive/tendon_law.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/rod/grid.hpp"
#include "cosserat/strong/frame_tangent.hpp"
#include "cosserat/strong/shot_tangent.hpp"
#include "cosserat/strong/spatial_scheme.hpp"

namespace cosserat {

namespace {

#if defined(__GNUC__)
#define COSSERAT_HOT inline __attribute__((always_inline))
#else
#define COSSERAT_HOT inline
#endif

using Sample = StaticShootingSolver::Sample;
using namespace internal;
using internal::Axpy;  // the scheme on states (spatial_scheme.hpp)
using internal::Rk4Update;

// The integration state and its tangent along the 6 unknowns (cosserat_rhs.hpp,
// shot_tangent.hpp): RK4 applied to (state, tangent) gives the exact derivative of the discrete
// map.
using ShotState = rhs::StaticPoint<double>;
using ShotTangent = rhs::StaticTangent;

static_assert(sizeof(ShotState) == 18 * sizeof(double), "ShotState must be 18 packed doubles");

ShotTangent Axpy(const ShotTangent& y, double a, const ShotTangent& d) {
  return {y.p + a * d.p,
          {y.R[0] + a * d.R[0], y.R[1] + a * d.R[1], y.R[2] + a * d.R[2]},
          y.m + a * d.m,
          y.n + a * d.n};
}

// RK4 combination y += h/6 (k1 + 2 k2 + 2 k3 + k4) for tangents (states: spatial_scheme.hpp).
void Rk4Update(double h, const ShotTangent& k1, const ShotTangent& k2, const ShotTangent& k3,
               const ShotTangent& k4, ShotTangent* y) {
  const double a = h / 6, b = h / 3;
  y->p += a * (k1.p + k4.p) + b * (k2.p + k3.p);
  for (int j = 0; j < 3; ++j) y->R[j] += a * (k1.R[j] + k4.R[j]) + b * (k2.R[j] + k3.R[j]);
  y->m += a * (k1.m + k4.m) + b * (k2.m + k3.m);
  y->n += a * (k1.n + k4.n) + b * (k2.n + k3.n);
}

COSSERAT_HOT Vec6 BodyWrench(const ShotState& y) {
  Vec6 W;
  W.head<3>() = y.m;
  W.tail<3>() = y.n;
  return W;
}

// The plain rod's derivative (cosserat_rhs.hpp): strain from the linear law, then the rates.
COSSERAT_HOT ShotState Derivative(const Sample& smp, const Vec3& f_W, const ShotState& y,
                                  Vec6* xi) {
  return rhs::StaticDerivative<double>(smp.rest_strain, smp.compliance_diagonal, f_W, y, xi);
}

// With tendons, the strain solves K (ξ − ξ*) + Σ τ a(ξ) = W (tendons.hpp), starting from the
// guess in *xi; H = K + ∂(Σ τ a)/∂ξ is written for the tangent. A failed solve gives NaN rates.
ShotState TendonDerivative(const Sample& smp, const StaticShootingSolver::TendonStage& ts,
                           const double* tension, const Vec3& f_W, const ShotState& y, Vec6* xi,
                           Mat6* H) {
  if (!SolveTendonStrain(ts.stiffness, smp.rest_strain, ts.tendons, tension, BodyWrench(y), xi, H))
    xi->setConstant(NAN);
  return rhs::StaticRates<double>(*xi, f_W, y);
}

// The linearisation of Derivative along dy (shot_tangent.hpp).
ShotTangent TangentDerivative(const Sample& smp, const Vec3& f_W, const ShotState& y,
                              const ShotTangent& dy, const Vec6& xi, const Mat6* H,
                              const Mat6* source, const Mat36* df_W) {
  return rhs::StaticTangentDerivative(smp.compliance_diagonal, f_W, y, dy, xi, H, source, df_W);
}

// Tip condition W(L) = W_tip in the tip body frame, made dimensionless by scale.
Vec6 TipResidual(const Mat3& R_tip, const Vec6& W_tip_B, const StaticLoads& loads,
                 const Vec6& scale) {
  return (W_tip_B - TipWrenchInBody(TotalTipWrench(loads), R_tip)).cwiseQuotient(scale);
}

// What a shot with tendons needs: each stage's tendon routing and the tensions (N); it returns
// the tendon path lengths (m) and, with a tangent, the tip's sensitivities.
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

// The tangent at s = 0: along the unknowns W(0) = scale ⊙ x, or zero when the directions are
// tendon tensions, or the seed's start value.
ShotTangent StartTangent(const Vec6& scale, const TendonContext* tc, const TangentSeed* seed) {
  if (seed && seed->start) return *seed->start;
  ShotTangent dy;
  dy.p.setZero();
  for (auto& c : dy.R) c.setZero();
  dy.m.setZero();
  dy.n.setZero();
  if (!(tc && tc->tension_block >= 0)) {
    dy.m.leftCols<3>() = scale.head<3>().asDiagonal();
    dy.n.rightCols<3>() = scale.tail<3>().asDiagonal();
  }
  return dy;
}

// The primal values of one RK4 segment's four stages the tangent needs: states, strains,
// distributed forces, sample indices and, with tendons, the law's ∂W/∂ξ.
struct SegmentStages {
  const ShotState* y[4];
  const Vec6* xi[4];
  const Vec3* f[4];
  const Mat6* H;  // 4 of them
  int q[4];
  const MotionJacobian* motion;  // 4 of them, for loads that depend on the pose; else null
};

// Carries the tangent dy through one RK4 segment of length h (the exact derivative of the
// discrete shot). With tension directions, the law's source term enters at every stage.
void PropagateSegment(const std::vector<Sample>& samples, const SegmentStages& st, double h,
                      const TendonContext* tc, ShotTangent* dy) {
  const bool tendons = tc != nullptr;
  const bool tension = tc && tc->tension_block >= 0;
  Mat6 src[4];
  if (tension)
    for (int j = 0; j < 4; ++j)
      src[j] = TensionSource((*tc->stages)[st.q[j]], tc->tension, *st.xi[j], tc->tension_block);
  const double step[4] = {0.0, 0.5, 0.5, 1.0};
  ShotTangent t[4];
  for (int j = 0; j < 4; ++j) {
    ShotTangent stage;
    if (j > 0) stage = Axpy(*dy, step[j] * h, t[j - 1]);
    const ShotTangent& dyj = j == 0 ? *dy : stage;
    Mat36 df;  // d f_W = ∂f/∂p dp + ∂f/∂t d(R e₃)
    if (st.motion) df = st.motion[j].position * dyj.p + st.motion[j].tangent * dyj.R[2];
    t[j] = TangentDerivative(samples[st.q[j]], *st.f[j], *st.y[j], dyj, *st.xi[j],
                             tendons ? &st.H[j] : nullptr, tension ? &src[j] : nullptr,
                             st.motion ? &df : nullptr);
  }
  Rk4Update(h, t[0], t[1], t[2], t[3], dy);
}

// d r / d x at the tip from the tangent: the section's wrench less the dead part of the tip
// wrench turning with the tip (the follower part does not turn), scaled.
Mat6 TipJacobian(const ShotTangent& dy, const StaticLoads& loads, const Vec6& scale) {
  Mat6 J;
  J.topRows<3>() = dy.m;
  J.bottomRows<3>() = dy.n;
  const SplitWrench tip = TotalTipWrench(loads);
  J.topRows<3>() -= TransposeTimesFixed(dy.R, Vec3(tip.dead_W.head<3>()));
  J.bottomRows<3>() -= TransposeTimesFixed(dy.R, Vec3(tip.dead_W.tail<3>()));
  return scale.cwiseInverse().asDiagonal() * J;
}

// The strain at the tip (quadrature sample q_tip) from the tip state: the linear law, or the
// tendon law started from the last stage's strain (NaN when it fails).
Vec6 TipStrain(const std::vector<Sample>& samples, int q_tip, const ShotState& y,
               const TendonContext* tc, const Vec6& guess) {
  const Sample& tip = samples[q_tip];
  Vec6 xi_tip;
  rhs::LinearStrain<double>(tip.rest_strain, tip.compliance_diagonal, y.m, y.n, &xi_tip);
  if (!tc) return xi_tip;
  xi_tip = guess;
  if (!SolveTendonStrain((*tc->stages)[q_tip].stiffness, tip.rest_strain,
                         (*tc->stages)[q_tip].tendons, tc->tension, BodyWrench(y), &xi_tip,
                         nullptr))
    xi_tip.setConstant(NAN);
  return xi_tip;
}

// Hands the tip tangent dy (node n − 1) to the seed and the tendon context; returns d r / d x.
Mat6 FinishTipTangent(const ShotTangent& dy, const StaticLoads& loads, const Vec6& scale, int n,
                      const TendonContext* tc, const TangentSeed* seed) {
  if (seed && seed->nodes) seed->nodes->back() = dy;
  if (seed && seed->node_rows) seed->node_rows[n - 1] = ToRows(dy);
  if (seed && seed->tip) *seed->tip = dy;
  if (tc && tc->tip_dp) *tc->tip_dp = dy.p;
  if (tc && tc->tip_dR) *tc->tip_dR = dy.R;
  return TipJacobian(dy, loads, scale);
}

// Integrates from s = 0 to L with RK4 on the grid and returns the dimensionless tip residual.
// With record, writes the node values; with J, propagates the tangent and writes d r / d x.
// With tendons (tc not null): the tendon strain law at every stage, and the tendon path lengths
// by the same RK4 quadrature.
// kMotion: some load depends on the pose (compiled apart, so the plain shot stays as lean).
template <bool kMotion>
Vec6 ShootWith(const std::vector<double>& grid, const std::vector<Sample>& samples,
               const Vec6& scale, const lie::SE3& base, const StaticLoads& loads, const Vec6& x,
               RodState* record, Mat6* J, const TendonContext* tc, const TangentSeed* seed) {
  const int n = static_cast<int>(grid.size());
  const Vec6 W0 = scale.cwiseProduct(x);
  ShotState y{base.p, base.R, W0.head<3>(), W0.tail<3>()};
  ShotTangent dy;
  if (J) dy = StartTangent(scale, tc, seed);
  auto record_node = [&](int i, const Vec6& xi) {
    record->position_W[i] = y.p;
    record->rotation_WB[i] = y.R;
    record->wrench_B[i] = BodyWrench(y);
    record->strain[i] = xi;
  };
  Vec6 xi1, xi2, xi3, xi4;
  Mat6 H[4];
  Vec6 guess = samples.front().rest_strain;  // tendon strain solves start from the last stage
  const int count = tc ? (*tc->stages)[0].tendons.count : 0;
  for (int k = 0; k < count; ++k) tc->length[k] = 0.0;
  // One stage: the plain law, or the tendon law from the running guess.
  auto derivative = [&](int q, const Vec3& f, const ShotState& ys, Vec6* xi, Mat6* H_q) {
    if (!tc) return Derivative(samples[q], f, ys, xi);
    *xi = guess;
    const ShotState d =
        TendonDerivative(samples[q], (*tc->stages)[q], tc->tension, f, ys, xi, J ? H_q : nullptr);
    guess = *xi;
    return d;
  };
  auto f_at = [&](int q) { return TotalDistributedForce_W(loads, samples[q].Site()); };
  // Loads that depend on the pose (a current's drag): added per stage.
  Vec3 f_stage[4];
  MotionJacobian jac[4];
  auto force = [&](int j, int q, const Vec3& f_dead, const ShotState& ys) -> const Vec3& {
    if constexpr (!kMotion) {
      return f_dead;
    } else {
      const SectionMotion at{ys.p, ys.R.col(2), Vec3::Zero()};
      f_stage[j] = f_dead + TotalMotionForce_W(loads, samples[q].Site(), at, J ? &jac[j] : nullptr);
      return f_stage[j];
    }
  };
  for (int i = 0; i + 1 < n; ++i) {
    const double h = grid[i + 1] - grid[i];
    const int q0 = 3 * i, qm = 3 * i + 1, q1 = 3 * i + 2;
    const Vec3 f0 = f_at(q0), fm = f_at(qm), f1 = f_at(q1);
    const Vec3& fa = force(0, q0, f0, y);
    const ShotState k1 = derivative(q0, fa, y, &xi1, &H[0]);
    if (record) record_node(i, xi1);
    const ShotState y2 = Axpy(y, 0.5 * h, k1);
    const Vec3& fb = force(1, qm, fm, y2);
    const ShotState k2 = derivative(qm, fb, y2, &xi2, &H[1]);
    const ShotState y3 = Axpy(y, 0.5 * h, k2);
    const Vec3& fc = force(2, qm, fm, y3);
    const ShotState k3 = derivative(qm, fc, y3, &xi3, &H[2]);
    const ShotState y4 = Axpy(y, h, k3);
    const Vec3& fd = force(3, q1, f1, y4);
    const ShotState k4 = derivative(q1, fd, y4, &xi4, &H[3]);
    if (J) {
      if (seed && seed->nodes) (*seed->nodes)[i] = dy;
      if (seed && seed->node_rows) seed->node_rows[i] = ToRows(dy);
      const SegmentStages st{{&y, &y2, &y3, &y4}, {&xi1, &xi2, &xi3, &xi4}, {&fa, &fb, &fc, &fd}, H,
                             {q0, qm, qm, q1},    kMotion ? jac : nullptr};
      PropagateSegment(samples, st, h, tc, &dy);
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
  if (record) record_node(n - 1, TipStrain(samples, 3 * (n - 2) + 2, y, tc, guess));
  if (J) *J = FinishTipTangent(dy, loads, scale, n, tc, seed);
  return TipResidual(y.R, BodyWrench(y), loads, scale);
}

Vec6 Shoot(const std::vector<double>& grid, const std::vector<Sample>& samples, const Vec6& scale,
           const lie::SE3& base, const StaticLoads& loads, const Vec6& x, RodState* record, Mat6* J,
           const TendonContext* tc = nullptr, const TangentSeed* seed = nullptr) {
  if (HasMotionLoads(loads))
    return ShootWith<true>(grid, samples, scale, base, loads, x, record, J, tc, seed);
  return ShootWith<false>(grid, samples, scale, base, loads, x, record, J, tc, seed);
}

}  // namespace

StaticShootingSolver::StaticShootingSolver(const RodModel& model, int num_nodes,
                                           const StaticShootingOptions& options,
                                           const Actuation& actuation)
    : model_(model), options_(options), actuation_(actuation) {
  std::string why;
  if (!options_.IsValid(&why)) throw std::invalid_argument("StaticShootingOptions: " + why);
  if (!model_.IsValid(&why)) throw std::invalid_argument("RodModel: " + why);
  actuation_.Require(static_cast<int>(model_.tendons.size()),
                     static_cast<int>(model_.chambers.size()));
  grid_ = ModelGrid(model_, num_nodes);
  const int n = static_cast<int>(grid_.size());
  sample_points_ = SegmentSamplePoints(grid_);
  samples_.resize(sample_points_.size());
  if (!model_.tendons.empty()) {
    tendon_stages_.resize(sample_points_.size());
    for (size_t q = 0; q < sample_points_.size(); ++q)
      tendon_stages_[q].tendons = SampleTendons(model_.tendons, sample_points_[q], model_.length);
  }
  SampleSections();

  const SectionProperties base_section = model_.section->At(0.0, actuation);
  const double EI = base_section.max_bending_stiffness();
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

namespace {

StaticShootingSolver::Sample SampleOf(const SectionLaw& law, double s) {
  StaticShootingSolver::Sample smp;
  smp.compliance_diagonal = law.stiffness.cwiseInverse();
  smp.rest_strain = law.rest_strain;
  smp.mass_per_length = law.mass_per_length();
  smp.s = s;
  smp.outer_diameter = law.outer_diameter;
  return smp;
}

}  // namespace

StaticShootingSolver::Sample StaticShootingSolver::SampleAt(double s) const {
  return SampleOf(SectionLaw::At(model_, s, actuation_), s);
}

void StaticShootingSolver::SampleSections() {
  for (size_t q = 0; q < sample_points_.size(); ++q) {
    const SectionLaw law = SectionLaw::At(model_, sample_points_[q], actuation_);
    samples_[q] = SampleOf(law, sample_points_[q]);
    if (!tendon_stages_.empty()) tendon_stages_[q].stiffness = law.stiffness.asDiagonal();
  }
}

void StaticShootingSolver::SetActuation(const Actuation& actuation) {
  actuation.Require(static_cast<int>(model_.tendons.size()),
                    static_cast<int>(model_.chambers.size()));
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
                                                           const StaticLoads& loads, const Vec6& x,
                                                           Vec6* residual) {
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
  if (J == nullptr)
    throw std::invalid_argument("StaticShootingSolver::TipJacobianWrtTensions: J is null");
  const int count = static_cast<int>(model_.tendons.size());
  J->setZero();
  if (!state_is_solution_ || count == 0) return false;
  // The derivative of the last solve's equilibrium: another base or other loads would give the
  // tangents of a state that is not one (a Jacobian 17 % off, returned as if true).
  if (!(loads == solved_loads_) || base.p != solved_base_.p || base.R != solved_base_.R)
    throw std::invalid_argument(
        "StaticShootingSolver::TipJacobianWrtTensions: base and loads must be those of the last "
        "converged Solve");
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

StaticShootingSolver::StateTangent StaticShootingSolver::ShootTangentOn(
    const std::vector<double>& grid, const std::vector<Sample>& samples, const lie::SE3& start,
    const Vec6& wrench_B, const StateTangent& start_tangent, const StaticLoads& loads,
    RodState* piece, std::vector<StateTangent>* tangents) const {
  const ShotTangent start_t = FromRows(start_tangent);
  ShotTangent tip_t;
  std::vector<ShotTangent> nodes(grid.size());
  const TangentSeed seed{&start_t, &nodes, &tip_t};
  piece->Resize(static_cast<int>(grid.size()));
  for (size_t j = 0; j < grid.size(); ++j) piece->s[j] = grid[j];
  Mat6 J;
  Shoot(grid, samples, scale_, start, loads, wrench_B.cwiseQuotient(scale_), piece, &J, nullptr,
        &seed);
  tangents->resize(nodes.size());
  for (size_t j = 0; j < nodes.size(); ++j) (*tangents)[j] = ToRows(nodes[j]);
  return ToRows(tip_t);
}

bool StaticShootingSolver::ShootSegmentRefined(int i, int parts, const StaticLoads& loads,
                                               const RodState& record,
                                               const std::vector<StateTangent>& node_tangents,
                                               RodState* states,
                                               std::vector<StateTangent>* tangents) const {
  const int n = static_cast<int>(grid_.size());
  if (!tendon_stages_.empty() || parts < 1 || i < 0 || i + 1 >= n || record.size() != n ||
      static_cast<int>(node_tangents.size()) != n)
    return false;
  std::vector<double> grid(parts + 1);
  for (int k = 0; k <= parts; ++k) grid[k] = grid_[i] + (grid_[i + 1] - grid_[i]) * k / parts;
  grid.back() = grid_[i + 1];
  std::vector<Sample> samples;
  for (const double s : SegmentSamplePoints(grid)) samples.push_back(SampleAt(s));
  ShootTangentOn(grid, samples, lie::SE3{record.rotation_WB[i], record.position_W[i]},
                 record.wrench_B[i], node_tangents[i], loads, states, tangents);
  return states->position_W.back().allFinite();
}

StaticShootingSolver::StateTangent StaticShootingSolver::ShootTangentBetween(
    int first, int last, const lie::SE3& start, const Vec6& wrench_B,
    const StateTangent& start_tangent, const StaticLoads& loads, RodState* record,
    std::vector<StateTangent>* node_tangents) const {
  if (!tendon_stages_.empty())
    throw std::logic_error("StaticShootingSolver::ShootTangentBetween: not for rods with tendons");
  // The piece's grid and its samples (three per segment, from 3 first on).
  const std::vector<double> grid(grid_.begin() + first, grid_.begin() + last + 1);
  const std::vector<Sample> samples(samples_.begin() + 3 * first, samples_.begin() + 3 * last);
  RodState piece;
  std::vector<StateTangent> tangents;
  const StateTangent tip =
      ShootTangentOn(grid, samples, start, wrench_B, start_tangent, loads, &piece, &tangents);
  for (int i = first; i <= last; ++i) {
    const int j = i - first;
    record->position_W[i] = piece.position_W[j];
    record->rotation_WB[i] = piece.rotation_WB[j];
    record->wrench_B[i] = piece.wrench_B[j];
    record->strain[i] = piece.strain[j];
    (*node_tangents)[i] = tangents[j];
  }
  return tip;
}

}  // namespace cosserat
