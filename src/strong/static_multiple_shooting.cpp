#include "cosserat/strong/static_multiple_shooting.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/lie/nearest_rotation.hpp"
#include "cosserat/lie/so3.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/rod/grid.hpp"
#include "cosserat/strong/shooting_exponent.hpp"
#include "cosserat/strong/spatial_scheme.hpp"

namespace cosserat {

namespace {

constexpr int kJunction = 12;  // unknowns per junction: δp/L, δθ, δm/(EI/L), δn/(EI/L²)

// Forward-difference step on the dimensionless unknowns. Round-off costs ~1e-16 × the piece's
// gain (≲ e^5) / step, 1.5e-5 relative at 1e-9; truncation follows the curvature of the loads,
// which a stiff contact surface's smoothing ramp makes large (k/ε): at 1e-7 a node in the ramp
// gets a Jacobian ~5 % off and the rod on a table of stiffness 1e6–1e7 N/m² stalls at a
// residual of 1e-4; at 1e-9 it converges on every grid from 51 to 501 nodes.
constexpr double kDifferenceStep = 1e-9;

// Halvings of a Newton step that does not reduce the residual before the load level fails.
// A rod coming down onto a stiff surface needs deep cuts: from a state not yet touching, the
// Newton step sags it through the surface (the rod on a table of examples/rod_on_table.json
// stalls with 6 halvings and converges with 12).
constexpr int kBacktracks = 12;

}  // namespace

double LoadForceBound(const RodModel& rod, const StaticLoads& loads, const Actuation& actuation) {
  const SectionProperties p = rod.section->At(0.0, actuation);
  const LoadSite site{0.0, 1.0, p.mass(3, 3), p.outer_diameter};
  const SplitWrench tip = TotalTipWrench(loads);
  return tip.dead_W.tail<3>().norm() + tip.follower_B.tail<3>().norm() +
         rod.length * TotalDistributedForce_W(loads, site).norm();
}

double StaticShootingExponent(const RodModel& rod, const StaticLoads& loads,
                              const Actuation& actuation) {
  const SectionProperties p = rod.section->At(0.0, actuation);
  const double ei = p.min_bending_stiffness();  // N·m²
  const double L = rod.length;
  double exponent = 0.0;
  for (int i = 0; i < loads.contact.count; ++i)
    exponent =
        std::max(exponent, std::pow(loads.contact.surface[i].stiffness / (4.0 * ei), 0.25) * L);
  return std::max(exponent, std::sqrt(LoadForceBound(rod, loads, actuation) / ei) * L);
}

StaticMultipleShootingSolver::StaticMultipleShootingSolver(
    const RodModel& model, int num_nodes, const StaticMultipleShootingOptions& options,
    const Actuation& actuation)
    : model_(model), options_(options), actuation_(actuation) {
  std::string why;
  if (!model_.IsValid(&why)) throw std::invalid_argument("RodModel: " + why);
  if (!model_.tendons.empty() || !model_.chambers.empty())
    throw std::invalid_argument(
        "StaticMultipleShootingSolver: rods with tendons or chambers (an actuation) are solved "
        "by StaticShootingSolver");
  if (num_nodes < 3)
    throw std::invalid_argument("StaticMultipleShootingSolver: at least 3 nodes are needed");
  if (options_.tip_guided && options_.tip_pinned)
    throw std::invalid_argument(
        "StaticMultipleShootingOptions: a tip is either guided along the axis or pinned at a "
        "point, not both");
  grid_ = ModelGrid(model_, num_nodes);
  const int n = static_cast<int>(grid_.size());
  if (options_.pieces < 0 || options_.pieces > n - 1)
    throw std::invalid_argument(
        "StaticMultipleShootingOptions: pieces (" + std::to_string(options_.pieces) +
        ") must be 0 (automatic) up to the grid's segments (" + std::to_string(n - 1) + ")");
  const std::vector<double> points = SegmentSamplePoints(grid_);
  samples_.resize(points.size());
  for (size_t q = 0; q < points.size(); ++q) {
    const SectionLaw law = SectionLaw::At(model_, points[q], actuation_);
    StaticShootingSolver::Sample& smp = samples_[q];
    smp.compliance_diagonal = law.stiffness.cwiseInverse();
    smp.rest_strain = law.rest_strain;
    smp.mass_per_length = law.mass_per_length();
    smp.s = points[q];
    smp.outer_diameter = law.outer_diameter;
  }
  SetScales(lie::SE3{}, 0.0);
  state_.Resize(n);
  for (int i = 0; i < n; ++i) state_.s[i] = grid_[i];
  SetPieces(options_.pieces > 0 ? options_.pieces : 1);
}

void StaticMultipleShootingSolver::SetScales(const lie::SE3& base, double force) {
  const Point start = BaseStart(base, x_);
  const SectionProperties p = model_.section->At(0.0, actuation_);
  const double ei = p.min_bending_stiffness(), ei_max = p.max_bending_stiffness();  // N·m²
  const double L = model_.length;
  scale_.head<3>().setConstant(std::max(ei_max / L, std::sqrt(force * ei)));
  scale_.tail<3>().setConstant(std::max(ei_max / (L * L), force));
  x_ = BaseUnknowns(base, start);
}

void StaticMultipleShootingSolver::SetPieces(int pieces) {
  const int segments = static_cast<int>(grid_.size()) - 1;
  junction_nodes_.resize(pieces - 1);
  junctions_.assign(pieces - 1, Point{Vec3::Zero(), Mat3::Identity(), Vec3::Zero(), Vec3::Zero()});
  for (int k = 1; k < pieces; ++k) {
    const int i = static_cast<int>(std::lround(double(k) * segments / pieces));
    junction_nodes_[k - 1] = i;
    if (has_solution_) {  // restart from the last solution there
      junctions_[k - 1] = {state_.position_W[i], state_.rotation_WB[i],
                           state_.wrench_B[i].head<3>(), state_.wrench_B[i].tail<3>()};
    }
  }
  const int unknowns = 6 + kJunction * (pieces - 1);
  for (auto* v : {&r_, &r_trial_, &dx_}) v->setZero(unknowns);
  // Junction k's rows reach back to the start of its piece and forward to its own unknowns:
  // 17 sub- and 17 super-diagonals.
  lu_.Resize(unknowns, 17, 17);
}

StaticMultipleShootingSolver::Point StaticMultipleShootingSolver::BaseStart(const lie::SE3& base,
                                                                            const Vec6& x) const {
  if (!options_.base_pinned) {
    const Vec6 W0 = scale_.cwiseProduct(x);
    return {base.p, base.R, W0.head<3>(), W0.tail<3>()};
  }
  // Pinned with the twist held: the rotation about the base frame's x and y, the torsional
  // moment (body z) and the force.
  return {base.p, base.R * lie::SO3Exp(Vec3(x(0), x(1), 0.0)), Vec3(0.0, 0.0, scale_(2) * x(2)),
          scale_.tail<3>().cwiseProduct(x.tail<3>())};
}

Vec6 StaticMultipleShootingSolver::BaseUnknowns(const lie::SE3& base, const Point& guess) const {
  Vec6 x;
  x.tail<3>() = guess.n.cwiseQuotient(scale_.tail<3>());
  if (!options_.base_pinned) {
    x.head<3>() = guess.m.cwiseQuotient(scale_.head<3>());
  } else {
    const Vec3 phi = lie::SO3Log(Mat3(base.R.transpose() * guess.R));
    x.head<3>() << phi(0), phi(1), guess.m(2) / scale_(2);
  }
  return x;
}

StaticMultipleShootingSolver::Point StaticMultipleShootingSolver::ShootPiece(
    int k, const Point& start, const StaticLoads& loads, bool record) {
  const int junctions = static_cast<int>(junction_nodes_.size());
  const int n = static_cast<int>(grid_.size());
  const int first = k == 0 ? 0 : junction_nodes_[k - 1];
  const int last = k < junctions ? junction_nodes_[k] : n - 1;
  const bool motion = HasMotionLoads(loads);
  // One RK4 stage at sample q: the distributed loads there (and those that depend on the pose,
  // at the stage's pose, at rest) and the static rates.
  auto stage = [&](int q, const Point& y, Vec6* xi) {
    const LoadSite site = samples_[q].Site();
    Vec3 f = TotalDistributedForce_W(loads, site);
    if (motion)
      f += TotalMotionForce_W(loads, site, SectionMotion{y.p, y.R.col(2), Vec3::Zero()}, nullptr);
    return rhs::StaticDerivative<double>(samples_[q].rest_strain, samples_[q].compliance_diagonal,
                                         f, y, xi);
  };
  auto record_node = [&](int i, const Point& y, const Vec6& xi) {
    state_.position_W[i] = y.p;
    state_.rotation_WB[i] = y.R;
    state_.wrench_B[i] << y.m, y.n;
    state_.twist_B[i].setZero();
    state_.strain[i] = xi;
  };
  Point y = start;
  Vec6 xi0, xi;
  for (int i = first; i < last; ++i) {
    const double h = grid_[i + 1] - grid_[i];
    const int q0 = 3 * i, qm = 3 * i + 1, q1 = 3 * i + 2;
    const Point k1 = stage(q0, y, &xi0);
    if (record) record_node(i, y, xi0);
    const Point k2 = stage(qm, internal::Axpy(y, 0.5 * h, k1), &xi);
    const Point k3 = stage(qm, internal::Axpy(y, 0.5 * h, k2), &xi);
    const Point k4 = stage(q1, internal::Axpy(y, h, k3), &xi);
    internal::Rk4Update(h, k1, k2, k3, k4, &y);
  }
  if (record && last == n - 1) {
    const StaticShootingSolver::Sample& tip = samples_[3 * (n - 2) + 2];
    rhs::LinearStrain<double>(tip.rest_strain, tip.compliance_diagonal, y.m, y.n, &xi);
    record_node(n - 1, y, xi);
  }
  return y;
}

Eigen::Matrix<double, 12, 1> StaticMultipleShootingSolver::Mismatch(const Point& arriving,
                                                                    const Point& restart) const {
  Eigen::Matrix<double, 12, 1> d;
  d.segment<3>(0) = (arriving.p - restart.p) / model_.length;
  d.segment<3>(3) = lie::SO3Log(Mat3(restart.R.transpose() * arriving.R));
  d.segment<3>(6) = (arriving.m - restart.m).cwiseQuotient(scale_.head<3>());
  d.segment<3>(9) = (arriving.n - restart.n).cwiseQuotient(scale_.tail<3>());
  return d;
}

Vec6 StaticMultipleShootingSolver::TipResidual(const lie::SE3& base, const Point& tip,
                                               const StaticLoads& loads) const {
  const Vec6 W_tip_B = TipWrenchInBody(TotalTipWrench(loads), tip.R);
  Vec6 W;
  W << tip.m, tip.n;
  Vec6 e = (W - W_tip_B).cwiseQuotient(scale_);
  if (options_.tip_pinned) e.tail<3>() = (tip.p - options_.tip_position_W) / model_.length;
  if (options_.tip_pinned && options_.tip_clamped)
    e.head<3>() = lie::SO3Log(Mat3(options_.tip_rotation_W.transpose() * tip.R));
  if (options_.tip_guided) {
    const Vec3 d = base.R.transpose() * (tip.p - base.p) / model_.length;
    const Vec3 axis = base.R.col(2);
    e(3) = d(0);
    e(4) = d(1);
    e(5) = axis.dot(tip.R * (tip.n - W_tip_B.tail<3>())) / scale_(5);
    if (options_.tip_clamped) e.head<3>() = lie::SO3Log(Mat3(base.R.transpose() * tip.R));
  }
  return e;
}

StaticMultipleShootingSolver::Point StaticMultipleShootingSolver::Moved(
    const Point& y, const Eigen::Ref<const Eigen::VectorXd>& dz) const {
  return {y.p + model_.length * dz.segment<3>(0), y.R * lie::SO3Exp(Vec3(dz.segment<3>(3))),
          y.m + scale_.head<3>().cwiseProduct(dz.segment<3>(6)),
          y.n + scale_.tail<3>().cwiseProduct(dz.segment<3>(9))};
}

bool StaticMultipleShootingSolver::Residual(const lie::SE3& base, const StaticLoads& loads,
                                            Eigen::VectorXd* r) {
  const int junctions = static_cast<int>(junction_nodes_.size());
  for (int k = 0; k <= junctions; ++k) {
    const Point start = k == 0 ? BaseStart(base, x_) : junctions_[k - 1];
    const Point arriving = ShootPiece(k, start, loads, false);
    if (k < junctions)
      r->segment<kJunction>(kJunction * k) = Mismatch(arriving, junctions_[k]);
    else
      r->tail<6>() = TipResidual(base, arriving, loads);
  }
  return r->allFinite();
}

bool StaticMultipleShootingSolver::Jacobian(const lie::SE3& base, const StaticLoads& loads,
                                            StaticShootingSummary* summary) {
  const int junctions = static_cast<int>(junction_nodes_.size());
  lu_.SetZero();
  for (int k = 0; k <= junctions; ++k) {
    const bool last = k == junctions;
    const int rows = last ? 6 : kJunction, cols = k == 0 ? 6 : kJunction;
    const int row0 = kJunction * k, col0 = k == 0 ? 0 : 6 + kJunction * (k - 1);
    // The piece's end residual from a start.
    auto end = [&](const Point& start) {
      const Point arriving = ShootPiece(k, start, loads, false);
      Eigen::Matrix<double, 12, 1> e = Eigen::Matrix<double, 12, 1>::Zero();
      if (last)
        e.head<6>() = TipResidual(base, arriving, loads);
      else
        e = Mismatch(arriving, junctions_[k]);
      return e;
    };
    const Point start = k == 0 ? BaseStart(base, x_) : junctions_[k - 1];
    const Eigen::Matrix<double, 12, 1> e0 = end(start);
    if (!e0.allFinite()) return false;
    for (int j = 0; j < cols; ++j) {
      Point moved;
      if (k == 0) {
        Vec6 x = x_;
        x(j) += kDifferenceStep;
        moved = BaseStart(base, x);
      } else {
        Eigen::Matrix<double, 12, 1> dz = Eigen::Matrix<double, 12, 1>::Zero();
        dz(j) = kDifferenceStep;
        moved = Moved(start, dz);
      }
      const Eigen::Matrix<double, 12, 1> e = end(moved);
      if (!e.allFinite()) return false;
      for (int r = 0; r < rows; ++r) lu_(row0 + r, col0 + j) = (e(r) - e0(r)) / kDifferenceStep;
    }
    summary->shots += cols + 1;  // shots of one piece each
    if (last) break;
    // The mismatch's derivative in the junction's own unknowns: −1, scaled as the unknowns are,
    // except for the rotation d = Log(R_jᵀ R_arriving) under R_j → R_j Exp(δ):
    // ∂d/∂δ = −J_l(d)⁻¹.
    const int zc = 6 + kJunction * k;
    for (int r = 0; r < kJunction; ++r) lu_(row0 + r, zc + r) = -1.0;
    const Mat3 rotation = -lie::SO3LeftJacobianInverse(Vec3(e0.segment<3>(3)));
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) lu_(row0 + 3 + r, zc + 3 + c) = rotation(r, c);
  }
  return lu_.Factorize();
}

bool StaticMultipleShootingSolver::Newton(const lie::SE3& base, const StaticLoads& loads,
                                          double tolerance, StaticShootingSummary* summary) {
  ++summary->shots;
  if (!Residual(base, loads, &r_)) return false;
  double norm = r_.norm();
  const int junctions = static_cast<int>(junction_nodes_.size());
  for (int it = 0; it < options_.max_iterations; ++it) {
    if (norm < tolerance) break;
    if (!Jacobian(base, loads, summary)) return false;
    dx_ = -r_;
    lu_.Solve(dx_);
    const Vec6 x_saved = x_;
    const std::vector<Point> saved = junctions_;
    bool reduced = false;
    for (int cut = 0; cut <= kBacktracks && !reduced; ++cut) {
      const double a = std::ldexp(1.0, -cut);
      x_ = x_saved + a * dx_.head<6>();
      for (int k = 0; k < junctions; ++k)
        junctions_[k] = Moved(saved[k], a * dx_.segment<kJunction>(6 + kJunction * k));
      ++summary->shots;
      reduced = Residual(base, loads, &r_trial_) && r_trial_.norm() < norm;
    }
    ++summary->iterations;
    if (!reduced) {
      x_ = x_saved;
      junctions_ = saved;
      return false;
    }
    std::swap(r_, r_trial_);
    norm = r_.norm();
  }
  summary->residual = norm;
  return norm < tolerance;
}

StaticShootingSummary StaticMultipleShootingSolver::SolveFrom(const lie::SE3& base,
                                                              const StaticLoads& loads,
                                                              const RodState& guess) {
  const auto t0 = std::chrono::steady_clock::now();
  if (guess.size() != static_cast<int>(grid_.size()))
    throw std::invalid_argument("StaticMultipleShootingSolver::SolveFrom: the guess has " +
                                std::to_string(guess.size()) + " nodes, the grid " +
                                std::to_string(grid_.size()));
  StaticShootingSummary summary;
  summary.stability_index = -1;
  if (!loads.IsValid(nullptr) || !base.p.allFinite() || !base.R.allFinite()) {
    summary.status = SolveStatus::kNonFinite;
    return summary;
  }
  // The exponent of a single shot under the guess's largest force (a held cable's tension is
  // not bounded by its loads), or of the loads and contact surfaces when larger.
  const SectionProperties p = model_.section->At(0.0, actuation_);
  const double ei = p.min_bending_stiffness();  // N·m²
  const double force = guess.MaxForce();  // N
  const double exponent =
      std::max(std::sqrt(force / ei) * model_.length,
               StaticShootingExponent(model_, loads, actuation_));
  const int pieces = PiecesFor(exponent);
  if (pieces != this->pieces()) SetPieces(pieces);
  // Unknowns and residuals in the guess's own scales: a cable's tension T is (kL)² times EI/L²
  // (10⁶ at kL = 1000), which would leave the forward differences of the force unknowns
  // (step 1e-9) at round-off. Its end moments are about sqrt(T EI) (a boundary layer of length
  // sqrt(EI/T)).
  guess_force_ = force;
  SetScales(base, std::max(force, LoadForceBound(model_, loads, actuation_)));
  // Each start in the guess's own frame there; the base's rotation from the node after it when
  // pinned (a state may report the support's frame at a pinned end, not the rod's).
  auto at_node = [&](int i, int frame) {
    const Mat3& R = guess.rotation_WB[frame];
    const Vec3 m_W = guess.rotation_WB[i] * guess.wrench_B[i].head<3>();
    const Vec3 n_W = guess.rotation_WB[i] * guess.wrench_B[i].tail<3>();
    return Point{guess.position_W[i], R, Vec3(R.transpose() * m_W), Vec3(R.transpose() * n_W)};
  };
  x_ = BaseUnknowns(base, at_node(0, options_.base_pinned ? 1 : 0));
  for (size_t k = 0; k < junction_nodes_.size(); ++k)
    junctions_[k] = at_node(junction_nodes_[k], junction_nodes_[k]);
  const bool converged = Newton(base, loads, options_.tolerance, &summary);
  Finish(base, loads, converged, &summary);
  summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return summary;
}

int StaticMultipleShootingSolver::PiecesFor(double exponent) const {
  if (options_.pieces > 0) return options_.pieces;
  return AutomaticShootingPieces(exponent, static_cast<int>(grid_.size()) - 1);
}

void StaticMultipleShootingSolver::Finish(const lie::SE3& base, const StaticLoads& last,
                                          bool converged, StaticShootingSummary* summary) {
  Shot(base, last);
  Residual(base, last, &r_);
  summary->residual = r_.norm();
  // Residuals met by a shot that ran away (RodState::RanAway) are no equilibrium.
  if (converged && state_.RanAway()) {
    summary->status = SolveStatus::kNonFinite;
    return;
  }
  summary->status = converged ? SolveStatus::kConverged
                              : (std::isfinite(summary->residual) ? SolveStatus::kMaxIterations
                                                                  : SolveStatus::kNonFinite);
  if (converged) {
    has_solution_ = true;
    solved_base_ = base;
    solved_loads_ = last;
  }
}

}  // namespace cosserat
