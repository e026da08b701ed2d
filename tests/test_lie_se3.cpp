// Property tests for the SE(3) layer: group operations, exp/log, Ad/ad/coad identities and every
// Jacobian against central finite differences.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "cosserat/lie/se3.hpp"
#include "support/lie_test_support.hpp"

namespace cosserat::lie {
namespace {

using namespace testing;

// Twist with rotation angle uniform in [0, max_angle) and translation part in [-2, 2]³ (m).
Vec6 RandomTwist(std::mt19937& rng, double max_angle) {
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  Vec6 xi;
  xi << std::uniform_real_distribution<double>(0.0, max_angle)(rng) * RandomAxis(rng), u(rng),
      u(rng), u(rng);
  return xi;
}

SE3 RandomPose(std::mt19937& rng) { return SE3Exp(RandomTwist(rng, kPi)); }

// Special angles (Taylor branches, near π) about several axes, then random twists, |ω| < max.
std::vector<Vec6> TestTwists(double max_angle = kPi) {
  const std::vector<Vec3> axes = {Vec3::UnitX(), Vec3::UnitZ(), Vec3(1, -2, 3).normalized()};
  const std::vector<double> angles = {0.0, 1e-12, 1e-8, 1e-4, 0.03, 0.1, kPi - 1e-6, kPi - 1e-10};
  const Vec3 v(0.3, -1.2, 0.7);
  std::vector<Vec6> xis;
  for (const Vec3& a : axes) {
    for (double t : angles) {
      if (t >= max_angle) continue;
      Vec6 xi;
      xi << t * a, v;
      xis.push_back(xi);
    }
  }
  std::mt19937 rng(20240502);
  for (int i = 0; i < kCases; ++i) xis.push_back(RandomTwist(rng, max_angle));
  return xis;
}

template <int N>
double MaxAbs(const Eigen::Matrix<double, N, N>& A) {
  return A.cwiseAbs().maxCoeff();
}
double PoseError(const SE3& a, const SE3& b) {
  return std::max(MaxAbs<3>(a.R - b.R), (a.p - b.p).cwiseAbs().maxCoeff());
}

// Central-difference Jacobian of f: R^6 -> R^M at x.
template <int M, typename F>
Eigen::Matrix<double, M, 6> NumericJacobian(F f, const Vec6& x) {
  Eigen::Matrix<double, M, 6> J;
  for (int j = 0; j < 6; ++j) {
    const Vec6 dx = kFdStep * Vec6::Unit(j);
    J.col(j) = (f(x + dx) - f(x - dx)) / (2 * kFdStep);
  }
  return J;
}

void ExpectFdClose(const Mat6& J, const Mat6& J_fd, const Vec6& xi) {
  EXPECT_LT(MaxAbs<6>(J - J_fd), kFdTol * std::max(1.0, MaxAbs<6>(J))) << xi.transpose();
}

TEST(SE3, ExactAtZero) {
  const Vec6 zero = Vec6::Zero();
  const SE3 g = SE3Exp(zero);
  EXPECT_EQ(g.R, Mat3::Identity());
  EXPECT_EQ(g.p, Vec3::Zero());
  EXPECT_EQ(SE3Log(SE3{}), zero);
  EXPECT_EQ(SE3LeftJacobian(zero), Mat6::Identity());
  EXPECT_EQ(SE3RightJacobian(zero), Mat6::Identity());
  EXPECT_EQ(SE3LeftJacobianInverse(zero), Mat6::Identity());
  EXPECT_EQ(SE3RightJacobianInverse(zero), Mat6::Identity());
}

TEST(SE3, GroupOperationsMatchMatrices) {
  std::mt19937 rng(1);
  for (int i = 0; i < kCases; ++i) {
    const SE3 a = RandomPose(rng), b = RandomPose(rng);
    const Vec3 x = RandomTwist(rng, 1.0).tail<3>();
    const SE3 ab = FromMatrix(ToMatrix(a));
    EXPECT_EQ(ab.R, a.R);  // pure copies: bitwise
    EXPECT_EQ(ab.p, a.p);
    EXPECT_LT(MaxAbs<4>(ToMatrix(Compose(a, b)) - ToMatrix(a) * ToMatrix(b)), kTight);
    EXPECT_LT(MaxAbs<4>(ToMatrix(Inverse(a)) - ToMatrix(a).inverse()), kTight);
    EXPECT_LT(PoseError(Compose(a, Inverse(a)), SE3{}), kTight);
    EXPECT_LT((Act(a, x) - (ToMatrix(a) * x.homogeneous()).head<3>()).norm(), kTight);
  }
}

TEST(SE3, HatVee) {
  std::mt19937 rng(2);
  for (int i = 0; i < kCases; ++i) {
    const Vec6 xi = RandomTwist(rng, 10.0);
    EXPECT_EQ(vee6(hat6(xi)), xi);  // copies and exact halving: bitwise
  }
}

TEST(SE3, ExpMatchesMatrixExponential) {
  // Independent reference: Eigen's Padé matrix exponential of the 4×4 hat6(ξ), also beyond π.
  std::mt19937 rng(3);
  for (int i = 0; i < kCases; ++i) {
    const Vec6 xi = RandomTwist(rng, 3 * kPi);
    const Mat4 X = hat6(xi);
    const Mat4 T_ref = X.exp();
    EXPECT_LT(MaxAbs<4>(ToMatrix(SE3Exp(xi)) - T_ref), kTight) << xi.transpose();
  }
  for (const Vec6& xi : TestTwists()) {
    const Mat4 X = hat6(xi);
    const Mat4 T_ref = X.exp();
    EXPECT_LT(MaxAbs<4>(ToMatrix(SE3Exp(xi)) - T_ref), kTight) << xi.transpose();
  }
}

TEST(SE3, LogExpRoundTrip) {
  for (const Vec6& xi : TestTwists()) {
    EXPECT_LT((SE3Log(SE3Exp(xi)) - xi).cwiseAbs().maxCoeff(), kTight) << xi.transpose();
  }
}

TEST(SE3, ExpLogRoundTrip) {
  std::mt19937 rng(4);
  std::vector<SE3> poses;
  for (int i = 0; i < kCases; ++i) poses.push_back(SE3Exp(RandomTwist(rng, 4 * kPi)));
  // Rotations by exactly π, where Log must take the axis from the symmetric part of R.
  for (const Vec3& a : {Vec3(Vec3::UnitX()), Vec3(Vec3::UnitY()), Vec3(Vec3::UnitZ()),
                        Vec3(Vec3(1, 1, 1).normalized())}) {
    poses.push_back({2.0 * a * a.transpose() - Mat3::Identity(), Vec3(0.5, -1.0, 2.0)});
  }
  for (const SE3& g : poses) {
    const Vec6 xi = SE3Log(g);
    EXPECT_LE(xi.head<3>().norm(), kPi + kTight);
    EXPECT_LT(PoseError(SE3Exp(xi), g), kTight);
  }
}

TEST(SE3, AdjointIsAHomomorphism) {
  std::mt19937 rng(5);
  for (int i = 0; i < kCases; ++i) {
    const SE3 a = RandomPose(rng), b = RandomPose(rng);
    const Vec6 xi = RandomTwist(rng, kPi);
    EXPECT_LT(MaxAbs<6>(Ad(Compose(a, b)) - Ad(a) * Ad(b)), kTight);
    EXPECT_LT(MaxAbs<6>(Ad(Inverse(a)) * Ad(a) - Mat6::Identity()), kTight);
    // Ad(g) ξ = vee6(g hat6(ξ) g^{-1}) and Exp(Ad(g) ξ) = g Exp(ξ) g^{-1}.
    const Mat4 T = ToMatrix(a);
    EXPECT_LT((Ad(a) * xi - vee6(T * hat6(xi) * T.inverse())).cwiseAbs().maxCoeff(), kTight);
    EXPECT_LT(PoseError(SE3Exp(Ad(a) * xi), Compose(Compose(a, SE3Exp(xi)), Inverse(a))), kTight);
  }
}

TEST(SE3, LieBracketAndCoadjoint) {
  std::mt19937 rng(6);
  for (int i = 0; i < kCases; ++i) {
    const Vec6 x = RandomTwist(rng, kPi), y = RandomTwist(rng, kPi), mu = RandomTwist(rng, kPi);
    // ad(x) y = vee6([hat6(x), hat6(y)]), and ad(x) x = 0.
    const Mat4 X = hat6(x), Y = hat6(y);
    EXPECT_LT(MaxAbs<4>(hat6(ad(x) * y) - (X * Y - Y * X)), kTight);
    EXPECT_LT((ad(x) * x).norm(), kTight);
    // Duality <coad(x) μ, η> = <μ, ad(x) η>, and the explicit form used by the rod equations.
    EXPECT_NEAR((coad(x) * mu).dot(y), mu.dot(ad(x) * y), kTight * 10);  // sums of ~36 products
    const Vec3 w = x.head<3>(), v = x.tail<3>(), m = mu.head<3>(), n = mu.tail<3>();
    Vec6 expected;
    expected << -(w.cross(m) + v.cross(n)), -w.cross(n);
    EXPECT_LT((coad(x) * mu - expected).norm(), kTight);
  }
}

TEST(SE3, SmallAdjointIsDerivativeOfAdjoint) {
  // ad(ξ) = d/dt Ad(Exp(t ξ)) at t = 0, by central differences (tolerance as for Jacobians).
  for (const Vec6& xi : TestTwists()) {
    const Mat6 dAd = (Ad(SE3Exp(kFdStep * xi)) - Ad(SE3Exp(-kFdStep * xi))) / (2 * kFdStep);
    EXPECT_LT(MaxAbs<6>(dAd - ad(xi)), kFdTol * std::max(1.0, MaxAbs<6>(ad(xi))));
  }
}

TEST(SE3, JacobianIdentities) {
  for (const Vec6& xi : TestTwists()) {
    const Mat6 Jl = SE3LeftJacobian(xi), Jr = SE3RightJacobian(xi);
    // Exp(ξ) Exp(J_r dξ) = Exp(Ad(Exp ξ) J_r dξ) Exp(ξ), so J_l = Ad(Exp ξ) J_r.
    EXPECT_LT(MaxAbs<6>(Jl - Ad(SE3Exp(xi)) * Jr), kTight) << xi.transpose();
    EXPECT_LT(MaxAbs<6>(SE3LeftJacobianInverse(xi) * Jl - Mat6::Identity()), kTight);
    EXPECT_LT(MaxAbs<6>(SE3RightJacobianInverse(xi) * Jr - Mat6::Identity()), kTight);
  }
}

TEST(SE3, JacobiansMatchFiniteDifferences) {
  // Stay 0.01 below π: the inverse Jacobians differentiate Log, which jumps at π.
  const Vec6 zero = Vec6::Zero();
  for (const Vec6& xi : TestTwists(kPi - 1e-2)) {
    const SE3 g = SE3Exp(xi), g_inv = Inverse(g);
    // Exp(ξ + dξ) Exp(ξ)^{-1} = Exp(J_l dξ), Exp(ξ)^{-1} Exp(ξ + dξ) = Exp(J_r dξ).
    const auto left = [&](const Vec6& x) { return SE3Log(Compose(SE3Exp(x), g_inv)); };
    const auto right = [&](const Vec6& x) { return SE3Log(Compose(g_inv, SE3Exp(x))); };
    // Log(Exp(d) g) ≈ ξ + J_l^{-1} d, Log(g Exp(d)) ≈ ξ + J_r^{-1} d.
    const auto left_inv = [&](const Vec6& d) { return SE3Log(Compose(SE3Exp(d), g)); };
    const auto right_inv = [&](const Vec6& d) { return SE3Log(Compose(g, SE3Exp(d))); };
    ExpectFdClose(SE3LeftJacobian(xi), NumericJacobian<6>(left, xi), xi);
    ExpectFdClose(SE3RightJacobian(xi), NumericJacobian<6>(right, xi), xi);
    ExpectFdClose(SE3LeftJacobianInverse(xi), NumericJacobian<6>(left_inv, zero), xi);
    ExpectFdClose(SE3RightJacobianInverse(xi), NumericJacobian<6>(right_inv, zero), xi);
  }
}

TEST(SE3, OperationJacobiansMatchFiniteDifferences) {
  // Right perturbations X ← X Exp(τ); J_Y_X = ∂ Log(Y^{-1} Y(X Exp(τ))) / ∂τ.
  std::mt19937 rng(7);
  const Vec6 zero = Vec6::Zero();
  for (int i = 0; i < kCases; ++i) {
    const SE3 a = RandomPose(rng), b = RandomPose(rng);
    const Vec3 x = RandomTwist(rng, 1.0).tail<3>();
    Mat6 J_ab_a, J_ab_b, J_ainv_a;
    const SE3 ab_inv = Inverse(Compose(a, b, &J_ab_a, &J_ab_b));
    Inverse(a, &J_ainv_a);
    const auto plus = [](const SE3& g, const Vec6& t) { return Compose(g, SE3Exp(t)); };
    const auto ab_of_a = [&](const Vec6& t) {
      return SE3Log(Compose(ab_inv, Compose(plus(a, t), b)));
    };
    const auto ab_of_b = [&](const Vec6& t) {
      return SE3Log(Compose(ab_inv, Compose(a, plus(b, t))));
    };
    const auto ainv_of_a = [&](const Vec6& t) { return SE3Log(Compose(a, Inverse(plus(a, t)))); };
    ExpectFdClose(J_ab_a, NumericJacobian<6>(ab_of_a, zero), zero);
    ExpectFdClose(J_ab_b, NumericJacobian<6>(ab_of_b, zero), zero);
    ExpectFdClose(J_ainv_a, NumericJacobian<6>(ainv_of_a, zero), zero);
    Eigen::Matrix<double, 3, 6> J_y_g;
    Mat3 J_y_x;
    Act(a, x, &J_y_g, &J_y_x);
    const Eigen::Matrix<double, 3, 6> J_y_g_fd =
        NumericJacobian<3>([&](const Vec6& t) { return Act(plus(a, t), x); }, zero);
    EXPECT_LT((J_y_g - J_y_g_fd).cwiseAbs().maxCoeff(), kFdTol * 10);  // |y| ≲ 10 m
    EXPECT_EQ(J_y_x, a.R);  // y is affine in x: the Jacobian is R itself
  }
}

TEST(SE3, TaylorBranchIsContinuous) {
  // Q switches to its series at θ² = kSE3Taylor2 (θ = 0.1). Across the tiny gap below, the true
  // J_l moves by ~1e-15; both branches are within ~1e-15 |v| of it (se3.hpp), |v| ≈ 1.4 here.
  // A mismatch above 1e-14 means one branch is inaccurate at the switch.
  const double t = std::sqrt(kSE3Taylor2);
  for (const Vec3& a : {Vec3(Vec3::UnitX()), Vec3(Vec3(1, -2, 3).normalized())}) {
    Vec6 lo, hi;
    lo << t * (1 - 1e-14) * a, 0.3, -1.2, 0.7;
    hi << t * (1 + 1e-14) * a, 0.3, -1.2, 0.7;
    ASSERT_LT(lo.head<3>().squaredNorm(), kSE3Taylor2);  // the points take different branches
    ASSERT_GE(hi.head<3>().squaredNorm(), kSE3Taylor2);
    EXPECT_LT(MaxAbs<6>(SE3LeftJacobian(lo) - SE3LeftJacobian(hi)), 1e-14);
    EXPECT_LT(MaxAbs<6>(SE3LeftJacobianInverse(lo) - SE3LeftJacobianInverse(hi)), 1e-14);
  }
}

}  // namespace
}  // namespace cosserat::lie
