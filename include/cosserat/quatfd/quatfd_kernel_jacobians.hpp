#pragma once
/// \file
/// Hand-derived Jacobians of the element kernels of quatfd_kernels.hpp (Lang & Linn 2009: "the
/// analytical Jacobian ∂f/∂(q, v)"). Each function returns the kernel's value, identical to the
/// kernel's, and its derivatives with respect to the raw unknowns (x differences, quaternion
/// components and their rates), exact also off the constraint |p| = 1.
///
/// Notation (all for a quaternion p = [w, x, y, z], n2 = |p|²):
///   E(p) (3×4): E(p) b = Im(p̄ b);   note Im(p̄ b) = −Im(b̄ p), so ∂(E(p) b)/∂p = −E(b).
///   G(p) = 2 E(p)/n2: the body rotation δθ of R(p) caused by δp (δR = R [δθ]×), and ω = G ṗ.
///   ∂ω/∂p = −(2/n2) (E(ṗ) + ω pᵀ).
///   δ(Rᵀ u) = [Rᵀu]× δθ,  δ(R u) = −R [u]× δθ.

#include <Eigen/Core>

#include "cosserat/quatfd/quatfd_kernels.hpp"

namespace cosserat::quatfd::kernels {

using M33 = Eigen::Matrix3d;
using M34 = Eigen::Matrix<double, 3, 4>;
using M43 = Eigen::Matrix<double, 4, 3>;
using M44 = Eigen::Matrix4d;

/// hat(v): Skew(v) u = v × u (lie/so3.hpp).
inline M33 Skew(const Eigen::Vector3d& v) { return lie::hat(v); }

/// E(p): E(p) b = Im(p̄ ⊗ b).
inline M34 ImConjMulMatrix(const Eigen::Vector4d& p) {
  M34 E;
  E << -p[1], p[0], p[3], -p[2],  //
      -p[2], -p[3], p[0], p[1],   //
      -p[3], p[2], -p[1], p[0];
  return E;
}

/// Left(a) b = a ⊗ b.
inline M44 LeftMulMatrix(const Eigen::Vector4d& a) {
  M44 m;
  m << a[0], -a[1], -a[2], -a[3],  //
      a[1], a[0], -a[3], a[2],     //
      a[2], a[3], a[0], -a[1],     //
      a[3], -a[2], a[1], a[0];
  return m;
}

/// Right(b) a = a ⊗ b.
inline M44 RightMulMatrix(const Eigen::Vector4d& b) {
  M44 m;
  m << b[0], -b[1], -b[2], -b[3],  //
      b[1], b[0], b[3], -b[2],     //
      b[2], -b[3], b[0], b[1],     //
      b[3], b[2], -b[1], b[0];
  return m;
}

/// R(p) = H(p)/|p|² for any non-zero p (body → world).
inline M33 RotationMatrix(const Eigen::Vector4d& p) {
  const double w = p[0], x = p[1], y = p[2], z = p[3];
  const double n2 = p.squaredNorm();
  M33 R;
  R << w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z;
  return R / n2;
}

/// Derivatives of SegmentForces' outputs (force on x_a, body torque) with respect to
/// dx = x_b − x_a (m), p, dv = ẋ_b − ẋ_a (m/s) and ṗ.
struct SegmentJacobian {
  M33 fa_dx, fa_dv, tau_dx, tau_dv;
  M34 fa_p, fa_pd, tau_p, tau_pd;
};

/// SegmentForces (same outputs) and its exact Jacobian. With u = dx/Δs, Γ = Rᵀu, ω = G ṗ,
/// Γ̇ = Rᵀ dv/Δs + Γ × ω, F = C (Γ − Γ*) + C̃ Γ̇, force_a = R F, torque = Δs Γ × F:
///   ∂Γ/∂dx = Rᵀ/Δs,            ∂Γ/∂p = [Γ]× G,
///   ∂Γ̇/∂dx = −[ω]× Rᵀ/Δs,      ∂Γ̇/∂p = [Rᵀdv/Δs]× G − [ω]×[Γ]× G + [Γ]× ∂ω/∂p,
///   ∂Γ̇/∂dv = Rᵀ/Δs,            ∂Γ̇/∂ṗ = [Γ]× G,
///   ∂(R F) = R (∂F − [F]× G δp),  ∂(Γ × F) = [Γ]× ∂F − [F]× ∂Γ.
inline void SegmentForcesJacobian(const SegmentConstants& c, const Eigen::Vector3d& dx,
                                  const Eigen::Vector4d& p, const Eigen::Vector3d& dv,
                                  const Eigen::Vector4d& pd, Eigen::Vector3d* force_a,
                                  Eigen::Vector3d* torque, SegmentJacobian* J) {
  const double inv = 1.0 / c.ds, n2 = p.squaredNorm();
  const M33 R = RotationMatrix(p);
  const M33 Rt_ds = R.transpose() * inv;
  const M34 E = ImConjMulMatrix(p);
  const M34 G = (2.0 / n2) * E;
  const Eigen::Vector3d gamma = Rt_ds * dx;
  const Eigen::Vector3d omega = G * pd;
  const Eigen::Vector3d gv = Rt_ds * dv;
  const Eigen::Vector3d gamma_dot = gv + gamma.cross(omega);
  const Eigen::Vector3d F = c.stiffness * (gamma - c.rest) + c.damping * gamma_dot;
  *force_a = R * F;
  *torque = c.ds * gamma.cross(F);

  const M33 Sg = Skew(gamma), Sw = Skew(omega), SF = Skew(F);
  const M34 dw_dp = (-2.0 / n2) * (ImConjMulMatrix(pd) + omega * p.transpose());
  const M34 SgG = Sg * G;  // ∂Γ/∂p = ∂Γ̇/∂ṗ
  const M34 dgd_dp = Skew(gv) * G - Sw * SgG + Sg * dw_dp;
  // ∂F: C ∂Γ + C̃ ∂Γ̇.
  const M33 F_dx = (c.stiffness - c.damping * Sw) * Rt_ds;
  const M34 F_p = c.stiffness * SgG + c.damping * dgd_dp;
  const M33 F_dv = c.damping * Rt_ds;
  const M34 F_pd = c.damping * SgG;
  J->fa_dx = R * F_dx;
  J->fa_p = R * (F_p - SF * G);
  J->fa_dv = R * F_dv;
  J->fa_pd = R * F_pd;
  J->tau_dx = c.ds * (Sg * F_dx - SF * Rt_ds);
  J->tau_p = c.ds * (Sg * F_p - SF * SgG);
  J->tau_dv = c.ds * (Sg * F_dv);
  J->tau_pd = c.ds * (Sg * F_pd);
}

/// Derivatives of BendTorques' outputs (torque_a, torque_b) with respect to p_a, p_b, ṗ_a, ṗ_b.
struct BendJacobian {
  M34 ta_pa, ta_pb, ta_pda, ta_pdb;
  M34 tb_pa, tb_pb, tb_pda, tb_pdb;
};

using M54 = Eigen::Matrix<double, 5, 4>;

/// ∂ξ/∂p_a and ∂ξ/∂p_b of the bending invariants ξ = (r0, r⃗, s) of BendTorquesJacobian (rows
/// r0, r⃗, s), with Ea = E(p_a), Eb = E(p_b); variant1: s is the variant-1 normaliser (else
/// s ≡ 1 and its row is zero).
inline void BendInvariantsJacobian(const Eigen::Vector4d& pa, const Eigen::Vector4d& pb,
                                   const M34& Ea, const M34& Eb, bool variant1, M54* xi_pa,
                                   M54* xi_pb) {
  xi_pa->row(0) = pb.transpose();
  xi_pb->row(0) = pa.transpose();
  xi_pa->middleRows<3>(1) = -Eb;
  xi_pb->middleRows<3>(1) = Ea;
  if (variant1) {
    xi_pa->row(4) = 0.5 * (pa + pb).transpose();
    xi_pb->row(4) = xi_pa->row(4);
  } else {
    xi_pa->row(4).setZero();
    xi_pb->row(4).setZero();
  }
}

/// BendTorques (same outputs) and its exact Jacobian. Write T_a = ∂K/∂θ_a, T_b = ∂K/∂θ_b (see
/// BendTorques); then K̇ = T_a ω_a + T_b ω_b and torque_x = −w T_xᵀ M. Everything else depends
/// on p_a, p_b through ξ = (r0, r⃗, s) with r = p̄_a p_b, s the variant-1 normaliser:
///   ∂r0/∂p_a = p_bᵀ, ∂r0/∂p_b = p_aᵀ; ∂r⃗/∂p_a = −E(p_b), ∂r⃗/∂p_b = E(p_a);
///   ∂s/∂p_a = ∂s/∂p_b = (p_a + p_b)ᵀ/2 (variant 1; s ≡ 1 for the basic choice).
/// With P = r0 ω_d + r⃗ × ω_s (ω_d = ω_b − ω_a, ω_s = ω_b + ω_a), 1/(hs) = i and c = 1/(4s):
///   K = 2 i r⃗:       ∂K/∂r⃗ = 2 i I, ∂K/∂s = −K/s;
///   K̇ = i P + c (r⃗·ω_d) K:
///     ∂K̇/∂r0 = i ω_d, ∂K̇/∂r⃗ = −i [ω_s]× + c K ω_dᵀ + 2 c i (r⃗·ω_d) I,
///     ∂K̇/∂s = −(i P + 2 c (r⃗·ω_d) K)/s, ∂K̇/∂ω_x = T_x;
///   torque_a = w (i (r0 M + r⃗ × M) + c (K·M) r⃗) at fixed M:
///     ∂/∂r0 = w i M, ∂/∂r⃗ = w (−i [M]× + c (K·M) I + 2 c i r⃗ Mᵀ),
///     ∂/∂s = −w (i (r0 M + r⃗ × M) + 2 c (K·M) r⃗)/s, ∂/∂M = −w T_aᵀ;
///   torque_b = −w (i (r0 M − r⃗ × M) + c (K·M) r⃗) likewise, ∂/∂M = −w T_bᵀ.
inline void BendTorquesJacobian(const BendConstants& c, const Eigen::Vector4d& pa,
                                const Eigen::Vector4d& pb, const Eigen::Vector4d& pda,
                                const Eigen::Vector4d& pdb, Eigen::Vector3d* torque_a,
                                Eigen::Vector3d* torque_b, BendJacobian* J) {
  using V3 = Eigen::Vector3d;
  using M35 = Eigen::Matrix<double, 3, 5>;
  const bool v1 = c.kind == CurvatureKind::kVariant1;
  const M34 Ea = ImConjMulMatrix(pa), Eb = ImConjMulMatrix(pb);
  const V3 rv = Ea * pb;
  const double r0 = pa.dot(pb);
  const double s = v1 ? 0.25 * (pa.squaredNorm() + pb.squaredNorm() + 2.0 * r0) : 1.0;
  const double ih = 1.0 / (c.h * s);
  const double cr = v1 ? 0.25 / s : 0.0;
  const V3 K = 2.0 * ih * rv;
  const double na2 = pa.squaredNorm(), nb2 = pb.squaredNorm();
  const M34 Ga = (2.0 / na2) * Ea, Gb = (2.0 / nb2) * Eb;
  const V3 wa = Ga * pda, wb = Gb * pdb;
  const V3 wd = wb - wa, ws = wb + wa;
  const M33 Srv = Skew(rv);
  const M33 KrT = cr * K * rv.transpose();
  const M33 Ta = -ih * (r0 * M33::Identity() - Srv) - KrT;
  const M33 Tb = ih * (r0 * M33::Identity() + Srv) + KrT;
  const V3 P = r0 * wd + rv.cross(ws);
  const double rwd = rv.dot(wd);
  const V3 K_dot = ih * P + (cr * rwd) * K;
  const V3 M = c.stiffness * (K - c.rest) + c.damping * K_dot;
  const double w = c.weight;
  const M33 taM = -w * Ta.transpose(), tbM = -w * Tb.transpose();  // ∂torque/∂M
  *torque_a = taM * M;
  *torque_b = tbM * M;

  M54 xa, xb;
  BendInvariantsJacobian(pa, pb, Ea, Eb, v1, &xa, &xb);
  // ∂K/∂ξ, ∂K̇/∂ξ at fixed ω, then ∂M/∂ξ.
  M35 K_xi, Kd_xi;
  K_xi.col(0).setZero();
  K_xi.middleCols<3>(1) = 2.0 * ih * M33::Identity();
  K_xi.col(4) = -K / s;
  Kd_xi.col(0) = ih * wd;
  Kd_xi.middleCols<3>(1) =
      -ih * Skew(ws) + cr * K * wd.transpose() + (2.0 * cr * ih * rwd) * M33::Identity();
  Kd_xi.col(4) = -(ih * P + 2.0 * cr * rwd * K) / s;
  const M35 M_xi = c.stiffness * K_xi + c.damping * Kd_xi;
  // Explicit ∂torque/∂ξ at fixed M.
  const double km = K.dot(M);
  const V3 rxM = rv.cross(M);
  const M33 SM = Skew(M);
  const M33 rMt = (2.0 * cr * ih) * rv * M.transpose() + (cr * km) * M33::Identity();
  M35 ta_xi, tb_xi;
  ta_xi.col(0) = w * ih * M;
  ta_xi.middleCols<3>(1) = w * (-ih * SM + rMt);
  ta_xi.col(4) = -w * (ih * (r0 * M + rxM) + 2.0 * cr * km * rv) / s;
  tb_xi.col(0) = -w * ih * M;
  tb_xi.middleCols<3>(1) = -w * (ih * SM + rMt);
  tb_xi.col(4) = w * (ih * (r0 * M - rxM) + 2.0 * cr * km * rv) / s;
  ta_xi += taM * M_xi;
  tb_xi += tbM * M_xi;
  // ω through M: ∂M/∂ω_x = C̃ T_x.
  const M33 DTa = c.damping * Ta, DTb = c.damping * Tb;
  const M34 wa_pa = (-2.0 / na2) * (ImConjMulMatrix(pda) + wa * pa.transpose());
  const M34 wb_pb = (-2.0 / nb2) * (ImConjMulMatrix(pdb) + wb * pb.transpose());
  const M34 Ma_pa = DTa * wa_pa, Mb_pb = DTb * wb_pb;
  const M34 Ma_pda = DTa * Ga, Mb_pdb = DTb * Gb;
  J->ta_pa = ta_xi * xa + taM * Ma_pa;
  J->ta_pb = ta_xi * xb + taM * Mb_pb;
  J->tb_pa = tb_xi * xa + tbM * Ma_pa;
  J->tb_pb = tb_xi * xb + tbM * Mb_pb;
  J->ta_pda = taM * Ma_pda;
  J->ta_pdb = taM * Mb_pdb;
  J->tb_pda = tbM * Ma_pda;
  J->tb_pdb = tbM * Mb_pdb;
}

/// QuaternionAcceleration (same value) and its exact Jacobian with respect to p, ṗ and the body
/// torque τ. With c = [c0; c⃗], p̈ = p ⊗ c / n2:
///   ∂p̈ = (Right(c) δp + Left(p) δc)/n2 − p̈ (2pᵀδp)/n2,
///   c⃗ = n2 ω̇/2 + (p·ṗ) ω,  ω̇ = J⁻¹ (τ − ω × Jω),  ∂ω̇/∂ω = −J⁻¹ ([ω]× J − [Jω]×),
///   c0 = −|ṗ|² − 2α p·ṗ − β²(n2 − 1)/2.
inline void QuaternionAccelerationJacobian(const RotationConstants& c, const Eigen::Vector4d& p,
                                           const Eigen::Vector4d& pd, const Eigen::Vector3d& torque,
                                           Eigen::Vector4d* acc, M44* acc_p, M44* acc_pd,
                                           M43* acc_tau) {
  using V3 = Eigen::Vector3d;
  const double n2 = p.squaredNorm(), ppd = p.dot(pd);
  const M34 G = (2.0 / n2) * ImConjMulMatrix(p);
  const V3 w = G * pd;
  const V3 Jw = c.inertia.cwiseProduct(w);
  const V3 inv_J = c.inertia.cwiseInverse();
  const V3 wdot = inv_J.cwiseProduct(torque - w.cross(Jw));
  const V3 cv = 0.5 * n2 * wdot + ppd * w;
  const double c0 = -pd.squaredNorm() - 2.0 * c.alpha * ppd - 0.5 * c.beta * c.beta * (n2 - 1.0);
  const Eigen::Vector4d cq(c0, cv[0], cv[1], cv[2]);
  const M44 Lp = LeftMulMatrix(p);
  *acc = Lp * cq / n2;

  const M33 wdot_w = inv_J.asDiagonal() * (Skew(Jw) - Skew(w) * c.inertia.asDiagonal());
  const M34 w_p = (-2.0 / n2) * (ImConjMulMatrix(pd) + w * p.transpose());
  M44 c_p, c_pd;
  c_p.row(0) = -2.0 * c.alpha * pd.transpose() - c.beta * c.beta * p.transpose();
  c_pd.row(0) = -2.0 * pd.transpose() - 2.0 * c.alpha * p.transpose();
  c_p.bottomRows<3>() =
      wdot * p.transpose() + (0.5 * n2) * wdot_w * w_p + w * pd.transpose() + ppd * w_p;
  c_pd.bottomRows<3>() = (0.5 * n2) * wdot_w * G + w * p.transpose() + ppd * G;
  *acc_p = (RightMulMatrix(cq) + Lp * c_p) / n2 - (2.0 / n2) * (*acc) * p.transpose();
  *acc_pd = Lp * c_pd / n2;
  *acc_tau = 0.5 * Lp.rightCols<3>() * inv_J.asDiagonal();
}

}  // namespace cosserat::quatfd::kernels
