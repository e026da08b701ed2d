#pragma once
/// \file
/// Element kernels of the quaternion finite-difference rod (Lang & Linn 2009), templated on the
/// scalar so the same code gives f (T = double) and the exact element Jacobians (T = ceres::Jet).
///
//// Quaternions are [w, x, y, z], Hamilton product. Every kernel depends on a quaternion p only
/// through the rotation it represents (R(p) = H(p) / |p|², body angular velocity
/// ω = 2 Im(p̄ ṗ) / |p|²) or, for the curvature, through r = p̄_a p_b; body torques are the
/// generalised forces of the rotations (work-conjugate to ω).

#include <Eigen/Core>

#include "cosserat/lie/quaternion.hpp"

namespace cosserat::quatfd::kernels {

template <typename T>
using V3 = Eigen::Matrix<T, 3, 1>;
template <typename T>
using V4 = Eigen::Matrix<T, 4, 1>;

template <typename T>
inline V3<T> Cross(const V3<T>& a, const V3<T>& b) {
  return V3<T>(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

/// a ⊗ b (lie/quaternion.hpp).
using lie::QuatMultiply;

/// Im(ā ⊗ b): the vector part of conj(a) ⊗ b.
template <typename T>
inline V3<T> ImConjMul(const V4<T>& a, const V4<T>& b) {
  return V3<T>(a[0] * b[1] - a[1] * b[0] - a[2] * b[3] + a[3] * b[2],
               a[0] * b[2] + a[1] * b[3] - a[2] * b[0] - a[3] * b[1],
               a[0] * b[3] - a[1] * b[2] + a[2] * b[1] - a[3] * b[0]);
}

/// R(p)ᵀ u (world to body) for any non-zero p: H(p)ᵀ u / |p|².
template <typename T>
inline V3<T> ToBody(const V4<T>& p, const V3<T>& u) {
  // H(p) u = |p|² u + w t + q × t with t = 2 q × u; the conjugate flips q.
  const V3<T> q(p[1], p[2], p[3]);
  const V3<T> t = T(2) * Cross<T>(u, q);
  const T n2 = p.squaredNorm();
  return (n2 * u + p[0] * t - Cross<T>(q, t)) / n2;
}

/// R(p) u (body to world) for any non-zero p.
template <typename T>
inline V3<T> ToWorld(const V4<T>& p, const V3<T>& u) {
  const V3<T> q(p[1], p[2], p[3]);
  const V3<T> t = T(2) * Cross<T>(q, u);
  const T n2 = p.squaredNorm();
  return (n2 * u + p[0] * t + Cross<T>(q, t)) / n2;
}

/// Body angular velocity ω = 2 Im(p̄ ṗ) / |p|² (rad/s).
template <typename T>
inline V3<T> AngularVelocity(const V4<T>& p, const V4<T>& pd) {
  return T(2) * ImConjMul<T>(p, pd) / p.squaredNorm();
}

struct SegmentConstants {
  double ds = 0;                     ///< Δs_ν, m
  Eigen::Matrix3d stiffness;         ///< C_Γ (N), body frame [shear1, shear2, extension]
  Eigen::Matrix3d damping;           ///< C̃_Γ (N·s)
  Eigen::Vector3d rest = {0, 0, 1};  ///< Γ* = rest value of Rᵀ ∂s x (dimensionless)
};

/// One segment between vertices a = n and b = n + 1 with quaternion p (Lang & Linn 2009, eq. 1 for
/// Γ), given dx = x_b − x_a and dv = ẋ_b − ẋ_a:
///   Γ = R(p)ᵀ (x_b − x_a) / Δs,  Γ̇ = R(p)ᵀ (ẋ_b − ẋ_a) / Δs + Γ × ω,
///   F = C_Γ (Γ − Γ*) + C̃_Γ Γ̇  (body frame, N; Antman/Kelvin–Voigt),
/// and its generalised forces: on x_a +R F (force_a), on x_b −R F (N, world), and the body torque
/// Δs Γ × F on p (N·m), i.e. −∂/∂(q) of Δs ½ (Γ−Γ*)ᵀC_Γ(Γ−Γ*) plus the Rayleigh damping force.
/// Here with ω = AngularVelocity(p, ṗ) given; SegmentForces below computes it.
template <typename T>
inline void SegmentForcesOmega(const SegmentConstants& c, const V3<T>& dx, const V4<T>& p,
                               const V3<T>& dv, const V3<T>& omega, V3<T>* force_a, V3<T>* torque,
                               V3<T>* strain = nullptr, V3<T>* stress = nullptr) {
  const T inv = T(1.0 / c.ds);
  const V3<T> gamma = ToBody<T>(p, V3<T>(dx * inv));
  const V3<T> gamma_dot = ToBody<T>(p, V3<T>(dv * inv)) + Cross<T>(gamma, omega);
  const V3<T> e = gamma - c.rest.cast<T>();
  const V3<T> F = c.stiffness.cast<T>() * e + c.damping.cast<T>() * gamma_dot;
  *force_a = ToWorld<T>(p, F);
  *torque = T(c.ds) * Cross<T>(gamma, F);
  if (strain) *strain = gamma;
  if (stress) *stress = F;
}

/// SegmentForcesOmega with ω = AngularVelocity(p, ṗ) (the f path computes ω once per segment
/// and shares it with the bending elements and the quaternion acceleration).
template <typename T>
inline void SegmentForces(const SegmentConstants& c, const V3<T>& dx, const V4<T>& p,
                          const V3<T>& dv, const V4<T>& pd, V3<T>* force_a, V3<T>* torque,
                          V3<T>* strain = nullptr, V3<T>* stress = nullptr) {
  SegmentForcesOmega<T>(c, dx, p, dv, AngularVelocity<T>(p, pd), force_a, torque, strain, stress);
}

/// Discrete curvature (Lang & Linn 2009: "several choices" for K_n from p_{n−1/2}, p_{n+1/2}).
enum class CurvatureKind {
  kBasic,     ///< K = 2 Im(p̄_a p_b) / h: the vertex quaternion is the plain mean (p_a + p_b)/2
  kVariant1,  ///< K = 2 Im(p̄_n p'_n) / |p_n|² with p_n = (p_a+p_b)/2, p'_n = (p_b−p_a)/h:
              ///< = 8 Im(p̄_a p_b) / (h |p_a + p_b|²), exact for the interpolated field
};

struct BendConstants {
  double h = 0;               ///< distance between the two quaternions' stations, m
  double weight = 0;          ///< length the vertex stands for (quadrature weight), m
  Eigen::Matrix3d stiffness;  ///< C_K (N·m²), [bending1, bending2, torsion]
  Eigen::Matrix3d damping;    ///< C̃_K (N·m²·s)
  Eigen::Vector3d rest = Eigen::Vector3d::Zero();  ///< K* (1/m)
  CurvatureKind kind = CurvatureKind::kVariant1;
};

/// The curvature at one vertex and the body torques of its bending/torsion element on the two
/// rotations: K(r) with r = p̄_a p_b, M = C_K (K − K*) + C̃_K K̇ (N·m, body frame of the vertex),
/// torque_x = −weight (∂K/∂θ_x)ᵀ M where θ_x is a body rotation of p_x. With h = weight = Δs and
/// r ≈ 1 this is torque_a ≈ +M, torque_b ≈ −M: the discrete ∂s M. Here with the body angular
/// velocities ω_a, ω_b of the two rotations given; BendTorques below computes them from ṗ_a, ṗ_b.
template <typename T>
inline void BendTorquesOmega(const BendConstants& c, const V4<T>& pa, const V4<T>& pb,
                             const V3<T>& wa, const V3<T>& wb, V3<T>* torque_a, V3<T>* torque_b,
                             V3<T>* curvature = nullptr, V3<T>* moment = nullptr) {
  const V4<T> conj_a(pa[0], -pa[1], -pa[2], -pa[3]);
  const V4<T> r = QuatMultiply<T>(conj_a, pb);
  const V3<T> rv(r[1], r[2], r[3]);
  const T r0 = r[0];
  // s = |p_n|² with p_n the mean (variant 1); 1 for the basic choice.
  const T s = c.kind == CurvatureKind::kVariant1
                  ? T(0.25) * (pa.squaredNorm() + pb.squaredNorm() + T(2) * r0)
                  : T(1);
  const T inv_hs = T(1.0 / c.h) / s;
  const V3<T> K = T(2) * inv_hs * rv;
  // p_b: δr = r ⊗ [0, δθ/2] → δr⃗ = (r0 δθ + r⃗ × δθ)/2, δr0 = −r⃗·δθ/2.
  // p_a: δr = −[0, δθ/2] ⊗ r → δr⃗ = −(r0 δθ − r⃗ × δθ)/2, δr0 = +r⃗·δθ/2.
  // K = 2 r⃗/(h s) and, for variant 1, δs = δr0/2, so
  //   ∂K/∂θ_b =  (r0 I + [r⃗]×)/(h s) + c K r⃗ᵀ,  ∂K/∂θ_a = −(r0 I − [r⃗]×)/(h s) − c K r⃗ᵀ,
  // with c = 1/(4 s) for variant 1 and 0 for the basic choice.
  const T cr = c.kind == CurvatureKind::kVariant1 ? T(0.25) / s : T(0);
  const V3<T> wd = wb - wa, ws = wb + wa;
  const V3<T> K_dot = inv_hs * (r0 * wd + Cross<T>(rv, ws)) + (cr * rv.dot(wd)) * K;
  const V3<T> M = c.stiffness.cast<T>() * (K - c.rest.cast<T>()) + c.damping.cast<T>() * K_dot;
  // (∂K/∂θ_b)ᵀ M = (r0 M − r⃗ × M)/(h s) + c r⃗ (K·M); (∂K/∂θ_a)ᵀ M = −(r0 M + r⃗ × M)/(h s) − c r⃗
  // (K·M).
  const V3<T> rxM = Cross<T>(rv, M);
  const V3<T> km = (cr * K.dot(M)) * rv;
  *torque_a = T(c.weight) * (inv_hs * (r0 * M + rxM) + km);
  *torque_b = -T(c.weight) * (inv_hs * (r0 * M - rxM) + km);
  if (curvature) *curvature = K;
  if (moment) *moment = M;
}

template <typename T>
inline void BendTorques(const BendConstants& c, const V4<T>& pa, const V4<T>& pb, const V4<T>& pda,
                        const V4<T>& pdb, V3<T>* torque_a, V3<T>* torque_b,
                        V3<T>* curvature = nullptr, V3<T>* moment = nullptr) {
  BendTorquesOmega<T>(c, pa, pb, AngularVelocity<T>(pa, pda), AngularVelocity<T>(pb, pdb), torque_a,
                      torque_b, curvature, moment);
}

struct RotationConstants {
  Eigen::Vector3d inertia = Eigen::Vector3d::Ones();  ///< J = diag(ρI1, ρI2, ρ(I1+I2)) Δs, kg·m²
  double alpha = 0;  ///< Baumgarte damping of g = (|p|² − 1)/2, 1/s
  double beta = 0;   ///< Baumgarte stiffness, 1/s
};

/// Quaternion acceleration from the body torque (Lang & Linn 2009, eq. 4, written with the exact
/// inverse of the quaternion mass matrix): with ω = 2 Im(p̄ ṗ)/|p|² and ω̇ = J⁻¹ (τ − ω × J ω),
///   p̈ = p ⊗ [c0, c] / |p|²,  c = |p|² ω̇ / 2 + (p·ṗ) ω,  c0 = −|ṗ|² − 2α p·ṗ − β²(|p|²−1)/2,
/// so that the represented rotation has angular acceleration ω̇ exactly, and g = (|p|²−1)/2
/// obeys g̈ + 2α ġ + β² g = 0 (g̈ = 0 without Baumgarte). Here with ω given (QuaternionAcceleration
/// below computes it).
template <typename T>
inline V4<T> QuaternionAccelerationOmega(const RotationConstants& c, const V4<T>& p,
                                         const V4<T>& pd, const V3<T>& w, const V3<T>& torque) {
  const T n2 = p.squaredNorm();
  const T ppd = p.dot(pd);
  const V3<T> Jw(T(c.inertia[0]) * w[0], T(c.inertia[1]) * w[1], T(c.inertia[2]) * w[2]);
  const V3<T> rhs = torque - Cross<T>(w, Jw);
  const V3<T> wdot(rhs[0] / T(c.inertia[0]), rhs[1] / T(c.inertia[1]), rhs[2] / T(c.inertia[2]));
  const V3<T> cv = T(0.5) * n2 * wdot + ppd * w;
  const T c0 = -pd.squaredNorm() - T(2 * c.alpha) * ppd - T(0.5 * c.beta * c.beta) * (n2 - T(1));
  return QuatMultiply<T>(p, V4<T>(c0, cv[0], cv[1], cv[2])) / n2;
}

/// QuaternionAccelerationOmega with ω = AngularVelocity(p, ṗ).
template <typename T>
inline V4<T> QuaternionAcceleration(const RotationConstants& c, const V4<T>& p, const V4<T>& pd,
                                    const V3<T>& torque) {
  return QuaternionAccelerationOmega<T>(c, p, pd, AngularVelocity<T>(p, pd), torque);
}

}  // namespace cosserat::quatfd::kernels
