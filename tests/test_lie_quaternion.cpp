// Unit-quaternion helpers: convention (Hamilton, scalar first), agreement with SO(3), and
// Shepperd's conversion at all angles including π.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "cosserat/lie/quaternion.hpp"
#include "support/lie_test_support.hpp"

namespace cosserat::lie {
namespace {

using namespace testing;

Vec4 RandomQuat(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return QuatNormalized(Vec4(n(rng), n(rng), n(rng), n(rng)));  // uniform on S³, either sign
}

// Rotation vectors with |w| < π: special angles about several axes, then random ones.
std::vector<Vec3> TestRotVecs() {
  const std::vector<Vec3> axes = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(),
                                  Vec3(1, 1, 0).normalized(), Vec3(1, -2, 3).normalized()};
  std::vector<Vec3> ws;
  for (const Vec3& a : axes)
    for (double t : {0.0, 1e-12, 1e-8, 1e-4, kPi - 1e-6, kPi - 1e-10}) ws.push_back(t * a);
  std::mt19937 rng(20240503);
  for (int i = 0; i < kCases; ++i) ws.push_back(RandomRotVec(rng, kPi));
  return ws;
}

double MaxAbs(const Mat3& A) { return A.cwiseAbs().maxCoeff(); }

TEST(Quaternion, HamiltonConvention) {
  // i ⊗ j = k (Hamilton; JPL would give −k), and a quarter turn about z maps x to y.
  const Vec4 i(0, 1, 0, 0), j(0, 0, 1, 0), k(0, 0, 0, 1);
  EXPECT_EQ(QuatMultiply(i, j), k);  // products of 0 and ±1: exact
  const Vec4 qz = QuatFromAxisAngle(0.5 * kPi * Vec3::UnitZ());
  EXPECT_LT((QuatRotate(qz, Vec3::UnitX()) - Vec3::UnitY()).norm(), 4 * kEps);
  EXPECT_EQ(QuatFromAxisAngle(Vec3::Zero()), Vec4(1, 0, 0, 0));
  EXPECT_EQ(QuatToAxisAngle(Vec4(1, 0, 0, 0)), Vec3::Zero());
}

TEST(Quaternion, AxisAngleMatchesSO3Exp) {
  for (const Vec3& w : TestRotVecs()) {
    const Vec4 q = QuatFromAxisAngle(w);
    EXPECT_NEAR(q.norm(), 1.0, 4 * kEps);
    EXPECT_LT(MaxAbs(QuatToRotation(q) - SO3Exp(w)), kTight) << w.transpose();
    EXPECT_LT((QuatToAxisAngle(q) - w).norm(), kTight) << w.transpose();
    EXPECT_LT((QuatToAxisAngle(-q) - w).norm(), kTight) << w.transpose();  // q and −q agree
  }
  // Tiny angles: the vector part must stay relatively accurate, not just close to 0.
  for (double t : {1e-12, 1e-8, 1e-4}) {
    const Vec3 w = t * Vec3(1, -2, 3).normalized();
    EXPECT_LT((QuatToAxisAngle(QuatFromAxisAngle(w)) - w).norm(), 4 * kEps * t);
  }
}

TEST(Quaternion, RotationRoundTrip) {
  std::vector<Mat3> rotations;
  for (const Vec3& w : TestRotVecs()) rotations.push_back(SO3Exp(w));
  // Exactly π about several axes (w = 0): Shepperd must pick x, y or z as the pivot.
  for (const Vec3& a : {Vec3(Vec3::UnitX()), Vec3(Vec3::UnitY()), Vec3(Vec3::UnitZ()),
                        Vec3(Vec3(1, 1, 0).normalized()), Vec3(Vec3(1, -2, 3).normalized())}) {
    rotations.push_back(2.0 * a * a.transpose() - Mat3::Identity());
  }
  for (const Mat3& R : rotations) {
    const Vec4 q = RotationToQuat(R);
    EXPECT_NEAR(q.norm(), 1.0, 4 * kEps);
    EXPECT_GE(q[0], 0.0);
    EXPECT_LT(MaxAbs(QuatToRotation(q) - R), kTight);
  }
  // Quaternion → rotation → quaternion recovers q up to sign.
  std::mt19937 rng(1);
  for (int n = 0; n < kCases; ++n) {
    const Vec4 q = RandomQuat(rng);
    const Vec4 q_back = RotationToQuat(QuatToRotation(q));
    EXPECT_LT(std::min((q_back - q).norm(), (q_back + q).norm()), kTight);
  }
}

TEST(Quaternion, ProductRotateConjugate) {
  std::mt19937 rng(2);
  const Vec4 identity(1, 0, 0, 0);
  for (int n = 0; n < kCases; ++n) {
    const Vec4 a = RandomQuat(rng), b = RandomQuat(rng);
    const Vec3 x = RandomRotVec(rng, 5.0);
    const Mat3 Ra = QuatToRotation(a), Rb = QuatToRotation(b);
    EXPECT_LT(MaxAbs(Ra.transpose() * Ra - Mat3::Identity()), kTight);
    EXPECT_NEAR(Ra.determinant(), 1.0, kTight);
    EXPECT_LT(MaxAbs(QuatToRotation(QuatMultiply(a, b)) - Ra * Rb), kTight);
    EXPECT_LT((QuatRotate(a, x) - Ra * x).norm(), kTight * 5);  // |x| < 5
    EXPECT_LT((QuatMultiply(a, QuatConjugate(a)) - identity).norm(), kTight);
    EXPECT_LT((QuatMultiply(QuatConjugate(a), a) - identity).norm(), kTight);
    EXPECT_LT(MaxAbs(QuatToRotation(QuatConjugate(a)) - Ra.transpose()), kTight);
  }
}

TEST(Quaternion, Normalized) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int n = 0; n < kCases; ++n) {
    const Vec4 q(u(rng), u(rng), u(rng), u(rng));
    const Vec4 qn = QuatNormalized(q);
    EXPECT_NEAR(qn.norm(), 1.0, 4 * kEps);
    EXPECT_LT((qn * q.norm() - q).norm(), kTight);
    // The axis-angle of a non-unit quaternion depends only on its direction.
    EXPECT_LT((QuatToAxisAngle(q) - QuatToAxisAngle(qn)).norm(), kTight);
  }
}

}  // namespace
}  // namespace cosserat::lie
