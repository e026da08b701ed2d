// Stability of a cantilever equilibrium found by shooting: the number of unstable directions
// (the Morse index of the second variation of the potential energy), by a Sturm count along s.
//
// Jacobi fields. Vary the unknown base wrench W(0) with the clamp held: the shot's tangent gives,
// at every node s, the variation of the pose, η(s) = [δθ_B; δp_B] (R⁻¹δR = δθ_B^, δp_B = Rᵀ δp_W;
// rad, m), and of the wrench, δW_B(s) (N·m, N), for 6 independent directions: U(s) = ∂η/∂W(0),
// and the wrench block.
//
// The rod [0, σ] clamped at 0 and loaded at σ by the dead wrench it carries at equilibrium has
// the potential V_σ(η(σ)) (the rest of the rod relaxed). Its gradient in the pairing
// dV = m_B·δθ_B + n_B·δp_B is the tip residual r = W_B(σ) − [Rᵀ M_W; Rᵀ F_W], and its Hessian at
// the equilibrium (r = 0), H(σ) = ∂r/∂η = V(σ) U(σ)⁻¹ with V = [δm − m × δθ; δn − n × δθ]
// (δ(Rᵀ F_W) = n_B × δθ_B for a dead force), is the stiffness of [0, σ] seen at σ. Near σ = 0 it
// is ≈ K/σ: positive definite. Its eigenvalues fall as σ grows (the Riccati equation of the
// Jacobi fields, for a positive definite K — the Legendre condition); one passes to −∞ and comes
// back from +∞ exactly where U is singular (a conjugate point of the clamped–clamped problem on
// [0, σ]). The index of the cantilever with its real tip load is then
//     (conjugate points in (0, L)) + (negative eigenvalues of H(L)),
// the Morse index theorem with one natural end. Each conjugate point shows as a drop of the count
// of negative eigenvalues of H between two nodes (one eigenvalue wraps from −∞ to +∞); counting
// eigenvalues of a symmetric matrix is indifferent to double roots (a circular section buckles in
// two planes at once, and det U or det J then touch zero without changing sign).
//
// H is symmetric only for conservative loads. A dead moment in the world frame is not (in 3-D it
// does work only along its axis), which makes H(σ) non-symmetric by ½[m]× in the rotation block
// wherever the rod carries a bending moment. Counting the symmetric part ½(H + Hᵀ) is then no
// criterion: it called a cantilever under a dead tip moment ML/EI = 3 unstable where the full
// spectrum of its linearisation (quaternion-FD modes) is real and positive. Tip moments, like
// follower tip loads (Beck's column loses stability by flutter, which statics cannot see), leave
// the index not defined, −1. (The count still takes ½(H + Hᵀ): for conservative loads, H to
// round-off.)
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "cosserat/loads/total_load.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat {

namespace {

// Negative eigenvalues (below −zero, N·m) of the symmetric part of H = V U⁻¹, in units where
// rotations (rad) and displacements (m) are comparable through the length scale `ell`
// (congruence keeps the count): H' = D⁻¹ H D⁻¹ maps [δθ; δp/ell] to [δm; ell δn], in N·m.
// Used at the tip, where the threshold matters (see StabilityIndex).
int NegativeEigenvalues(const Mat6& U, const Mat6& V, double ell, double zero) {
  Vec6 d;
  d << Vec3::Constant(1.0), Vec3::Constant(1.0 / ell);
  const Eigen::PartialPivLU<Mat6> lu(d.asDiagonal() * U);
  // H' = (D⁻¹ V)(D U)⁻¹, solved as a transpose: (D U)ᵀ H'ᵀ = (D⁻¹ V)ᵀ.
  const Mat6 Vs = d.cwiseInverse().asDiagonal() * V;
  const Mat6 Ht = lu.transpose().solve(Vs.transpose());
  const Mat6 Hs = 0.5 * (Ht + Ht.transpose());
  if (!Hs.allFinite()) return -1;
  const Eigen::SelfAdjointEigenSolver<Mat6> eig(Hs, Eigen::EigenvaluesOnly);
  int negative = 0;
  for (int k = 0; k < 6; ++k) negative += eig.eigenvalues()(k) < -zero;
  return negative;
}

// The same count without the threshold, cheaply, for the interior nodes: Uᵀ H U = Uᵀ V, so the
// symmetric part of Uᵀ V is congruent to that of H (symmetrising commutes with congruence) and
// has its inertia (Sylvester), read off the pivots of an LDLᵀ factorisation (6 × 6, no inverse).
// Falls back to the eigenvalues if the diagonal pivoting breaks down (a zero pivot).
int NegativeEigenvaluesFast(const Mat6& U, const Mat6& V) {
  const Mat6 S0 = U.transpose() * V;
  const Mat6 S = 0.5 * (S0 + S0.transpose());
  if (!S.allFinite()) return -1;
  const Eigen::LDLT<Mat6> ldlt(S);
  const Vec6 D = ldlt.vectorD();
  const double tiny = 1e-13 * S.cwiseAbs().maxCoeff();
  if (ldlt.info() == Eigen::Success && D.allFinite() && D.cwiseAbs().minCoeff() > tiny) {
    int negative = 0;
    for (int k = 0; k < 6; ++k) negative += D(k) < 0;
    return negative;
  }
  const Eigen::SelfAdjointEigenSolver<Mat6> eig(S, Eigen::EigenvaluesOnly);
  int negative = 0;
  for (int k = 0; k < 6; ++k) negative += eig.eigenvalues()(k) < 0;
  return negative;
}

}  // namespace

int StaticShootingSolver::StabilityIndex(const lie::SE3& base, const StaticLoads& loads,
                                         const Vec6& base_wrench_B) const {
  StateTangent start = StateTangent::Zero();
  start.bottomRows<6>() = Mat6::Identity();  // δW(0) along each unit direction; pose clamped
  RodState record;
  std::vector<StateTangent> nodes;
  ShootTangent(base, loads, base_wrench_B, start, &record, &nodes);
  return StabilityIndexFromShot(loads, record, nodes);
}

// Any 6 independent directions of W(0) will do: H = V U⁻¹ does not depend on the basis
// ((V A)(U A)⁻¹ = V U⁻¹), and sym(UᵀV) changes by a congruence. So the tangent of the solver's own
// Jacobian shot (directions: the scaled unknowns) serves as well as the unit directions.
int StaticShootingSolver::StabilityIndexFromShot(const StaticLoads& loads, const RodState& record,
                                                 const std::vector<StateTangent>& nodes) const {
  const SplitWrench tip = TotalTipWrench(loads);
  if (!tip.follower_B.isZero(0.0) || !tip.dead_W.head<3>().isZero(0.0))
    return -1;  // not conservative
  // Drag is not the gradient of a potential; contact in statics is (a penalty on the position
  // alone, no damping or friction at rest), and the tangent shot carries its stiffness.
  if (HasDrag(loads)) return -1;
  // An eigenvalue counts as negative below −1e-8 EI/L. A rod symmetric about its axis has, past
  // buckling, a whole circle of equilibria (the shape turned about the load axis, with the section
  // turned back at the clamp): H(L) is exactly singular along it, and the solve tolerance (1e-10
  // in units of EI/L) leaves that eigenvalue at ±1e-10 EI/L. An unstable direction weaker than
  // 1e-8 EI/L is one the load is within about 1e-8 of its critical value: marginal either way.
  const double zero = 1e-8 * scale_(0);
  const int n = static_cast<int>(grid_.size());
  int conjugate = 0, previous = 0, negative = 0;
  for (int i = 1; i < n; ++i) {
    const Mat3& R = record.rotation_WB[i];
    const Vec3 m = record.wrench_B[i].head<3>(), f = record.wrench_B[i].tail<3>();
    const StateTangent& T = nodes[i];
    Mat6 U, V;
    for (int c = 0; c < 6; ++c) {
      // A = Rᵀ dR is skew to first order: δθ_B = vee(A), from its antisymmetric part.
      Mat3 A;
      for (int j = 0; j < 3; ++j) A.col(j) = R.transpose() * T.block<3, 1>(3 + 3 * j, c);
      const Vec3 dtheta(0.5 * (A(2, 1) - A(1, 2)), 0.5 * (A(0, 2) - A(2, 0)),
                        0.5 * (A(1, 0) - A(0, 1)));
      U.col(c) << dtheta, R.transpose() * T.block<3, 1>(0, c);
      V.col(c) << T.block<3, 1>(12, c) - m.cross(dtheta), T.block<3, 1>(15, c) - f.cross(dtheta);
    }
    negative = i + 1 < n ? NegativeEigenvaluesFast(U, V)
                         : NegativeEigenvalues(U, V, model_.length, zero);
    if (negative < 0) return -1;  // U singular to rounding at a node: no count
    if (negative < previous) conjugate += previous - negative;
    previous = negative;
  }
  return conjugate + negative;
}

}  // namespace cosserat
