#include "cosserat/strong/rod_integrals.hpp"

#include <Eigen/Geometry>

#include "cosserat/loads/total_load.hpp"

namespace cosserat {

RodEnergy Energy(const RodQuadrature& points, const StaticLoads& loads) {
  RodEnergy e;
  for (const RodQuadraturePoint& pt : points) {
    const rhs::SectionSample& smp = *pt.section;
    const double w = pt.weight;
    const Vec6 dxi = pt.strain - smp.rest_strain;
    e.kinetic += w * 0.5 * pt.twist_B.dot(smp.mass.cwiseProduct(pt.twist_B));
    // The fluid's added mass moves with the section's velocity across its tangent d3.
    const double added = TotalNormalAddedMass(loads, smp.Site());  // kg/m
    if (added > 0.0) e.kinetic += w * 0.5 * added * pt.twist_B.segment<2>(3).squaredNorm();
    e.elastic += w * 0.5 * dxi.dot(smp.stiffness.cwiseProduct(dxi));
    e.potential += w * TotalDistributedPotential(loads, smp.Site(), pt.position_W);
  }
  return e;
}

RodMomentum Momentum(const RodQuadrature& points) {
  RodMomentum out;
  for (const RodQuadraturePoint& pt : points) {
    const rhs::SectionSample& smp = *pt.section;
    const Vec3 linear = smp.mass(5) * (pt.rotation_WB * pt.twist_B.tail<3>());
    const Vec3 spin = pt.rotation_WB * smp.mass.head<3>().cwiseProduct(pt.twist_B.head<3>());
    out.linear_W += pt.weight * linear;
    out.angular_W += pt.weight * (pt.position_W.cross(linear) + spin);
  }
  return out;
}

double Mass(const RodQuadrature& points) {
  double mass = 0;
  for (const RodQuadraturePoint& pt : points) mass += pt.weight * pt.section->mass(5);
  return mass;
}

Vec3 CentreOfMass_W(const RodQuadrature& points) {
  Vec3 first = Vec3::Zero();
  for (const RodQuadraturePoint& pt : points)
    first += pt.weight * pt.section->mass(5) * pt.position_W;
  return first / Mass(points);
}

RodEnergy TipBodyEnergy(double mass, const Vec3& inertia_B, const Vec3& gravity_W,
                        const RodState& state) {
  const Vec6& twist = state.twist_B.back();  // [ω; v], tip frame
  const Vec3 w = twist.head<3>();
  RodEnergy e;
  e.kinetic = 0.5 * mass * twist.tail<3>().squaredNorm() + 0.5 * w.dot(inertia_B.cwiseProduct(w));
  e.potential = -mass * gravity_W.dot(state.tip_position_W());
  return e;
}

RodMomentum TipBodyMomentum(double mass, const Vec3& inertia_B, const RodState& state) {
  const Vec6& twist = state.twist_B.back();
  const Mat3 R = state.tip_rotation_WB();
  RodMomentum p;
  p.linear_W = mass * (R * twist.tail<3>());
  p.angular_W = state.tip_position_W().cross(p.linear_W) +
                R * inertia_B.cwiseProduct(twist.head<3>());
  return p;
}

}  // namespace cosserat
