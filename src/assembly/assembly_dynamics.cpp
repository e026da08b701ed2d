#include "cosserat/assembly/assembly_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cosserat/lie/so3.hpp"
#include "cosserat/rod/section_profile.hpp"

namespace cosserat {

namespace {

using Coefficients = Bdf2ShootingStepper::Coefficients;

// Forward-difference step of the Jacobian, in the scaled unknowns (positions over the body's
// length scale, rotations in rad): above the rods' solve noise (their tolerance, 1e-11 by
// default, makes the balance noisy at that level: ~1e-3 of a difference) and small against the
// nonlinearity. Axially a rod is stiff: 1e-6 L moved a 4 mm steel wire's tension by 2.5 N of its
// 25, and its own Newton solve from the last equilibrium then failed.
constexpr double kDifferenceStep = 1e-8;
// A Newton step below this (positions over the length scale, rotations in rad) ends a solve
// whose balance is within kNoiseAllowance of the tolerance: the rods' noise, not the poses.
constexpr double kPoseResolution = 1e-10;
constexpr double kNoiseAllowance = 1e4;
// A Newton step a fresh Jacobian cannot make reduce a balance within kNoiseAllowance of the
// tolerance ends the solve below this (the scaled unknowns of kPoseResolution): the rods' noise.
constexpr double kStallStep = 1e-6;
// Backtracking halvings of a Newton step whose balance grows, before the Jacobian is renewed.
constexpr int kBacktracks = 4;

TipHold HoldOf(TipJoint joint) {
  switch (joint) {
    case TipJoint::kClamped:
      return TipHold::kClamped;
    case TipJoint::kTorsionFree:
      return TipHold::kTorsionFree;
    case TipJoint::kPinned:
      return TipHold::kPinned;
    case TipJoint::kFree:
      break;
  }
  return TipHold::kFree;
}

// The wrench a rod end puts on what holds it, moved to the point o (world): at the base (sign +1)
// the internal wrench there, at the tip (sign −1) its negative (AssemblyStaticsSolver's rule).
void EndWrench(const RodState& state, int node, double sign, const Vec3& o, Vec3* f, Vec3* m) {
  const Mat3& R = state.rotation_WB[node];
  const Vec3 n_W = sign * (R * state.wrench_B[node].tail<3>());
  *f += n_W;
  *m += sign * (R * state.wrench_B[node].head<3>()) + (state.position_W[node] - o).cross(n_W);
}

}  // namespace

AssemblyDynamics::AssemblyDynamics(const Assembly& assembly,
                                   const AssemblyDynamicsOptions& options)
    : assembly_(assembly), options_(options) {
  std::string why;
  if (!assembly_.IsValid(&why)) throw std::invalid_argument("Assembly: " + why);
  if (!(std::isfinite(options_.dt) && options_.dt > 0))
    throw std::invalid_argument("AssemblyDynamics: dt must be a finite positive number");
  if (!(options_.tolerance > 0) || options_.max_iterations < 1)
    throw std::invalid_argument("AssemblyDynamics: tolerance and max_iterations must be positive");
  Bdf2Options rod_options = options_.rod;
  rod_options.dt = options_.dt;
  rod_options.max_halvings = 0;
  rod_options.ends = EndConditions::kCantilever;
  rod_options.tip_mass = 0.0;
  rod_options.tip_inertia_B.setZero();
  if (!rod_options.IsValid(&why)) throw std::invalid_argument("AssemblyDynamics: rod: " + why);

  const int B = static_cast<int>(assembly_.bodies.size());
  bodies_.resize(B);
  for (Body& b : bodies_) {
    b.force_scale = b.moment_scale = 0.0;
    b.length_scale = std::numeric_limits<double>::infinity();
  }
  for (size_t i = 0; i < assembly_.rods.size(); ++i) {
    const AssemblyRod& a = assembly_.rods[i];
    if (a.base_joint != BaseJoint::kClamped)
      throw std::invalid_argument("rods[" + std::to_string(i) + "] (" + a.name +
                                  ").base_joint: dynamics needs a clamped base");
    rods_.push_back(std::make_unique<Bdf2ShootingStepper>(a.model, a.nodes, rod_options));
    const SectionProperties p = a.model.section->At(0.0, Actuation{});
    const double EI = p.max_bending_stiffness(), L = a.model.length;
    for (int b : {a.body, a.base_body}) {
      if (b < 0) continue;
      bodies_[b].force_scale = std::max(bodies_[b].force_scale, EI / (L * L));
      bodies_[b].moment_scale = std::max(bodies_[b].moment_scale, EI / L);
      bodies_[b].length_scale = std::min(bodies_[b].length_scale, L);
    }
  }
  for (int b = 0; b < B; ++b) {
    if (!(bodies_[b].force_scale > 0))
      throw std::invalid_argument("bodies[" + std::to_string(b) + "] (" +
                                  assembly_.bodies[b].name + "): no rod holds it");
    bodies_[b].now.pose = bodies_[b].before.pose = bodies_[b].trial.pose = assembly_.bodies[b].pose;
  }
  accepted_.resize(rods_.size());
  base_wrench_guess_.assign(rods_.size(), Vec6::Zero());
}

void AssemblyDynamics::SetBodyLoad(int b, const Vec3& force_W, const Vec3& moment_W) {
  assembly_.bodies.at(b).force_W = force_W;
  assembly_.bodies.at(b).moment_W = moment_W;
}

void AssemblyDynamics::SetTrialPoses(const Eigen::VectorXd& z, const std::vector<lie::SE3>& from,
                                     const Coefficients& c, bool statics) {
  for (size_t b = 0; b < bodies_.size(); ++b) {
    Body& body = bodies_[b];
    Kinematics& k = body.trial;
    k.pose.p = from[b].p + body.length_scale * z.segment<3>(6 * b);
    k.pose.R = from[b].R * lie::SO3Exp(Vec3(z.segment<3>(6 * b + 3)));
    if (statics) {
      k.velocity_W.setZero();
      k.omega_B.setZero();
      continue;
    }
    const Kinematics &k1 = body.now, &k2 = body.before;
    k.velocity_W = c.c0 * k.pose.p + c.c1 * k1.pose.p + c.c2 * k2.pose.p;
    // Local coordinates of the older frames about the new one, Log(Rᵀ R_k) ≈ (t_k − t) ω.
    k.omega_B = c.c1 * lie::SO3Log(Mat3(k.pose.R.transpose() * k1.pose.R)) +
                c.c2 * lie::SO3Log(Mat3(k.pose.R.transpose() * k2.pose.R));
  }
}

StepInput AssemblyDynamics::RodInput(int i, const StaticLoads& loads) const {
  const AssemblyRod& a = assembly_.rods[i];
  StepInput in;
  in.loads = loads;
  in.loads.tip_force.setZero();  // the bodies carry the point loads
  in.loads.tip_moment.setZero();
  if (a.base_body < 0) {
    in.base_pose = a.base;
  } else {
    const Kinematics& k = bodies_[a.base_body].trial;
    in.base_pose = lie::Compose(k.pose, a.base);
    // The twist of the base frame riding on the body: ω and the velocity of its origin.
    const Vec3 v_B = k.pose.R.transpose() * k.velocity_W + k.omega_B.cross(a.base.p);
    in.base_twist_B << a.base.R.transpose() * k.omega_B, a.base.R.transpose() * v_B;
  }
  if (a.body >= 0) {
    in.tip_hold = HoldOf(a.tip_joint);
    in.tip_pose = lie::Compose(bodies_[a.body].trial.pose, a.attachment);
  }
  return in;
}

bool AssemblyDynamics::Balance(const StaticLoads& loads, const Coefficients& c, bool statics,
                               Eigen::VectorXd* r) {
  for (size_t i = 0; i < rods_.size(); ++i) {
    const StepInput in = RodInput(static_cast<int>(i), loads);
    StepSummary s;
    if (statics) {
      if (statics_states_.empty()) {
        s = rods_[i]->InitializeAtRest(in, &base_wrench_guess_[i]);
      } else {
        // From the rod's last equilibrium (the poses move little between the balances of a
        // solve), or the statics solver's before the first.
        const RodState last = rods_[i]->state();
        s = rods_[i]->InitializeAtRest(
            in, last.wrench_B.front().allFinite() ? last : statics_states_[i]);
      }
    } else {
      rods_[i]->Restore(accepted_[i]);
      s = rods_[i]->Step(in);
    }
    if (!s.converged()) {
      failed_rod_ = static_cast<int>(i);
      failed_rod_summary_ = s;
      return false;
    }
  }
  const int B = static_cast<int>(bodies_.size());
  r->resize(6 * B);
  for (int b = 0; b < B; ++b) {
    const RigidBody& rb = assembly_.bodies[b];
    const Body& body = bodies_[b];
    const Kinematics& k = body.trial;
    Vec3 f = rb.mass * loads.gravity_W + rb.force_W, m = rb.moment_W;
    for (size_t i = 0; i < rods_.size(); ++i) {
      const AssemblyRod& a = assembly_.rods[i];
      const RodState& state = rods_[i]->state();
      if (a.base_body == b) EndWrench(state, 0, 1.0, k.pose.p, &f, &m);
      if (a.body == b) EndWrench(state, state.size() - 1, -1.0, k.pose.p, &f, &m);
    }
    Vec3 inertial_force = Vec3::Zero(), inertial_moment_B = Vec3::Zero();
    if (!statics) {
      const Kinematics &k1 = body.now, &k2 = body.before;
      const Vec3 a_W = c.c0 * k.velocity_W + c.c1 * k1.velocity_W + c.c2 * k2.velocity_W;
      const Vec3 alpha = c.c0 * k.omega_B + c.c1 * k1.omega_B + c.c2 * k2.omega_B;
      inertial_force = rb.mass * a_W;
      inertial_moment_B = rb.inertia_B * alpha + k.omega_B.cross(rb.inertia_B * k.omega_B);
    }
    r->segment<3>(6 * b) = (inertial_force - f) / body.force_scale;
    r->segment<3>(6 * b + 3) =
        (inertial_moment_B - k.pose.R.transpose() * m) / body.moment_scale;
  }
  return r->allFinite();
}

bool AssemblyDynamics::RenewJacobian(const StaticLoads& loads, const std::vector<lie::SE3>& from,
                                     const Coefficients& c, bool statics,
                                     const Eigen::VectorXd& z, const Eigen::VectorXd& r) {
  const Eigen::Index n = z.size();
  Eigen::MatrixXd J(n, n);
  Eigen::VectorXd zp = z, rp;
  for (Eigen::Index j = 0; j < n; ++j) {
    zp(j) = z(j) + kDifferenceStep;
    SetTrialPoses(zp, from, c, statics);
    if (!Balance(loads, c, statics, &rp)) return false;
    J.col(j) = (rp - r) / kDifferenceStep;
    zp(j) = z(j);
  }
  lu_.compute(J);
  jacobian_c0_ = c.c0;
  jacobian_statics_ = statics;
  return std::abs(lu_.determinant()) > 0;
}

bool AssemblyDynamics::Solve(const StaticLoads& loads, const std::vector<lie::SE3>& from,
                             const Coefficients& c, bool statics, AssemblySummary* summary) {
  const Eigen::Index n = 6 * static_cast<Eigen::Index>(bodies_.size());
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n), r, r_trial;
  SetTrialPoses(z, from, c, statics);
  if (!Balance(loads, c, statics, &r)) return false;
  // A Jacobian computed for other weights (or the other problem) is not reused.
  bool fresh = false;
  if (jacobian_statics_ != statics || jacobian_c0_ != c.c0) jacobian_c0_ = -1.0;
  for (int it = 0; it < options_.max_iterations; ++it) {
    summary->residual = r.norm();
    if (summary->residual < options_.tolerance) return true;
    if (jacobian_c0_ < 0) {
      // RenewJacobian leaves the rods at perturbed poses: Balance at z puts them back.
      if (!RenewJacobian(loads, from, c, statics, z, r)) return false;
      ++summary->jacobians;
      fresh = true;
      SetTrialPoses(z, from, c, statics);
      if (!Balance(loads, c, statics, &r)) return false;
    }
    ++summary->iterations;
    const Eigen::VectorXd dz = -lu_.solve(r);
    // The poses are resolved to round-off: what is left of the balance is the rods' solve
    // noise times their axial stiffness (a held end's position error of 1e-13 L is a force
    // of EA 1e-12, 1e-6 of EI/L² for a rod of L/r = 500, which 1e-10 L of pose balances).
    if (dz.lpNorm<Eigen::Infinity>() < kPoseResolution &&
        summary->residual < kNoiseAllowance * options_.tolerance)
      return true;
    double step = 1.0;
    bool better = false;
    for (int k = 0; k <= kBacktracks; ++k, step *= 0.5) {
      SetTrialPoses(z + step * dz, from, c, statics);
      better = Balance(loads, c, statics, &r_trial) && r_trial.norm() < summary->residual;
      if (better) break;
    }
    if (better) {
      z += step * dz;
      r = r_trial;
      fresh = false;
      continue;
    }
    // Back at z, the best iterate (the rods and bodies hold the last trial's state).
    SetTrialPoses(z, from, c, statics);
    if (!Balance(loads, c, statics, &r)) return false;
    // A new Jacobian could not reduce the balance: converged when it is down to the rods' noise
    // as for a step below kPoseResolution, with a step below kStallStep (an L-frame's end mass
    // swinging through its rest position stalls at balances up to 8.4e-7, steps up to 4.3e-8);
    // failed otherwise.
    if (fresh)
      return summary->residual < kNoiseAllowance * options_.tolerance &&
             dz.lpNorm<Eigen::Infinity>() < kStallStep;
    jacobian_c0_ = -1.0;  // an old one: renew it and try again from z
  }
  summary->residual = r.norm();
  return summary->residual < options_.tolerance;
}

AssemblySummary AssemblyDynamics::InitializeAtRest(const StaticLoads& loads) {
  const auto t0 = std::chrono::steady_clock::now();
  AssemblySummary summary;
  initialized_ = false;
  failed_rod_ = -1;
  std::vector<lie::SE3> from;
  for (const RigidBody& b : assembly_.bodies) from.push_back(b.pose);
  const bool held = std::any_of(assembly_.rods.begin(), assembly_.rods.end(),
                                [](const AssemblyRod& a) { return a.base_body < 0; });
  statics_states_.clear();
  if (held) {
    // The shooting solver of statics (continuation included) gives the poses and the rods'
    // base wrenches; the steppers' equations then differ from its only by round-off.
    AssemblyStaticsSolver statics(assembly_, options_.statics);
    summary = statics.Solve(loads);
    if (!summary.converged()) return summary;
    from = statics.body_poses();
    for (size_t i = 0; i < rods_.size(); ++i) {
      const RodState& s = statics.rod_state(static_cast<int>(i));
      base_wrench_guess_[i] = s.wrench_B.front();
      statics_states_.push_back(s);
    }
  }
  summary.status = SolveStatus::kMaxIterations;
  if (Solve(loads, from, Coefficients{}, true, &summary)) {
    summary.status = SolveStatus::kConverged;
    for (size_t i = 0; i < rods_.size(); ++i) accepted_[i] = rods_[i]->Save();
    for (Body& b : bodies_) b.now = b.before = b.trial;
    time_ = last_dt_ = 0.0;
    initialized_ = true;
  }
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

AssemblySummary AssemblyDynamics::Step(const StaticLoads& loads) {
  const auto t0 = std::chrono::steady_clock::now();
  AssemblySummary summary;
  if (!initialized_) return summary;  // kNotRun
  failed_rod_ = -1;
  const double h = options_.dt;
  const Coefficients c = Bdf2ShootingStepper::Weights(h, last_dt_, options_.rod.first_step);
  // Start from the poses the last velocities reach.
  std::vector<lie::SE3> from;
  for (const Body& b : bodies_) {
    lie::SE3 g;
    g.p = b.now.pose.p + h * b.now.velocity_W;
    g.R = b.now.pose.R * lie::SO3Exp(Vec3(h * b.now.omega_B));
    from.push_back(g);
  }
  summary.status = SolveStatus::kMaxIterations;
  if (Solve(loads, from, c, false, &summary)) {
    summary.status = SolveStatus::kConverged;
    for (size_t i = 0; i < rods_.size(); ++i) accepted_[i] = rods_[i]->Save();
    for (Body& b : bodies_) {
      b.before = b.now;
      b.now = b.trial;
    }
    time_ += h;
    last_dt_ = h;
  } else {
    for (size_t i = 0; i < rods_.size(); ++i) rods_[i]->Restore(accepted_[i]);
  }
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

AssemblyMomentum AssemblyDynamics::Momentum() const {
  AssemblyMomentum total;
  for (const auto& rod : rods_) {
    const RodMomentum m = rod->Momentum();
    total.linear_W += m.linear_W;
    total.angular_W += m.angular_W;
  }
  for (size_t b = 0; b < bodies_.size(); ++b) {
    const RigidBody& rb = assembly_.bodies[b];
    const Kinematics& k = bodies_[b].now;
    const Vec3 P = rb.mass * k.velocity_W;
    total.linear_W += P;
    total.angular_W += k.pose.p.cross(P) + k.pose.R * (rb.inertia_B * k.omega_B);
  }
  return total;
}

double AssemblyDynamics::Energy(const StaticLoads& loads) const {
  double e = 0.0;
  for (const auto& rod : rods_) e += rod->Energy(loads).total();
  for (size_t b = 0; b < bodies_.size(); ++b) {
    const RigidBody& rb = assembly_.bodies[b];
    const Kinematics& k = bodies_[b].now;
    e += 0.5 * rb.mass * k.velocity_W.squaredNorm() +
         0.5 * k.omega_B.dot(rb.inertia_B * k.omega_B) - rb.mass * loads.gravity_W.dot(k.pose.p);
  }
  return e;
}

}  // namespace cosserat
