#pragma once
/// \file
/// The hand-written linearisations of the Cosserat right-hand sides of cosserat_rhs.hpp along
/// six directions at once (one column each): what the shooting solvers propagate through their
/// spatial scheme to get the exact Jacobian of a shot. tests/test_cosserat_rhs.cpp checks each
/// against ceres::Jet applied to the templated right-hand side.

#include <Eigen/LU>

#include "cosserat/strong/cosserat_rhs.hpp"
#include "cosserat/strong/frame_tangent.hpp"

namespace cosserat::rhs {

using internal::Mat36;
using internal::RotationTangent;

/// Derivative of a StaticPoint along 6 directions, in the same coordinates.
struct StaticTangent {
  Mat36 p;
  RotationTangent R;  ///< d(R e_j)
  Mat36 m;
  Mat36 n;
};

/// Derivative of a DynamicPoint along 6 directions, in the same coordinates.
struct DynamicTangent {
  Mat36 p;
  RotationTangent R;  ///< d(R e_j)
  Mat36 m, n, w, v;
};

/// The linearisation of StaticDerivative along dy, at the primal state y with strain xi and
/// distributed force f_W; df_W, when given, is the derivative of f_W along the directions (loads
/// that depend on the pose). With the tendon law, H = ∂W/∂ξ of that law and
/// dξ = H⁻¹ (dW − source), the source being the law's derivative along the directions (tension
/// directions); otherwise dξ = C dW with the diagonal compliance.
inline StaticTangent StaticTangentDerivative(const Vec6& compliance, const Vec3& f_W,
                                             const StaticPoint<double>& y, const StaticTangent& dy,
                                             const Vec6& xi, const Mat6* H = nullptr,
                                             const Mat6* source = nullptr,
                                             const Mat36* df_W = nullptr) {
  using namespace internal;
  Mat6 dW;
  dW << dy.m, dy.n;
  if (source) dW -= *source;
  const Mat6 dxi = H ? Mat6(H->partialPivLu().solve(dW)) : Mat6(compliance.asDiagonal() * dW);
  const Mat36 dK = dxi.topRows<3>(), dG = dxi.bottomRows<3>();
  const Vec3 K = xi.head<3>(), G = xi.tail<3>();
  StaticTangent dd;
  dd.p = RotateTangent(y.R, dy.R, G, dG);
  dd.R = RotationRateTangent(y.R, dy.R, K, dK);
  // d(m × K + n × Γ) and d(n × K − Rᵀ f)
  dd.m = Cross(y.m, dK) + Cross(dy.m, K) + Cross(y.n, dG) + Cross(dy.n, G);
  dd.n = Cross(y.n, dK) + Cross(dy.n, K) - TransposeTimesFixed(dy.R, f_W);
  if (df_W) dd.n -= y.R.transpose() * *df_W;
  return dd;
}

/// What the loads that depend on the state add to a dynamic stage's tangent: the derivative of
/// the distributed force along the directions and a fluid's added mass with the stage's
/// acceleration.
struct StageLoadTangent {
  Mat36 force_W = Mat36::Zero();       ///< d f_W, N/m per unit of each direction
  double added_mass = 0.0;             ///< m_a, kg/m
  Vec3 acceleration_W = Vec3::Zero();  ///< a_W = c0 R v + v_Wʰ at the stage, m/s²
};

/// The linearisation of DynamicDerivative along dy, given the primal state y and the stage's
/// strain xi, with the state-dependent loads of `loads` (none when null). With the tendon law
/// (H = its ∂W/∂ξ, the implicit stiffness included), dξ = H⁻¹ dW.
inline DynamicTangent DynamicTangentDerivative(const SectionSample& smp,
                                               const DynamicPoint<double>& y,
                                               const DynamicTangent& dy, const Vec6& xi, double c0,
                                               bool statics, const Mat6* H = nullptr,
                                               const StageLoadTangent* loads = nullptr) {
  using namespace internal;
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
  DynamicTangent dd;
  dd.p = RotateTangent(y.R, dy.R, G, dG);
  dd.R = RotationRateTangent(y.R, dy.R, K, dK);
  dd.w = rate * dK + Cross(dy.w, K) + Cross(y.w, dK);
  dd.v = rate * dG + Cross(dy.w, G) + Cross(y.w, dG) + Cross(dy.v, K) + Cross(y.v, dK);
  const Vec3 Jw = J.cwiseProduct(y.w);
  const Mat36 J_dw = J.asDiagonal() * dy.w;
  dd.m = Cross(dy.m, K) + Cross(y.m, dK) + Cross(dn_B, G) + Cross(n_B, dG) + rate * J_dw +
         Cross(dy.w, Jw) + Cross(y.w, J_dw);
  dd.n = rhoA * rate * RotateTangent(y.R, dy.R, y.v, dy.v);  // d(ρA c0 R v)
  if (loads) {
    dd.n -= loads->force_W;
    if (loads->added_mass != 0.0 && !statics) {
      // d[m_a (a − t (t·a))] with da = c0 d(R v) and dt = d(R e₃)
      const Vec3 t = y.R.col(2);
      const Vec3& a = loads->acceleration_W;
      const Mat36 da = c0 * RotateTangent(y.R, dy.R, y.v, dy.v);
      const Mat36& dt = dy.R[2];
      dd.n += loads->added_mass *
              (da - t * (t.transpose() * da) - dt * t.dot(a) - t * (a.transpose() * dt));
    }
  }
  return dd;
}

}  // namespace cosserat::rhs
