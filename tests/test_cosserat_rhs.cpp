// The hand-written tangents of the shooting solvers (shot_tangent.hpp) and the Jacobians of the
// lie layer, checked against automatic differentiation: ceres::Jet pushed through the templated
// right-hand sides of cosserat_rhs.hpp and the templated maps of lie/.
//
// Both sides are exact derivatives of the same expressions, so they agree to round-off: the
// tolerance 1e-11 (relative to the largest entry) leaves a margin of ~100 over the double
// precision of the ~20 operations per entry, and any wrong or missing term is O(1) off.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <random>

#include "cosserat/lie/se3.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/strong/cosserat_rhs.hpp"
#include "cosserat/strong/shot_tangent.hpp"

namespace cosserat {
namespace {

using Jet = ceres::Jet<double, 6>;
using rhs::DynamicPoint;
using rhs::DynamicTangent;
using rhs::StaticPoint;
using rhs::StaticTangent;
using Mat36 = Eigen::Matrix<double, 3, 6>;

constexpr double kRoundOff = 1e-11;

std::mt19937 rng(20261125);  // fixed: every run draws the same cases
double Uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
Vec3 RandomVec3(double scale) {
  return Vec3(Uniform(-1, 1), Uniform(-1, 1), Uniform(-1, 1)) * scale;
}
Vec6 RandomVec6(double lo, double hi) {
  Vec6 v;
  for (int i = 0; i < 6; ++i) v(i) = Uniform(lo, hi);
  return v;
}
Mat36 RandomMat36() { return Mat36::Random(); }

// A Jet vector with value x and derivative rows dx (one column per direction).
Vector3<Jet> Seed(const Vec3& x, const Mat36& dx) {
  Vector3<Jet> out;
  for (int i = 0; i < 3; ++i) {
    out(i) = Jet(x(i));
    out(i).v = dx.row(i).transpose();
  }
  return out;
}
Matrix3<Jet> Seed(const Mat3& R, const rhs::RotationTangent& dR) {
  Matrix3<Jet> out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      out(i, j) = Jet(R(i, j));
      out(i, j).v = dR[j].row(i).transpose();
    }
  return out;
}
Mat36 Derivative(const Vector3<Jet>& x) {
  Mat36 d;
  for (int i = 0; i < 3; ++i) d.row(i) = x(i).v.transpose();
  return d;
}
Vector3<Jet> Constant(const Vec3& x) { return x.cast<Jet>(); }

// max |a − b| / max(1, max |b|), over every block.
double RelativeError(const Mat36& a, const Mat36& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}
double RotationError(const Matrix3<Jet>& R, const rhs::RotationTangent& dR) {
  double e = 0;
  for (int j = 0; j < 3; ++j) {
    Mat36 col;
    for (int i = 0; i < 3; ++i) col.row(i) = R(i, j).v.transpose();
    e = std::max(e, RelativeError(col, dR[j]));
  }
  return e;
}

TEST(CosseratRhs, StaticTangentMatchesAutomaticDifferentiation) {
  for (int trial = 0; trial < 20; ++trial) {
    StaticPoint<double> y{RandomVec3(1), lie::SO3Exp(RandomVec3(2)), RandomVec3(3), RandomVec3(5)};
    StaticTangent dy{
        RandomMat36(), {RandomMat36(), RandomMat36(), RandomMat36()}, RandomMat36(), RandomMat36()};
    const Vec6 rest = RandomVec6(-0.5, 0.5), compliance = RandomVec6(0.1, 2.0);
    const Vec3 f_W = RandomVec3(4);

    Vec6 xi;
    rhs::StaticDerivative<double>(rest, compliance, f_W, y, &xi);
    const StaticTangent expected = rhs::StaticTangentDerivative(compliance, f_W, y, dy, xi);

    const StaticPoint<Jet> yj{Seed(y.p, dy.p), Seed(y.R, dy.R), Seed(y.m, dy.m), Seed(y.n, dy.n)};
    Vector6<Jet> xij;
    const StaticPoint<Jet> d =
        rhs::StaticDerivative<Jet>(rest, compliance, Constant(f_W), yj, &xij);
    EXPECT_LT(RelativeError(Derivative(d.p), expected.p), kRoundOff);
    EXPECT_LT(RotationError(d.R, expected.R), kRoundOff);
    EXPECT_LT(RelativeError(Derivative(d.m), expected.m), kRoundOff);
    EXPECT_LT(RelativeError(Derivative(d.n), expected.n), kRoundOff);
  }
}

// A section with damping and the BDF2 coefficients of a step of dt = 2 ms.
rhs::SectionSample RandomSection(double c0) {
  rhs::SectionSample s;
  s.stiffness = RandomVec6(0.5, 3.0);
  s.damping = RandomVec6(0.01, 0.1);
  s.compliance = s.stiffness.cwiseInverse();
  s.rest_strain = RandomVec6(-0.3, 0.3);
  s.mass = RandomVec6(0.1, 1.0);
  s.implicit_compliance = (s.stiffness + c0 * s.damping).cwiseInverse();
  s.implicit_damping = s.implicit_compliance.cwiseProduct(s.damping);
  s.implicit_offset = s.rest_strain - c0 * s.implicit_damping.cwiseProduct(s.rest_strain);
  s.damped = true;
  return s;
}

void CheckDynamicTangent(bool statics) {
  for (int trial = 0; trial < 20; ++trial) {
    const double c0 = 1.5 / 2e-3;
    const rhs::SectionSample smp = RandomSection(c0);
    DynamicPoint<double> y{RandomVec3(1), lie::SO3Exp(RandomVec3(2)),
                           RandomVec3(3), RandomVec3(5),
                           RandomVec3(2), RandomVec3(0.5)};
    DynamicTangent dy{RandomMat36(), {RandomMat36(), RandomMat36(), RandomMat36()},
                      RandomMat36(), RandomMat36(),
                      RandomMat36(), RandomMat36()};
    const Vec6 strain_h = RandomVec6(-100, 100), twist_h = RandomVec6(-100, 100);
    const Vec3 velocity_h = RandomVec3(100), f_W = RandomVec3(4);
    const rhs::StageHistory history{&strain_h, &twist_h, &velocity_h, c0, statics};

    Vec6 xi, V;
    Vec3 vel;
    rhs::DynamicDerivative<double>(smp, f_W, y, history, &xi, &V, &vel);
    const DynamicTangent expected = rhs::DynamicTangentDerivative(smp, y, dy, xi, c0, statics);

    const DynamicPoint<Jet> yj{Seed(y.p, dy.p), Seed(y.R, dy.R), Seed(y.m, dy.m),
                               Seed(y.n, dy.n), Seed(y.w, dy.w), Seed(y.v, dy.v)};
    Vector6<Jet> xij, Vj;
    Vector3<Jet> velj;
    const DynamicPoint<Jet> d =
        rhs::DynamicDerivative<Jet>(smp, Constant(f_W), yj, history, &xij, &Vj, &velj);
    EXPECT_LT(RelativeError(Derivative(d.p), expected.p), kRoundOff);
    EXPECT_LT(RotationError(d.R, expected.R), kRoundOff);
    EXPECT_LT(RelativeError(Derivative(d.m), expected.m), kRoundOff);
    EXPECT_LT(RelativeError(Derivative(d.n), expected.n), kRoundOff);
    EXPECT_LT(RelativeError(Derivative(d.w), expected.w), kRoundOff);
    EXPECT_LT(RelativeError(Derivative(d.v), expected.v), kRoundOff);
  }
}

TEST(CosseratRhs, DynamicTangentMatchesAutomaticDifferentiation) { CheckDynamicTangent(false); }
TEST(CosseratRhs, DynamicTangentInStaticsMatchesAutomaticDifferentiation) {
  CheckDynamicTangent(true);
}

// The dynamic right-hand side at zero twist and zero rates is the static one: the same
// equations in two frames for n (n_W = R n_B).
TEST(CosseratRhs, DynamicAtRestIsTheStaticRightHandSide) {
  const rhs::SectionSample smp = RandomSection(0.0);
  const StaticPoint<double> ys{RandomVec3(1), lie::SO3Exp(RandomVec3(2)), RandomVec3(3),
                               RandomVec3(5)};
  const DynamicPoint<double> yd{ys.p, ys.R, ys.m, ys.R * ys.n, Vec3::Zero(), Vec3::Zero()};
  const Vec3 f_W = RandomVec3(4);
  Vec6 xi_s, xi_d, V;
  Vec3 vel;
  const StaticPoint<double> ds =
      rhs::StaticDerivative<double>(smp.rest_strain, smp.compliance, f_W, ys, &xi_s);
  const DynamicPoint<double> dd =
      rhs::DynamicDerivative<double>(smp, f_W, yd, rhs::StageHistory{}, &xi_d, &V, &vel);
  EXPECT_LT((xi_s - xi_d).norm(), 1e-14);
  EXPECT_LT((ds.p - dd.p).norm(), 1e-14);
  EXPECT_LT((ds.R - dd.R).norm(), 1e-14);
  EXPECT_LT((ds.m - dd.m).norm(), 1e-13);
  // d/ds (R n_B) = R' n_B + R n_B'
  EXPECT_LT((ds.R * ys.n + ys.R * ds.n - dd.n).norm(), 1e-13);
  EXPECT_EQ(dd.w, Vec3::Zero());
}

// Lie layer: d/dt Exp(w + t dw) = Exp(w) hat(J_r(w) dw) at t = 0, on both sides of the Taylor
// switch, and d/dt Log(R Exp(t δ)) = J_r⁻¹(Log R) δ.
TEST(LieJet, SO3ExpAndLogDerivativesAreTheJacobians) {
  using J1 = ceres::Jet<double, 1>;
  for (double scale : {1e-5, 1e-2, 0.5, 2.5}) {
    for (int trial = 0; trial < 5; ++trial) {
      const Vec3 w = RandomVec3(scale), dw = RandomVec3(1.0);
      Vector3<J1> wj;
      for (int i = 0; i < 3; ++i) wj(i) = J1(w(i), 0), wj(i).v(0) = dw(i);
      const Matrix3<J1> Rj = lie::SO3Exp<J1>(wj);
      Mat3 dR;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) dR(i, j) = Rj(i, j).v(0);
      const Mat3 expected = lie::SO3Exp(w) * lie::hat<double>(lie::SO3RightJacobian(w) * dw);
      EXPECT_LT((dR - expected).cwiseAbs().maxCoeff(), 1e-12) << "|w| = " << w.norm();

      // Log: R(t) = R Exp(t δ) as a Jet through the exact first-order expansion R (I + t δ^).
      // Log inverts Exp only for |w| < π, so w is first brought inside that ball.
      if (w.norm() > 3.0) continue;
      const Mat3 R = lie::SO3Exp(w);
      const Vec3 delta = dw;
      const Mat3 dRt = R * lie::hat<double>(delta);
      Matrix3<J1> Rt;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Rt(i, j) = J1(R(i, j), 0), Rt(i, j).v(0) = dRt(i, j);
      const Vector3<J1> logj = lie::SO3Log<J1>(Rt);
      Vec3 dlog;
      for (int i = 0; i < 3; ++i) dlog(i) = logj(i).v(0);
      const Vec3 expected_log = lie::SO3RightJacobianInverse(w) * delta;
      EXPECT_LT((dlog - expected_log).norm(), 1e-9 * std::max(1.0, 1.0 / w.norm()))
          << "|w| = " << w.norm();
    }
  }
}

TEST(LieJet, SE3ExpDerivativeIsTheRightJacobian) {
  using J1 = ceres::Jet<double, 1>;
  for (double scale : {1e-4, 0.05, 1.0, 2.5}) {
    const Vec6 xi = RandomVec6(-scale, scale), dxi = RandomVec6(-1, 1);
    Vector6<J1> xj;
    for (int i = 0; i < 6; ++i) xj(i) = J1(xi(i), 0), xj(i).v(0) = dxi(i);
    const lie::SE3T<J1> gj = lie::SE3Exp<J1>(xj);
    Mat4 dg = Mat4::Zero();
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) dg(i, j) = gj.R(i, j).v(0);
      dg(i, 3) = gj.p(i).v(0);
    }
    const Mat4 expected =
        lie::ToMatrix(lie::SE3Exp(xi)) * lie::hat6(Vec6(lie::SE3RightJacobian(xi) * dxi));
    EXPECT_LT((dg - expected).cwiseAbs().maxCoeff(), 1e-12) << "|xi| = " << xi.norm();
  }
}

}  // namespace
}  // namespace cosserat
