// Multiple shooting for one BDF2 step (Bdf2Options::shooting_segments > 1, or chosen by the
// stepper).
//
// Single shooting integrates the whole rod from the 6 unknowns at s = 0; an error there grows
// like e^{λL}, λ ≈ (c0² ρA / EI)^{1/4} (the BDF2 inertia against bending), which for small dt
// or soft rods exceeds what double precision can resolve (the peer rod at dt = 0.5 ms: e^17).
// Here the shot restarts at interior junctions from 18 extra unknowns each (pose, wrench and
// twist there, as displacements from the last accepted state) and continuity at each junction
// joins the tip condition as residual. Same discrete equations, so the same solution as single
// shooting; each piece amplifies by only e^{λL/pieces}.
//
// Piece k depends only on its start (x for the first piece, junction k − 1's unknowns after),
// so with the residual ordered [mismatch at junction 0, 1, …; tip] and the unknowns
// [x; z₀; z₁; …] the Jacobian is block-banded: each junction's rows hold the derivative of the
// arriving state in the piece's start (forward differences through that piece alone, 18 shots
// of one piece) and that of the restart state in the junction's own unknowns (closed form).
// A renewal costs about 19 shots of the whole rod whatever the number of pieces, and its banded
// LU O(pieces) (Ascher, Mattheij & Russell 1995, ch. 4). Newton keeps the factors across
// iterations and steps (chord iterations) and renews them when an iteration contracts the
// residual by less than kRenewContraction; a step whose freshly renewed Newton step does not
// reduce the residual fails and is halved (or given more pieces) by the caller.

#include <algorithm>
#include <cmath>

#include "cosserat/lie/so3.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/cosserat_rhs.hpp"

namespace cosserat {

namespace {

// A chord iteration that reduces the residual by less than this factor renews the Jacobian
// (one full-rod shot per iteration against ~19 per renewal). On the soft cantilever of
// bench/problems the run time is flat within noise from 0.1 to 0.5 (fewer renewals, more
// iterations).
constexpr double kRenewContraction = 0.25;

// Forward-difference step for the unknowns, which are dimensionless and O(1) at most: 1e-7
// balances truncation (~1e-7 relative; the shot is smooth) against round-off (~1e-16 × the
// piece's gain / 1e-7). A Jacobian this accurate only slows Newton from quadratic to fast
// linear convergence.
constexpr double kDifferenceStep = 1e-7;

// Halvings of a fresh Newton step that does not reduce the residual before the step fails.
constexpr int kBacktracks = 4;

// Statics: chord steps from a full Newton step that raised the residual, before backtracking.
constexpr int kChordSteps = 4;

}  // namespace

bool Bdf2ShootingStepper::RenewJunctionJacobian(const StepInput& input, const Coefficients& c,
                                                bool statics, StepSummary* summary) {
  const int junctions = static_cast<int>(junction_nodes_.size());
  const Eigen::Index nz = junction_z_.size();
  run_.junction_factors.SetZero();
  junction_z_ = ms_x_.tail(nz);
  for (int piece = 0; piece <= junctions; ++piece) {
    const bool last = piece == junctions;
    const int rows = last ? 6 : 18;
    const Eigen::Index row0 = 18 * piece;
    const Eigen::Index col0 = piece == 0 ? 0 : 6 + 18 * (piece - 1);
    const int cols = piece == 0 ? 6 : 18;
    // The piece's end residual: the tip residual, or its junction's mismatch.
    auto shoot = [&](const Vec6& x, Eigen::VectorXd* out) {
      const Vec6 tip = ShootPiece(input, c, statics, piece, x);
      if (last)
        out->head<6>() = tip;
      else
        *out = junction_mismatch_.segment<18>(row0);
      return out->head(rows).allFinite();
    };
    Vec6 x = ms_x_.head<6>();
    if (!shoot(x, &ms_piece_base_)) return false;
    for (int j = 0; j < cols; ++j) {
      const Eigen::Index col = col0 + j;
      const double step = kDifferenceStep * std::max(1.0, std::abs(ms_x_(col)));
      double& unknown = piece == 0 ? x(j) : junction_z_(col - 6);
      const double saved = unknown;
      unknown += step;
      const bool finite = shoot(x, &ms_piece_new_);
      unknown = saved;
      if (!finite) return false;
      for (int r = 0; r < rows; ++r)
        run_.junction_factors(row0 + r, col) = (ms_piece_new_(r) - ms_piece_base_(r)) / step;
    }
    summary->shots += cols + 1;
    if (last) break;
    // The mismatch's derivative in the junction's own unknowns: −1 on the diagonal, scaled as
    // the unknowns are, except for the rotation d = Log(Exp(z)ᵀ A) (A = R_refᵀ R_arriving):
    // Exp(z + δ) = Exp(z) Exp(J_r(z) δ) gives ∂d/∂z = −J_l(d)⁻¹ J_r(z).
    const Eigen::Index zc = 6 + 18 * piece;
    for (int r = 0; r < 18; ++r) run_.junction_factors(row0 + r, zc + r) = -1.0;
    const Vec3 z_rot = junction_z_.segment<3>(18 * piece + 3);
    const Vec3 d_rot = ms_piece_base_.segment<3>(3);
    const Mat3 block = -lie::SO3LeftJacobianInverse(d_rot) * lie::SO3RightJacobian(z_rot);
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) run_.junction_factors(row0 + 3 + r, zc + 3 + k) = block(r, k);
  }
  ++summary->jacobians;
  if (!run_.junction_factors.Factorize()) return false;
  run_.junction_factors_c0 = c.c0;
  return true;
}

bool Bdf2ShootingStepper::SolveStepMultiple(const StepInput& input, const Coefficients& c, double h,
                                            bool statics, StepSummary* summary) {
  const Eigen::Index nz = junction_z_.size();
  auto evaluate = [&](const Eigen::VectorXd& X, Eigen::VectorXd* R) {
    return MultipleResidual(input, c, statics, X, R, summary);
  };

  junctions_active_ = true;
  // First guess: x extrapolated like single shooting's; the junction states moving on by the
  // change of the last step (run_.junction_unknowns is that change). In statics: the given x
  // and the junctions at the guess in run_.state, with factors of their own.
  ms_x_.head<6>() = statics ? run_.unknowns.latest() : run_.unknowns.Predict(h);
  ms_x_.tail(nz) = run_.junction_unknowns;
  if (statics) ms_x_.tail(nz).setZero();
  bool ok = false;
  if (evaluate(ms_x_, &ms_r_)) {
    double norm = ms_r_.norm();
    bool fresh = false;  // the factors were renewed at ms_x_
    bool have_factors = !statics && run_.junction_factors_c0 == c.c0;
    for (int it = 0; it <= options_.max_iterations; ++it) {
      if (norm < Tolerance(ms_x_.head<6>(), input)) {
        ok = true;
        break;
      }
      if (it == options_.max_iterations) break;
      if (!have_factors) {
        // Renewing shoots the pieces from perturbed starts and leaves the trial state there, but
        // norm ≥ tolerance, so a full shot follows before any acceptance.
        if (!RenewJunctionJacobian(input, c, statics, summary)) break;
        have_factors = fresh = true;
      }
      ms_dx_ = -ms_r_;
      run_.junction_factors.Solve(ms_dx_);
      // With fresh factors, a Newton step that does not reduce the residual is shortened
      // (halved up to kBacktracks times) before the step is given up: far from the solution
      // (a poor first guess on a very soft rod) the full step overshoots.
      bool reduced = false;
      double new_norm = norm;
      for (int cut = 0; cut <= (fresh ? kBacktracks : 0) && !reduced; ++cut) {
        ms_x_new_ = ms_x_ + std::ldexp(1.0, -cut) * ms_dx_;
        const bool finite = evaluate(ms_x_new_, &ms_r_new_);
        new_norm = ms_r_new_.norm();
        ++summary->iterations;
        reduced = finite && new_norm < norm;
        if (!reduced && finite && statics && fresh && cut == 0) {
          // A held rod in tension (ChordStepsBelow): chord steps on from the full step decide.
          reduced = ChordStepsBelow(input, c, norm, summary);
          if (reduced) new_norm = ms_r_new_.norm();
        }
      }
      if (reduced) {
        std::swap(ms_x_, ms_x_new_);
        std::swap(ms_r_, ms_r_new_);
        // Slow contraction: renew, unless this iterate already converged.
        if (new_norm > kRenewContraction * norm &&
            new_norm >= Tolerance(ms_x_.head<6>(), input))
          have_factors = false;
        norm = new_norm;
        fresh = false;
      } else if (fresh) {
        break;  // not even a shortened step along a fresh Newton direction helps: the step fails
      } else {
        have_factors = false;  // ms_r_ is still the residual at ms_x_: renew there
      }
    }
    if (!have_factors || statics) run_.junction_factors_c0 = -1.0;  // the factors are stale
  }
  junctions_active_ = false;
  summary->residual = ms_r_.norm();
  if (!ok) {
    summary->status =
        std::isfinite(summary->residual) ? SolveStatus::kMaxIterations : SolveStatus::kNonFinite;
    return false;
  }
  solved_unknowns_ = ms_x_.head<6>();
  predictor_term_ = solved_unknowns_;
  // The junctions of the next step move from this state: in statics it becomes run_.state.
  run_.junction_unknowns = ms_x_.tail(nz);
  if (statics) run_.junction_unknowns.setZero();
  return true;
}

bool Bdf2ShootingStepper::MultipleResidual(const StepInput& input, const Coefficients& c,
                                           bool statics, const Eigen::VectorXd& X,
                                           Eigen::VectorXd* R, StepSummary* summary) {
  const Eigen::Index nz = junction_z_.size();
  junction_z_ = X.tail(nz);
  R->tail<6>() = Residual(input, c, statics, X.head<6>());
  R->head(nz) = junction_mismatch_;
  ++summary->shots;
  return R->allFinite();
}

bool Bdf2ShootingStepper::ChordStepsBelow(const StepInput& input, const Coefficients& c,
                                          double norm, StepSummary* summary) {
  Eigen::VectorXd x_on = ms_x_new_, r_on = ms_r_new_, dx_on;
  for (int k = 0; k < kChordSteps; ++k) {
    dx_on = -r_on;
    run_.junction_factors.Solve(dx_on);
    x_on += dx_on;
    ++summary->iterations;
    if (!MultipleResidual(input, c, true, x_on, &r_on, summary)) return false;
    if (r_on.norm() < norm) {
      ms_x_new_ = x_on;
      ms_r_new_ = r_on;
      return true;
    }
  }
  return false;
}

// The restart state of junction k, its mismatch against the state arriving there, and both
// at once (the shot crossing a junction).
template <typename State>
State Bdf2ShootingStepper::JunctionRestart(int k) const {
  const int i = junction_nodes_[k];
  const RodState& ref = run_.state;  // the last accepted state at the junction node
  const auto z = junction_z_.segment<18>(18 * k);
  State restart;
  restart.p = ref.position_W[i] + model_.length * z.segment<3>(0);
  // The stored frame is the product of explicit RK stages, orthonormal only to their error
  // (~1e-7 in a tension boundary layer); a piece restarted from it would carry that error as a
  // stretch its mismatch (the skew part of Log) cannot see, and the solution would depend on the
  // state the junctions were taken from (a taut 1 mm steel wire's tension by 1 % for frames
  // 1e-7 off). One step of Björck & Bowie 1971, R (3I − RᵀR)/2, makes it orthonormal to
  // O(error²).
  const Mat3& R0 = ref.rotation_WB[i];
  const Mat3 R_ref = 0.5 * R0 * (3.0 * Mat3::Identity() - R0.transpose() * R0);
  restart.R = R_ref * lie::SO3Exp(Vec3(z.segment<3>(3)));
  restart.m = ref.wrench_B[i].head<3>() + scale_.head<3>().cwiseProduct(z.segment<3>(6));
  restart.n = ref.rotation_WB[i] * ref.wrench_B[i].tail<3>() +
              scale_.tail<3>().cwiseProduct(z.segment<3>(9));
  restart.w = ref.twist_B[i].head<3>() + twist_scale_.head<3>().cwiseProduct(z.segment<3>(12));
  restart.v = ref.twist_B[i].tail<3>() + twist_scale_.tail<3>().cwiseProduct(z.segment<3>(15));
  return restart;
}

template <typename State>
void Bdf2ShootingStepper::RecordJunctionMismatch(int k, const State& y, const State& restart) {
  auto d = junction_mismatch_.segment<18>(18 * k);
  d.segment<3>(0) = (y.p - restart.p) / model_.length;
  d.segment<3>(3) = lie::SO3Log(Mat3(restart.R.transpose() * y.R));
  d.segment<3>(6) = (y.m - restart.m).cwiseQuotient(scale_.head<3>());
  d.segment<3>(9) = (y.n - restart.n).cwiseQuotient(scale_.tail<3>());
  d.segment<3>(12) = (y.w - restart.w).cwiseQuotient(twist_scale_.head<3>());
  d.segment<3>(15) = (y.v - restart.v).cwiseQuotient(twist_scale_.tail<3>());
}

template <typename State>
void Bdf2ShootingStepper::ApplyJunction(int k, State* y) {
  const State restart = JunctionRestart<State>(k);
  RecordJunctionMismatch(k, *y, restart);
  *y = restart;
}

// The shot's state at junctions (bdf2_shot.cpp): one instantiation, the shot's point.
template rhs::DynamicPoint<double> Bdf2ShootingStepper::JunctionRestart(int k) const;
template void Bdf2ShootingStepper::RecordJunctionMismatch(int k, const rhs::DynamicPoint<double>& y,
                                                          const rhs::DynamicPoint<double>& restart);
template void Bdf2ShootingStepper::ApplyJunction(int k, rhs::DynamicPoint<double>* y);

}  // namespace cosserat
