#include "cosserat/loads/fluid_drag.hpp"

#include <cmath>

namespace cosserat {
namespace {

// c |w| w and its derivative c (|w| I + w wᵀ / |w|) (zero at w = 0, where it is continuous).
Vec3 QuadraticLaw(double c, const Vec3& w, Mat3* d_w) {
  const double norm = w.norm();
  if (d_w) {
    *d_w = norm > 0.0 ? Mat3(c * (norm * Mat3::Identity() + w * w.transpose() / norm))
                      : Mat3(Mat3::Zero());
  }
  return c * norm * w;
}

}  // namespace

Vec3 FluidDrag::MotionForce_W(const LoadSite& site, const SectionMotion& motion,
                              MotionJacobian* J) const {
  const double D = fluid_.diameter > 0.0 ? fluid_.diameter : site.outer_diameter;
  const double cn = 0.5 * fluid_.density * fluid_.drag_normal * D * site.length;
  const double ct = 0.5 * fluid_.density * fluid_.drag_tangential * M_PI * D * site.length;
  Mat3 dU_dp;
  const Vec3 u = fluid_.FlowVelocity_W(motion.position_W, J ? &dU_dp : nullptr) - motion.velocity_W;
  const Vec3& t = motion.tangent_W;
  const double ut = t.dot(u);
  const Vec3 w_t = ut * t;
  const Vec3 w_n = u - w_t;
  Mat3 dn, dt;
  const Vec3 f =
      QuadraticLaw(cn, w_n, J ? &dn : nullptr) + QuadraticLaw(ct, w_t, J ? &dt : nullptr);
  if (J) {
    // w_n = (I − t tᵀ) u, w_t = t tᵀ u: ∂/∂u and ∂/∂t (with ∂(t tᵀ u)/∂t = (tᵀu) I + t uᵀ).
    const Mat3 tt = t * t.transpose();
    const Mat3 d_wt_dt = ut * Mat3::Identity() + t * u.transpose();
    const Mat3 df_du = dn * (Mat3::Identity() - tt) + dt * tt;
    J->velocity = -df_du;
    J->position = df_du * dU_dp;
    J->tangent = (dt - dn) * d_wt_dt;
  }
  return f;
}

}  // namespace cosserat
