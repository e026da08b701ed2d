// Assemblies of rods and rigid bodies (AssemblyStaticsSolver): two parallel rods joined at their
// tips by a plate share an axial load equally and, loaded sideways, deflect as guided beams,
// P L³/(12 · 2EI); as a portal frame with a rigid girder they sway at their Euler load; the six-rod continuum Stewart–Gough robot of Till, Aloi & Rucker (2019)
// solves its inverse kinematics self-consistently (forward kinematics of the lengths returns the
// pose), its base reactions balance the platform's load and the rods' weight, and its pose
// Jacobian matches central differences.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "cosserat/assembly/assembly_statics.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/robots/stewart_gough.hpp"
#include "support/rods.hpp"

namespace cosserat {
namespace {

using testing::SteelRod;

/// Two vertical steel rods (0.5 m, r = 1 mm) from (±d/2, 0, 0), their tips clamped to a plate
/// at height L carrying `force` at its centre.
Assembly TwoRodsAndAPlate(double d, const Vec3& force) {
  const SteelRod rod{0.5, 0.001};
  Assembly a;
  RigidBody plate;
  plate.name = "plate";
  plate.pose.p = Vec3(0, 0, rod.length);
  plate.force_W = force;
  a.bodies.push_back(plate);
  for (double x : {-0.5 * d, 0.5 * d}) {
    AssemblyRod r;
    r.name = x < 0 ? "left" : "right";
    r.model = rod.model();
    r.nodes = 51;
    r.base.p = Vec3(x, 0, 0);
    r.tip_joint = TipJoint::kClamped;
    r.body = 0;
    r.attachment.p = Vec3(x, 0, 0);
    a.rods.push_back(r);
  }
  return a;
}

// An axial load on the plate's centre: by symmetry each rod carries half, and each shortens by
// (P/2) L/EA; RK4 integrates the constant strain exactly, so both hold to round-off (the solve's
// tolerance, 1e-10 of EI/L² ≈ 3e-11 N, bounds the force).
TEST(Assembly, TwoParallelRodsShareAnAxialLoadEqually) {
  const SteelRod rod{0.5, 0.001};
  const double P = 50.0;  // N
  AssemblyStaticsSolver solver(TwoRodsAndAPlate(0.1, Vec3(0, 0, -P)));
  const AssemblySummary s = solver.Solve(StaticLoads{});
  ASSERT_TRUE(s.converged()) << ToString(s.status);
  for (int i = 0; i < 2; ++i) {
    const double reaction = solver.rod_state(i).BaseReaction_W()(5);  // N, up
    EXPECT_NEAR(reaction, 0.5 * P, 1e-9 * P) << "rod " << i;
  }
  const double drop = rod.length - solver.body_poses()[0].p.z();
  const double expected = 0.5 * P * rod.length / rod.EA();
  std::printf("axial: plate drops %.9e m, (P/2) L/EA = %.9e m\n", drop, expected);
  EXPECT_NEAR(drop, expected, 1e-9 * expected);
}

// A small sideways load P along x on the plate: the rods, 0.1 m apart, keep the plate from
// turning (their axial stiffness against the couple), so each is a guided beam carrying P/2:
// δ = P L³/(12 · 2EI). The plate's residual turn adds 3 r²/d² ≈ 3e-4 of δ, shear 3e-5, the
// geometric nonlinearity (δ/L)² ≈ 1e-6: within 0.1 % (the acceptance asks 0.5 %).
TEST(Assembly, TwoRodsJoinedAtTheirTipsDeflectAsAGuidedBeam) {
  const SteelRod rod{0.5, 0.001};
  const double P = 0.01;  // N
  AssemblyStaticsSolver solver(TwoRodsAndAPlate(0.1, Vec3(P, 0, 0)));
  const AssemblySummary s = solver.Solve(StaticLoads{});
  ASSERT_TRUE(s.converged()) << ToString(s.status);
  const double delta = solver.body_poses()[0].p.x();
  const double expected = P * std::pow(rod.length, 3) / (12 * 2 * rod.EI());
  const double turn = lie::SO3Log(solver.body_poses()[0].R).norm();
  std::printf("guided beam: plate moves %.6e m (P L^3/(24 EI) = %.6e m), turns %.2e rad, "
              "%d iterations\n",
              delta, expected, turn, s.iterations);
  EXPECT_NEAR(delta, expected, 1e-3 * expected);
}

// A portal frame whose girder is rigid (the plate on the two rods) sways under a vertical load P
// on each column: each column is clamped at its foot and guided at its head, so the frame's sway
// stiffness is 2 · 12EI/L³ · φ(u), φ = u³/(3(tan u − u)), u = (L/2) sqrt(P/EI), and vanishes at
// the columns' Euler load π²EI/L² (Timoshenko & Gere 1961, §2.2 and the stability functions of
// §1.11). Measured: the stiffness ε/δ under a lateral load ε = 1e-4 N at P = 0.5, 0.95 and 0.97
// P_cr; the critical load from the secant through the last two (the closed form's own secant
// root lies 2.4e-5 above P_cr). The acceptance asks 1 %; the plate's turn (3r²/d² ≈ 3e-4), shear
// and the columns' shortening (~P/EA ≈ 4e-5) shift both by less than 1e-3, so 2e-3 is asserted.
TEST(Assembly, APortalFrameWithARigidGirderSwaysAtTheEulerLoadOfItsColumns) {
  const SteelRod rod{0.5, 0.001};
  const double L = rod.length, euler = M_PI * M_PI * rod.EI() / (L * L), eps = 1e-4;
  auto stiffness = [&](double ratio) {
    AssemblyStaticsSolver solver(TwoRodsAndAPlate(0.1, Vec3(eps, 0, -2 * ratio * euler)));
    const AssemblySummary s = solver.Solve(StaticLoads{});
    EXPECT_TRUE(s.converged()) << "P = " << ratio << " P_cr: " << ToString(s.status);
    return eps / solver.body_poses()[0].p.x();
  };
  auto closed_form = [&](double ratio) {
    const double u = 0.5 * M_PI * std::sqrt(ratio);
    return 2 * 12 * rod.EI() / std::pow(L, 3) * std::pow(u, 3) / (3 * (std::tan(u) - u));
  };
  const double k_half = stiffness(0.5), k_a = stiffness(0.95), k_b = stiffness(0.97);
  const double critical = 0.97 - k_b * (0.97 - 0.95) / (k_b - k_a);  // in units of π²EI/L²
  std::printf("portal frame: sway stiffness %.6f N/m at P_cr/2 (closed form %.6f); critical "
              "load %.6f pi^2 EI/L^2 per column\n",
              k_half, closed_form(0.5), critical);
  EXPECT_NEAR(k_half, closed_form(0.5), 2e-3 * closed_form(0.5));
  EXPECT_NEAR(critical, 1.0, 2e-3);
}

/// The continuum Stewart–Gough robot of Till, Aloi & Rucker (2019) as their example code builds
/// it (robots/stewart_gough.hpp), with a platform of `platform_mass` and rods of `nodes`.
Assembly StewartGough(double platform_mass, int nodes = 40) {
  StewartGoughParameters p;
  p.platform_mass = platform_mass;
  p.nodes = nodes;
  return ContinuumStewartGough(p);
}

lie::SE3 Pose(const Vec3& p, const Vec3& rotation) {
  lie::SE3 pose;
  pose.p = p;
  pose.R = lie::SO3Exp(rotation);
  return pose;
}

// Inverse kinematics of a pose, then forward kinematics of the lengths it found, from the
// unloaded robot: the pose comes back within 1e-6 m and 1e-6 rad (the acceptance; both solves
// converge to 1e-10 of their scales, so the pose returns to ~1e-10 m).
TEST(Assembly, StewartGoughInverseKinematicsIsSelfConsistent) {
  const lie::SE3 target = Pose(Vec3(0.01, 0.02, 0.46), Vec3(0.1, -0.05, 0.2));
  AssemblyStaticsSolver inverse(StewartGough(0.0));
  const AssemblySummary si = inverse.SolveLengths(StaticLoads{}, {target});
  ASSERT_TRUE(si.converged()) << ToString(si.status);
  const std::vector<double> lengths = inverse.lengths();
  AssemblyStaticsSolver forward(StewartGough(0.0));
  const AssemblySummary sf = forward.Solve(StaticLoads{}, lengths);
  ASSERT_TRUE(sf.converged()) << ToString(sf.status);
  const lie::SE3& pose = forward.body_poses()[0];
  const double dp = (pose.p - target.p).norm();
  const double dr = lie::SO3Log(Mat3(target.R.transpose() * pose.R)).norm();
  std::printf("Stewart-Gough: lengths %.6f %.6f %.6f %.6f %.6f %.6f m; forward kinematics back "
              "within %.2e m, %.2e rad (%d + %d iterations, %d continuation levels)\n",
              lengths[0], lengths[1], lengths[2], lengths[3], lengths[4], lengths[5], dp, dr,
              si.iterations, sf.iterations, sf.load_steps);
  EXPECT_LT(dp, 1e-6);
  EXPECT_LT(dr, 1e-6);
}

/// The force and the moment about the origin (world) that the loads leave unbalanced by the six
/// base reactions of the Stewart–Gough robot with a 0.5 kg platform under gravity, on `nodes`.
Vec6 StewartGoughImbalance(int nodes, double* weight) {
  AssemblyStaticsSolver solver(StewartGough(0.5, nodes));
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  EXPECT_TRUE(
      solver.SolveLengths(loads, {Pose(Vec3(0, 0.02, 0.45), Vec3(0, 0, 0.1))}).converged());
  const double rhoA = 8000 * M_PI * 0.00065 * 0.00065, g = 9.81;
  Vec3 force = Vec3(0, 0, -0.5 * g), moment = solver.body_poses()[0].p.cross(force);
  *weight = 0.5 * g;
  for (int i = 0; i < 6; ++i) {
    const RodState& st = solver.rod_state(i);
    const Vec6 reaction = st.BaseReaction_W();  // [moment about p(0); force]
    force += reaction.tail<3>();
    moment += reaction.head<3>() + st.position_W[0].cross(Vec3(reaction.tail<3>()));
    // The rod's weight, at the centroid of its centreline (trapezoid rule per segment).
    const double w = rhoA * solver.lengths()[i] * g;
    Vec3 centroid = Vec3::Zero();
    for (int n = 0; n + 1 < st.size(); ++n)
      centroid += 0.5 * (st.position_W[n] + st.position_W[n + 1]) * (st.s[n + 1] - st.s[n]);
    centroid /= solver.lengths()[i];
    force.z() -= w;
    moment += centroid.cross(Vec3(0, 0, -w));
    *weight += w;
  }
  Vec6 out;
  out << force, moment;
  return out;
}

// The six base reactions balance the platform's weight and the rods' weight. Not to round-off:
// the shot carries the internal force in the body frame, where RK4 does not integrate
// n' = −K × n − Rᵀ f exactly, and the rods' centroids are taken by the trapezoid rule. Both errors
// fall with the grid, as h⁴ and h²: the imbalance must be below 1e-7 of the weight on 40 nodes
// and fall at least 3.5 times from 40 to 80 nodes (a missing load or a wrong lever arm would not
// fall).
TEST(Assembly, StewartGoughBaseReactionsBalanceTheLoads) {
  double weight = 0.0;
  const Vec6 coarse = StewartGoughImbalance(40, &weight);
  const Vec6 fine = StewartGoughImbalance(80, &weight);
  std::printf("balance: force imbalance %.2e N, moment %.2e N m on 40 nodes; %.2e N, %.2e N m "
              "on 80 (weight %.4f N)\n",
              coarse.head<3>().norm(), coarse.tail<3>().norm(), fine.head<3>().norm(),
              fine.tail<3>().norm(), weight);
  EXPECT_LT(coarse.head<3>().norm(), 1e-7 * weight);
  EXPECT_LT(coarse.tail<3>().norm(), 1e-7 * weight * 0.1);  // lever arms ≲ 0.1 m
  EXPECT_LT(fine.head<3>().norm(), coarse.head<3>().norm() / 3.5);
  EXPECT_LT(fine.tail<3>().norm(), coarse.tail<3>().norm() / 3.5);
}

// d(pose)/d(lengths) by the implicit function theorem (each rod's shot differentiated exactly in
// its base unknowns and by a forward difference of 1e-7 L in its length: ~1e-8 relative) against
// central differences of forward kinematics (h = 1e-6 m: truncation ~h² |d³pose/dL³| ≈ 1e-10,
// round-off of the 1e-13-converged poses 1e-13/h = 1e-7 of a column of order 1): within 1e-5 of
// the largest entry (measured 1.3e-8).
TEST(Assembly, StewartGoughPoseJacobianMatchesCentralDifferences) {
  AssemblyStaticsSolver solver(StewartGough(0.0));
  AssemblyOptions tight;
  tight.tolerance = 1e-13;
  ASSERT_TRUE(solver.SolveLengths(StaticLoads{}, {Pose(Vec3(0, 0.02, 0.45), Vec3(0.05, 0, 0))})
                  .converged());
  const std::vector<double> lengths = solver.lengths();
  AssemblyStaticsSolver forward(StewartGough(0.0), tight);
  ASSERT_TRUE(forward.Solve(StaticLoads{}, lengths).converged());
  const Eigen::MatrixXd J = forward.PoseJacobian(0, StaticLoads{});
  ASSERT_EQ(J.rows(), 6);
  ASSERT_EQ(J.cols(), 6);
  const lie::SE3 at = forward.body_poses()[0];
  const double h = 1e-6;
  Eigen::MatrixXd numeric(6, 6);
  for (int j = 0; j < 6; ++j) {
    std::vector<lie::SE3> poses;
    for (double sign : {1.0, -1.0}) {
      std::vector<double> L = lengths;
      L[j] += sign * h;
      ASSERT_TRUE(forward.Solve(StaticLoads{}, L).converged());
      poses.push_back(forward.body_poses()[0]);
    }
    numeric.block<3, 1>(0, j) = (poses[0].p - poses[1].p) / (2 * h);
    numeric.block<3, 1>(3, j) =
        (lie::SO3Log(Mat3(at.R.transpose() * poses[0].R)) -
         lie::SO3Log(Mat3(at.R.transpose() * poses[1].R))) / (2 * h);
  }
  const double scale = numeric.cwiseAbs().maxCoeff();
  std::printf("pose Jacobian: largest entry %.4f, largest difference %.2e\n", scale,
              (J - numeric).cwiseAbs().maxCoeff());
  EXPECT_LT((J - numeric).cwiseAbs().maxCoeff(), 1e-5 * scale);
}

}  // namespace
}  // namespace cosserat
