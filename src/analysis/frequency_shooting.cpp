#include "cosserat/analysis/frequency_shooting.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <stdexcept>

#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/rod/grid.hpp"

namespace cosserat {
namespace {

Mat3 Hat(const Vec3& a) {
  Mat3 m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}

// The equilibrium carried along s, as in the statics solver (StaticShootingSolver::Shoot).
struct Primal {
  Vec3 p;
  Mat3 R;
  Vec3 m, n;
};

struct Sample {
  Mat6 compliance;
  Vec6 rest;
  Vec3 J;
  double rhoA;
  double s;  // arc length, m
};

Primal Rates(const Sample& smp, const Vec3& f_W, const Primal& y, Vec6* xi_out) {
  Vec6 W;
  W << y.m, y.n;
  const Vec6 xi = smp.rest + smp.compliance * W;
  const Vec3 K = xi.head<3>(), G = xi.tail<3>();
  Primal d;
  d.p = y.R * G;
  d.R = y.R * Hat(K);
  d.m = y.m.cross(K) + y.n.cross(G);
  d.n = y.n.cross(K) - y.R.transpose() * f_W;
  *xi_out = xi;
  return d;
}

Primal Axpy(const Primal& y, double a, const Primal& d) {
  return {y.p + a * d.p, y.R + a * d.R, y.m + a * d.m, y.n + a * d.n};
}

}  // namespace

FrequencyShooting::FrequencyShooting(const RodModel& rod, const std::vector<double>& grid,
                                     const lie::SE3& base, const StaticLoads& loads,
                                     const Vec6& base_wrench_B, const Actuation& actuation)
    : grid_(grid) {
  if (!rod.tendons.empty())
    throw std::invalid_argument(
        "FrequencyShooting: rods with tendons are not supported (the tendon strain law is not "
        "linearised here)");
  const int n = static_cast<int>(grid_.size());
  if (n < 2) throw std::invalid_argument("FrequencyShooting: the grid needs at least 2 nodes");
  const SectionProperties s0 = PrincipalAxesSectionAt(rod, 0.0, actuation);
  EI_ = std::max(s0.stiffness(0, 0), s0.stiffness(1, 1));
  rhoA0_ = s0.mass(5, 5);
  const double L = rod.length;
  scale_ << EI_ / L, EI_ / L, EI_ / L, EI_ / (L * L), EI_ / (L * L), EI_ / (L * L);

  const std::vector<double> points = SegmentSamplePoints(grid_);
  std::vector<Sample> samples(points.size());
  for (size_t q = 0; q < points.size(); ++q) {
    const SectionProperties sp = PrincipalAxesSectionAt(rod, points[q], actuation);
    samples[q] = {sp.stiffness.inverse(), rod.RestStrainAt(points[q]), sp.mass.diagonal().head<3>(),
                  sp.mass(5, 5), points[q]};
  }
  auto f_at = [&](const Sample& smp) -> Vec3 {
    return TotalDistributedForce_W(loads, {smp.s, 1.0, smp.rhoA});
  };
  // The stage matrix A0 at a primal state with strain xi (see the file comment).
  auto stage = [&](const Sample& smp, const Primal& y, const Vec6& xi) {
    const Vec3 K = xi.head<3>(), G = xi.tail<3>();
    const Mat3 Kh = Hat(K), Gh = Hat(G), mh = Hat(y.m), nh = Hat(y.n);
    const Eigen::Matrix<double, 3, 6> Ct = smp.compliance.topRows<3>();
    const Eigen::Matrix<double, 3, 6> Cb = smp.compliance.bottomRows<3>();
    Stage st;
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
    A.block<3, 3>(9, 0) = -Hat(y.R.transpose() * f_at(smp));
    A.block<3, 6>(9, 6) = nh * Ct;
    A.block<3, 3>(9, 9) -= Kh;
    st.J = smp.J;
    st.rhoA = smp.rhoA;
    return st;
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
    const Primal k1 = Rates(a, f_at(a), y, &xi1);
    const Primal y2 = Axpy(y, 0.5 * h, k1);
    const Primal k2 = Rates(b, f_at(b), y2, &xi2);
    const Primal y3 = Axpy(y, 0.5 * h, k2);
    const Primal k3 = Rates(b, f_at(b), y3, &xi3);
    const Primal y4 = Axpy(y, h, k3);
    const Primal k4 = Rates(c, f_at(c), y4, &xi4);
    stages_.push_back(stage(a, y, xi1));
    stages_.push_back(stage(b, y2, xi2));
    stages_.push_back(stage(b, y3, xi3));
    stages_.push_back(stage(c, y4, xi4));
    y.p += h / 6 * (k1.p + 2 * k2.p + 2 * k3.p + k4.p);
    y.R += h / 6 * (k1.R + 2 * k2.R + 2 * k3.R + k4.R);
    y.m += h / 6 * (k1.m + 2 * k2.m + 2 * k3.m + k4.m);
    y.n += h / 6 * (k1.n + 2 * k2.n + 2 * k3.n + k4.n);
  }
  node_R_[n - 1] = y.R;
  const Mat3 Rt = y.R.transpose();
  // Only the dead part of the tip wrench turns relative to the tip section.
  const SplitWrench tip = TotalTipWrench(loads);
  tip_moment_cross_ = Hat(Rt * tip.dead_W.head<3>());
  tip_force_cross_ = Hat(Rt * tip.dead_W.tail<3>());
}

template <typename Visit>
Eigen::Matrix<double, 12, 6> FrequencyShooting::Integrate(double omega,
                                                          const Eigen::Matrix<double, 12, 6>& z0,
                                                          Visit&& visit) const {
  using Z = Eigen::Matrix<double, 12, 6>;
  const double w2 = omega * omega;
  auto rate = [&](const Stage& st, const Z& z) {
    Z d = st.a0 * z;
    d.middleRows<3>(6) -= w2 * st.J.asDiagonal() * z.topRows<3>();
    d.bottomRows<3>() -= (w2 * st.rhoA) * z.middleRows<3>(3);
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

Mat6 FrequencyShooting::BoundaryMatrix(double omega) const {
  Eigen::Matrix<double, 12, 6> z0 = Eigen::Matrix<double, 12, 6>::Zero();
  z0.bottomRows<6>() = scale_.asDiagonal();
  const Eigen::Matrix<double, 12, 6> z = Integrate(omega, z0, [](int, const auto&) {});
  Mat6 B;
  B.topRows<3>() = z.middleRows<3>(6) - tip_moment_cross_ * z.topRows<3>();
  B.bottomRows<3>() = z.bottomRows<3>() - tip_force_cross_ * z.topRows<3>();
  return scale_.cwiseInverse().asDiagonal() * B;
}

void FrequencyShooting::Shape(double omega, const Vec6& x, std::vector<Vec3>* displacement_W,
                              std::vector<Vec3>* rotation_W) const {
  Eigen::Matrix<double, 12, 6> z0 = Eigen::Matrix<double, 12, 6>::Zero();
  z0.bottomRows<6>() = scale_.asDiagonal();
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
