#include "cosserat/assembly/assembly_statics.hpp"

#include <ceres/jet.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cosserat/lie/so3.hpp"

namespace cosserat {

namespace {

// A rod's 6 base unknowns, its length and the pose of the body its base is on.
using Jet13 = ceres::Jet<double, 13>;
using Jet6 = ceres::Jet<double, 6>;  // a body's pose increment [δp; δθ]

constexpr double kMinStep = 1.0 / 1024.0;  // the smallest continuation step: ten halvings
// Levenberg–Marquardt: retries with a larger damping before an iteration fails.
constexpr int kDampingRetries = 12;

}  // namespace

AssemblyStaticsSolver::AssemblyStaticsSolver(const Assembly& assembly,
                                             const AssemblyOptions& options)
    : assembly_(assembly), options_(options) {
  std::string why;
  if (!assembly_.IsValid(&why)) throw std::invalid_argument("Assembly: " + why);
  const int R = static_cast<int>(assembly_.rods.size());
  const int B = static_cast<int>(assembly_.bodies.size());
  // Every body's balance is measured in the force and moment scales of the assembly's most
  // compliant rod: a force left unbalanced on any body is carried through the structure to that
  // rod, where it moves the bodies most. (In a body's own stiffest rod's scale, the load at the
  // end of a stiff beam hanging off a soft column can fall below the tolerance before the first
  // iteration, and the unloaded frame pass as converged.)
  double force_scale = std::numeric_limits<double>::infinity(), moment_scale = force_scale;
  for (int i = 0; i < R; ++i) {
    const AssemblyRod& a = assembly_.rods[i];
    Rod rod{RodShot(a.model, a.nodes), 1.0, 1.0, {}};
    const double L = a.model.length, EI = rod.shot.bending_stiffness();
    rod.moment_scale = EI / L;
    rod.force_scale = EI / (L * L);
    force_scale = std::min(force_scale, rod.force_scale);
    moment_scale = std::min(moment_scale, rod.moment_scale);
    rods_.push_back(std::move(rod));
    lengths_.push_back(L);
  }
  body_force_scale_.assign(B, force_scale);
  body_moment_scale_.assign(B, moment_scale);
  for (const RigidBody& b : assembly_.bodies) poses_.push_back(b.pose);
  x_.setZero(6 * R);
  states_.resize(R);
}

template <typename T>
AssemblyStaticsSolver::Point<T> AssemblyStaticsSolver::BaseStart(int i, const Vector6<T>& x,
                                                                 const Vector3<T>& p_body,
                                                                 const Matrix3<T>& R_body) const {
  const AssemblyRod& a = assembly_.rods[i];
  const Rod& rod = rods_[i];
  Point<T> y;
  y.p = p_body + R_body * a.base.p.cast<T>();
  y.R = R_body * a.base.R.cast<T>();
  y.n = x.template tail<3>() * rod.force_scale;
  if (a.base_joint == BaseJoint::kClamped) {
    y.m = x.template head<3>() * rod.moment_scale;
  } else {  // spun by x0 about its tangent, no moment about it
    y.R = y.R * lie::SO3Exp<T>(Vector3<T>(T(0.0), T(0.0), x(0)));
    y.m = Vector3<T>(x(1) * rod.moment_scale, x(2) * rod.moment_scale, T(0.0));
  }
  return y;
}

AssemblyStaticsSolver::Point<double> AssemblyStaticsSolver::BaseStart(int i) const {
  const int b = assembly_.rods[i].base_body;
  const Vec6 x = x_.segment<6>(6 * i);
  return b < 0 ? BaseStart<double>(i, x, Vec3::Zero(), Mat3::Identity())
               : BaseStart<double>(i, x, poses_[b].p, poses_[b].R);
}

template <typename T>
Vector6<T> AssemblyStaticsSolver::TipResidual(int i, const Point<T>& tip, const Vector3<T>& p_b,
                                              const Matrix3<T>& R_b) const {
  const AssemblyRod& a = assembly_.rods[i];
  const Rod& rod = rods_[i];
  Vector6<T> e;
  if (a.tip_joint == TipJoint::kFree) {
    e.template head<3>() = tip.m / rod.moment_scale;
    e.template tail<3>() = tip.n / rod.force_scale;
    return e;
  }
  const Vector3<T> p_target = p_b + R_b * a.attachment.p.cast<T>();
  const Matrix3<T> R_target = R_b * a.attachment.R.cast<T>();
  e.template head<3>() = (tip.p - p_target) / a.model.length;
  switch (a.tip_joint) {
    case TipJoint::kClamped:
      e.template tail<3>() = lie::SO3Log<T>(Matrix3<T>(R_target.transpose() * tip.R));
      break;
    case TipJoint::kTorsionFree: {  // the tangents aligned, no moment about the tangent
      const Vector3<T> t = R_target.transpose() * tip.R.col(2);
      e(3) = t(0);
      e(4) = t(1);
      e(5) = tip.m(2) / rod.moment_scale;
      break;
    }
    case TipJoint::kPinned:
      e.template tail<3>() = tip.m / rod.moment_scale;
      break;
    case TipJoint::kFree:
      break;
  }
  return e;
}

template <typename T>
void AssemblyStaticsSolver::EndWrenchOnBody(const Point<T>& end, double sign,
                                            const Vector3<T>& p_b, Vector3<T>* f,
                                            Vector3<T>* m) const {
  // The internal wrench at s is what the part beyond s exerts on the part before it: at the
  // base (sign +1) the rod's pull on what holds it, at the tip (sign −1) the negative of the
  // body's pull on the rod. Moved to the body's origin.
  const Vector3<T> n_W = sign * (end.R * end.n);
  *f = n_W;
  *m = sign * (end.R * end.m) + (end.p - p_b).cross(n_W);
}

rhs::StaticTangent AssemblyStaticsSolver::StartTangent(int i, const Point<double>& start) const {
  const Rod& rod = rods_[i];
  rhs::StaticTangent d;
  d.p.setZero();
  for (auto& c : d.R) c.setZero();
  d.m.setZero();
  d.n.setZero();
  d.n.rightCols<3>() = rod.force_scale * Mat3::Identity();
  if (assembly_.rods[i].base_joint == BaseJoint::kClamped) {
    d.m.leftCols<3>() = rod.moment_scale * Mat3::Identity();
  } else {  // x0 spins the frame about its z: d(R e_j) = R (e_z × e_j)
    for (int j = 0; j < 3; ++j) d.R[j].col(0) = start.R * Vec3::UnitZ().cross(Vec3::Unit(j));
    d.m(0, 1) = rod.moment_scale;
    d.m(1, 2) = rod.moment_scale;
  }
  return d;
}

rhs::StaticTangent AssemblyStaticsSolver::BodyStartTangent(int i, const Point<double>& start) const {
  // p0 = p_b + R_b a, R0 = R_b Exp(δθ) A under p_b → p_b + δp, R_b → R_b Exp(δθ):
  // dp0 = δp − R_b [a]× δθ and d(R0 e_j) = −R_b [A e_j]× δθ, A e_j = R_bᵀ R0 e_j.
  const Mat3& R_b = poses_[assembly_.rods[i].base_body].R;
  rhs::StaticTangent d;
  d.p.leftCols<3>() = Mat3::Identity();
  d.p.rightCols<3>() = -R_b * lie::hat(Vec3(assembly_.rods[i].base.p));
  for (int j = 0; j < 3; ++j) {
    d.R[j].leftCols<3>().setZero();
    d.R[j].rightCols<3>() = -R_b * lie::hat(Vec3(R_b.transpose() * start.R.col(j)));
  }
  d.m.setZero();
  d.n.setZero();
  return d;
}

int AssemblyStaticsSolver::Unknowns() const {
  const int R = rod_count();
  return 6 * R + (mode_ == Mode::kForward ? 6 * static_cast<int>(poses_.size()) : R);
}

bool AssemblyStaticsSolver::ShootAll() {
  for (int i = 0; i < rod_count(); ++i) {
    rods_[i].tip = rods_[i].shot.Shoot<double>(BaseStart(i), lengths_[i]);
    if (!rods_[i].tip.p.allFinite() || !rods_[i].tip.n.allFinite()) return false;
  }
  return true;
}

void AssemblyStaticsSolver::Residual(const StaticLoads& loads, Eigen::VectorXd* r) const {
  const int R = rod_count(), B = static_cast<int>(poses_.size());
  r->setZero(6 * R + 6 * B);
  for (int b = 0; b < B; ++b) {
    const RigidBody& body = assembly_.bodies[b];
    r->segment<3>(6 * R + 6 * b) = body.mass * loads.gravity_W + body_load_factor_ * body.force_W;
    r->segment<3>(6 * R + 6 * b + 3) = body_load_factor_ * body.moment_W;
  }
  for (int i = 0; i < R; ++i) {
    const int b = assembly_.rods[i].body;
    const Vec3 p_b = b >= 0 ? poses_[b].p : Vec3::Zero();
    const Mat3 R_b = b >= 0 ? poses_[b].R : Mat3::Identity();
    r->segment<6>(6 * i) = TipResidual<double>(i, rods_[i].tip, p_b, R_b);
    if (const int bb = assembly_.rods[i].base_body; bb >= 0) {
      Vec3 f, m;
      EndWrenchOnBody<double>(BaseStart(i), 1.0, poses_[bb].p, &f, &m);
      r->segment<3>(6 * R + 6 * bb) += f;
      r->segment<3>(6 * R + 6 * bb + 3) += m;
    }
    if (b < 0) continue;
    Vec3 f, m;
    EndWrenchOnBody<double>(rods_[i].tip, -1.0, p_b, &f, &m);
    r->segment<3>(6 * R + 6 * b) += f;
    r->segment<3>(6 * R + 6 * b + 3) += m;
  }
  for (int b = 0; b < B; ++b) {
    r->segment<3>(6 * R + 6 * b) /= body_force_scale_[b];
    r->segment<3>(6 * R + 6 * b + 3) /= body_moment_scale_[b];
  }
}

void AssemblyStaticsSolver::Jacobian(const StaticLoads& loads, Eigen::MatrixXd* J,
                                     Eigen::MatrixXd* J_length) {
  (void)loads;  // the loads' derivatives in the unknowns are zero (dead loads)
  const int R = rod_count(), B = static_cast<int>(poses_.size());
  const int rows = 6 * R + 6 * B;
  J->setZero(rows, Unknowns());
  if (J_length) J_length->setZero(rows, R);
  for (int i = 0; i < R; ++i) AddRodColumns(i, J, J_length);
  if (mode_ != Mode::kForward) return;
  for (int b = 0; b < B; ++b) AddBodyColumns(b, J);
}

void AssemblyStaticsSolver::AddRodColumns(int i, Eigen::MatrixXd* J, Eigen::MatrixXd* J_length) {
  const int R = rod_count();
  const bool forward = mode_ == Mode::kForward;
  // The tip's derivatives: along the 6 base unknowns and the base body's pose exactly (tangent
  // shots), along the length by a forward difference (one more shot; its error, ~1e-7
  // relative, only slows Newton, whose residual is exact). Then the joints' algebra in Jet
  // arithmetic.
  const int bb = assembly_.rods[i].base_body;
  const bool on_body = forward && bb >= 0;
  const Point<double> start = BaseStart(i);
  rhs::StaticTangent dtip, dtip_body;
  const Point<double> tip_value =
      rods_[i].shot.ShootTangent(start, StartTangent(i, start), lengths_[i], &dtip);
  if (on_body)
    rods_[i].shot.ShootTangent(start, BodyStartTangent(i, start), lengths_[i], &dtip_body);
  const double dL = 1e-7 * lengths_[i];
  const Point<double> longer = rods_[i].shot.Shoot<double>(start, lengths_[i] + dL);
  auto lift = [&](double value, double longer_value, const auto& row_x, const auto& row_b) {
    Jet13 j(value);
    j.v.head<6>() = row_x.transpose();
    j.v[6] = (longer_value - value) / dL;
    if (on_body) j.v.tail<6>() = row_b.transpose();
    return j;
  };
  Point<Jet13> tip;
  for (int r = 0; r < 3; ++r) {
    tip.p(r) = lift(tip_value.p(r), longer.p(r), dtip.p.row(r), dtip_body.p.row(r));
    tip.m(r) = lift(tip_value.m(r), longer.m(r), dtip.m.row(r), dtip_body.m.row(r));
    tip.n(r) = lift(tip_value.n(r), longer.n(r), dtip.n.row(r), dtip_body.n.row(r));
    for (int c = 0; c < 3; ++c)
      tip.R(r, c) =
          lift(tip_value.R(r, c), longer.R(r, c), dtip.R[c].row(r), dtip_body.R[c].row(r));
  }
  auto put = [&](int row, const Jet13& value) {
    for (int k = 0; k < 6; ++k) (*J)(row, 6 * i + k) += value.v[k];
    if (!forward) (*J)(row, 6 * R + i) += value.v[6];
    if (J_length) (*J_length)(row, i) += value.v[6];
    if (on_body)
      for (int k = 0; k < 6; ++k) (*J)(row, 6 * R + 6 * bb + k) += value.v[7 + k];
  };
  const int b = assembly_.rods[i].body;
  const Vector3<Jet13> p_b = (b >= 0 ? poses_[b].p : Vec3::Zero()).cast<Jet13>();
  const Matrix3<Jet13> R_b = (b >= 0 ? poses_[b].R : Mat3::Identity()).cast<Jet13>();
  const Vector6<Jet13> e = TipResidual<Jet13>(i, tip, p_b, R_b);
  for (int r = 0; r < 6; ++r) put(6 * i + r, e(r));
  if (b >= 0) {
    Vector3<Jet13> f, m;
    EndWrenchOnBody<Jet13>(tip, -1.0, p_b, &f, &m);
    for (int r = 0; r < 3; ++r) {
      put(6 * R + 6 * b + r, f(r) / body_force_scale_[b]);
      put(6 * R + 6 * b + 3 + r, m(r) / body_moment_scale_[b]);
    }
  }
  if (bb < 0) return;
  // What the base exerts on its body, along the base unknowns and the body's pose.
  Vector6<Jet13> x;
  for (int k = 0; k < 6; ++k) x(k) = Jet13(x_(6 * i + k), k);
  Vector3<Jet13> dp, dth;
  for (int k = 0; k < 3; ++k) {
    dp(k) = on_body ? Jet13(0.0, 7 + k) : Jet13(0.0);
    dth(k) = on_body ? Jet13(0.0, 10 + k) : Jet13(0.0);
  }
  const Vector3<Jet13> p_bb = poses_[bb].p.cast<Jet13>() + dp;
  const Matrix3<Jet13> R_bb = poses_[bb].R.cast<Jet13>() * lie::SO3Exp<Jet13>(dth);
  Vector3<Jet13> f, m;
  EndWrenchOnBody<Jet13>(BaseStart<Jet13>(i, x, p_bb, R_bb), 1.0, p_bb, &f, &m);
  for (int r = 0; r < 3; ++r) {
    put(6 * R + 6 * bb + r, f(r) / body_force_scale_[bb]);
    put(6 * R + 6 * bb + 3 + r, m(r) / body_moment_scale_[bb]);
  }
}

void AssemblyStaticsSolver::AddBodyColumns(int b, Eigen::MatrixXd* J) {
  const int R = rod_count();
  Vector3<Jet6> dp, dth;
  for (int k = 0; k < 3; ++k) {
    dp(k) = Jet6(0.0, k);
    dth(k) = Jet6(0.0, 3 + k);
  }
  const Vector3<Jet6> p_b = poses_[b].p.cast<Jet6>() + dp;
  const Matrix3<Jet6> R_b = poses_[b].R.cast<Jet6>() * lie::SO3Exp<Jet6>(dth);
  const int col = 6 * R + 6 * b;
  for (int i = 0; i < R; ++i) {
    if (assembly_.rods[i].body != b) continue;
    const Point<double>& t = rods_[i].tip;
    const Point<Jet6> tip{t.p.cast<Jet6>(), t.R.cast<Jet6>(), t.m.cast<Jet6>(),
                          t.n.cast<Jet6>()};
    const Vector6<Jet6> e = TipResidual<Jet6>(i, tip, p_b, R_b);
    Vector3<Jet6> f, m;
    EndWrenchOnBody<Jet6>(tip, -1.0, p_b, &f, &m);
    for (int k = 0; k < 6; ++k) {
      for (int r = 0; r < 6; ++r) (*J)(6 * i + r, col + k) += e(r).v[k];
      for (int r = 0; r < 3; ++r) {
        (*J)(col + r, col + k) += f(r).v[k] / body_force_scale_[b];
        (*J)(col + 3 + r, col + k) += m(r).v[k] / body_moment_scale_[b];
      }
    }
  }
}

void AssemblyStaticsSolver::Apply(const Eigen::VectorXd& dz, double scale) {
  const int R = rod_count();
  x_ += scale * dz.head(6 * R);
  if (mode_ == Mode::kForward) {
    for (size_t b = 0; b < poses_.size(); ++b) {
      poses_[b].p += scale * dz.segment<3>(6 * R + 6 * b);
      poses_[b].R = poses_[b].R * lie::SO3Exp(Vec3(scale * dz.segment<3>(6 * R + 6 * b + 3)));
    }
  } else {
    for (int i = 0; i < R; ++i) lengths_[i] += scale * dz(6 * R + i);
  }
}

void AssemblyStaticsSolver::Store(Iterate* u) const {
  u->x = x_;  // assignments into buffers of the same size: no allocation after the first
  u->poses = poses_;
  u->lengths = lengths_;
}

void AssemblyStaticsSolver::Load(const Iterate& u) {
  x_ = u.x;
  poses_ = u.poses;
  lengths_ = u.lengths;
}

void AssemblyStaticsSolver::Conclude(bool converged, const StaticLoads& loads,
                                     const Iterate& start,
                                     std::chrono::steady_clock::time_point t0,
                                     AssemblySummary* summary) {
  if (converged) {
    has_solution_ = true;
    solved_loads_ = loads;
  } else if (has_solution_) {
    Load(start);  // back to the last solution, the next solve's start
  }
  states_dirty_ = true;
  summary->status = converged ? SolveStatus::kConverged : SolveStatus::kLoadSteppingFailed;
  summary->wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

bool AssemblyStaticsSolver::LevenbergMarquardt(const StaticLoads& loads,
                                               AssemblySummary* summary) {
  if (!shot_loads_set_ || !(loads == shot_loads_)) {  // the samples' loads, once per change
    for (Rod& rod : rods_) rod.shot.SetLoads(loads);
    shot_loads_ = loads;
    shot_loads_set_ = true;
  }
  if (!ShootAll()) return false;
  Residual(loads, &r_);
  double stall_floor = 0.0;
  const double tolerance = Tolerance(loads, &stall_floor);
  double norm = r_.norm(), damping = 0.0;
  bool fresh = false;  // the Jacobian is this state's (else the last one's, for chord steps)
  for (int it = 0; it < options_.max_iterations; ++it) {
    summary->residual = norm;
    if (norm < tolerance) return true;
    ++summary->iterations;
    // A quasi-Newton step with the inverse Jacobian of an earlier state, updated by Broyden's
    // rank-one formula after each step (a warm re-solve after a small change converges at a
    // fraction of the cost of new Jacobians), kept while it more than halves the residual.
    if (jacobian_mode_ == mode_ && !fresh) {
      dz_ = -(inverse_ * r_);
      const bool ok = TryStep(loads, norm);
      if (ok) {  // Broyden's good update of the inverse: H += (s − H y) sᵀH / (sᵀ H y)
        broyden_y_ = r_trial_ - r_;
        broyden_Hy_.noalias() = inverse_ * broyden_y_;
        const double denominator = dz_.dot(broyden_Hy_);
        if (std::abs(denominator) > 1e-12 * dz_.norm() * broyden_Hy_.norm()) {
          broyden_sH_.noalias() = inverse_.transpose() * dz_;  // (sᵀH)ᵀ
          broyden_y_ = (dz_ - broyden_Hy_) / denominator;
          inverse_.noalias() += broyden_y_ * broyden_sH_.transpose();
        }
        const bool enough = r_trial_.norm() < 0.5 * norm;
        r_.swap(r_trial_);
        norm = r_.norm();
        if (enough) continue;  // else it reduced the residual, just not enough: refresh
      }
    }
    Jacobian(loads, &J_, nullptr);
    ++summary->jacobians;
    lu_.compute(J_);
    inverse_ = lu_.inverse();
    jacobian_mode_ = mode_;
    fresh = true;
    bool accepted = false;
    for (int attempt = 0; attempt <= kDampingRetries && !accepted; ++attempt) {
      if (damping == 0.0) {  // a Newton step first
        dz_ = lu_.solve(-r_);
      } else {  // Levenberg–Marquardt: (JᵀJ + λ diag JᵀJ) dz = −Jᵀ r
        A_.noalias() = J_.transpose() * J_;
        A_.diagonal() += damping * (A_.diagonal().array() + 1e-12).matrix();
        dz_ = A_.ldlt().solve(-(J_.transpose() * r_));
      }
      accepted = TryStep(loads, norm, damping == 0.0);
      if (accepted) {
        damping = damping < 3e-8 ? 0.0 : damping / 3.0;
      } else {
        damping = damping == 0.0 ? 1e-6 : 4.0 * damping;
      }
    }
    if (!accepted) {  // stalled: converged only if within what the rods resolve
      ShootAll();
      summary->residual = norm;
      return norm < stall_floor;
    }
    r_.swap(r_trial_);
    norm = r_.norm();
    fresh = damping != 0.0;  // after a Newton step, try chord steps with this Jacobian
  }
  summary->residual = norm;
  return norm < stall_floor;  // out of iterations: as stalled
}

const RodState& AssemblyStaticsSolver::rod_state(int i) {
  if (states_dirty_) RecordStates();
  return states_[i];
}

void AssemblyStaticsSolver::RecordStates() {
  states_dirty_ = false;
  for (int i = 0; i < rod_count(); ++i) {
    rods_[i].shot.Record(BaseStart(i), lengths_[i], &states_[i]);
  }
}

bool AssemblyStaticsSolver::JumpedFrom(const Iterate& from) const {
  // A body that turns by more than ~30° or moves by more than a quarter of the shortest rod in
  // one solve has left the branch the loads follow: a plate on taut wires, pushed sideways,
  // came back "converged" turned 125° and above its wires' clamps. Smaller load steps follow a
  // real large motion.
  if (mode_ != Mode::kForward) return false;  // the poses are given
  constexpr double kMaxTurn = 0.5;   // rad
  constexpr double kMaxMove = 0.25;  // of the shortest rod
  const double reach = kMaxMove * *std::min_element(lengths_.begin(), lengths_.end());
  for (size_t b = 0; b < poses_.size(); ++b) {
    const double turn = lie::SO3Log(Mat3(from.poses[b].R.transpose() * poses_[b].R)).norm();
    if (turn > kMaxTurn || (poses_[b].p - from.poses[b].p).norm() > reach) return true;
  }
  return false;
}

bool AssemblyStaticsSolver::HasBodyForces() const {
  return std::any_of(assembly_.bodies.begin(), assembly_.bodies.end(), [](const RigidBody& b) {
    return b.force_W.squaredNorm() > 0 || b.moment_W.squaredNorm() > 0;
  });
}

template <typename At>
double AssemblyStaticsSolver::Follow(const At& at, AssemblySummary* summary) {
  double mu = 0.0, step = 1.0;
  int levels = 0;
  Iterate accepted;
  while (mu < 1.0 && step >= kMinStep && levels < options_.max_load_steps) {
    Store(&accepted);
    const double trial = std::min(1.0, mu + step);
    ++levels;
    const StaticLoads loads = at(trial);
    if (LevenbergMarquardt(loads, summary) && !JumpedFrom(accepted)) {
      mu = trial;
      step *= 2.0;
    } else {
      Load(accepted);
      step *= 0.5;
    }
  }
  summary->load_steps += levels;
  return mu;
}

AssemblySummary AssemblyStaticsSolver::Solve(const StaticLoads& loads,
                                             const std::vector<double>& lengths) {
  const auto t0 = std::chrono::steady_clock::now();
  AssemblySummary summary;
  std::vector<double> target = lengths;
  if (target.empty())
    for (const AssemblyRod& a : assembly_.rods) target.push_back(a.model.length);
  if (static_cast<int>(target.size()) != rod_count())
    throw std::invalid_argument("AssemblyStaticsSolver::Solve: " + std::to_string(target.size()) +
                                " lengths for " + std::to_string(rod_count()) + " rods");
  bool valid = loads.IsValid(nullptr);
  for (double L : target) valid = valid && std::isfinite(L) && L > 0;
  if (!valid) {
    summary.status = SolveStatus::kNonFinite;
    return summary;
  }
  mode_ = Mode::kForward;
  // The start: the last solution, else the rods unloaded at the model's lengths.
  const StaticLoads start_loads = has_solution_ ? solved_loads_ : loads.Scaled(0.0);
  const double start_body_loads = has_solution_ ? 1.0 : 0.0;
  Iterate start;
  Store(&start);
  // Directly at the target first.
  lengths_ = target;
  bool converged = LevenbergMarquardt(loads, &summary) && !JumpedFrom(start);
  if (!converged) {
    Load(start);
    // From the unloaded structure, the weights come first and the bodies' applied forces and
    // moments after them: slack wires have no lateral stiffness, and a plate pushed sideways
    // while its wires took up their load wandered off to a branch above their clamps.
    const bool forces_last = !has_solution_ && HasBodyForces();
    auto at = [&](double mu) {
      for (int i = 0; i < rod_count(); ++i)
        lengths_[i] = start.lengths[i] + mu * (target[i] - start.lengths[i]);
      body_load_factor_ =
          forces_last ? 0.0 : start_body_loads + mu * (1.0 - start_body_loads);
      return mu == 1.0 ? loads : StaticLoads::Blend(start_loads, loads, mu);
    };
    if (!has_solution_) {  // the unloaded structure at the start lengths first
      at(0.0);
      converged = LevenbergMarquardt(start_loads, &summary);
    } else {
      converged = true;
    }
    summary.load_fraction = converged ? Follow(at, &summary) : 0.0;
    if (forces_last && summary.load_fraction == 1.0) {
      auto forces = [&](double mu) {
        body_load_factor_ = mu;
        return loads;
      };
      summary.load_fraction = Follow(forces, &summary);
    }
    converged = converged && summary.load_fraction == 1.0;
    body_load_factor_ = 1.0;
  }
  Conclude(converged, loads, start, t0, &summary);
  return summary;
}

AssemblySummary AssemblyStaticsSolver::SolveLengths(const StaticLoads& loads,
                                                    const std::vector<lie::SE3>& poses) {
  const auto t0 = std::chrono::steady_clock::now();
  if (rod_count() != 6 * static_cast<int>(poses_.size()) || poses.size() != poses_.size())
    throw std::invalid_argument(
        "AssemblyStaticsSolver::SolveLengths: needs six rods per body and one pose per body");
  AssemblySummary summary;
  mode_ = Mode::kInverse;
  const StaticLoads start_loads = has_solution_ ? solved_loads_ : loads;
  Iterate start;
  Store(&start);
  poses_ = poses;
  bool converged = LevenbergMarquardt(loads, &summary);
  const bool followed = !converged && has_solution_;
  if (followed) {  // follow the poses from the last solution
    Load(start);
    auto at = [&](double mu) {
      for (size_t b = 0; b < poses_.size(); ++b) {
        const lie::SE3& from = start.poses[b];
        poses_[b].p = from.p + mu * (poses[b].p - from.p);
        const Vec3 turn = lie::SO3Log(Mat3(from.R.transpose() * poses[b].R));
        poses_[b].R = from.R * lie::SO3Exp(Vec3(mu * turn));
      }
      return mu == 1.0 ? loads : StaticLoads::Blend(start_loads, loads, mu);
    };
    summary.load_fraction = Follow(at, &summary);
    converged = summary.load_fraction == 1.0;
  }
  // A root with a rod of zero or negative length (the robot's mirror image through its base) is
  // no robot: out of reach. So is a stall with rods shrunk to nothing (a pose on the base plate).
  bool reachable = true;
  for (size_t i = 0; i < lengths_.size(); ++i)
    reachable = reachable && lengths_[i] > 1e-9 * assembly_.rods[i].model.length;
  Conclude(converged && reachable, loads, start, t0, &summary);
  if (!reachable) summary.status = SolveStatus::kOutOfReach;
  else if (!converged && !followed) summary.status = SolveStatus::kMaxIterations;  // no stepping
  return summary;
}

Eigen::MatrixXd AssemblyStaticsSolver::PoseJacobian(int body, const StaticLoads& loads) {
  if (!has_solution_ || body < 0 || body >= static_cast<int>(poses_.size()))
    return Eigen::MatrixXd();
  mode_ = Mode::kForward;
  ShootAll();
  Eigen::MatrixXd J, J_length;
  Jacobian(loads, &J, &J_length);
  const Eigen::MatrixXd dz = J.partialPivLu().solve(-J_length);
  return dz.middleRows(6 * rod_count() + 6 * body, 6);
}

}  // namespace cosserat
