// The quaternion finite-difference model (Lang & Linn 2009): banded LU, the exact Jacobian against
// central differences, bandwidth, frame indifference, the rest state and energy balance.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <stdexcept>

#include "cosserat/lie/quaternion.hpp"
#include "cosserat/numerics/banded_matrix.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/quatfd/quatfd_statics.hpp"
#include "cosserat/rod/tendon_route.hpp"

namespace cosserat::quatfd {
namespace {

using L = QuatFdLayout;

TEST(BandedMatrix, LuSolveMatchesDenseSolve) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int kl : {1, 3, 10}) {
    const int n = 57, ku = kl + 1;
    BandedMatrix A(n, kl, ku);
    for (int j = 0; j < n; ++j)
      for (int i = std::max(0, j - ku); i <= std::min(n - 1, j + kl); ++i) A(i, j) = u(rng);
    const Eigen::MatrixXd dense = A.ToDense();
    Eigen::VectorXd b(n), y(n);
    for (int i = 0; i < n; ++i) b[i] = u(rng);
    A.Multiply(b, y);
    EXPECT_LT((y - dense * b).norm(), 1e-12 * dense.norm() * b.norm());
    ASSERT_TRUE(A.Factorize());
    Eigen::VectorXd x = b;
    A.Solve(x);
    const Eigen::VectorXd ref = dense.partialPivLu().solve(b);
    // Random matrices without diagonal dominance need pivoting: both solves agree to round-off
    // times the condition number (moderate for these sizes).
    EXPECT_LT((x - ref).norm(), 1e-9 * ref.norm()) << "kl = " << kl;
  }
}

TEST(BandedMatrix, ZeroPivotIsReported) {
  BandedMatrix A(4, 1, 1);
  A(0, 0) = 1;
  A(1, 0) = 0;  // column 1 is zero below and on the diagonal
  A(2, 2) = 1;
  A(3, 3) = 1;
  EXPECT_FALSE(A.Factorize());
}

RodModel RubberRod(double length, bool damped) {
  // Non-symmetric section (I1 ≠ I2) so every stiffness entry differs.
  Material m = Material::FromPoissonRatio(5e6, 0.45, 1100);
  if (damped) m.damping = {1e-4, 2e-4, 0.5, 0.8};
  return RodModel::Uniform(length, CrossSection::Rectangle(0.012, 0.006), m);
}

/// A deformed, moving state: the rest state plus random perturbations, quaternions renormalised
/// except where `off_manifold` (f must be differentiable off the constraint too).
void RandomState(const QuatFdModel& model, unsigned seed, bool off_manifold, Eigen::VectorXd* q,
                 Eigen::VectorXd* v) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  const int n = model.size();
  q->resize(n);
  v->resize(n);
  model.RestState(*q, *v);
  const double L = model.length();
  for (int i = 0; i < n; ++i) {
    if (model.IsFixed(i)) continue;
    (*q)[i] += 0.02 * (i % 7 < 3 ? L : 1.0) * g(rng);
    (*v)[i] = (i % 7 < 3 ? 0.3 : 2.0) * g(rng);
  }
  for (int s = 0; s < model.layout().segments; ++s) {
    auto p = q->segment<4>(L::P(s));
    p *= off_manifold ? 1.0 + 0.01 * g(rng) : 1.0 / p.norm();
  }
}

struct JacobianCase {
  Curvature curvature;
  EndCondition base;
  LoadFrame force_frame, moment_frame;
  bool off_manifold;
  EndCondition tip = EndCondition::kFree;
  /// A sheared current with drag and added mass, and a plane some vertices press into.
  bool environment = false;
};

class QuatFdJacobian : public ::testing::TestWithParam<JacobianCase> {};

TEST_P(QuatFdJacobian, MatchesCentralDifferences) {
  const JacobianCase c = GetParam();
  QuatFdOptions opt;
  opt.segments = 6;
  opt.curvature = c.curvature;
  opt.base_end = c.base;
  opt.tip_end = c.tip;  // a held tip at a point and a turn of its own
  opt.tip_position_W = Vec3(0.3, 0.1, 0.2);
  opt.tip_rotation_W = lie::QuatToRotation(lie::QuatFromAxisAngle(Vec3(-0.5, 0.7, 0.1)));
  opt.baumgarte_alpha = 3.0;
  opt.baumgarte_beta = 5.0;
  opt.grid = {0.0, 0.05, 0.12, 0.2, 0.31, 0.4, 0.5};  // non-equidistant
  lie::SE3 base;
  base.R = lie::QuatToRotation(lie::QuatFromAxisAngle(Vec3(0.3, -1.2, 0.4)));
  base.p = Vec3(0.1, 0.2, -0.3);
  QuatFdModel model(RubberRod(0.5, true), base, opt);
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  loads.distributed_force_W = Vec3(0.1, 0, 0.2);
  loads.tip_force = Vec3(0.05, -0.02, 0.01);
  loads.tip_force_frame = c.force_frame;
  loads.tip_moment = Vec3(0.001, 0.003, -0.002);
  loads.tip_moment_frame = c.moment_frame;
  Eigen::VectorXd q, v;
  RandomState(model, 11, c.off_manifold, &q, &v);
  if (c.environment) {
    loads.fluid.density = 1000;
    loads.fluid.velocity_W = Vec3(0.3, -0.2, 0.1);
    loads.fluid.profile.kind = FluidFlowProfile::Kind::kPowerLaw;
    loads.fluid.profile.origin_W = Vec3(0, 0, -1);
    loads.fluid.profile.exponent = 0.3;
    loads.fluid.drag_normal = 1.2;
    loads.fluid.drag_tangential = 0.1;
    loads.fluid.added_mass = 1.0;
    // A plane through the mean of the free vertices, tilted: about half of them press into it.
    // The penalty's second derivative jumps at the gaps 0 and −ε; each vertex (checked below)
    // is ten difference steps (1e-5 m) clear of both, so the differences see no kink.
    ContactSurface& plane = loads.contact.surface[loads.contact.count++];
    plane.direction_W = Vec3(0.2, 0.3, 1.0).normalized();
    plane.stiffness = 50.0;
    plane.damping = 0.5;
    plane.friction = 0.4;
    plane.smoothing = 1e-6;
    Vec3 mean = Vec3::Zero();
    for (int k = 0; k <= opt.segments; ++k) mean += q.segment<3>(L::X(k)) / (opt.segments + 1);
    plane.point_W = mean;
  }
  model.set_loads(loads);
  if (c.environment) {
    const ContactSurface& plane = loads.contact.surface[0];
    int pressing = 0;
    for (int k = 0; k <= opt.segments; ++k) {
      Vec3 normal;
      const double gap = plane.Distance(q.segment<3>(L::X(k)), &normal) -
                         0.5 * model.VertexSite(k).outer_diameter;
      ASSERT_GT(std::abs(gap), 1e-4 + plane.smoothing) << "vertex " << k << " near the ramp";
      pressing += gap < 0;
    }
    ASSERT_GT(pressing, 0);
  }
  BandedMatrix A, B;
  Eigen::VectorXd a;
  model.Jacobian(q, v, &A, &B, &a);
  const int n = model.size();
  Eigen::VectorXd a_plain(n);
  model.Acceleration(q, v, a_plain);
  EXPECT_LT((a - a_plain).norm(), 1e-12 * a_plain.norm());

  // The automatic-differentiation oracle: same derivatives, evaluated in a different order, so
  // they agree to round-off (1e-10 of each row's largest entry; the rows span ~1e8 in scale).
  {
    BandedMatrix Aad, Bad;
    model.JacobianAutoDiff(q, v, opt.baumgarte_alpha, opt.baumgarte_beta, &Aad, &Bad, nullptr);
    const Eigen::MatrixXd Ad = A.ToDense(), Bd = B.ToDense();
    const Eigen::MatrixXd Aj = Aad.ToDense(), Bj = Bad.ToDense();
    for (int i = 0; i < n; ++i) {
      const double sa = std::max(Aj.row(i).cwiseAbs().maxCoeff(), 1e-300);
      const double sb = std::max(Bj.row(i).cwiseAbs().maxCoeff(), 1e-300);
      EXPECT_LT((Ad.row(i) - Aj.row(i)).cwiseAbs().maxCoeff() / sa, 1e-10) << "AD df/dq row " << i;
      EXPECT_LT((Bd.row(i) - Bj.row(i)).cwiseAbs().maxCoeff() / sb, 1e-10) << "AD df/dv row " << i;
    }
  }
  // Central differences, step ~ eps^(1/3) scaled per unknown: truncation and round-off errors are
  // both ~1e-10 relative, far below the 1e-6 asked.
  Eigen::MatrixXd Afd(n, n), Bfd(n, n);
  Eigen::VectorXd ap(n), am(n);
  for (int j = 0; j < n; ++j) {
    for (int which = 0; which < 2; ++which) {
      Eigen::VectorXd qp = q, qm = q, vp = v, vm = v;
      const double scale =
          which == 0 ? std::max(1.0, std::abs(q[j])) : std::max(1.0, std::abs(v[j]));
      const double h = 1e-5 * scale;
      if (which == 0) {
        qp[j] += h;
        qm[j] -= h;
      } else {
        vp[j] += h;
        vm[j] -= h;
      }
      model.Acceleration(qp, vp, ap);
      model.Acceleration(qm, vm, am);
      (which == 0 ? Afd : Bfd).col(j) = (ap - am) / (2 * h);
    }
  }
  const Eigen::MatrixXd Ad = A.ToDense(), Bd = B.ToDense();
  // Entries outside the band are zero by construction (ToDense only reads the band): the finite
  // differences must vanish there too.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (std::abs(i - j) > L::kBandwidth) {
        ASSERT_EQ(Afd(i, j), 0.0) << i << "," << j;
        ASSERT_EQ(Bfd(i, j), 0.0) << i << "," << j;
      }
  // Row-wise relative error against the row's largest entry (rows mix very different scales:
  // translational and rotational accelerations).
  for (int i = 0; i < n; ++i) {
    const double sa = std::max(Afd.row(i).cwiseAbs().maxCoeff(), 1e-300);
    const double sb = std::max(Bfd.row(i).cwiseAbs().maxCoeff(), 1e-300);
    EXPECT_LT((Ad.row(i) - Afd.row(i)).cwiseAbs().maxCoeff() / sa, 1e-6) << "df/dq row " << i;
    EXPECT_LT((Bd.row(i) - Bfd.row(i)).cwiseAbs().maxCoeff() / sb, 1e-6) << "df/dv row " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, QuatFdJacobian,
    ::testing::Values(JacobianCase{Curvature::kVariant1, EndCondition::kClamped, LoadFrame::kWorld,
                                   LoadFrame::kWorld, false},
                      JacobianCase{Curvature::kVariant1, EndCondition::kClamped, LoadFrame::kBody,
                                   LoadFrame::kBody, true},
                      JacobianCase{Curvature::kBasic, EndCondition::kPinned, LoadFrame::kBody,
                                   LoadFrame::kWorld, true},
                      JacobianCase{Curvature::kBasic, EndCondition::kFree, LoadFrame::kWorld,
                                   LoadFrame::kBody, false},
                      JacobianCase{Curvature::kVariant1, EndCondition::kClamped, LoadFrame::kWorld,
                                   LoadFrame::kWorld, true, EndCondition::kClamped},
                      JacobianCase{Curvature::kVariant1, EndCondition::kClamped, LoadFrame::kWorld,
                                   LoadFrame::kBody, false, EndCondition::kFree, true},
                      JacobianCase{Curvature::kBasic, EndCondition::kPinned, LoadFrame::kBody,
                                   LoadFrame::kWorld, false, EndCondition::kClamped, true}));

TEST(QuatFdModel, RestStateIsStressFreeEquilibrium) {
  for (Curvature k : {Curvature::kBasic, Curvature::kVariant1}) {
    QuatFdOptions opt;
    opt.segments = 8;
    opt.curvature = k;
    RodModel rod = RubberRod(0.5, false);
    rod.rest_strain = ConstantRestCurvature(Vec3(2.0, -1.0, 0.5));
    QuatFdModel model(rod, lie::SE3(), opt);
    Eigen::VectorXd q(model.size()), v(model.size()), a(model.size());
    model.RestState(q, v);
    model.Acceleration(q, v, a);
    // No load, rest shape: the elastic forces vanish up to round-off (accelerations are force /
    // tiny rotational inertia, so compare against the bending-moment scale over the inertia).
    EXPECT_LT(a.cwiseAbs().maxCoeff(), 1e-6) << static_cast<int>(k);
    EXPECT_LT(model.Energy(q, v).elastic, 1e-20);
  }
}

TEST(QuatFdModel, FrameIndifference) {
  // A rigid rotation of the whole free rod (positions and quaternions) rotates the translational
  // accelerations and leaves the body-frame quantities unchanged: Γ and K are objective.
  QuatFdOptions opt;
  opt.segments = 5;
  opt.base_end = EndCondition::kFree;
  QuatFdModel model(RubberRod(0.5, true), lie::SE3(), opt);
  Eigen::VectorXd q, v;
  RandomState(model, 3, false, &q, &v);
  const Vec4 r = lie::QuatFromAxisAngle(Vec3(0.7, -0.4, 2.1));
  const Mat3 R = lie::QuatToRotation(r);
  Eigen::VectorXd q2 = q, v2 = v;
  for (int n = 0; n <= 5; ++n) {
    q2.segment<3>(L::X(n)) = R * q.segment<3>(L::X(n));
    v2.segment<3>(L::X(n)) = R * v.segment<3>(L::X(n));
  }
  for (int s = 0; s < 5; ++s) {
    q2.segment<4>(L::P(s)) = lie::QuatMultiply(r, q.segment<4>(L::P(s)));
    v2.segment<4>(L::P(s)) = lie::QuatMultiply(r, v.segment<4>(L::P(s)));
  }
  Eigen::VectorXd a(model.size()), a2(model.size());
  model.Acceleration(q, v, a);
  model.Acceleration(q2, v2, a2);
  for (int n = 0; n <= 5; ++n)
    EXPECT_LT((a2.segment<3>(L::X(n)) - R * a.segment<3>(L::X(n))).norm(),
              1e-9 * (1 + a.segment<3>(L::X(n)).norm()));
  for (int s = 0; s < 5; ++s) {
    const Vec4 expect = lie::QuatMultiply(r, a.segment<4>(L::P(s)));
    EXPECT_LT((a2.segment<4>(L::P(s)) - expect).norm(), 1e-9 * (1 + expect.norm()));
  }
}

TEST(QuatFdModel, BadInputIsAClearError) {
  QuatFdOptions opt;
  opt.segments = 1;
  try {
    QuatFdModel model(RubberRod(0.5, false), lie::SE3(), opt);
    FAIL() << "accepted 1 segment";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("segments"), std::string::npos) << e.what();
  }
  opt.segments = 4;
  opt.tip_end = EndCondition::kClamped;
  opt.tip_rotation_W = 2.0 * Mat3::Identity();  // not a rotation
  EXPECT_THROW(QuatFdModel(RubberRod(0.5, false), lie::SE3(), opt), std::invalid_argument);
  opt.tip_end = EndCondition::kFree;
  opt.grid = {0, 0.2, 0.1, 0.3, 0.5};
  EXPECT_THROW(QuatFdModel(RubberRod(0.5, false), lie::SE3(), opt), std::invalid_argument);
  opt.grid.clear();
  // A tendon's pull is no load of this model: under tension it is refused, naming the tendon,
  // where it would otherwise leave the rod straight (the SE(3) solvers bend it).
  RodModel rod = RubberRod(0.5, false);
  rod.tendons.push_back(Tendon{"t0", TendonRoute::Parallel(Vec2(0.002, 0))});
  Actuation pulled;
  pulled.tendon_tension[0] = 1.0;
  try {
    QuatFdModel model(rod, lie::SE3(), opt, pulled);
    FAIL() << "accepted a tendon under tension";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("tendon_tension[0]"), std::string::npos) << e.what();
  }
  pulled.tendon_tension[1] = 1.0;  // a second tension on a rod of one tendon
  EXPECT_THROW(QuatFdModel(rod, lie::SE3(), opt, pulled), std::invalid_argument);
  // Slack, it carries nothing: the rod is the plain one.
  const QuatFdModel slack(rod, lie::SE3(), opt);
  // A state of the wrong size is an error, not a read past its end.
  Eigen::VectorXd q(10), v(slack.size());
  EXPECT_THROW(slack.RestState(q, v), std::invalid_argument);
  QuatFdModel model(RubberRod(0.5, false), lie::SE3(), opt);
  EXPECT_THROW(SolveStatics(&model, StaticLoads{}, q), std::invalid_argument);
}

}  // namespace
}  // namespace cosserat::quatfd
