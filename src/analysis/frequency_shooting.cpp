#include "cosserat/analysis/frequency_shooting.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/rod/grid.hpp"
#include "cosserat/strong/cosserat_rhs.hpp"
#include "cosserat/strong/spatial_scheme.hpp"

namespace cosserat {
namespace {

using lie::hat;
using Primal = rhs::StaticPoint<double>;  // the equilibrium carried along s (cosserat_rhs.hpp)
using Mat12 = FrequencyShooting::Mat12;

struct Sample {
  Vec6 compliance;  ///< diag K⁻¹ (principal axes)
  Vec6 rest;
  Vec3 J;
  double rhoA;
  double s;               // arc length, m
  double outer_diameter;  // m
};

/// The distributed force at a stage of the equilibrium (N/m, world), as the static solver
/// applies it: the dead loads and those of the pose at rest (a current's drag, contact), with the
/// latter's derivative in `jac` (when not null).
Vec3 ForceAt(const StaticLoads& loads, const Sample& smp, const Primal& y, MotionJacobian* jac) {
  const LoadSite site{smp.s, 1.0, smp.rhoA, smp.outer_diameter};
  Vec3 f = TotalDistributedForce_W(loads, site);
  if (HasMotionLoads(loads))
    f += TotalMotionForce_W(loads, site, {y.p, y.R.col(2), Vec3::Zero()}, jac);
  return f;
}

/// What FrequencyShooting keeps of one RK4 stage (its Stage).
struct StageTerms {
  Mat12 a0;
  Vec3 J;     // ρ I per length, kg·m
  Vec3 mass;  // translational mass per length, body frame, kg/m (with added mass)
};

/// The stage matrix A0 at a primal state y with strain xi (see the file comment), with the
/// rotary and translational inertia per length.
StageTerms StageAt(const StaticLoads& loads, const Sample& smp, const Primal& y, const Vec6& xi) {
  const bool motion = HasMotionLoads(loads);
  const Vec3 K = xi.head<3>(), G = xi.tail<3>();
  const Mat3 Kh = hat(K), Gh = hat(G), mh = hat(y.m), nh = hat(y.n);
  const Mat6 C = smp.compliance.asDiagonal();
  const Eigen::Matrix<double, 3, 6> Ct = C.topRows<3>();
  const Eigen::Matrix<double, 3, 6> Cb = C.bottomRows<3>();
  StageTerms st;
  Mat12& A = st.a0;
  A.setZero();
  A.block<3, 3>(0, 0) = -Kh;
  A.block<3, 6>(0, 6) = Ct;
  A.block<3, 3>(3, 0) = -Gh;
  A.block<3, 3>(3, 3) = -Kh;
  A.block<3, 6>(3, 6) = Cb;
  A.block<3, 6>(6, 6) = mh * Ct + nh * Cb;
  A.block<3, 3>(6, 6) -= Kh;
  A.block<3, 3>(6, 9) -= Gh;
  MotionJacobian jac;
  A.block<3, 3>(9, 0) = -hat(y.R.transpose() * ForceAt(loads, smp, y, motion ? &jac : nullptr));
  if (motion) {
    // A pose-dependent force moves with the section: δp = R₀ u and δt = R₀ (θ × e₃), and its
    // change δf_W enters δn' as −R₀ᵀ δf_W.
    const Mat3 Rt = y.R.transpose();
    A.block<3, 3>(9, 3) -= Rt * jac.position * y.R;
    A.block<3, 3>(9, 0) += Rt * jac.tangent * y.R * hat(Vec3::UnitZ());
  }
  A.block<3, 6>(9, 6) = nh * Ct;
  A.block<3, 3>(9, 9) -= Kh;
  st.J = smp.J;
  const double added = TotalNormalAddedMass(loads, {smp.s, 1.0, smp.rhoA, smp.outer_diameter});
  st.mass = Vec3(smp.rhoA + added, smp.rhoA + added, smp.rhoA);
  return st;
}

}  // namespace

FrequencyShooting::FrequencyShooting(const RodModel& rod, const std::vector<double>& grid,
                                     const lie::SE3& base, const StaticLoads& loads,
                                     const Vec6& base_wrench_B, const Actuation& actuation,
                                     const ShootingEnds& ends)
    : grid_(grid), ends_(ends) {
  if (!rod.tendons.empty())
    throw std::invalid_argument(
        "FrequencyShooting: rods with tendons are not supported (the tendon strain law is not "
        "linearised here)");
  const int n = static_cast<int>(grid_.size());
  if (n < 2) throw std::invalid_argument("FrequencyShooting: the grid needs at least 2 nodes");
  if (!(std::isfinite(ends.tip_mass) && ends.tip_mass >= 0 && ends.tip_inertia.allFinite() &&
        (ends.tip_inertia.array() >= 0).all()))
    throw std::invalid_argument("FrequencyShooting: tip_mass and tip_inertia must be >= 0");
  if (ends.tip_guided && (ends.tip_mass > 0 || !ends.tip_inertia.isZero()))
    throw std::invalid_argument("FrequencyShooting: a body at the tip needs a free tip");
  const SectionProperties s0 = PrincipalAxesSectionAt(rod, 0.0, actuation);
  EI_ = s0.max_bending_stiffness();
  rhoA0_ = s0.mass(5, 5);
  const double L = rod.length;
  scale_ << EI_ / L, EI_ / L, EI_ / L, EI_ / (L * L), EI_ / (L * L), EI_ / (L * L);

  const std::vector<double> points = SegmentSamplePoints(grid_);
  std::vector<Sample> samples(points.size());
  for (size_t q = 0; q < points.size(); ++q) {
    const SectionLaw law = SectionLaw::At(rod, points[q], actuation);  // ξ* with chambers
    samples[q] = {law.stiffness.cwiseInverse(),
                  law.rest_strain,
                  law.mass.head<3>(),
                  law.mass(5),
                  points[q],
                  law.outer_diameter};
  }
  const auto f_at = [&](const Sample& smp, const Primal& y) {
    return ForceAt(loads, smp, y, nullptr);
  };
  const auto stage = [&](const Sample& smp, const Primal& y, const Vec6& xi) {
    const StageTerms t = StageAt(loads, smp, y, xi);
    return Stage{t.a0, t.J, t.mass};
  };

  Primal y{base.p, base.R, base_wrench_B.head<3>(), base_wrench_B.tail<3>()};
  stages_.reserve(4 * (n - 1));
  node_R_.assign(n, Mat3::Identity());
  Vec6 xi1, xi2, xi3, xi4;
  for (int i = 0; i + 1 < n; ++i) {
    const double h = grid_[i + 1] - grid_[i];
    const Sample& a = samples[3 * i];
    const Sample& b = samples[3 * i + 1];
    const Sample& c = samples[3 * i + 2];
    node_R_[i] = y.R;
    auto rates = [&](const Sample& smp, const Primal& ys, Vec6* xi) {
      return rhs::StaticDerivative<double>(smp.rest, smp.compliance, f_at(smp, ys), ys, xi);
    };
    const Primal k1 = rates(a, y, &xi1);
    const Primal y2 = internal::Axpy(y, 0.5 * h, k1);
    const Primal k2 = rates(b, y2, &xi2);
    const Primal y3 = internal::Axpy(y, 0.5 * h, k2);
    const Primal k3 = rates(b, y3, &xi3);
    const Primal y4 = internal::Axpy(y, h, k3);
    const Primal k4 = rates(c, y4, &xi4);
    stages_.push_back(stage(a, y, xi1));
    stages_.push_back(stage(b, y2, xi2));
    stages_.push_back(stage(b, y3, xi3));
    stages_.push_back(stage(c, y4, xi4));
    internal::Rk4Update(h, k1, k2, k3, k4, &y);
  }
  node_R_[n - 1] = y.R;
  const Mat3 Rt = y.R.transpose();
  // Only the dead part of the tip wrench turns relative to the tip section.
  const SplitWrench tip = TotalTipWrench(loads);
  tip_force_B_ = y.n - tip.follower_B.tail<3>();  // the part of n(L) that turns with the tip
  tip_moment_cross_ = hat(Rt * tip.dead_W.head<3>());
  tip_force_cross_ = hat(Rt * tip.dead_W.tail<3>());
}

template <typename Visit>
Eigen::Matrix<double, 12, 6> FrequencyShooting::Integrate(double omega,
                                                          const Eigen::Matrix<double, 12, 6>& z0,
                                                          Visit&& visit) const {
  using Z = Eigen::Matrix<double, 12, 6>;
  const double w2 = sign_ * omega * omega;
  auto rate = [&](const Stage& st, const Z& z) {
    Z d = st.a0 * z;
    d.middleRows<3>(6) -= w2 * st.J.asDiagonal() * z.topRows<3>();
    d.bottomRows<3>() -= w2 * st.mass.asDiagonal() * z.middleRows<3>(3);
    return d;
  };
  Z z = z0;
  const int n = static_cast<int>(grid_.size());
  for (int i = 0; i + 1 < n; ++i) {
    visit(i, z);
    const double h = grid_[i + 1] - grid_[i];
    const Stage* st = &stages_[4 * i];
    const Z k1 = rate(st[0], z);
    const Z k2 = rate(st[1], z + 0.5 * h * k1);
    const Z k3 = rate(st[2], z + 0.5 * h * k2);
    const Z k4 = rate(st[3], z + h * k3);
    z += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  visit(n - 1, z);
  return z;
}

Eigen::Matrix<double, 12, 6> FrequencyShooting::Start() const {
  Eigen::Matrix<double, 12, 6> z0 = Eigen::Matrix<double, 12, 6>::Zero();
  if (!ends_.base_pinned) {
    z0.bottomRows<6>() = scale_.asDiagonal();  // δW(0); θ(0) = u(0) = 0
    return z0;
  }
  z0(0, 0) = 1.0;  // θ_x(0), rad
  z0(1, 1) = 1.0;  // θ_y(0)
  z0(8, 2) = scale_(2);  // δm_z(0), the torque that holds the twist
  z0.block<3, 3>(9, 3) = scale_.tail<3>().asDiagonal();  // δn(0)
  return z0;
}

Mat6 FrequencyShooting::BoundaryMatrix(double omega) const {
  const Eigen::Matrix<double, 12, 6> z = Integrate(omega, Start(), [](int, const auto&) {});
  Mat6 B;
  const auto moments = z.middleRows<3>(6) - tip_moment_cross_ * z.topRows<3>();
  if (!ends_.tip_guided) {
    // A body at the tip: its inertia's reaction −ω² [J_b θ; m_b u] joins the loads there.
    const double w2 = sign_ * omega * omega;
    B.topRows<3>() = moments - w2 * ends_.tip_inertia.asDiagonal() * z.topRows<3>();
    B.bottomRows<3>() = z.bottomRows<3>() - tip_force_cross_ * z.topRows<3>() -
                        w2 * ends_.tip_mass * z.middleRows<3>(3);
    return scale_.cwiseInverse().asDiagonal() * B;
  }
  // A guided tip: its frame held (clamped, rad) or its moments free (pinned); its displacement
  // across the axis zero (over L); the axial part of its world force less the load's,
  // δ(R n − F_W) = R (δn + θ × (n − f)) with f the follower part of the tip force (which turns
  // with the tip), zero (over EI/L²).
  const Mat3& R = node_R_.back();
  B.topRows<3>() = ends_.tip_clamped ? Eigen::Matrix<double, 3, 6>(R * z.topRows<3>())
                                     : Eigen::Matrix<double, 3, 6>(moments / scale_(0));
  const Eigen::Matrix<double, 3, 6> displacement_W = R * z.middleRows<3>(3);
  const double L = grid_.back() - grid_.front();
  B.row(3) = ends_.axes_W.col(0).transpose() * displacement_W / L;
  B.row(4) = ends_.axes_W.col(1).transpose() * displacement_W / L;
  B.row(5) = ends_.axes_W.col(2).transpose() * R *
             (z.bottomRows<3>() - hat(tip_force_B_) * z.topRows<3>()) / scale_(3);
  return B;
}

void FrequencyShooting::Shape(double omega, const Vec6& x, std::vector<Vec3>* displacement_W,
                              std::vector<Vec3>* rotation_W) const {
  const Eigen::Matrix<double, 12, 6> z0 = Start();
  const int n = static_cast<int>(grid_.size());
  displacement_W->assign(n, Vec3::Zero());
  rotation_W->assign(n, Vec3::Zero());
  Integrate(omega, z0, [&](int i, const Eigen::Matrix<double, 12, 6>& z) {
    const Eigen::Matrix<double, 6, 1> eta = z.topRows<6>() * x;
    (*rotation_W)[i] = node_R_[i] * eta.head<3>();
    (*displacement_W)[i] = node_R_[i] * eta.tail<3>();
  });
}

}  // namespace cosserat
