#include "cosserat/strong/bdf2_stepper.hpp"

#include <ceres/tiny_solver.h>

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "cosserat/loads/tendons.hpp"
#include "cosserat/rod/grid.hpp"
#include "cosserat/strong/secant_filter.hpp"
#include "frame_tangent.hpp"

namespace cosserat {

bool Bdf2Options::IsValid(std::string* why) const {
  auto fail = [&](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (!(std::isfinite(dt) && dt > 0)) return fail("dt must be a finite positive number");
  if (!(std::isfinite(tolerance) && tolerance > 0)) return fail("tolerance must be positive");
  if (max_iterations < 1) return fail("max_iterations must be at least 1");
  if (max_halvings < 0) return fail("max_halvings must be >= 0");
  if (!(std::isfinite(tip_mass) && tip_mass >= 0)) return fail("tip_mass must be finite and >= 0");
  if (!(tip_inertia_B.allFinite() && (tip_inertia_B.array() >= 0).all()))
    return fail("tip_inertia must be finite and >= 0");
  if (shooting_segments < 1) return fail("shooting_segments must be at least 1");
  if (spatial_scheme != SpatialScheme::kRk4 && spatial_scheme != SpatialScheme::kHeun)
    return fail("spatial_scheme must be rk4 or heun");
  return true;
}

namespace {

using Sample = Bdf2ShootingStepper::Sample;
using Coefficients = Bdf2ShootingStepper::Coefficients;

// The secant filter's covariance for a Jacobian just computed exactly (SolveStep): unit
// variance for J's rows, 1e-2 for their change per step, uncorrelated (only ratios matter).

#if defined(__GNUC__)
#define COSSERAT_HOT inline __attribute__((always_inline))
#define COSSERAT_HOT_LAMBDA __attribute__((always_inline))
#else
#define COSSERAT_HOT inline
#define COSSERAT_HOT_LAMBDA
#endif

// Integration state in s: pose in the world, wrench and twist in the body frame.
struct DynState {
  Vec3 p;  // p_W, m
  Mat3 R;  // R_WB
  Vec3 m;  // N·m
  Vec3 n;  // n_W, N: world frame, so that the scheme sums the balance of linear momentum exactly
  Vec3 w;  // ω, rad/s
  Vec3 v;  // m/s
};
static_assert(sizeof(DynState) == 24 * sizeof(double), "DynState must be 24 packed doubles");

COSSERAT_HOT DynState Axpy(const DynState& y, double a, const DynState& d) {
  DynState out;
  const double* py = y.p.data();
  const double* pd = d.p.data();
  double* o = out.p.data();
  for (int i = 0; i < 24; ++i) o[i] = py[i] + a * pd[i];
  return out;
}

// y += h Σ_j b_j k_j for the two schemes (spatial_scheme.hpp): RK4 and Heun.
COSSERAT_HOT void Rk4Update(double h, const DynState& k1, const DynState& k2, const DynState& k3,
                            const DynState& k4, DynState* y) {
  const double a = h / 6, b = h / 3;
  const double *p1 = k1.p.data(), *p2 = k2.p.data(), *p3 = k3.p.data(), *p4 = k4.p.data();
  double* o = y->p.data();
  for (int i = 0; i < 24; ++i) o[i] += a * (p1[i] + p4[i]) + b * (p2[i] + p3[i]);
}

COSSERAT_HOT void HeunUpdate(double h, const DynState& k1, const DynState& k2, DynState* y) {
  const double a = 0.5 * h;
  const double *p1 = k1.p.data(), *p2 = k2.p.data();
  double* o = y->p.data();
  for (int i = 0; i < 24; ++i) o[i] += a * (p1[i] + p2[i]);
}

// d/ds of the state at one stage point (see the header for the equations), written out: this is
// the innermost loop of every step. Writes the strain and twist of the stage for the history.
// With tendons, `given` is the strain of the tendon-augmented law (solved by the caller).
COSSERAT_HOT DynState Derivative(const Sample& smp, const Vec3& f_W, const DynState& y,
                                 const Vec6& xi_h, const Vec6& V_h, const Vec3& v_W_h, double c0,
                                 bool statics, Vec6* strain, Vec6* twist, Vec3* velocity_W,
                                 const Vec6* given = nullptr) {
  const Mat3& R = y.R;
  const double m0 = y.m(0), m1 = y.m(1), m2 = y.m(2);
  const Vec3 n_B = R.transpose() * y.n;
  const double n0 = n_B(0), n1 = n_B(1), n2 = n_B(2);
  const double w0 = y.w(0), w1 = y.w(1), w2 = y.w(2);
  const double v0 = y.v(0), v1 = y.v(1), v2 = y.v(2);
  double xi[6], xt[6], Vt[6];
  const double W[6] = {m0, m1, m2, n0, n1, n2};
  if (given && statics) {
    for (int i = 0; i < 6; ++i) {
      xi[i] = (*given)(i);
      xt[i] = 0.0;
      Vt[i] = 0.0;
    }
  } else if (statics) {
    for (int i = 0; i < 6; ++i) {
      xi[i] = smp.rest_strain(i) + smp.compliance(i) * W[i];
      xt[i] = 0.0;
      Vt[i] = 0.0;
    }
  } else {
    // W = K (ξ − ξ*) + D (c0 ξ + ξʰ)  ⇒  ξ = [ξ* − c0 A D ξ*] + A W − A D ξʰ, A = (K + c0 D)⁻¹;
    // with D = 0 this is the static law, operation for operation.
    if (given) {
      for (int i = 0; i < 6; ++i) xi[i] = (*given)(i);
    } else {
      for (int i = 0; i < 6; ++i)
        xi[i] = smp.implicit_offset(i) + smp.implicit_compliance(i) * W[i];
      if (smp.damped)
        for (int i = 0; i < 6; ++i) xi[i] -= smp.implicit_damping(i) * xi_h(i);
    }
    for (int i = 0; i < 6; ++i) xt[i] = c0 * xi[i] + xi_h(i);
    Vt[0] = c0 * w0 + V_h(0);
    Vt[1] = c0 * w1 + V_h(1);
    Vt[2] = c0 * w2 + V_h(2);
    Vt[3] = c0 * v0 + V_h(3);
    Vt[4] = c0 * v1 + V_h(4);
    Vt[5] = c0 * v2 + V_h(5);
  }
  for (int i = 0; i < 6; ++i) (*strain)(i) = xi[i];
  (*twist) << w0, w1, w2, v0, v1, v2;
  const double k0 = xi[0], k1 = xi[1], k2 = xi[2], g0 = xi[3], g1 = xi[4], g2 = xi[5];
  const double J0 = smp.mass(0), J1 = smp.mass(1), J2 = smp.mass(2), rhoA = smp.mass(5);
  DynState d;
  for (int i = 0; i < 3; ++i) {
    d.p(i) = R(i, 0) * g0 + R(i, 1) * g1 + R(i, 2) * g2;
    d.R(i, 0) = R(i, 1) * k2 - R(i, 2) * k1;  // (R K̂) row i = (row i of R) × K
    d.R(i, 1) = R(i, 2) * k0 - R(i, 0) * k2;
    d.R(i, 2) = R(i, 0) * k1 - R(i, 1) * k0;
  }
  // ω' = K_t + ω × K,  v' = Γ_t + ω × Γ + v × K
  d.w(0) = xt[0] + w1 * k2 - w2 * k1;
  d.w(1) = xt[1] + w2 * k0 - w0 * k2;
  d.w(2) = xt[2] + w0 * k1 - w1 * k0;
  d.v(0) = xt[3] + w1 * g2 - w2 * g1 + v1 * k2 - v2 * k1;
  d.v(1) = xt[4] + w2 * g0 - w0 * g2 + v2 * k0 - v0 * k2;
  d.v(2) = xt[5] + w0 * g1 - w1 * g0 + v0 * k1 - v1 * k0;
  // m' = m × K + n × Γ + J ω_t + ω × J ω
  const double Jw0 = J0 * w0, Jw1 = J1 * w1, Jw2 = J2 * w2;
  d.m(0) = m1 * k2 - m2 * k1 + n1 * g2 - n2 * g1 + J0 * Vt[0] + w1 * Jw2 - w2 * Jw1;
  d.m(1) = m2 * k0 - m0 * k2 + n2 * g0 - n0 * g2 + J1 * Vt[1] + w2 * Jw0 - w0 * Jw2;
  d.m(2) = m0 * k1 - m1 * k0 + n0 * g1 - n1 * g0 + J2 * Vt[2] + w0 * Jw1 - w1 * Jw0;
  // n_W' = −f + ρA a_W, with the centreline acceleration a_W the BDF2 rate of the world
  // velocity R v (continuous limit: R (v_t + ω × v)). Linear momentum then obeys the BDF2
  // recurrence exactly, to round-off, when no force acts.
  *velocity_W = R * y.v;
  d.n = -f_W;
  if (!statics) d.n += rhoA * (c0 * *velocity_W + v_W_h);
  return d;
}

// Tip condition (eq. 28, with a rigid tip body of mass m_t and inertia J_t at the tip):
//   W(L) = [M_B − J_t ω_t − ω × J_t ω;  F_B + m_t Rᵀ g − m_t (v_t + ω × v)]   (body frame),
// made dimensionless by scale. V_t is the BDF2 rate of the tip twist (zero in statics).
Vec6 TipResidual(const DynState& y, const StaticLoads& loads, const Bdf2Options& opt,
                 const Vec6& V_t, const Vec6& scale) {
  const Mat3 Rt = y.R.transpose();
  Vec3 M =
      loads.tip_moment_frame == LoadFrame::kWorld ? Vec3(Rt * loads.tip_moment) : loads.tip_moment;
  Vec3 F =
      loads.tip_force_frame == LoadFrame::kWorld ? Vec3(Rt * loads.tip_force) : loads.tip_force;
  if (opt.tip_mass > 0 || opt.tip_inertia_B.any()) {
    const Vec3 Jw = opt.tip_inertia_B.cwiseProduct(y.w);
    M -= opt.tip_inertia_B.cwiseProduct(V_t.head<3>()) + y.w.cross(Jw);
    F += opt.tip_mass * (Rt * loads.gravity_W - V_t.tail<3>() - y.w.cross(y.v));
  }
  Vec6 r;
  r << y.m - M, Rt * y.n - F;
  return r.cwiseQuotient(scale);
}

using namespace internal;

// Derivative of DynState with respect to the 6 unknowns (one column each), in the same
// coordinates, so the scheme on (state, tangent) is the exact derivative of the discrete shot.
struct DynTangent {
  Mat36 p;
  RotationTangent R;  // d(R e_j)
  Mat36 m, n, w, v;
};

DynTangent Axpy(const DynTangent& y, double a, const DynTangent& d) {
  return {y.p + a * d.p, {y.R[0] + a * d.R[0], y.R[1] + a * d.R[1], y.R[2] + a * d.R[2]},
          y.m + a * d.m, y.n + a * d.n,
          y.w + a * d.w, y.v + a * d.v};
}

template <int S>
void RkUpdate(double h, const double (&b)[4], const DynTangent (&k)[S], DynTangent* y) {
  for (int j = 0; j < S; ++j) {
    const double a = h * b[j];
    y->p += a * k[j].p;
    for (int c = 0; c < 3; ++c) y->R[c] += a * k[j].R[c];
    y->m += a * k[j].m;
    y->n += a * k[j].n;
    y->w += a * k[j].w;
    y->v += a * k[j].v;
  }
}

// The linearisation of Derivative along dy, given the primal state and the stage strain.
// With tendons (H given: the derivative of the tendon-augmented law in ξ), dξ = H⁻¹ dW.
DynTangent TangentDerivative(const Sample& smp, const DynState& y, const DynTangent& dy,
                             const Vec6& xi, double c0, bool statics, const Mat6* H = nullptr) {
  const Vec6& C = statics ? smp.compliance : smp.implicit_compliance;
  const Vec3 n_B = y.R.transpose() * y.n;
  const Mat36 dn_B = y.R.transpose() * dy.n + TransposeTimesFixed(dy.R, y.n);
  Mat36 dK, dG;
  if (H) {
    Mat6 dW;
    dW << dy.m, dn_B;
    const Mat6 dxi = H->partialPivLu().solve(dW);
    dK = dxi.topRows<3>();
    dG = dxi.bottomRows<3>();
  } else {
    dK = C.head<3>().asDiagonal() * dy.m;
    dG = C.tail<3>().asDiagonal() * dn_B;
  }
  const double rate = statics ? 0.0 : c0;  // d ξ_t = c0 dξ, d V_t = c0 dV
  const Vec3 K = xi.head<3>(), G = xi.tail<3>();
  const Vec3 J = smp.mass.head<3>();
  const double rhoA = smp.mass(5);
  DynTangent dd;
  dd.p = RotateTangent(y.R, dy.R, G, dG);
  dd.R = RotationRateTangent(y.R, dy.R, K, dK);
  dd.w = rate * dK + Cross(dy.w, K) + Cross(y.w, dK);
  dd.v = rate * dG + Cross(dy.w, G) + Cross(y.w, dG) + Cross(dy.v, K) + Cross(y.v, dK);
  const Vec3 Jw = J.cwiseProduct(y.w);
  const Mat36 J_dw = J.asDiagonal() * dy.w;
  dd.m = Cross(dy.m, K) + Cross(y.m, dK) + Cross(dn_B, G) + Cross(n_B, dG) + rate * J_dw +
         Cross(dy.w, Jw) + Cross(y.w, J_dw);
  dd.n = rhoA * rate * RotateTangent(y.R, dy.R, y.v, dy.v);  // d(ρA c0 R v)
  return dd;
}

// Weights (c0, c1, c2) of the variable-step BDF2 derivative for a step h after a step h_prev:
// y' ≈ c0 y_n + c1 y_{n−1} + c2 y_{n−2}. Equal steps give eq. 23: 3/(2h), −2/h, 1/(2h).
Coefficients Bdf2Weights(double h, double h_prev) {
  const double w = h_prev > 0 ? h / h_prev : 1.0;
  return {(1 + 2 * w) / ((1 + w) * h), -(1 + w) / h, w * w / ((1 + w) * h)};
}

// a + t (b − a) for every input; the base rotation along the geodesic R_a Exp(t Log(R_aᵀ R_b)).
StepInput BlendInputs(const StepInput& a, const StepInput& b, double t) {
  StepInput out = b;
  out.base_pose.p = a.base_pose.p + t * (b.base_pose.p - a.base_pose.p);
  out.base_pose.R =
      a.base_pose.R * lie::SO3Exp(t * lie::SO3Log(a.base_pose.R.transpose() * b.base_pose.R));
  out.base_twist_B = a.base_twist_B + t * (b.base_twist_B - a.base_twist_B);
  out.base_wrench_B = a.base_wrench_B + t * (b.base_wrench_B - a.base_wrench_B);
  out.loads = StaticLoads::Blend(a.loads, b.loads, t);
  out.actuation.pressure = a.actuation.pressure + t * (b.actuation.pressure - a.actuation.pressure);
  for (int i = 0; i < Actuation::kMaxTendons; ++i)
    out.actuation.tendon_tension[i] =
        a.actuation.tendon_tension[i] +
        t * (b.actuation.tendon_tension[i] - a.actuation.tendon_tension[i]);
  for (int i = 0; i < Actuation::kMaxSegments; ++i)
    out.actuation.jamming_pressure[i] =
        a.actuation.jamming_pressure[i] +
        t * (b.actuation.jamming_pressure[i] - a.actuation.jamming_pressure[i]);
  return out;
}

}  // namespace

Bdf2ShootingStepper::Bdf2ShootingStepper(const RodModel& model, int num_nodes,
                                         const Bdf2Options& options)
    : model_(model), options_(options) {
  std::string why;
  if (!options_.IsValid(&why)) throw std::invalid_argument("Bdf2Options: " + why);
  grid_ = ModelGrid(model_, num_nodes);
  const int n = static_cast<int>(grid_.size());

  if (!model_.IsValid(&why)) throw std::invalid_argument("RodModel: " + why);
  SampleGrid();
  run_.model_fingerprint = ModelFingerprint();
  const double EI = std::max(samples_[0].stiffness(0), samples_[0].stiffness(1));
  const double L = model_.length;
  scale_ << EI / L, EI / L, EI / L, EI / (L * L), EI / (L * L), EI / (L * L);

  const int stages = StagesPerSegment() * (n - 1);
  for (auto* v : {&strain_now_, &run_.strain1, &run_.strain2, &twist_now_, &run_.twist1,
                  &run_.twist2, &strain_h_, &twist_h_})
    v->assign(stages, Vec6::Zero());
  position_now_.assign(stages, Vec3::Zero());
  run_.position1.assign(stages, Vec3::Zero());
  rotation_now_.assign(stages, Mat3::Identity());
  for (auto* v : {&velocity_W_now_, &run_.velocity_W1, &run_.velocity_W2, &velocity_W_h_})
    v->assign(stages, Vec3::Zero());
  run_.rotation1.assign(stages, Mat3::Identity());
  twist_scale_ << 1, 1, 1, L, L, L;
  run_.state.Resize(n);
  for (int i = 0; i < n; ++i) run_.state.s[i] = grid_[i];
  trial_ = run_.state;

  const int pieces = options_.shooting_segments;
  if (pieces > n - 1)
    throw std::invalid_argument("Bdf2Options: shooting_segments (" + std::to_string(pieces) +
                                ") exceeds the number of grid segments (" +
                                std::to_string(n - 1) + ")");
  if (pieces > 1) {
    const int unknowns = 6 + 18 * (pieces - 1);
    junction_nodes_.resize(pieces - 1);
    PlaceJunctions();
    junction_z_.setZero(18 * (pieces - 1));
    junction_mismatch_.setZero(18 * (pieces - 1));
    run_.junction_unknowns.setZero(18 * (pieces - 1));
    for (auto* v : {&ms_x_, &ms_x_new_, &ms_r_, &ms_r_new_, &ms_dx_, &ms_r_base_, &ms_u_, &ms_w_})
      v->setZero(unknowns);
    ms_jacobian_.setZero(unknowns, unknowns);
    ms_inverse_.setZero(unknowns, unknowns);
    ms_lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(unknowns);
  }
}

void Bdf2ShootingStepper::PlaceJunctions() {
  // Pieces of about equal node count (junction k at node round(k (n − 1) / pieces)).
  const int segments = static_cast<int>(grid_.size()) - 1;
  const int pieces = static_cast<int>(junction_nodes_.size()) + 1;
  for (int k = 1; k < pieces; ++k)
    junction_nodes_[k - 1] = static_cast<int>(std::lround(double(k) * segments / pieces));
}

template <typename State>
void Bdf2ShootingStepper::ApplyJunction(int k, State* y) {
  const int i = junction_nodes_[k];
  const RodState& ref = run_.state;  // the last accepted state at the junction node
  const auto z = junction_z_.segment<18>(18 * k);
  const double L = model_.length;
  State restart;
  restart.p = ref.position_W[i] + L * z.segment<3>(0);
  restart.R = ref.rotation_WB[i] * lie::SO3Exp(z.segment<3>(3));
  restart.m = ref.wrench_B[i].head<3>() + scale_.head<3>().cwiseProduct(z.segment<3>(6));
  restart.n = ref.rotation_WB[i] * ref.wrench_B[i].tail<3>() +
              scale_.tail<3>().cwiseProduct(z.segment<3>(9));
  restart.w = ref.twist_B[i].head<3>() + twist_scale_.head<3>().cwiseProduct(z.segment<3>(12));
  restart.v = ref.twist_B[i].tail<3>() + twist_scale_.tail<3>().cwiseProduct(z.segment<3>(15));
  auto d = junction_mismatch_.segment<18>(18 * k);
  d.segment<3>(0) = (y->p - restart.p) / L;
  d.segment<3>(3) = lie::SO3Log(restart.R.transpose() * y->R);
  d.segment<3>(6) = (y->m - restart.m).cwiseQuotient(scale_.head<3>());
  d.segment<3>(9) = (y->n - restart.n).cwiseQuotient(scale_.tail<3>());
  d.segment<3>(12) = (y->w - restart.w).cwiseQuotient(twist_scale_.head<3>());
  d.segment<3>(15) = (y->v - restart.v).cwiseQuotient(twist_scale_.tail<3>());
  *y = restart;
}

std::uint64_t Bdf2ShootingStepper::ModelFingerprint() const {
  // FNV-1a over the bytes of what a run's state depends on.
  std::uint64_t h = 1469598103934665603ull;
  auto add = [&h](const void* data, std::size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  const int ends = static_cast<int>(options_.ends), scheme = static_cast<int>(options_.spatial_scheme);
  add(&ends, sizeof ends);
  add(&scheme, sizeof scheme);
  for (const double s : grid_) {
    const SectionProperties p = model_.section->At(s, Actuation{});
    const Vec6 k = p.stiffness.diagonal(), m = p.mass.diagonal();
    add(&s, sizeof s);
    add(k.data(), sizeof(double) * 6);
    add(m.data(), sizeof(double) * 6);
  }
  return h;
}

void Bdf2ShootingStepper::SampleGrid() {
  sample_points_ = SegmentSamplePoints(grid_);
  samples_.resize(sample_points_.size());
  if (!model_.tendons.empty()) {
    tendons_.resize(sample_points_.size());
    for (size_t q = 0; q < sample_points_.size(); ++q)
      tendons_[q] = SampleTendons(model_.tendons, sample_points_[q], model_.length);
  }
  SampleSections();
}

void Bdf2ShootingStepper::SampleSections() {
  for (size_t q = 0; q < sample_points_.size(); ++q) {
    const double s = sample_points_[q];
    const SectionProperties p = model_.section->At(s, actuation_);
    auto diagonal = [](const Mat6& A) { return (A - Mat6(A.diagonal().asDiagonal())).norm() == 0; };
    if (!diagonal(p.stiffness) || !diagonal(p.damping) || !diagonal(p.mass))
      throw std::invalid_argument(
          "Bdf2ShootingStepper: sections must be principal-axes "
          "(diagonal stiffness, damping and mass)");
    Sample& smp = samples_[q];
    smp.stiffness = p.stiffness.diagonal();
    smp.damping = p.damping.diagonal();
    smp.compliance = smp.stiffness.cwiseInverse();
    smp.rest_strain = model_.RestStrainAt(s);
    smp.mass = p.mass.diagonal();
    smp.implicit_compliance = smp.compliance;
    smp.implicit_damping.setZero();
    smp.implicit_offset = smp.rest_strain;
  }
  current_c0_ = -1.0;  // the implicit compliance must be recomputed
}

void Bdf2ShootingStepper::ApplyActuation(const Actuation& a) {
  // Tensions enter the strain law directly; the section only depends on the other fields, so
  // only their change costs a re-sampling (no allocation either way).
  const bool section_changed = a.stiffness_scale != actuation_.stiffness_scale ||
                               a.pressure != actuation_.pressure ||
                               a.jamming_pressure != actuation_.jamming_pressure;
  actuation_ = a;
  if (section_changed) SampleSections();
}

void Bdf2ShootingStepper::SetImplicitCompliance(double c0) {
  if (c0 == current_c0_) return;
  for (Sample& smp : samples_) {
    smp.implicit_compliance = (smp.stiffness + c0 * smp.damping).cwiseInverse();
    smp.implicit_damping = smp.implicit_compliance.cwiseProduct(smp.damping);
    smp.implicit_offset = smp.rest_strain - c0 * smp.implicit_damping.cwiseProduct(smp.rest_strain);
    smp.damped = (smp.damping.array() != 0.0).any();
  }
  current_c0_ = c0;
}

void Bdf2ShootingStepper::PrepareHistory(const Coefficients& c) {
  if (history_ready_ && c.c0 == history_c_.c0 && c.c2 == history_c_.c2) return;
  // Written so that a constant history gives exactly zero rates:
  // ξ_t = c0 ξ + ξʰ with ξʰ = c2 (ξ₂ − ξ₁) − c0 ξ₁ (c1 = −c0 − c2), likewise for V. Each
  // std::vector of fixed-size vectors is one contiguous array of doubles: one vectorised
  // expression per quantity (element-wise loops over Vec6 were ~8 % of a Heun step).
  auto history = [&](auto& out, const auto& older, const auto& old) {
    using V = typename std::decay_t<decltype(out)>::value_type;
    const Eigen::Index size = static_cast<Eigen::Index>(out.size()) * V::SizeAtCompileTime;
    using Array = Eigen::Map<Eigen::ArrayXd>;
    using ConstArray = Eigen::Map<const Eigen::ArrayXd>;
    const ConstArray a(older.front().data(), size), b(old.front().data(), size);
    Array(out.front().data(), size) = c.c2 * (a - b) - c.c0 * b;
  };
  history(strain_h_, run_.strain2, run_.strain1);
  history(twist_h_, run_.twist2, run_.twist1);
  history(velocity_W_h_, run_.velocity_W2, run_.velocity_W1);
  history_c_ = c;
  history_ready_ = true;
}

Vec6 Bdf2ShootingStepper::Residual(const StepInput& in, const Coefficients& c, bool statics,
                                   const Vec6& x, Mat6* J) {
  const int n = static_cast<int>(grid_.size());
  const bool free_free = options_.ends == EndConditions::kFreeFree;
  DynState y;
  DynTangent dy;
  if (J) {
    for (Mat36* t : {&dy.p, &dy.R[0], &dy.R[1], &dy.R[2], &dy.m, &dy.n, &dy.w, &dy.v}) t->setZero();
  }
  if (!free_free) {
    // Cantilever (eq. 28): pose and twist of the base given, the unknown is W(0).
    const Vec6 W0 = scale_.cwiseProduct(x);
    base_now_ = in.base_pose;
    y.m = W0.head<3>();
    y.n = base_now_.R * W0.tail<3>();
    y.w = statics ? Vec3::Zero() : Vec3(in.base_twist_B.head<3>());
    y.v = statics ? Vec3::Zero() : Vec3(in.base_twist_B.tail<3>());
    if (J) {
      dy.m.leftCols<3>() = scale_.head<3>().asDiagonal();
      dy.n.rightCols<3>() = base_now_.R * scale_.tail<3>().asDiagonal();
    }
  } else {
    // Free-free (eq. 29): W(0) = −applied wrench, the unknown is V(0). The base pose follows
    // from BDF2 on the group in coordinates at g₁: g = g₁ Exp(ξ) with ξ̇ = J_r(ξ)⁻¹ V, so
    // c0 ξ + c2 ξ_back = J_r(ξ)⁻¹ V(0), solved by fixed point (ξ = O(dt), contraction O(dt)).
    const Vec6 V0 = statics ? Vec6::Zero() : Vec6(twist_scale_.cwiseProduct(x));
    Vec6 xi = Vec6::Zero();
    if (!statics) {
      for (int k = 0; k < 4; ++k)
        xi = (lie::SE3RightJacobianInverse(xi) * V0 - c.c2 * xi_back_) / c.c0;
    }
    base_now_ = lie::Compose(run_.base1, lie::SE3Exp(xi));
    y.m = -in.base_wrench_B.head<3>();
    y.n = base_now_.R * -in.base_wrench_B.tail<3>();
    y.w = V0.head<3>();
    y.v = V0.tail<3>();
    if (J && !statics) {
      // d g(0) = g(0) Exp(τ) with τ = J_r(ξ) dξ ≈ dV(0) / c0 (dropping the O(dt) change of J_r).
      const Mat6 tau = twist_scale_.asDiagonal() * (1.0 / c.c0);
      const Mat36 tau_w = tau.topRows<3>(), tau_v = tau.bottomRows<3>();
      dy.w.leftCols<3>() = twist_scale_.head<3>().asDiagonal();
      dy.v.rightCols<3>() = twist_scale_.tail<3>().asDiagonal();
      dy.p = base_now_.R * tau_v;
      for (int j = 0; j < 3; ++j) dy.R[j] = base_now_.R * CrossUnit(tau_w, j);  // R (τ_ω × e_j)
      dy.n = RotateTangent(base_now_.R, dy.R, -in.base_wrench_B.tail<3>(), Mat36::Zero());
    }
  }
  y.p = base_now_.p;
  y.R = base_now_.R;
  const StaticLoads& loads = in.loads;
  auto f_at = [&](const Sample& smp) -> Vec3 {
    return smp.mass(5) * loads.gravity_W + loads.distributed_force_W;
  };
  if (!statics) PrepareHistory(c);
  auto record_node = [&](int i, const Vec6& xi) {
    trial_.position_W[i] = y.p;
    trial_.rotation_WB[i] = y.R;
    trial_.wrench_B[i].head<3>() = y.m;
    trial_.wrench_B[i].tail<3>() = y.R.transpose() * y.n;
    trial_.twist_B[i].head<3>() = y.w;
    trial_.twist_B[i].tail<3>() = y.v;
    trial_.strain[i] = xi;
  };

  const Vec6 zero6 = Vec6::Zero();
  const Vec3 zero3 = Vec3::Zero();
  // One stage q at state ys: record it and return its derivative.
  // With tendons: the strain of K (ξ − ξ*) + D ξ_t + Σ τ a(ξ) = W (tendons.hpp) at a sample,
  // written as K' (ξ − ξ') + Σ τ a(ξ) = W with K' = K + c0 D, ξ' = its offset; from `guess`.
  Vec6 guess = samples_.front().rest_strain;
  Mat6 H_stage[4];
  // In dynamics a stage's strain moves little between shots and steps: the best first guess is
  // its value in the last shot of this step, or at the last step (about 3 simplified-Newton
  // iterations per stage from the neighbouring stage's strain, 2 from these).
  const bool shot_this_step = stage_strains_current_;
  auto stage_guess = [&](int q) -> const Vec6& {
    if (statics) return guess;
    const Vec6& last = shot_this_step ? strain_now_[q] : run_.strain1[q];
    return last.allFinite() ? last : guess;
  };
  auto tendon_strain = [&](int sample_index, const Vec6& start, const Vec6& xi_h, const Vec6& W,
                           Mat6* H) {
    const Sample& smp = samples_[sample_index];
    Mat6 K = Mat6::Zero();
    Vec6 offset;
    if (statics) {
      K.diagonal() = smp.stiffness;
      offset = smp.rest_strain;
    } else {
      K.diagonal() = smp.stiffness + c.c0 * smp.damping;  // the implicit stiffness K + c0 D
      offset = smp.implicit_offset - smp.implicit_damping.cwiseProduct(xi_h);
    }
    Vec6 xi = start;
    if (!SolveTendonStrain(K, offset, tendons_[sample_index], actuation_.tendon_tension.data(), W,
                           &xi, H))
      xi.setConstant(NAN);
    guess = xi;
    return xi;
  };
  auto stage = [&](int q, int sample_index, const DynState& ys) COSSERAT_HOT_LAMBDA {
    const Sample& smp = samples_[sample_index];
    const Vec6& xh = statics ? zero6 : strain_h_[q];  // history terms ξʰ, Vʰ
    const Vec6& Vh = statics ? zero6 : twist_h_[q];
    position_now_[q] = ys.p;
    std::memcpy(rotation_now_[q].data(), ys.R.data(), sizeof(Mat3));  // inlined: 72 bytes
    Vec6 given;
    if (!tendons_.empty()) {
      Vec6 W;
      W << ys.m, ys.R.transpose() * ys.n;
      given = tendon_strain(sample_index, stage_guess(q), xh, W,
                            J ? &H_stage[q % StagesPerSegment()] : nullptr);
    }
    return Derivative(smp, f_at(smp), ys, xh, Vh, statics ? zero3 : velocity_W_h_[q], c.c0, statics,
                      &strain_now_[q], &twist_now_[q], &velocity_W_now_[q],
                      tendons_.empty() ? nullptr : &given);
  };
  // The tangent dy through the stages ys of segment i (the exact derivative of the shot).
  auto propagate = [&](auto scheme, const auto& ys, int q, int smp, double h) {
    constexpr const SchemeTable& T = Table(decltype(scheme)::value);
    constexpr int S = T.stages;
    static_assert(std::tuple_size<std::decay_t<decltype(ys)>>::value == S);
    DynTangent dk[S];
    for (int j = 0; j < S; ++j)
      dk[j] = TangentDerivative(samples_[smp + T.sample[j]], *ys[j],
                                j == 0 ? dy : Axpy(dy, T.step[j] * h, dk[j - 1]), strain_now_[q + j],
                                c.c0, statics, tendons_.empty() ? nullptr : &H_stage[j]);
    RkUpdate<S>(h, T.weight, dk, &dy);
  };
  // Segment by segment with the explicit scheme's S stages (spatial_scheme.hpp), written out
  // per scheme: a loop over stage arrays made the RK4 shot ~25 % slower.
  auto shoot = [&](auto scheme) {
    constexpr int S = Table(decltype(scheme)::value).stages;
    size_t next_junction = 0;
    for (int i = 0; i + 1 < n; ++i) {
      if (junctions_active_ && next_junction < junction_nodes_.size() &&
          i == junction_nodes_[next_junction])
        ApplyJunction(static_cast<int>(next_junction++), &y);
      const double h = grid_[i + 1] - grid_[i];
      const int q = S * i;
      const int smp = 3 * i;
      const DynState k1 = stage(q, smp, y);
      record_node(i, strain_now_[q]);
      if constexpr (S == 4) {
        const DynState y2 = Axpy(y, 0.5 * h, k1);
        const DynState k2 = stage(q + 1, smp + 1, y2);
        const DynState y3 = Axpy(y, 0.5 * h, k2);
        const DynState k3 = stage(q + 2, smp + 1, y3);
        const DynState y4 = Axpy(y, h, k3);
        const DynState k4 = stage(q + 3, smp + 2, y4);
        if (J) propagate(scheme, std::array<const DynState*, 4>{&y, &y2, &y3, &y4}, q, smp, h);
        Rk4Update(h, k1, k2, k3, k4, &y);
      } else {
        const DynState y2 = Axpy(y, h, k1);
        const DynState k2 = stage(q + 1, smp + 2, y2);
        if (J) propagate(scheme, std::array<const DynState*, 2>{&y, &y2}, q, smp, h);
        HeunUpdate(h, k1, k2, &y);
      }
    }
  };
  if (options_.spatial_scheme == SpatialScheme::kHeun)
    shoot(std::integral_constant<SpatialScheme, SpatialScheme::kHeun>());
  else
    shoot(std::integral_constant<SpatialScheme, SpatialScheme::kRk4>());
  // The tip node: its strain from the last stage's section with the final wrench.
  Vec6 W_tip;
  W_tip << y.m, y.R.transpose() * y.n;
  const Sample& s_tip = samples_[3 * (n - 2) + 2];
  // The tip node has a history of its own (the last stage sits at y + h k_{S−1}, not at the tip).
  Vec6 xi_h_tip = Vec6::Zero(), V_h_tip = Vec6::Zero();
  if (!statics) {
    xi_h_tip = c.c2 * (run_.tip_strain2 - run_.tip_strain1) - c.c0 * run_.tip_strain1;
    V_h_tip = c.c2 * (run_.tip_twist2 - run_.tip_twist1) - c.c0 * run_.tip_twist1;
  }
  Vec6 xi_tip = statics
                    ? Vec6(s_tip.rest_strain + s_tip.compliance.cwiseProduct(W_tip))
                    : Vec6(s_tip.implicit_offset + s_tip.implicit_compliance.cwiseProduct(W_tip) -
                           s_tip.implicit_damping.cwiseProduct(xi_h_tip));
  if (!tendons_.empty()) {
    xi_tip = tendon_strain(3 * (n - 2) + 2, guess, xi_h_tip, W_tip, nullptr);
  }
  record_node(n - 1, xi_tip);
  stage_strains_current_ = !statics;
  tip_strain_now_ = xi_tip;
  tip_twist_now_ << y.w, y.v;
  Vec6 V_t_tip = Vec6::Zero();  // BDF2 rate of the tip twist
  if (!statics) {
    V_t_tip << c.c0 * y.w, c.c0 * y.v;
    V_t_tip += V_h_tip;
  }
  if (J) {
    J->topRows<3>() = dy.m;
    J->bottomRows<3>() = y.R.transpose() * dy.n + TransposeTimesFixed(dy.R, y.n);
    if (loads.tip_moment_frame == LoadFrame::kWorld)
      J->topRows<3>() -= TransposeTimesFixed(dy.R, loads.tip_moment);
    if (loads.tip_force_frame == LoadFrame::kWorld)
      J->bottomRows<3>() -= TransposeTimesFixed(dy.R, loads.tip_force);
    const double rate = statics ? 0.0 : c.c0;
    const Vec3& Jt = options_.tip_inertia_B;
    const double mt = options_.tip_mass;
    if (mt > 0 || Jt.any()) {
      const Mat36 Jt_dw = Jt.asDiagonal() * dy.w;
      J->topRows<3>() += rate * Jt_dw + Cross(dy.w, Vec3(Jt.cwiseProduct(y.w))) + Cross(y.w, Jt_dw);
      J->bottomRows<3>() -= mt * TransposeTimesFixed(dy.R, loads.gravity_W);
      J->bottomRows<3>() += mt * (rate * dy.v + Cross(dy.w, y.v) + Cross(y.w, dy.v));
    }
    *J = scale_.cwiseInverse().asDiagonal() * *J;
  }
  return TipResidual(y, loads, options_, V_t_tip, scale_);
}

namespace {

// The shooting problem in the form ceres::TinySolver expects, with the exact Jacobian.
struct StepCost {
  using Scalar = double;
  enum { NUM_RESIDUALS = 6, NUM_PARAMETERS = 6 };
  Bdf2ShootingStepper* stepper;
  const StepInput* input;
  const Coefficients* c;
  bool statics;
  int* shots;
  int* jacobians;
  Mat6* last_jacobian;

  bool operator()(const double* x_ptr, double* r_ptr, double* J_ptr) const {
    const Eigen::Map<const Vec6> x(x_ptr);
    Eigen::Map<Vec6> r(r_ptr);
    ++*shots;
    if (J_ptr) {
      Mat6 J;
      ++*jacobians;
      r = stepper->Residual(*input, *c, statics, x, &J);
      Eigen::Map<Mat6> J_out(J_ptr);
      J_out = J;
      *last_jacobian = J;
    } else {
      r = stepper->Residual(*input, *c, statics, x);
    }
    return r.allFinite();
  }
};

}  // namespace

bool Bdf2ShootingStepper::SolveStep(const StepInput& input, const Coefficients& c, double h,
                                    bool statics, StepSummary* summary) {
  if (!statics && !junction_nodes_.empty()) return SolveStepMultiple(input, c, h, summary);
  // 1. Newton with the last steps' Jacobian, tracked by the secant filter below, from an
  //    extrapolation of the last steps' unknowns. A Jacobian from another c0 (statics, another
  //    step size) is replaced by the exact one first.
  Vec6 x = statics ? run_.unknowns.latest() : run_.unknowns.Predict(h);
  Vec6 r;
  bool fresh = false;  // the filter's J is the exact Jacobian at x, not yet updated
  // The Jacobian: the secant filter's estimate (secant_filter.hpp), carried from the last steps;
  // this step's copy replaces it only if the step converges.
  SecantFilter filter = run_.jacobian_filter;
  if (run_.jacobian_c0 != c.c0) {
    Mat6 exact;
    r = Residual(input, c, statics, x, &exact);
    filter.Restart(exact);
    ++summary->jacobians;
    run_.jacobian_c0 = c.c0;
    fresh = true;
  } else {
    r = Residual(input, c, statics, x);
    if (!statics) filter.Advance();
  }
  ++summary->shots;
  const Mat6& J = filter.jacobian();
  Eigen::PartialPivLU<Mat6> lu(J);
  bool ok = false;
  bool retried = false;  // a rejected Broyden step has been retried with its secant
  for (int it = 0; it < options_.max_iterations; ++it) {
    const double norm = r.norm();
    if (!std::isfinite(norm)) break;
    if (norm < options_.tolerance) {
      ok = true;
      break;
    }
    Vec6 dx = -lu.solve(r);
    Vec6 r_new = Residual(input, c, statics, x + dx);
    ++summary->shots;
    ++summary->iterations;
    bool accepted = r_new.allFinite() && r_new.norm() < 0.5 * norm;
    if (!accepted && !fresh && r_new.allFinite() && !retried) {
      // A Broyden step that failed to halve the residual still measured the shot along dx: put
      // that secant into J and try again from x once, before paying for the exact Jacobian
      // (about ten shots; on the peer problem this retry avoids it in all but one of 12 500 steps,
      // which is what keeps the slowest steps near the median).
      retried = true;
      filter.Update(dx, r_new - r);
      lu.compute(J);
      continue;
    }
    if (!accepted && fresh) {
      // An exact Newton step overshot (the shot is strongly nonlinear when its exponent λL is
      // large): backtrack along it, accepting a sufficient decrease.
      for (double alpha = 0.5; alpha >= 1.0 / 16 && !accepted; alpha *= 0.5) {
        dx *= 0.5;
        r_new = Residual(input, c, statics, x + dx);
        ++summary->shots;
        accepted = r_new.allFinite() && r_new.norm() < (1 - 0.5 * alpha) * norm;
      }
      if (!accepted) break;  // leave it to Levenberg–Marquardt
    }
    if (accepted) {
      filter.Update(dx, r_new - r);
      fresh = false;
      x += dx;
      r = r_new;
    } else {
      // The filtered Jacobian has drifted: replace it by the exact one at x and retry. The
      // exact J restarts the filter here too: kept, the rate that had made J fail would be added
      // again at the next step (an out-of-plane kick after a planar swing then needed an exact J
      // in nearly every one of the next ~80 steps).
      Mat6 exact;
      r = Residual(input, c, statics, x, &exact);
      filter.Restart(exact);
      ++summary->jacobians;
      ++summary->shots;
      fresh = true;
    }
    lu.compute(J);
  }
  if (ok) {
    summary->residual = r.norm();
    run_.jacobian_filter = filter;
    solved_unknowns_ = x;
    // The root estimate one more (shot-free) Newton step gives: x's residual, up to the
    // tolerance, would otherwise enter the extrapolation of the next steps as noise.
    predictor_term_ = x - lu.solve(r);
    return true;
  }

  // 2. Levenberg–Marquardt with the exact Jacobian, from the best point Newton reached (it only
  //    moves on a decrease of the residual), or the last step's unknowns if that is not finite.
  Mat6 J_lm = run_.jacobian_filter.jacobian();
  const StepCost cost{this, &input, &c, statics, &summary->shots, &summary->jacobians, &J_lm};
  ceres::TinySolver<StepCost> lm;
  lm.options.max_num_iterations = options_.max_iterations + 1;  // TinySolver runs n − 1 steps
  lm.options.cost_threshold = 0.5 * options_.tolerance * options_.tolerance;
  lm.options.gradient_tolerance = 0.0;
  lm.options.parameter_tolerance = 1e-15;
  lm.options.function_tolerance = 0.0;
  Vec6 x_lm = r.allFinite() ? x : run_.unknowns.latest();
  const auto& s = lm.Solve(cost, &x_lm);
  summary->iterations += s.iterations;
  const Vec6 r_final = Residual(input, c, statics, x_lm);  // leaves the trial state at x_lm
  ++summary->shots;
  summary->residual = r_final.norm();
  if (!(r_final.allFinite() && summary->residual < options_.tolerance)) {
    summary->status = r_final.allFinite() ? SolveStatus::kMaxIterations : SolveStatus::kNonFinite;
    return false;
  }
  run_.jacobian_filter.Restart(J_lm);
  run_.jacobian_c0 = c.c0;
  solved_unknowns_ = x_lm;
  predictor_term_ = x_lm;
  return true;
}

void Bdf2ShootingStepper::Commit(double h) {
  // Degrees scored in residual units with the Jacobian the next step starts from (single
  // shooting; multiple shooting keeps its own).
  run_.unknowns.Push(predictor_term_, h, junction_nodes_.empty() ? &run_.jacobian_filter.jacobian() : nullptr);
  std::swap(run_.strain2, run_.strain1);
  std::swap(run_.strain1, strain_now_);
  std::swap(run_.twist2, run_.twist1);
  std::swap(run_.twist1, twist_now_);
  std::swap(run_.position1, position_now_);
  std::swap(run_.rotation1, rotation_now_);
  std::swap(run_.velocity_W2, run_.velocity_W1);
  std::swap(run_.velocity_W1, velocity_W_now_);
  run_.tip_strain2 = run_.tip_strain1;
  run_.tip_strain1 = tip_strain_now_;
  run_.tip_twist2 = run_.tip_twist1;
  run_.tip_twist1 = tip_twist_now_;
  std::swap(run_.state, trial_);
  history_ready_ = false;
  stage_strains_current_ = false;
  run_.base2 = run_.base1;
  run_.base1 = base_now_;
  run_.time += h;
  run_.last_dt = h;
  ++run_.steps_taken;
}

StepSummary Bdf2ShootingStepper::InitializeAtRest(const StepInput& input) {
  const auto t0 = std::chrono::steady_clock::now();
  StepSummary summary;
  initialized_ = false;  // until this succeeds, Step() refuses to run
  run_.base1 = run_.base2 = input.base_pose;
  run_.steps_taken = 0;
  run_.jacobian_c0 = -1.0;  // the first solve computes the exact Jacobian
  ApplyActuation(input.actuation);
  const Coefficients c{};
  bool ok = false;
  if (options_.ends == EndConditions::kFreeFree) {
    // Nothing to solve: W(0) is given, V = 0. The rod is at rest only if the loads balance.
    run_.unknowns.Reset(Vec6::Zero());
    const Vec6 r = Residual(input, c, true, Vec6::Zero());
    ++summary.shots;
    summary.residual = r.norm();
    ok = summary.residual < options_.tolerance;
    if (!ok) summary.status = SolveStatus::kMaxIterations;  // not an equilibrium
  } else {
    // A rigid-body guess is good enough for moderate preloads; large ones are the statics
    // solver's job (continuation).
    const Vec3 total = model_.length * (samples_[1].mass(5) * input.loads.gravity_W +
                                        input.loads.distributed_force_W) +
                       input.loads.tip_force;
    Vec6 W;
    W << Vec3::Zero(), input.base_pose.R.transpose() * total;
    run_.unknowns.Reset(W.cwiseQuotient(scale_));
    ok = SolveStep(input, c, 0.0, true, &summary);
    if (ok) run_.unknowns.Reset(solved_unknowns_);
  }
  if (!ok) {
    summary.wall_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return summary;
  }
  // At rest: both history levels equal the equilibrium, twists zero.
  std::copy(strain_now_.begin(), strain_now_.end(), run_.strain1.begin());
  std::copy(strain_now_.begin(), strain_now_.end(), run_.strain2.begin());
  std::copy(position_now_.begin(), position_now_.end(), run_.position1.begin());
  std::copy(rotation_now_.begin(), rotation_now_.end(), run_.rotation1.begin());
  std::swap(run_.state, trial_);
  for (auto* v : {&run_.twist1, &run_.twist2}) std::fill(v->begin(), v->end(), Vec6::Zero());
  for (auto* v : {&run_.velocity_W1, &run_.velocity_W2})
    std::fill(v->begin(), v->end(), Vec3::Zero());
  run_.tip_strain1 = run_.tip_strain2 = tip_strain_now_;
  run_.tip_twist1 = run_.tip_twist2 = Vec6::Zero();
  run_.last_input = input;
  run_.last_input.base_twist_B.setZero();
  history_ready_ = false;
  run_.time = 0.0;
  run_.last_dt = 0.0;
  run_.steps_taken = 0;
  run_.initialized = true;
  initialized_ = true;
  summary.status = SolveStatus::kConverged;
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

bool Bdf2ShootingStepper::Attempt(const StepInput& input, double h, StepSummary* summary) {
  ApplyActuation(input.actuation);
  const Coefficients c = Bdf2Weights(h, run_.last_dt);
  SetImplicitCompliance(c.c0);
  xi_back_ = lie::SE3Log(lie::Compose(lie::Inverse(run_.base1), run_.base2));
  if (SolveStep(input, c, h, false, summary)) {
    Commit(h);
    run_.last_input = input;
    return true;
  }
  return false;
}

bool Bdf2ShootingStepper::AttemptInterval(const StepInput& from, const StepInput& to, double h,
                                          int depth, StepSummary* summary) {
  if (Attempt(to, h, summary)) return true;
  if (depth >= options_.max_halvings) return false;
  summary->halvings = std::max(summary->halvings, depth + 1);
  // Sub-steps see the input interpolated between the start and the end of the interval.
  const StepInput mid = BlendInputs(from, to, 0.5);
  return AttemptInterval(from, mid, 0.5 * h, depth + 1, summary) &&
         AttemptInterval(mid, to, 0.5 * h, depth + 1, summary);
}

StepSummary Bdf2ShootingStepper::Step(const StepInput& input) {
  const auto t0 = std::chrono::steady_clock::now();
  StepSummary summary;
  if (!initialized_) {
    summary.status = SolveStatus::kNotRun;
    return summary;
  }
  // Try the whole step; on failure, two half steps, recursively up to max_halvings deep. Sub-steps
  // commit as they go, so a failure part-way leaves the last converged sub-step. (With shooting,
  // smaller steps raise the shot's exponent λL ∝ dt^(-1/2), so halving helps less than usual.)
  if (!input.loads.IsValid(nullptr) || !input.base_twist_B.allFinite() ||
      !input.base_wrench_B.allFinite() || !input.base_pose.R.allFinite() ||
      !input.base_pose.p.allFinite()) {
    summary.status = SolveStatus::kNonFinite;  // NaN or Inf in the input: the state stays put
    return summary;
  }
  const StepInput start = run_.last_input;
  const bool ok = AttemptInterval(start, input, options_.dt, 0, &summary);
  if (ok) summary.status = SolveStatus::kConverged;
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

template <typename Visit>
void Bdf2ShootingStepper::ForEachStage(Visit&& visit) const {
  // The scheme's quadrature on each segment (RK4: h/6, h/3, h/3, h/6; Heun: h/2, h/2).
  const internal::SchemeTable& T = internal::Table(options_.spatial_scheme);
  for (size_t i = 0; i + 1 < grid_.size(); ++i) {
    const double h = grid_[i + 1] - grid_[i];
    for (int j = 0; j < T.stages; ++j)
      visit(static_cast<int>(T.stages * i + j), samples_[3 * i + T.sample[j]], h * T.weight[j]);
  }
}

RodEnergy Bdf2ShootingStepper::Energy(const StaticLoads& loads) const {
  RodEnergy e;
  ForEachStage([&](int q, const Sample& smp, double w) {
    const Vec6 dxi = run_.strain1[q] - smp.rest_strain;
    e.kinetic += w * 0.5 * run_.twist1[q].dot(smp.mass.cwiseProduct(run_.twist1[q]));
    e.elastic += w * 0.5 * dxi.dot(smp.stiffness.cwiseProduct(dxi));
    e.gravity -= w * smp.mass(5) * loads.gravity_W.dot(run_.position1[q]);
  });
  return e;
}

RodMomentum Bdf2ShootingStepper::Momentum() const {
  RodMomentum out;
  ForEachStage([&](int q, const Sample& smp, double w) {
    const Vec3 linear = smp.mass(5) * (run_.rotation1[q] * run_.twist1[q].tail<3>());
    const Vec3 spin = run_.rotation1[q] * smp.mass.head<3>().cwiseProduct(run_.twist1[q].head<3>());
    out.linear_W += w * linear;
    out.angular_W += w * (run_.position1[q].cross(linear) + spin);
  });
  return out;
}

double Bdf2ShootingStepper::Mass() const {
  double mass = 0;
  ForEachStage([&](int, const Sample& smp, double w) { mass += w * smp.mass(5); });
  return mass;
}

Vec3 Bdf2ShootingStepper::CentreOfMass_W() const {
  Vec3 first = Vec3::Zero();
  ForEachStage(
      [&](int q, const Sample& smp, double w) { first += w * smp.mass(5) * run_.position1[q]; });
  return first / Mass();
}

void Bdf2ShootingStepper::Grow(const RodModel& longer, int new_segments) {
  std::string why;
  if (!longer.IsValid(&why)) throw std::invalid_argument("Grow: " + why);
  const double L_old = model_.length, L_new = longer.length;
  if (!(L_new > L_old)) throw std::invalid_argument("Grow: the new length must exceed the old");
  if (new_segments < 1) throw std::invalid_argument("Grow: new_segments must be at least 1");
  if (longer.tendons.size() != model_.tendons.size())
    throw std::invalid_argument("Grow: the tendons must stay the same");
  // New nodes: evenly spaced on (L_old, L_new], plus the new model's breakpoints there.
  std::vector<double> added;
  for (int k = 1; k <= new_segments; ++k)
    added.push_back(L_old + (L_new - L_old) * k / new_segments);
  for (double b : longer.section->Breakpoints())
    if (b > L_old && b < L_new) added.push_back(b);
  std::sort(added.begin(), added.end());
  const int n_old = static_cast<int>(grid_.size());
  for (double s : added)
    if (s - grid_.back() > 1e-12 * L_new) grid_.push_back(s);
  grid_.back() = L_new;
  model_ = longer;
  const int n = static_cast<int>(grid_.size());
  SampleGrid();
  run_.model_fingerprint = ModelFingerprint();
  if (!junction_nodes_.empty()) PlaceJunctions();

  // New stages and nodes start with the old tip's history, placed along its tangent.
  const int S = StagesPerSegment();
  const int stages_old = S * (n_old - 1), stages = S * (n - 1);
  const Mat3 R_tip = run_.state.rotation_WB.back();
  const Vec3 p_tip = run_.state.position_W.back();
  auto along = [&](double s) { return Vec3(p_tip + R_tip.col(2) * (s - L_old)); };
  const Vec3 v1 = R_tip * run_.tip_twist1.tail<3>(), v2 = R_tip * run_.tip_twist2.tail<3>();
  for (auto* v : {&strain_now_, &twist_now_, &strain_h_, &twist_h_}) v->resize(stages);
  for (auto* v : {&position_now_, &velocity_W_now_, &velocity_W_h_}) v->resize(stages);
  rotation_now_.resize(stages, R_tip);
  run_.strain1.resize(stages, run_.tip_strain1);
  run_.strain2.resize(stages, run_.tip_strain2);
  run_.twist1.resize(stages, run_.tip_twist1);
  run_.twist2.resize(stages, run_.tip_twist2);
  run_.rotation1.resize(stages, R_tip);
  run_.velocity_W1.resize(stages, v1);
  run_.velocity_W2.resize(stages, v2);
  run_.position1.resize(stages);
  for (int q = stages_old; q < stages; ++q) {
    const int i = q / S;
    const double offset = internal::Table(options_.spatial_scheme).step[q % S];
    run_.position1[q] = along(grid_[i] + offset * (grid_[i + 1] - grid_[i]));
  }
  RodState& st = run_.state;
  const RodState old = st;
  st.Resize(n);
  for (int i = 0; i < n; ++i) {
    st.s[i] = grid_[i];
    const int j = std::min(i, n_old - 1);
    st.position_W[i] = i < n_old ? old.position_W[i] : along(grid_[i]);
    st.rotation_WB[i] = old.rotation_WB[j];
    st.strain[i] = old.strain[j];
    st.wrench_B[i] = old.wrench_B[j];
    st.twist_B[i] = old.twist_B[j];
  }
  trial_ = st;
  history_ready_ = false;
  stage_strains_current_ = false;
  run_.jacobian_c0 = -1.0;  // another shot: start from its exact Jacobian
}

void Bdf2ShootingStepper::Restore(const Snapshot& s) {
  if (s.strain1.size() != run_.strain1.size() || s.state.size() != run_.state.size() ||
      s.junction_unknowns.size() != run_.junction_unknowns.size())
    throw std::invalid_argument("Snapshot is from a stepper with another grid");
  if (!s.initialized)
    throw std::invalid_argument("Snapshot was saved before InitializeAtRest: it holds no run");
  if (s.model_fingerprint != run_.model_fingerprint)
    throw std::invalid_argument(
        "Snapshot is from a stepper of another rod, grid or end conditions");
  run_ = s;  // equal sizes: vectors copy into their existing storage
  history_ready_ = false;
  stage_strains_current_ = false;
  initialized_ = true;
}

}  // namespace cosserat
