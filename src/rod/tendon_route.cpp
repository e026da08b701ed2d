#include "cosserat/rod/tendon_route.hpp"

#include <cmath>

namespace cosserat {

TendonRoute TendonRoute::Parallel(const Vec2& offset) { return Converging(offset, offset); }

TendonRoute TendonRoute::Converging(const Vec2& offset_base, const Vec2& offset_tip) {
  TendonRoute r;
  r.kind = Kind::kLinear;
  r.offset_base = offset_base;
  r.offset_tip = offset_tip;
  return r;
}

TendonRoute TendonRoute::Helical(double radius, double pitch, double phase) {
  TendonRoute r;
  r.kind = Kind::kHelical;
  r.radius = radius;
  r.pitch = pitch;
  r.phase = phase;
  return r;
}

Vec3 TendonRoute::OffsetAt(double s, double length) const {
  if (kind == Kind::kLinear) {
    const Vec2 r = offset_base + (s / length) * (offset_tip - offset_base);
    return Vec3(r.x(), r.y(), 0.0);
  }
  const double phi = phase + 2 * M_PI * s / pitch;
  return Vec3(radius * std::cos(phi), radius * std::sin(phi), 0.0);
}

Vec3 TendonRoute::OffsetRateAt(double s, double length) const {
  if (kind == Kind::kLinear) {
    const Vec2 d = (offset_tip - offset_base) / length;
    return Vec3(d.x(), d.y(), 0.0);
  }
  const double w = 2 * M_PI / pitch;
  const double phi = phase + w * s;
  return Vec3(-radius * w * std::sin(phi), radius * w * std::cos(phi), 0.0);
}

double TendonRoute::MaxOffset() const {
  return kind == Kind::kLinear ? std::max(offset_base.norm(), offset_tip.norm()) : radius;
}

bool TendonRoute::IsValid(std::string* why) const {
  auto fail = [&](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (kind == Kind::kLinear) {
    if (!offset_base.allFinite() || !offset_tip.allFinite()) return fail("offset must be finite");
    return true;
  }
  if (!(std::isfinite(radius) && radius > 0)) return fail("radius must be positive");
  if (!(std::isfinite(pitch) && pitch != 0)) return fail("pitch must be finite and non-zero");
  if (!std::isfinite(phase)) return fail("phase must be finite");
  return true;
}

TendonSample SampleTendons(const std::vector<Tendon>& tendons, double s, double length) {
  TendonSample out;
  out.count = static_cast<int>(tendons.size());
  for (int i = 0; i < out.count; ++i) {
    out.offset[i] = tendons[i].route.OffsetAt(s, length);
    out.offset_rate[i] = tendons[i].route.OffsetRateAt(s, length);
    out.ended[i] = tendons[i].anchor > 0.0 && s >= tendons[i].anchor;
  }
  return out;
}

}  // namespace cosserat
