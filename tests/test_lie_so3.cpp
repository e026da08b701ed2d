// Property tests for the SO(3) layer: exp/log round trips, exactness at 0, behaviour near π,
// and every Jacobian against central finite differences.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "cosserat/lie/so3.hpp"
#include "support/lie_test_support.hpp"

namespace cosserat::lie {
namespace {

using namespace testing;

// Angles that exercise the Taylor branches and the neighbourhood of π.
const std::vector<double> kSpecialAngles = {0.0, 1e-12, 1e-8, 1e-4, kPi - 1e-6, kPi - 1e-10};

std::vector<Vec3> SpecialAxes() {
  return {Vec3::UnitX(),
          Vec3::UnitY(),
          Vec3::UnitZ(),
          -Vec3::UnitY(),
          Vec3(1, 1, 0).normalized(),
          Vec3(1, -2, 3).normalized(),
          Vec3(-1, -1, -1).normalized()};
}

// All test rotation vectors with |w| < π: special angles about special axes, then random ones.
std::vector<Vec3> TestRotVecs(double max_angle = kPi) {
  std::vector<Vec3> ws;
  for (const Vec3& a : SpecialAxes())
    for (double t : kSpecialAngles)
      if (t < max_angle) ws.push_back(t * a);
  std::mt19937 rng(20240501);
  for (int i = 0; i < kCases; ++i) ws.push_back(RandomRotVec(rng, max_angle));
  return ws;
}

// Central-difference Jacobian of f: R^3 -> R^3 at x.
template <typename F>
Mat3 NumericJacobian(F f, const Vec3& x) {
  Mat3 J;
  for (int j = 0; j < 3; ++j) {
    const Vec3 dx = kFdStep * Vec3::Unit(j);
    J.col(j) = (f(x + dx) - f(x - dx)) / (2 * kFdStep);
  }
  return J;
}

double MaxAbs(const Mat3& A) { return A.cwiseAbs().maxCoeff(); }

TEST(SO3, HatVee) {
  std::mt19937 rng(1);
  for (int i = 0; i < kCases; ++i) {
    const Vec3 w = RandomRotVec(rng, 10.0), x = RandomRotVec(rng, 10.0);
    EXPECT_EQ(vee(hat(w)), w);  // pure copies and exact halving: bitwise
    EXPECT_LT((hat(w) * x - w.cross(x)).norm(),
              kTight * 100);  // |w||x| ≤ 100: same flops, reordered
  }
}

TEST(SO3, ExactAtZero) {
  const Vec3 zero = Vec3::Zero();
  EXPECT_EQ(SO3Exp(zero), Mat3::Identity());
  EXPECT_EQ(SO3Log(Mat3::Identity()), zero);
  EXPECT_EQ(SO3LeftJacobian(zero), Mat3::Identity());
  EXPECT_EQ(SO3RightJacobian(zero), Mat3::Identity());
  EXPECT_EQ(SO3LeftJacobianInverse(zero), Mat3::Identity());
  EXPECT_EQ(SO3RightJacobianInverse(zero), Mat3::Identity());
}

TEST(SO3, ExpMatchesMatrixExponential) {
  // Independent reference: Eigen's Padé matrix exponential of hat(w), also beyond π.
  std::mt19937 rng(2);
  for (int i = 0; i < kCases; ++i) {
    const Vec3 w = RandomRotVec(rng, 3 * kPi);
    const Mat3 R = SO3Exp(w);
    const Mat3 W = hat(w);
    const Mat3 R_ref = W.exp();
    EXPECT_LT(MaxAbs(R - R_ref), kTight) << w.transpose();
    EXPECT_LT(MaxAbs(R.transpose() * R - Mat3::Identity()), kTight);
    EXPECT_NEAR(R.determinant(), 1.0, kTight);
  }
}

TEST(SO3, ExpAccurateAtTinyAngles) {
  // The skew part of Exp(w) is sin θ · a = w (1 − θ²/6 + …); compare it relatively, since an
  // absolute test against I would not see errors in entries of size 1e-8.
  for (const Vec3& a : SpecialAxes()) {
    for (double t : {1e-12, 1e-8, 1e-4}) {
      const Vec3 w = t * a;
      const Vec3 expected = w * (1.0 - t * t / 6.0 + t * t * t * t / 120.0);  // exact to O(θ⁷)
      // A few roundings of O(θ) quantities: 4 eps relative.
      EXPECT_LT((vee(SO3Exp(w)) - expected).norm(), 4 * kEps * t) << t;
      EXPECT_LT((SO3Log(SO3Exp(w)) - w).norm(), 4 * kEps * t) << t;
    }
  }
}

TEST(SO3, LogExpRoundTrip) {
  for (const Vec3& w : TestRotVecs()) {
    EXPECT_LT((SO3Log(SO3Exp(w)) - w).norm(), kTight) << w.transpose();
  }
}

TEST(SO3, ExpLogRoundTrip) {
  // Any rotation, including angles past π (Log must wrap to |w| ≤ π).
  std::mt19937 rng(3);
  for (int i = 0; i < kCases; ++i) {
    const Mat3 R = SO3Exp(RandomRotVec(rng, 4 * kPi));
    const Vec3 w = SO3Log(R);
    EXPECT_LE(w.norm(), kPi + kTight);
    EXPECT_LT(MaxAbs(SO3Exp(w) - R), kTight);
  }
}

TEST(SO3, LogAtExactlyPi) {
  // R = 2 a a^T − I is a rotation by exactly π; the skew part is zero, so the axis must come from
  // the symmetric part. Both ±π a are correct answers.
  for (const Vec3& a : SpecialAxes()) {
    const Mat3 R = 2.0 * a * a.transpose() - Mat3::Identity();
    const Vec3 w = SO3Log(R);
    EXPECT_NEAR(w.norm(), kPi, kTight);
    EXPECT_NEAR(std::abs(w.normalized().dot(a)), 1.0, kTight);
    EXPECT_LT(MaxAbs(SO3Exp(w) - R), kTight);
  }
}

TEST(SO3, JacobianIdentities) {
  for (const Vec3& w : TestRotVecs()) {
    const Mat3 Jl = SO3LeftJacobian(w), Jr = SO3RightJacobian(w);
    EXPECT_LT(MaxAbs(Jr - Jl.transpose()), kTight);
    // Exp(w) Exp(J_r dw) = Exp(R J_r dw) Exp(w), so J_l = R J_r.
    EXPECT_LT(MaxAbs(Jl - SO3Exp(w) * Jr), kTight);
    // For |w| ≤ π the singular values of J_l lie in [2/π, 1]: products are well conditioned.
    EXPECT_LT(MaxAbs(SO3LeftJacobianInverse(w) * Jl - Mat3::Identity()), kTight);
    EXPECT_LT(MaxAbs(SO3RightJacobianInverse(w) * Jr - Mat3::Identity()), kTight);
  }
}

TEST(SO3, JacobiansMatchFiniteDifferences) {
  // Stay 0.01 below π: the inverse Jacobians differentiate Log, which jumps at π.
  for (const Vec3& w : TestRotVecs(kPi - 1e-2)) {
    const Mat3 R = SO3Exp(w);
    // Exp(w + dw) Exp(w)^T = Exp(J_l dw), Exp(w)^T Exp(w + dw) = Exp(J_r dw).
    const Mat3 Jl_fd =
        NumericJacobian([&](const Vec3& x) { return SO3Log(SO3Exp(x) * R.transpose()); }, w);
    const Mat3 Jr_fd =
        NumericJacobian([&](const Vec3& x) { return SO3Log(R.transpose() * SO3Exp(x)); }, w);
    // Log(Exp(d) R) ≈ w + J_l^{-1} d, Log(R Exp(d)) ≈ w + J_r^{-1} d.
    const Mat3 Jli_fd =
        NumericJacobian([&](const Vec3& d) { return SO3Log(SO3Exp(d) * R); }, Vec3::Zero());
    const Mat3 Jri_fd =
        NumericJacobian([&](const Vec3& d) { return SO3Log(R * SO3Exp(d)); }, Vec3::Zero());
    const Mat3 Jl = SO3LeftJacobian(w), Jr = SO3RightJacobian(w);
    const Mat3 Jli = SO3LeftJacobianInverse(w), Jri = SO3RightJacobianInverse(w);
    EXPECT_LT(MaxAbs(Jl - Jl_fd), kFdTol * std::max(1.0, MaxAbs(Jl))) << w.transpose();
    EXPECT_LT(MaxAbs(Jr - Jr_fd), kFdTol * std::max(1.0, MaxAbs(Jr))) << w.transpose();
    EXPECT_LT(MaxAbs(Jli - Jli_fd), kFdTol * std::max(1.0, MaxAbs(Jli))) << w.transpose();
    EXPECT_LT(MaxAbs(Jri - Jri_fd), kFdTol * std::max(1.0, MaxAbs(Jri))) << w.transpose();
  }
}

TEST(SO3, TaylorBranchesAreContinuous) {
  // Evaluate on both sides of the switch θ² = kSO3Taylor2. The true functions move by
  // O(1e-14 θ) across this gap, so a mismatch above round-off means one branch is inaccurate
  // there (a wrong leading coefficient gives ~1e-3 · θ^k, far above the tolerance).
  const double t = std::sqrt(kSO3Taylor2);
  for (const Vec3& a : SpecialAxes()) {
    const Vec3 lo = t * (1 - 1e-14) * a, hi = t * (1 + 1e-14) * a;
    ASSERT_LT(lo.squaredNorm(), kSO3Taylor2);  // the two points do take different branches
    ASSERT_GE(hi.squaredNorm(), kSO3Taylor2);
    // Round-off of the closed forms at θ = 1e-3 is a few eps (see so3.hpp), so 1e-15.
    constexpr double kTol = 1e-15;
    EXPECT_LT(MaxAbs(SO3Exp(lo) - SO3Exp(hi)), kTol);
    EXPECT_LT(MaxAbs(SO3LeftJacobian(lo) - SO3LeftJacobian(hi)), kTol);
    EXPECT_LT(MaxAbs(SO3LeftJacobianInverse(lo) - SO3LeftJacobianInverse(hi)), kTol);
    EXPECT_LT((SO3Log(SO3Exp(lo)) - lo).norm(), kTol);
    EXPECT_LT((SO3Log(SO3Exp(hi)) - hi).norm(), kTol);
  }
}

// SO3TurnedOnto lays a frame's third axis along a direction by the least rotation: the axis
// lands on d to rounding, and the turn's rotation vector is normal to both (no turn about
// either), of angle acos(z · d). Antiparallel, half a turn about the frame's first axis; a zero
// direction leaves the frame. Tolerance 1e-14: a few roundings of unit-sized products.
TEST(SO3, TurnedOntoLaysTheThirdAxisAlongADirectionByTheLeastRotation) {
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  for (int k = 0; k < 100; ++k) {
    const Mat3 R = SO3Exp(Vec3(g(rng), g(rng), g(rng)));
    const Vec3 d = Vec3(g(rng), g(rng), g(rng)) * 3.0;
    const Mat3 T = SO3TurnedOnto(R, d);
    EXPECT_LT((T.col(2) - d.normalized()).norm(), 1e-14);
    const Vec3 turn = SO3Log(Mat3(T * R.transpose()));
    EXPECT_LT(std::abs(turn.dot(R.col(2))), 1e-14 * (1 + turn.norm()));
    EXPECT_LT(std::abs(turn.dot(d.normalized())), 1e-14 * (1 + turn.norm()));
    EXPECT_NEAR(turn.norm(), std::acos(std::clamp(R.col(2).dot(d.normalized()), -1.0, 1.0)),
                1e-12);
  }
  const Mat3 R = SO3Exp(Vec3(0.3, -0.2, 0.5));
  const Mat3 flipped = SO3TurnedOnto(R, -R.col(2));
  EXPECT_LT((flipped.col(2) + R.col(2)).norm(), 1e-14);
  EXPECT_LT((flipped.col(0) - R.col(0)).norm(), 1e-14);
  EXPECT_EQ(MaxAbs(SO3TurnedOnto(R, Vec3::Zero()) - R), 0.0);
}

}  // namespace
}  // namespace cosserat::lie
