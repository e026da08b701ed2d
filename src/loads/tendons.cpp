#include "cosserat/loads/tendons.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "cosserat/lie/so3.hpp"

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
  }
  return out;
}

namespace {

Vec3 PathTangent(const TendonSample& sample, int i, const Vec6& xi) {
  return xi.tail<3>() + xi.head<3>().cross(sample.offset[i]) + sample.offset_rate[i];
}

}  // namespace

double TendonPathRate(const TendonSample& sample, int i, const Vec6& xi) {
  return PathTangent(sample, i, xi).norm();
}

Vec6 TendonWrench(const TendonSample& sample, const double* tension, const Vec6& xi, Mat6* d_xi,
                  std::array<Vec6, Actuation::kMaxTendons>* a) {
  Vec6 total = Vec6::Zero();
  if (d_xi) d_xi->setZero();
  for (int i = 0; i < sample.count; ++i) {
    const Vec3& r = sample.offset[i];
    const Vec3 q = PathTangent(sample, i, xi);
    const double q_norm = q.norm();
    const Vec3 t = q / q_norm;
    Vec6 a_i;
    a_i << r.cross(t), t;
    if (a) (*a)[i] = a_i;
    const double tau = tension[i];
    if (tau == 0.0) continue;
    total += tau * a_i;
    if (d_xi) {
      // dt = (I − t tᵀ)/|q| dq,  dq = dΓ − r × dK  ⇒  dt/dξ = P [−r̂, I] / |q|
      const Mat3 P = (Mat3::Identity() - t * t.transpose()) / q_norm;
      Eigen::Matrix<double, 3, 6> dt;
      dt << -P * lie::hat(r), P;
      d_xi->topRows<3>() += tau * lie::hat(r) * dt;
      d_xi->bottomRows<3>() += tau * dt;
    }
  }
  return total;
}

bool SolveTendonStrain(const Mat6& stiffness, const Vec6& rest_strain, const TendonSample& sample,
                       const double* tension, const Vec6& W, Vec6* xi, Mat6* H) {
  // Newton on g(ξ) = K (ξ − ξ*) + T(ξ) − W. T is a small, smooth perturbation of the elastic
  // law (τ ≪ EA), so from the previous stage's strain the iteration is quadratic at once: a step
  // below 1e-12 (relative) leaves an error of order its square, so it is the last one, and the
  // H of that iteration (at most 1e-12 away from the solution) serves the tangent.
  Mat6 dT, H_k;
  for (int it = 0; it < 8; ++it) {
    const Vec6 g = stiffness * (*xi - rest_strain) + TendonWrench(sample, tension, *xi, &dT) - W;
    H_k = stiffness + dT;
    const Vec6 step = H_k.partialPivLu().solve(g);
    *xi -= step;
    if (!xi->allFinite()) return false;
    if (step.norm() <= 1e-12 * (1.0 + xi->norm())) {
      if (H) *H = H_k;
      return true;
    }
  }
  return false;
}

}  // namespace cosserat
