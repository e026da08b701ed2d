#include "cosserat/loads/contact.hpp"

#include <algorithm>
#include <cmath>

namespace cosserat {

bool PressesOn(const ContactSurface& surface, const RodState& state,
               const std::function<double(double)>& outer_radius) {
  Vec3 normal;
  for (int i = 0; i < state.size(); ++i)
    if (surface.Distance(state.position_W[i], &normal) < outer_radius(state.s[i])) return true;
  return false;
}

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
         damping == o.damping && smoothing == o.smoothing && friction == o.friction &&
         slip_velocity == o.slip_velocity;
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
  if (!(std::isfinite(friction) && friction >= 0)) return fail("friction must be finite and >= 0");
  if (!(std::isfinite(slip_velocity) && slip_velocity > 0))
    return fail("slip_velocity must be positive (m/s)");
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
    // A surface only pushes: where the rod leaves faster than the spring pushes it out, the
    // damper does not pull it back (the force and its derivatives are zero there).
    if (magnitude <= 0.0) continue;
    total += magnitude * n;
    if (!J) {
      if (s.friction > 0)
        AddFriction(s, n, Mat3::Zero(), magnitude, Vec3::Zero(), Vec3::Zero(), motion.velocity_W,
                    &total, nullptr);
      continue;
    }
    // ∂/∂p: dδ/dp = −n; ∂(ψ)/∂δ = 1/ε below ε; ∂vn/∂p = vᵀ dn.
    const double dpsi = delta < eps ? 1.0 / eps : 0.0;
    const Vec3 d_magnitude_dp =
        -(k * psi - c * dpsi * vn) * n - c * psi * (dn.transpose() * motion.velocity_W);
    J->position += n * d_magnitude_dp.transpose() + magnitude * dn;
    J->velocity += -c * psi * n * n.transpose();
    if (s.friction > 0)
      AddFriction(s, n, dn, magnitude, d_magnitude_dp, -c * psi * n, motion.velocity_W, &total, J);
  }
  return total;
}

void PenaltyContact::AddFriction(const ContactSurface& s, const Vec3& n, const Mat3& dn,
                                 double normal, const Vec3& d_normal_dp, const Vec3& d_normal_dv,
                                 const Vec3& v, Vec3* force, MotionJacobian* J) {
  // f = −μ N u, u = v_s / σ, v_s = (I − n nᵀ) v, σ = sqrt(|v_s|² + v_ε²).
  const double vn = n.dot(v);
  const Vec3 v_s = v - vn * n;
  const double sigma = std::sqrt(v_s.squaredNorm() + s.slip_velocity * s.slip_velocity);
  const Vec3 u = v_s / sigma;
  *force -= s.friction * normal * u;
  if (!J) return;
  // ∂u/∂v_s = (I − u uᵀ) / σ; ∂v_s/∂v = I − n nᵀ; ∂v_s/∂p = −vn dn − n (dnᵀ v)ᵀ.
  const Mat3 du = (Mat3::Identity() - u * u.transpose()) / sigma;
  const Mat3 dvs_dv = Mat3::Identity() - n * n.transpose();
  const Mat3 dvs_dp = -vn * dn - n * (dn.transpose() * v).transpose();
  J->velocity -= s.friction * (u * d_normal_dv.transpose() + normal * du * dvs_dv);
  J->position -= s.friction * (u * d_normal_dp.transpose() + normal * du * dvs_dp);
}

}  // namespace cosserat
