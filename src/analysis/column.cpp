#include "cosserat/analysis/column.hpp"

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cosserat/lie/so3.hpp"
#include "cosserat/loads/obstacle_core.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/strong/load_parameter.hpp"
#include "cosserat/strong/morse_index.hpp"
#include "cosserat/strong/pinned_base.hpp"

namespace cosserat {

const char* ToString(ColumnEnds ends) {
  switch (ends) {
    case ColumnEnds::kClampedFree:
      return "cantilever";
    case ColumnEnds::kPinnedPinned:
      return "pinned-pinned";
    case ColumnEnds::kClampedClamped:
      return "clamped-clamped";
    case ColumnEnds::kClampedPinned:
      return "clamped-pinned";
  }
  return "unknown";
}

StaticMultipleShootingOptions MultipleShootingOptionsFor(ColumnEnds ends) {
  StaticMultipleShootingOptions o;
  o.base_pinned = ends == ColumnEnds::kPinnedPinned;
  o.tip_guided = ends != ColumnEnds::kClampedFree;
  o.tip_clamped = ends == ColumnEnds::kClampedClamped;
  return o;
}

double EulerLoadCoefficient(ColumnEnds ends) {
  switch (ends) {
    case ColumnEnds::kClampedFree:
      return 2.4674;  // π²/4
    case ColumnEnds::kPinnedPinned:
      return 9.8696;  // π²
    case ColumnEnds::kClampedPinned:
      return 20.19;  // 4.4934², the root of tan x = x
    case ColumnEnds::kClampedClamped:
      return 39.478;  // 4π²
  }
  return 0.0;
}

bool ParseColumnEnds(const std::string& name, ColumnEnds* ends) {
  for (ColumnEnds e : {ColumnEnds::kClampedFree, ColumnEnds::kPinnedPinned,
                       ColumnEnds::kClampedClamped, ColumnEnds::kClampedPinned}) {
    if (name == ToString(e)) {
      *ends = e;
      return true;
    }
  }
  return false;
}

namespace {

// Rows of a StateTangent.
constexpr int kP = 0, kR = 3, kM = 12, kN = 15;

Eigen::Matrix<double, 3, 6> RotationColumn(const ColumnSolver::StateTangent& T, int j) {
  return T.middleRows<3>(kR + 3 * j);
}

}  // namespace

ColumnSolver::ColumnSolver(const RodModel& model, int num_nodes, ColumnEnds ends,
                           const StaticShootingOptions& options, const Actuation& actuation)
    : shooter_(model, num_nodes, options, actuation),
      ends_(ends),
      options_(options),
      model_(model) {
  const SectionProperties p = model.section->At(0.0, actuation);
  const double EI = p.max_bending_stiffness();
  const double L = model.length;
  scale_ << EI / L, EI / L, EI / L, EI / (L * L), EI / (L * L), EI / (L * L);
  ForgetState();
}

void ColumnSolver::ForgetState() {
  state_ = RodState{};
  state_.Resize(static_cast<int>(shooter_.grid().size()));
  for (int i = 0; i < state_.size(); ++i) state_.s[i] = shooter_.grid()[i];
}

void ColumnSolver::Start(const lie::SE3& base, const Vec6& u, lie::SE3* start, Vec6* W0,
                         StateTangent* dstart, bool for_index) const {
  dstart->setZero();
  start->p = base.p;
  if (ends_ == ColumnEnds::kPinnedPinned) {
    // R(0) = R_WB Exp(θ), θ = [u₀, u₁, 0]; d R(0) = R(0) (J_r(θ) dθ)^.
    const Vec3 theta(u(0), u(1), 0.0);
    start->R = base.R * lie::SO3Exp(theta);
    const Mat3 Jr = lie::SO3RightJacobian(theta);
    for (int k = 0; k < 2; ++k) {
      const Vec3 w = Jr.col(k);
      for (int j = 0; j < 3; ++j)
        dstart->block<3, 1>(kR + 3 * j, k) = start->R * w.cross(Vec3::Unit(j));
    }
    *W0 << 0.0, 0.0, scale_(2) * u(2), scale_.tail<3>().cwiseProduct(u.tail<3>());
    if (for_index)
      dstart->block<3, 1>(kM, 2) = scale_(2) * PinnedTwistAxis(u(0), u(1));
    else
      (*dstart)(kM + 2, 2) = scale_(2);
  } else {
    start->R = base.R;
    *W0 = scale_.cwiseProduct(u);
    for (int k = 0; k < 3; ++k) (*dstart)(kM + k, k) = scale_(k);
  }
  for (int k = 3; k < 6; ++k) (*dstart)(kN + k - 3, k) = scale_(k);
}

Vec6 ColumnSolver::UnknownsOf(const lie::SE3& base, const Mat3& R0, const Vec6& W0) const {
  Vec6 u = W0.cwiseQuotient(scale_);
  if (ends_ == ColumnEnds::kPinnedPinned)
    u.head<2>() = lie::SO3Log(Mat3(base.R.transpose() * R0)).head<2>();  // θ₃ = 0 by the pin
  return u;
}

Vec6 ColumnSolver::Residual(const lie::SE3& base, const StaticLoads& loads, const Vec6& u, Mat6* J,
                            RodState* record, std::vector<StateTangent>* tangents) const {
  lie::SE3 start;
  Vec6 W0;
  StateTangent dstart;
  Start(base, u, &start, &W0, &dstart);
  RodState local;
  RodState* rec = record ? record : &local;
  const StateTangent T = shooter_.ShootTangent(start, loads, W0, dstart, rec, tangents);
  return TipResidual(base, loads, *rec, T, J);
}

Vec6 ColumnSolver::TipResidual(const lie::SE3& base, const StaticLoads& loads,
                               const RodState& record, const StateTangent& T, Mat6* J) const {
  const Mat3& R = record.rotation_WB.back();
  const Vec3& p = record.position_W.back();
  const Vec3 m = record.wrench_B.back().head<3>();
  const Vec3 n = record.wrench_B.back().tail<3>();
  const double L = length();
  const Eigen::Matrix<double, 3, 6> dp = T.middleRows<3>(kP), dm = T.middleRows<3>(kM),
                                    dn = T.middleRows<3>(kN);
  // The tip wrench: its dead part (world) turns relative to the tip section, its follower part
  // (tip body frame) does not.
  const SplitWrench tip = TotalTipWrench(loads);
  const Vec3 moment_dead = tip.dead_W.head<3>(), moment_follower = tip.follower_B.head<3>();
  const Vec3 force_dead = tip.dead_W.tail<3>(), force_follower = tip.follower_B.tail<3>();
  // d(Rᵀ v) for a fixed world vector v: row j is v · d(R e_j).
  auto transpose_times = [&](const Vec3& v) {
    Eigen::Matrix<double, 3, 6> out;
    for (int j = 0; j < 3; ++j) out.row(j) = v.transpose() * RotationColumn(T, j);
    return out;
  };
  // d(R v) for a fixed body vector v.
  auto times = [&](const Vec3& v) {
    Eigen::Matrix<double, 3, 6> out = Eigen::Matrix<double, 3, 6>::Zero();
    for (int j = 0; j < 3; ++j) out += v(j) * RotationColumn(T, j);
    return out;
  };

  Vec6 r;
  Mat6 dr;
  // Moment balance at a free or pinned tip: m(L) = M_tip in the tip body frame.
  auto moment_rows = [&]() {
    r.head<3>() = (m - (R.transpose() * moment_dead + moment_follower)).cwiseQuotient(scale_.head<3>());
    dr.topRows<3>() = dm - transpose_times(moment_dead);
    dr.topRows<3>() = scale_.head<3>().cwiseInverse().asDiagonal() * dr.topRows<3>();
  };

  if (ends_ == ColumnEnds::kClampedFree) {
    moment_rows();
    r.tail<3>() = (n - (R.transpose() * force_dead + force_follower)).cwiseQuotient(scale_.tail<3>());
    dr.bottomRows<3>() = dn - transpose_times(force_dead);
    dr.bottomRows<3>() = scale_.tail<3>().cwiseInverse().asDiagonal() * dr.bottomRows<3>();
  } else {
    // Rows 0–2: the tip end condition on the rotation; rows 3–5: lateral x, lateral y, axial.
    if (ends_ == ColumnEnds::kClampedClamped) {
      const Mat3 Q = base.R.transpose() * R;
      r.head<3>() = 0.5 * Vec3(Q(2, 1) - Q(1, 2), Q(0, 2) - Q(2, 0), Q(1, 0) - Q(0, 1));
      // dQ column j = R_WBᵀ d(R e_j): entry (i, j) is row i of that.
      for (int k = 0; k < 6; ++k) {
        Mat3 dQ;
        for (int j = 0; j < 3; ++j) dQ.col(j) = base.R.transpose() * RotationColumn(T, j).col(k);
        dr.col(k).head<3>() =
            0.5 * Vec3(dQ(2, 1) - dQ(1, 2), dQ(0, 2) - dQ(2, 0), dQ(1, 0) - dQ(0, 1));
      }
    } else {
      moment_rows();
    }
    const Vec3 d = base.R.transpose() * (p - base.p);
    const Eigen::Matrix<double, 3, 6> dd = base.R.transpose() * dp;
    r(3) = d(0) / L;
    r(4) = d(1) / L;
    dr.row(3) = dd.row(0) / L;
    dr.row(4) = dd.row(1) / L;
    const Vec3 e = base.R.col(2);
    const Vec3 F_W = force_dead + R * force_follower;
    r(5) = e.dot(R * n - F_W) / scale_(5);
    const Eigen::Matrix<double, 3, 6> dforce = times(n) + R * dn - times(force_follower);
    dr.row(5) = e.transpose() * dforce / scale_(5);
  }
  if (J) *J = dr;
  return r;
}

ColumnSummary ColumnSolver::Solve(const lie::SE3& base, const StaticLoads& loads) {
  ColumnSummary summary;
  Vec6 u = u_;
  Mat6 J;
  RodState record;
  Vec6 r = Residual(base, loads, u, &J, &record);
  ++summary.shots;
  for (int it = 0;; ++it) {
    const double norm = r.norm();
    summary.residual = norm;
    if (!std::isfinite(norm)) {
      summary.status = SolveStatus::kNonFinite;
      return summary;
    }
    if (norm < options_.tolerance) break;
    if (it == options_.max_iterations) {
      summary.status = SolveStatus::kMaxIterations;
      return summary;
    }
    ++summary.iterations;
    // Minimum-norm Newton step: directions with σ < 1e-10 σ_max are not moved along.
    Eigen::CompleteOrthogonalDecomposition<Mat6> cod;
    cod.setThreshold(1e-10);
    cod.compute(J);
    const Vec6 step = -cod.solve(r);
    // Backtracking on ‖r‖; the shape of the rod can change a lot in one full step.
    double t = 1.0;
    Vec6 u_try, r_try;
    Mat6 J_try;
    RodState rec_try;
    bool accepted = false;
    for (int k = 0; k < 12; ++k, t *= 0.5) {
      u_try = u + t * step;
      r_try = Residual(base, loads, u_try, &J_try, &rec_try);
      ++summary.shots;
      if (r_try.allFinite() && r_try.norm() < (1.0 - 1e-4 * t) * norm) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      summary.status = SolveStatus::kMaxIterations;
      return summary;
    }
    u = u_try;
    r = r_try;
    J = J_try;
    record = std::move(rec_try);
  }
  u_ = u;
  state_ = std::move(record);
  summary.status = SolveStatus::kConverged;
  return summary;
}

int ColumnSolver::StabilityIndexAtUnknowns(const lie::SE3& base, const StaticLoads& loads) const {
  RodState record;
  std::vector<StateTangent> tangents;
  Residual(base, loads, u_, nullptr, &record, &tangents);
  return StabilityIndexFromShot(base, loads, u_, record, tangents);
}

ColumnSummary ColumnSolver::SolveFromUnloaded(const lie::SE3& base, const StaticLoads& loads) {
  ColumnSummary total;
  u_.setZero();  // the straight column without load: every residual is zero, so this solve
  const ColumnSummary unloaded = Solve(base, loads.Scaled(0.0));  // only records its state
  total.shots = unloaded.shots;
  if (!unloaded.converged()) {
    // A non-finite base pose, or contact surfaces that already hold the straight column: its
    // shot is the state reported (no solve has recorded one yet).
    Residual(base, loads.Scaled(0.0), u_, nullptr, &state_);
    return unloaded;
  }
  const double measure = StaticLoadParameter(model_, loads, shooter_.actuation());
  const double max_step =
      measure > options_.max_load_increment ? options_.max_load_increment / measure : 1.0;
  double lambda = 0.0, step = max_step;
  int attempts = 0;
  while (lambda < 1.0) {
    step = std::min(step, 1.0 - lambda);
    if (step < options_.min_load_step || attempts == options_.max_load_steps) {
      total.status = SolveStatus::kLoadSteppingFailed;
      return total;
    }
    ++attempts;
    const double next = step == 1.0 - lambda ? 1.0 : lambda + step;
    const Vec6 u_accepted = u_;
    const RodState accepted = state_;
    const ColumnSummary s = Solve(base, loads.Scaled(next));
    total.iterations += s.iterations;
    total.shots += s.shots;
    total.residual = s.residual;
    // A step that takes the rod through a contact surface jumped it (obstacle_core.hpp).
    if (s.converged() &&
        ReachesObstacleCore(loads.contact, accepted.position_W, state_.position_W)) {
      u_ = u_accepted;
      state_ = accepted;
      step *= 0.5;
      continue;
    }
    if (s.converged()) {
      lambda = next;
      ++total.load_steps;
      step = std::min(2.0 * step, max_step);
    } else {
      step *= 0.5;
    }
  }
  total.status = SolveStatus::kConverged;
  return total;
}

std::vector<Eigen::Matrix<double, 18, 1>> ColumnSolver::Perturbation(const lie::SE3& base,
                                                                     const StaticLoads& loads,
                                                                     const Vec6& u,
                                                                     const Vec6& du) const {
  std::vector<StateTangent> tangents;
  RodState record;
  Residual(base, loads, u, nullptr, &record, &tangents);
  std::vector<Eigen::Matrix<double, 18, 1>> out(tangents.size());
  for (size_t i = 0; i < tangents.size(); ++i) out[i] = tangents[i] * du;
  return out;
}

ColumnSolver::PiecewiseFields ColumnSolver::FieldsInPieces(const lie::SE3& base,
                                                          const StaticLoads& loads,
                                                          const RodState& solved,
                                                          int pieces) const {
  return FieldsInPieces(base, loads, solved, pieces, false);
}

ColumnSolver::PiecewiseFields ColumnSolver::FieldsInPieces(const lie::SE3& base,
                                                          const StaticLoads& loads,
                                                          const RodState& solved, int pieces,
                                                          bool for_index) const {
  PiecewiseFields f;
  const int n = static_cast<int>(grid().size());
  if (solved.size() != n || pieces < 1) return f;
  f.u = UnknownsOf(base, solved.rotation_WB.front(), solved.wrench_B.front());
  lie::SE3 start;
  Vec6 W0;
  StateTangent tangent;
  Start(base, f.u, &start, &W0, &tangent, for_index);
  f.record.Resize(n);
  for (int i = 0; i < n; ++i) f.record.s[i] = grid()[i];
  f.tangents.resize(n);
  // Rows of a tangent in comparable units: d p / L, d R, d m / (EI/L), d n / (EI/L²).
  Eigen::Matrix<double, 18, 1> unit = Eigen::Matrix<double, 18, 1>::Ones();
  unit.segment<3>(kP).setConstant(1.0 / length());
  unit.segment<3>(kM).setConstant(1.0 / scale_(0));
  unit.segment<3>(kN).setConstant(1.0 / scale_(3));
  const int k_max = std::min(pieces, n - 1);
  for (int k = 0; k < k_max; ++k) {
    const int first = static_cast<int>(std::lround(static_cast<double>(k) * (n - 1) / k_max));
    const int last = static_cast<int>(std::lround(static_cast<double>(k + 1) * (n - 1) / k_max));
    Mat6 A = Mat6::Identity();
    if (k > 0) {
      const Eigen::HouseholderQR<StateTangent> qr(unit.asDiagonal() * tangent);
      A = qr.matrixQR().topRows<6>().triangularView<Eigen::Upper>().solve(Mat6::Identity());
      if (A.determinant() < 0) A.col(0) *= -1.0;
      tangent = tangent * A;
      start = lie::SE3{solved.rotation_WB[first], solved.position_W[first]};
      W0 = solved.wrench_B[first];
    }
    f.first_node.push_back(first);
    f.basis_change.push_back(A);
    tangent = shooter_.ShootTangentBetween(first, last, start, W0, tangent, loads, &f.record,
                                           &f.tangents);
  }
  f.finite = f.record.position_W.back().allFinite() && tangent.allFinite();
  return f;
}

int ColumnSolver::StabilityIndexInPieces(const lie::SE3& base, const StaticLoads& loads,
                                         const RodState& solved, int pieces, double zero) const {
  const PiecewiseFields f = FieldsInPieces(base, loads, solved, pieces, true);
  if (!f.finite || !IndexIsDefined(loads, f.u)) return -1;
  return CountIndex(base, loads, f.record, f.tangents, zero);
}

int ColumnSolver::StabilityIndexFromShot(const lie::SE3& base, const StaticLoads& loads,
                                         const Vec6& u, const RodState& record,
                                         const std::vector<StateTangent>& tangents,
                                         double zero) const {
  if (!IndexIsDefined(loads, u)) return -1;
  if (ends_ != ColumnEnds::kPinnedPinned || (u(0) == 0.0 && u(1) == 0.0))
    return CountIndex(base, loads, record, tangents, zero);
  // A pin turned from its base frame: the fields again, started as the index needs (Start).
  lie::SE3 start;
  Vec6 W0;
  StateTangent dstart;
  Start(base, u, &start, &W0, &dstart, true);
  RodState shot;
  std::vector<StateTangent> fields;
  shooter_.ShootTangent(start, loads, W0, dstart, &shot, &fields);
  return CountIndex(base, loads, shot, fields, zero);
}

bool ColumnSolver::IndexIsDefined(const StaticLoads& loads, const Vec6& u) const {
  if (!LoadsAreConservative(loads)) return false;
  // A pinned base holding a torque turns it with the base section (Start), a follower moment
  // that no potential has. 1e-8 EI/L is far below any torque that matters and far above the
  // solve's rounding of m₃(0) = 0.
  return ends_ != ColumnEnds::kPinnedPinned || std::abs(u(2)) <= 1e-8;
}

int ColumnSolver::CountIndex(const lie::SE3& base, const StaticLoads& loads, const RodState& record,
                             const std::vector<StateTangent>& tangents, double zero) const {
  // The admissible tip variations η(L) = [δθ_B; δp_B]: a guided tip keeps its lateral position,
  // moving only along the base axis, R(L)ᵀ R_WB e₃ in the tip body frame; a clamped tip also
  // keeps its rotation, δθ_B = 0.
  TipVariations Z = TipVariations::Identity(6, 6);
  if (ends_ != ColumnEnds::kClampedFree) {
    const Vec3 axial = record.rotation_WB.back().transpose() * base.R.col(2);
    const bool free_rotation = ends_ != ColumnEnds::kClampedClamped;
    Z = TipVariations::Zero(6, free_rotation ? 4 : 1);
    if (free_rotation) Z.topLeftCorner<3, 3>().setIdentity();
    Z.col(Z.cols() - 1).tail<3>() = axial;
  }
  const RefineSegment refine = [&](int i, int parts, RodState* states,
                                   std::vector<ShotTangent>* sub) {
    return shooter_.ShootSegmentRefined(i, parts, loads, record, tangents, states, sub);
  };
  return MorseIndexOfShot(record, tangents, Z, length(), zero * scale_(0), refine);
}

}  // namespace cosserat
