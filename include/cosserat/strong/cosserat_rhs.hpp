#pragma once
/// \file
/// The Cosserat rod equations in s, written once for every SE(3) shooting solver: the static
/// shot (StaticShootingSolver, ColumnSolver, the frequency linearisation's base state) and the
/// BDF2 dynamic shot. Templated on the scalar so that ceres::Jet differentiates them, which is
/// how the hand-written tangents of shot_tangent.hpp are checked.
///
/// Strain ξ = [K; Γ] and twist V = [ω; v] in the body frame, wrench W = [m; n] (Antman 2005;
/// Till, Aloi & Rucker 2019, eqs. 14-29), with the law's strain from W given by the caller:
///   p' = R Γ,   R' = R K̂                                  (kinematics)
///   ω' = K_t + ω × K,   v' = Γ_t + ω × Γ + v × K          (compatibility; dynamics only)
///   m' = m × K + n_B × Γ + J ω_t + ω × J ω                (balance of moments)
///   statics:  n_B' = n_B × K − Rᵀ f_W                     (balance of forces, body frame)
///   dynamics: n_W' = −f_W + ρA a_W                         (balance of forces, world frame)
/// f_W is the distributed force per unit length (N/m, world) of every load. Statics carries n in
/// the body frame (the shortest chain of dependent operations per stage, which bounds the speed of
/// a shot); dynamics carries it in the world frame, so that the scheme sums the balance of linear
/// momentum exactly. The inertia terms vanish in statics, where both forms are the same equations.

#include "cosserat/lie/types.hpp"
#include "cosserat/loads/load.hpp"

#ifdef __GNUC__
#define COSSERAT_RHS_INLINE inline __attribute__((always_inline))
#else
#define COSSERAT_RHS_INLINE inline
#endif

namespace cosserat::rhs {

/// State of a static shot: centreline and frame in the world, internal wrench in the body frame.
template <typename T>
struct StaticPoint {
  Vector3<T> p;  ///< p_W, m
  Matrix3<T> R;  ///< R_WB
  Vector3<T> m;  ///< m_B, N·m
  Vector3<T> n;  ///< n_B, N
};

/// State of a dynamic shot: pose in the world, moment and twist in the body frame, force in the
/// world frame.
template <typename T>
struct DynamicPoint {
  Vector3<T> p;  ///< p_W, m
  Matrix3<T> R;  ///< R_WB
  Vector3<T> m;  ///< m_B, N·m
  Vector3<T> n;  ///< n_W, N
  Vector3<T> w;  ///< ω_B, rad/s
  Vector3<T> v;  ///< v_B, m/s
};

/// p' = R Γ and R' = R K̂ for the strain xi = [K; Γ], written out by component.
template <typename T>
COSSERAT_RHS_INLINE void KinematicRates(const Matrix3<T>& R, const T* xi, Vector3<T>* dp,
                                        Matrix3<T>* dR) {
  const T k0 = xi[0], k1 = xi[1], k2 = xi[2], g0 = xi[3], g1 = xi[4], g2 = xi[5];
  for (int i = 0; i < 3; ++i) {
    (*dp)(i) = R(i, 0) * g0 + R(i, 1) * g1 + R(i, 2) * g2;
    // (R K̂) row i = (row i of R) × K
    (*dR)(i, 0) = R(i, 1) * k2 - R(i, 2) * k1;
    (*dR)(i, 1) = R(i, 2) * k0 - R(i, 0) * k2;
    (*dR)(i, 2) = R(i, 0) * k1 - R(i, 1) * k0;
  }
}

/// Rᵀ v: a world vector in the body frame, written out in the order of Eigen's product (whose
/// call gcc does not always inline into the shot's loop).
template <typename T>
COSSERAT_RHS_INLINE Vector3<T> RotateToBody(const Matrix3<T>& R, const Vector3<T>& v) {
  return Vector3<T>(R(0, 0) * v(0) + R(1, 0) * v(1) + R(2, 0) * v(2),
                    R(0, 1) * v(0) + R(1, 1) * v(1) + R(2, 1) * v(2),
                    R(0, 2) * v(0) + R(1, 2) * v(1) + R(2, 2) * v(2));
}

/// The elastic part of the balance of moments, m × K + n_B × Γ.
template <typename T>
COSSERAT_RHS_INLINE Vector3<T> ElasticMomentRate(const Vector3<T>& m, const T* n_B, const T* xi) {
  const T k0 = xi[0], k1 = xi[1], k2 = xi[2], g0 = xi[3], g1 = xi[4], g2 = xi[5];
  return Vector3<T>(m(1) * k2 - m(2) * k1 + n_B[1] * g2 - n_B[2] * g1,
                    m(2) * k0 - m(0) * k2 + n_B[2] * g0 - n_B[0] * g2,
                    m(0) * k1 - m(1) * k0 + n_B[0] * g1 - n_B[1] * g0);
}

/// The linear law's strain in statics: ξ = ξ* + C W with C = K⁻¹ diagonal (principal axes),
/// written element by element into *xi.
template <typename T>
COSSERAT_RHS_INLINE void LinearStrain(const Vec6& rest_strain, const Vec6& compliance,
                                      const Vector3<T>& m, const Vector3<T>& n_B, Vector6<T>* xi) {
  const double* c = compliance.data();
  const double* r = rest_strain.data();
  (*xi)(0) = r[0] + c[0] * m(0);
  (*xi)(1) = r[1] + c[1] * m(1);
  (*xi)(2) = r[2] + c[2] * m(2);
  (*xi)(3) = r[3] + c[3] * n_B(0);
  (*xi)(4) = r[4] + c[4] * n_B(1);
  (*xi)(5) = r[5] + c[5] * n_B(2);
}

/// d/ds of a static point for the strain xi and the distributed force f_W (N/m, world).
template <typename T>
COSSERAT_RHS_INLINE StaticPoint<T> StaticRates(const Vector6<T>& xi, const Vector3<T>& f_W,
                                               const StaticPoint<T>& y) {
  const T* x = xi.data();
  const Matrix3<T>& R = y.R;
  StaticPoint<T> d;
  KinematicRates<T>(R, x, &d.p, &d.R);
  d.m = ElasticMomentRate<T>(y.m, y.n.data(), x);
  const T k0 = x[0], k1 = x[1], k2 = x[2];
  const T n0 = y.n(0), n1 = y.n(1), n2 = y.n(2);
  const T f0 = f_W(0), f1 = f_W(1), f2 = f_W(2);
  d.n(0) = n1 * k2 - n2 * k1 - (R(0, 0) * f0 + R(1, 0) * f1 + R(2, 0) * f2);
  d.n(1) = n2 * k0 - n0 * k2 - (R(0, 1) * f0 + R(1, 1) * f1 + R(2, 1) * f2);
  d.n(2) = n0 * k1 - n1 * k0 - (R(0, 2) * f0 + R(1, 2) * f1 + R(2, 2) * f2);
  return d;
}

/// The plain rod's static derivative: the linear law's strain (written to *xi), then the rates.
template <typename T>
COSSERAT_RHS_INLINE StaticPoint<T> StaticDerivative(const Vec6& rest_strain, const Vec6& compliance,
                                                    const Vector3<T>& f_W, const StaticPoint<T>& y,
                                                    Vector6<T>* xi) {
  LinearStrain<T>(rest_strain, compliance, y.m, y.n, xi);
  return StaticRates<T>(*xi, f_W, y);
}

/// The section numbers of one sample point a dynamic stage reads (principal axes: every
/// matrix is diagonal and stored as its diagonal).
struct SectionSample {
  Vec6 stiffness;               ///< diag K
  Vec6 damping;                 ///< diag D
  Vec6 compliance;              ///< diag K⁻¹ (statics)
  Vec6 rest_strain;             ///< ξ*
  Vec6 mass;                    ///< diag M = [ρI1, ρI2, ρ(I1+I2), ρA, ρA, ρA]
  Vec6 implicit_compliance;     ///< A = diag (K + c0 D)⁻¹ for the current c0
  Vec6 implicit_damping;        ///< A D
  Vec6 implicit_offset;         ///< ξ* − c0 A D ξ*
  bool damped = false;          ///< D ≠ 0
  double s = 0.0;               ///< arc length of the sample point, m
  double outer_diameter = 0.0;  ///< m (what the section displaces in a fluid)
  /// The piece of unit length at this sample, for the loads (load.hpp).
  LoadSite Site() const { return {s, 1.0, mass(5), outer_diameter}; }
};

/// What a dynamic stage reads besides the state: the BDF2 history terms ξʰ, Vʰ and (ρA a)ʰ's
/// velocity part v_Wʰ (t_n = c0 x + xʰ for each), and c0 (1/s). With statics, all of them are
/// unused: the stage is the static equations.
struct StageHistory {
  const Vec6* strain = nullptr;      ///< ξʰ
  const Vec6* twist = nullptr;       ///< Vʰ
  const Vec3* velocity_W = nullptr;  ///< v_Wʰ, m/s
  double c0 = 0.0;
  bool statics = true;
};

/// d/ds of a dynamic point at one stage: the Kelvin–Voigt law with BDF2 rates (or `given`, the
/// strain of the tendon-augmented law solved by the caller), then the rates of the file comment.
/// added_mass m_a (kg/m, a fluid's) adds m_a (I − t tᵀ) a_W to ρA a_W, t = R e₃.
/// Writes the stage's strain, twist and world velocity R v (m/s) for the BDF2 history of the next
/// steps. Written out: this is the innermost loop of every dynamic step.
template <typename T>
COSSERAT_RHS_INLINE DynamicPoint<T> DynamicDerivative(
    const SectionSample& smp, const Vector3<T>& f_W, const DynamicPoint<T>& y,
    const StageHistory& h, Vector6<T>* strain, Vector6<T>* twist, Vector3<T>* velocity_W,
    const Vector6<T>* given = nullptr, double added_mass = 0.0) {
  const Matrix3<T>& R = y.R;
  const Vector3<T> n_B = RotateToBody(R, y.n);
  const T W[6] = {y.m(0), y.m(1), y.m(2), n_B(0), n_B(1), n_B(2)};
  T xi[6], xt[6], Vt[6];
  if (given) {
    for (int i = 0; i < 6; ++i) xi[i] = (*given)(i);
  } else if (h.statics) {
    for (int i = 0; i < 6; ++i) xi[i] = smp.rest_strain(i) + smp.compliance(i) * W[i];
  } else {
    // W = K (ξ − ξ*) + D (c0 ξ + ξʰ)  ⇒  ξ = [ξ* − c0 A D ξ*] + A W − A D ξʰ, A = (K + c0 D)⁻¹;
    // with D = 0 this is the static law, operation for operation.
    for (int i = 0; i < 6; ++i) xi[i] = smp.implicit_offset(i) + smp.implicit_compliance(i) * W[i];
    if (smp.damped)
      for (int i = 0; i < 6; ++i) xi[i] -= smp.implicit_damping(i) * (*h.strain)(i);
  }
  const Vector3<T> w = y.w;
  const Vector3<T> v = y.v;
  if (h.statics) {
    for (int i = 0; i < 6; ++i) xt[i] = Vt[i] = T(0.0);
  } else {
    for (int i = 0; i < 6; ++i) xt[i] = h.c0 * xi[i] + (*h.strain)(i);
    for (int i = 0; i < 3; ++i) {
      Vt[i] = h.c0 * w(i) + (*h.twist)(i);
      Vt[3 + i] = h.c0 * v(i) + (*h.twist)(3 + i);
    }
  }
  for (int i = 0; i < 6; ++i) (*strain)(i) = xi[i];
  twist->template head<3>() = w;  // not a comma initializer: gcc leaves that out of line
  twist->template tail<3>() = v;
  const T k0 = xi[0], k1 = xi[1], k2 = xi[2], g0 = xi[3], g1 = xi[4], g2 = xi[5];
  const double J0 = smp.mass(0), J1 = smp.mass(1), J2 = smp.mass(2), rhoA = smp.mass(5);
  DynamicPoint<T> d;
  KinematicRates<T>(R, xi, &d.p, &d.R);
  // ω' = K_t + ω × K,  v' = Γ_t + ω × Γ + v × K
  d.w(0) = xt[0] + w(1) * k2 - w(2) * k1;
  d.w(1) = xt[1] + w(2) * k0 - w(0) * k2;
  d.w(2) = xt[2] + w(0) * k1 - w(1) * k0;
  d.v(0) = xt[3] + w(1) * g2 - w(2) * g1 + v(1) * k2 - v(2) * k1;
  d.v(1) = xt[4] + w(2) * g0 - w(0) * g2 + v(2) * k0 - v(0) * k2;
  d.v(2) = xt[5] + w(0) * g1 - w(1) * g0 + v(0) * k1 - v(1) * k0;
  // m' = m × K + n × Γ + J ω_t + ω × J ω
  const T Jw0 = J0 * w(0), Jw1 = J1 * w(1), Jw2 = J2 * w(2);
  d.m = ElasticMomentRate<T>(y.m, W + 3, xi);
  d.m(0) += J0 * Vt[0];
  d.m(0) += w(1) * Jw2;
  d.m(0) -= w(2) * Jw1;
  d.m(1) += J1 * Vt[1];
  d.m(1) += w(2) * Jw0;
  d.m(1) -= w(0) * Jw2;
  d.m(2) += J2 * Vt[2];
  d.m(2) += w(0) * Jw1;
  d.m(2) -= w(1) * Jw0;
  // n_W' = −f + ρA a_W, with the centreline acceleration a_W the BDF2 rate of the world
  // velocity R v (continuous limit: R (v_t + ω × v)). Linear momentum then obeys the BDF2
  // recurrence exactly, to round-off, when no force acts.
  *velocity_W = R * v;
  d.n = -f_W;
  if (!h.statics) {
    for (int i = 0; i < 3; ++i) d.n(i) += rhoA * (h.c0 * (*velocity_W)(i) + (*h.velocity_W)(i));
    if (added_mass != 0.0) {
      Vector3<T> a;
      for (int i = 0; i < 3; ++i) a(i) = h.c0 * (*velocity_W)(i) + (*h.velocity_W)(i);
      const Vector3<T> t = R.col(2);
      d.n += added_mass * (a - t * t.dot(a));
    }
  }
  return d;
}

}  // namespace cosserat::rhs
