// One shot of the BDF2 shooting stepper: the Cosserat equations in s with the BDF2 rates of
// strain and twist (Till, Aloi & Rucker 2019, eqs. 14-29), integrated by the explicit spatial
// scheme (spatial_scheme.hpp) with the exact tangent of the discrete map. The solve that drives
// its residual to zero is in bdf2_stepper.cpp.
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "cosserat/constitutive/tendon_law.hpp"
#include "cosserat/lie/se3.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "frame_tangent.hpp"

namespace cosserat {

namespace {

using Sample = Bdf2ShootingStepper::Sample;
using Coefficients = Bdf2ShootingStepper::Coefficients;
using namespace internal;

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
//   W(L) = [M_B − J_t ω_t − ω × J_t ω;  F_B − m_t (v_t + ω × v)]   (body frame),
// where [M_B; F_B] is the loads' tip wrench on the section and the body (its weight included),
// made dimensionless by scale. V_t is the BDF2 rate of the tip twist (zero in statics).
Vec6 TipResidual(const DynState& y, const StaticLoads& loads, const Bdf2Options& opt,
                 const Vec6& V_t, const Vec6& scale) {
  const Mat3 Rt = y.R.transpose();
  const Vec6 applied = TipWrenchInBody(TotalTipWrench(loads, opt.tip_mass), y.R);
  Vec3 M = applied.head<3>(), F = applied.tail<3>();
  if (opt.tip_mass > 0 || opt.tip_inertia_B.any()) {
    const Vec3 Jw = opt.tip_inertia_B.cwiseProduct(y.w);
    M -= opt.tip_inertia_B.cwiseProduct(V_t.head<3>()) + y.w.cross(Jw);
    F -= opt.tip_mass * (V_t.tail<3>() + y.w.cross(y.v));
  }
  Vec6 r;
  r << y.m - M, Rt * y.n - F;
  return r.cwiseQuotient(scale);
}

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

}  // namespace

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
    return TotalDistributedForce_W(loads, {smp.s, 1.0, smp.mass(5)});
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
      dk[j] = TangentDerivative(
          samples_[smp + T.sample[j]], *ys[j], j == 0 ? dy : Axpy(dy, T.step[j] * h, dk[j - 1]),
          strain_now_[q + j], c.c0, statics, tendons_.empty() ? nullptr : &H_stage[j]);
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
    // d(Rᵀ w_dead) for the dead part of the tip wrench (the tip body's weight included).
    const SplitWrench tip = TotalTipWrench(loads, options_.tip_mass);
    J->topRows<3>() -= TransposeTimesFixed(dy.R, Vec3(tip.dead_W.head<3>()));
    J->bottomRows<3>() -= TransposeTimesFixed(dy.R, Vec3(tip.dead_W.tail<3>()));
    const double rate = statics ? 0.0 : c.c0;
    const Vec3& Jt = options_.tip_inertia_B;
    const double mt = options_.tip_mass;
    if (mt > 0 || Jt.any()) {
      const Mat36 Jt_dw = Jt.asDiagonal() * dy.w;
      J->topRows<3>() += rate * Jt_dw + Cross(dy.w, Vec3(Jt.cwiseProduct(y.w))) + Cross(y.w, Jt_dw);
      J->bottomRows<3>() += mt * (rate * dy.v + Cross(dy.w, y.v) + Cross(y.w, dy.v));
    }
    *J = scale_.cwiseInverse().asDiagonal() * *J;
  }
  return TipResidual(y, loads, options_, V_t_tip, scale_);
}

}  // namespace cosserat
