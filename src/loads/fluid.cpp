#include "cosserat/loads/fluid.hpp"

#include <cmath>

namespace cosserat {

double FluidFlowProfile::Factor(double h, double* slope) const {
  *slope = 0.0;
  switch (kind) {
    case Kind::kUniform:
      return 1.0;
    case Kind::kPowerLaw: {
      if (h <= 0.0) return 0.0;
      const double phi = std::pow(h / reference_height, exponent);
      *slope = exponent * phi / h;
      return phi;
    }
    case Kind::kTable: {
      if (h <= height[0]) return factor[0];
      if (h >= height[points - 1]) return factor[points - 1];
      int i = 0;
      while (h > height[i + 1]) ++i;
      *slope = (factor[i + 1] - factor[i]) / (height[i + 1] - height[i]);
      return factor[i] + *slope * (h - height[i]);
    }
  }
  return 1.0;
}

bool FluidFlowProfile::operator==(const FluidFlowProfile& o) const {
  return kind == o.kind && axis_W == o.axis_W && origin_W == o.origin_W &&
         reference_height == o.reference_height && exponent == o.exponent && points == o.points &&
         height == o.height && factor == o.factor;
}

Vec3 Fluid::FlowVelocity_W(const Vec3& p_W, Mat3* grad) const {
  if (profile.kind == FluidFlowProfile::Kind::kUniform) {
    if (grad) grad->setZero();
    return velocity_W;
  }
  double slope = 0.0;
  const double phi = profile.Factor(profile.axis_W.dot(p_W - profile.origin_W), &slope);
  if (grad) *grad = velocity_W * (slope * profile.axis_W.transpose());
  return phi * velocity_W;
}

bool Fluid::operator==(const Fluid& o) const {
  return density == o.density && velocity_W == o.velocity_W && profile == o.profile &&
         drag_normal == o.drag_normal && drag_tangential == o.drag_tangential &&
         added_mass == o.added_mass && diameter == o.diameter;
}

bool Fluid::IsValid(std::string* why) const {
  auto fail = [&](const std::string& msg) {
    if (why) *why = "environment.fluid." + msg;
    return false;
  };
  auto nonnegative = [](double x) { return std::isfinite(x) && x >= 0.0; };
  if (!nonnegative(density)) return fail("density must be finite and >= 0 (kg/m^3)");
  if (!velocity_W.allFinite()) return fail("velocity must be finite (m/s)");
  if (!nonnegative(drag_normal)) return fail("drag_normal must be finite and >= 0");
  if (!nonnegative(drag_tangential)) return fail("drag_tangential must be finite and >= 0");
  if (!nonnegative(added_mass)) return fail("added_mass must be finite and >= 0");
  if (!nonnegative(diameter)) return fail("diameter must be finite and >= 0 (m)");
  if (profile.kind == FluidFlowProfile::Kind::kUniform) return true;
  if (!(profile.axis_W.allFinite() && std::abs(profile.axis_W.norm() - 1.0) < 1e-12))
    return fail("profile.axis must be a unit vector");
  if (!profile.origin_W.allFinite()) return fail("profile.origin must be finite (m)");
  if (profile.kind == FluidFlowProfile::Kind::kPowerLaw) {
    if (!(std::isfinite(profile.reference_height) && profile.reference_height > 0))
      return fail("profile.reference_height must be positive (m)");
    if (!nonnegative(profile.exponent)) return fail("profile.exponent must be finite and >= 0");
    return true;
  }
  if (profile.points < 2 || profile.points > FluidFlowProfile::kMaxPoints)
    return fail("profile.heights must have 2 to 16 entries");
  for (int i = 0; i < profile.points; ++i) {
    if (!std::isfinite(profile.height[i]) || !std::isfinite(profile.factor[i]))
      return fail("profile.heights and profile.factors must be finite");
    if (i > 0 && !(profile.height[i] > profile.height[i - 1]))
      return fail("profile.heights must increase");
  }
  return true;
}

double FluidGust::Factor(double t) const {
  return present() ? 1.0 + amplitude * std::sin(2.0 * M_PI * t / period) : 1.0;
}

Fluid FluidGust::At(const Fluid& steady, double t) const {
  Fluid f = steady;
  f.velocity_W *= Factor(t);
  return f;
}

}  // namespace cosserat
