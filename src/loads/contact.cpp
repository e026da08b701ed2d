#include "cosserat/loads/contact.hpp"

#include <algorithm>
#include <cmath>

namespace cosserat {

double ContactSurface::Distance(const Vec3& p_W, Vec3* normal, Mat3* dn) const {
  const Vec3 r = p_W - point_W;
  switch (shape) {
    case Shape::kPlane:
      *normal = direction_W;
      if (dn) dn->setZero();
      return direction_W.dot(r);
    case Shape::kSphere: {
      const double rho = r.norm();
      *normal = r / rho;
      if (dn) *dn = (Mat3::Identity() - *normal * normal->transpose()) / rho;
      return rho - radius;
    }
    case Shape::kCylinder: {
      const Vec3 radial = r - direction_W * direction_W.dot(r);
      const double rho = radial.norm();
      const Vec3 out = radial / rho;
      *normal = inside ? Vec3(-out) : out;
      if (dn) {
        const Mat3 d_out =
            (Mat3::Identity() - direction_W * direction_W.transpose() - out * out.transpose()) /
            rho;
        *dn = inside ? Mat3(-d_out) : d_out;
      }
      return inside ? radius - rho : rho - radius;
    }
  }
  return 0.0;
}

bool ContactSurface::operator==(const ContactSurface& o) const {
  return shape == o.shape && point_W == o.point_W && direction_W == o.direction_W &&
         radius == o.radius && inside == o.inside && stiffness == o.stiffness &&
         damping == o.damping && smoothing == o.smoothing;
}

bool ContactSurface::IsValid(int index, std::string* why) const {
  auto fail = [&](const std::string& msg) {
    if (why) *why = "environment.contact[" + std::to_string(index) + "]." + msg;
    return false;
  };
  if (!point_W.allFinite()) return fail("point must be finite (m)");
  if (!(direction_W.allFinite() && std::abs(direction_W.norm() - 1.0) < 1e-12))
    return fail(shape == Shape::kPlane ? "normal must be a non-zero vector"
                                       : "axis must be a non-zero vector");
  if (shape != Shape::kPlane && !(std::isfinite(radius) && radius > 0))
    return fail("radius must be positive (m)");
  if (!(std::isfinite(stiffness) && stiffness >= 0))
    return fail("stiffness must be finite and >= 0 (N/m per m)");
  if (!(std::isfinite(damping) && damping >= 0))
    return fail("damping must be finite and >= 0 (N s/m per m)");
  if (!(std::isfinite(smoothing) && smoothing >= 0)) return fail("smoothing must be >= 0 (m)");
  return true;
}

bool ContactSurfaces::operator==(const ContactSurfaces& o) const {
  if (count != o.count) return false;
  for (int i = 0; i < count; ++i)
    if (!(surface[i] == o.surface[i])) return false;
  return true;
}

bool ContactSurfaces::IsValid(std::string* why) const {
  if (count < 0 || count > kMaxContactSurfaces) {
    if (why) *why = "environment.contact: at most 8 surfaces";
    return false;
  }
  for (int i = 0; i < count; ++i)
    if (!surface[i].IsValid(i, why)) return false;
  return true;
}

Vec3 PenaltyContact::MotionForce_W(const LoadSite& site, const SectionMotion& motion,
                                   MotionJacobian* J) const {
  if (J) *J = MotionJacobian{};
  Vec3 total = Vec3::Zero();
  const double r_o = 0.5 * site.outer_diameter;
  for (int i = 0; i < surfaces_.count; ++i) {
    const ContactSurface& s = surfaces_.surface[i];
    Vec3 n;
    Mat3 dn;
    const double gap = s.Distance(motion.position_W, &n, J ? &dn : nullptr) - r_o;
    const double delta = -gap;  // penetration, m
    if (delta <= 0.0) continue;
    const double eps = s.smoothing > 0 ? s.smoothing : 1e-3 * site.outer_diameter;
    // φ(δ) and φ'(δ): the C¹ ramp; ψ = φ' (0 … 1) weighs the damping in.
    const double phi = delta < eps ? 0.5 * delta * delta / eps : delta - 0.5 * eps;
    const double psi = delta < eps ? delta / eps : 1.0;
    const double k = s.stiffness * site.length, c = s.damping * site.length;
    const double vn = n.dot(motion.velocity_W);
    const double magnitude = k * phi - c * psi * vn;  // along n
    total += magnitude * n;
    if (!J) continue;
    // ∂/∂p: dδ/dp = −n; ∂(ψ)/∂δ = 1/ε below ε; ∂vn/∂p = vᵀ dn.
    const double dpsi = delta < eps ? 1.0 / eps : 0.0;
    const Vec3 d_magnitude_dp =
        -(k * psi - c * dpsi * vn) * n - c * psi * (dn.transpose() * motion.velocity_W);
    J->position += n * d_magnitude_dp.transpose() + magnitude * dn;
    J->velocity += -c * psi * n * n.transpose();
  }
  return total;
}

}  // namespace cosserat
