// The Morse index of a rod equilibrium found by shooting, by a Sturm count along s.
//
// Jacobi fields. Vary the shot's unknowns (those that satisfy the base end conditions): the
// shot's tangent gives, at every node s, the variation of the pose, η(s) = [δθ_B; δp_B]
// (R⁻¹δR = δθ_B^, δp_B = Rᵀ δp_W; rad, m), and of the wrench, δW_B(s) (N·m, N), for 6
// independent directions: U(s) = ∂η/∂u, and the wrench block.
//
// The rod [0, σ] held at 0 by its base conditions and loaded at σ by the dead wrench it carries
// at equilibrium has the potential V_σ(η(σ)) (the rest of the rod relaxed). Its gradient in the
// pairing dV = m_B·δθ_B + n_B·δp_B is the tip residual r = W_B(σ) − [Rᵀ M_W; Rᵀ F_W], and its
// Hessian at the equilibrium (r = 0), H(σ) = ∂r/∂η = V(σ) U(σ)⁻¹ with
// V = [δm − m × δθ; δn − n × δθ] (δ(Rᵀ F_W) = n_B × δθ_B for a dead force), is the stiffness of
// [0, σ] seen at σ. Near a clamped base it is ≈ K/σ: positive definite. Where U is singular (a
// conjugate point, or a focal point of a pinned base: the problem on [0, σ] held fixed at σ is
// singular) one eigenvalue passes to −∞ and comes back from +∞, always that way round (the
// Riccati equation of the Jacobi fields is dominated there by −H K⁻¹ H, K positive definite: the
// Legendre condition).
// The index with the real tip conditions is then
//     (conjugate points in (0, L)) + (negative eigenvalues of H(L) on the admissible η(L)),
// the Morse index theorem. At a conjugate point one eigenvalue of H wraps from −∞ to +∞, so the
// count of its negative eigenvalues drops; but it also drops where an eigenvalue rises through
// zero, which the eigenvalues of H are free to do (they fall monotonically only near a pole: a
// pinned beam sagging under its weight has one that does, near the pin). So a change of that
// count, or of the sign of det U (a pole and a rise through zero in one interval leave the count
// alone: a pipe in a bore between two close Winkler roots), only says where to look. There the
// conjugate points are counted by the multi-dimensional Prüfer angles (Atkinson 1964; Reid
// 1980): (U, V) spans a Lagrangian subspace (Uᵀ V symmetric), W = (U + iV)(U − iV)⁻¹ is
// unitary, and W has the eigenvalue −1 exactly where U is singular.
// With K positive definite the eigenvalues e^{iφ} of W pass −1 only one way (φ decreasing), so
// the passes between two nodes are (ΔΨ − ΔΦ) / 2π, with Ψ the sum of the principal angles
// φ ∈ (−π, π] and ΔΦ = 2 Δarg det(U + iV) their continuous change. A double root (a circular
// section buckles in two planes at once; det U and det J touch zero without changing sign) is two
// passes.
//
// A guided or clamped tip. Its constraints (the lateral position in the world; a clamped tip's
// rotation) carry reactions; treating the whole tip wrench as dead in the world frame, as V does,
// makes V_σ the Lagrangian, stationary at the equilibrium, whose Hessian restricted to the
// admissible variations is the second variation of the constrained problem. The lateral
// constraint is linear in p_W (no curvature term); the rotation constraint of a clamped tip
// leaves no rotation to vary. So the tip term counts the negative eigenvalues of Zᵀ H(L) Z, Z an
// orthonormal basis of the admissible η(L) (in the units of Units).
#include "cosserat/strong/morse_index.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <algorithm>
#include <complex>
#include <functional>
#include <vector>

namespace cosserat {

namespace {

// The units in which rotations (rad) and displacements (m) are comparable through the length
// scale `ell`: y = D η = [δθ; δp/ell] (congruence keeps every count), and D⁻¹ V = [δm; ell δn].
Vec6 Units(double ell) {
  Vec6 d;
  d << Vec3::Constant(1.0), Vec3::Constant(1.0 / ell);
  return d;
}

// The symmetric part of H' = D⁻¹ H D⁻¹ = (D⁻¹ V)(D U)⁻¹ (N·m), solved as a transpose:
// (D U)ᵀ H'ᵀ = (D⁻¹ V)ᵀ. False when it is not finite (U singular to rounding).
bool ScaledStiffness(const Mat6& U, const Mat6& V, double ell, Mat6* Hs) {
  const Vec6 d = Units(ell);
  const Mat6 Ht = (d.asDiagonal() * U).transpose().partialPivLu().solve(
      (d.cwiseInverse().asDiagonal() * V).transpose());
  *Hs = 0.5 * (Ht + Ht.transpose());
  return Hs->allFinite();
}

// Negative eigenvalues (below −zero, N·m) of the scaled stiffness Hs on the admissible tip
// variations, D · span(tip), orthonormalised.
int NegativeEigenvalues(const Mat6& Hs, const TipVariations& tip, double ell, double zero) {
  const Eigen::HouseholderQR<TipVariations> qr(Units(ell).asDiagonal() * tip);
  const TipVariations Z = qr.householderQ() * TipVariations::Identity(6, tip.cols());
  const Eigen::MatrixXd Hz = Z.transpose() * Hs * Z;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Hz, Eigen::EigenvaluesOnly);
  int negative = 0;
  for (int k = 0; k < Hz.rows(); ++k) negative += eig.eigenvalues()(k) < -zero;
  return negative;
}

// The count on all of η without the threshold, cheaply, for the interior nodes: Uᵀ H U = Uᵀ V,
// so the symmetric part of Uᵀ V is congruent to that of H (symmetrising commutes with
// congruence) and has its inertia (Sylvester), read off the pivots of an LDLᵀ factorisation
// (6 × 6, no inverse). Falls back to the eigenvalues if the diagonal pivoting breaks down (a
// zero pivot).
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

// The Prüfer angles' passes of −1 between the frames (U0, V0) and (U1, V1) of two neighbouring
// nodes, in the units of Units (y = D η, D⁻¹ V), with V also divided by a stiffness c > 0 (N·m).
// Where U is invertible, W = (U + iV/c)(U − iV/c)⁻¹ is the Cayley transform of H/c: its angles
// are φ_k = 2 atan(μ_k / c), μ_k the eigenvalues of sym(H), and
// arg det(U + iV/c) = arg det U + Σ atan(μ_k / c). The count needs the continuous change ΔΦ of
// 2 arg det(U + iV/c) between the nodes, but the ratio of the determinants gives it only modulo
// 2π, and |ΔΦ| < π/2 read from it does not rule out a true ΔΦ of ±2π or ±4π. How far an angle
// turns depends on c (the count does not): an eigenvalue that passes its pole between the nodes
// turns almost a full circle unless c is well below |μ| at both nodes, one that passes zero
// unless c is well above. So c is tried on a ladder from the ratio of V's and U's sizes outwards
// (two per decade over 16 decades either way) and in every gap of the |μ| of both nodes, and the
// readings kept are the whole numbers ≥ 0 with |ΔΦ| < π/2 and the parity of det U's change
// (`odd`: it changes sign at each simple pass), in the order tried. A lost simple pass shows as
// the wrong parity, but two lost or two false ones do not, and from the two nodes alone a pair of
// conjugate points (a round rod's double root) reads exactly as a pair of eigenvalues rising
// through zero: 2 at small c, 0 at large c, either way. Readings that differ say so.
struct PrueferReading {
  int first = -1;          ///< the first reading (from the ladder's start); −1: none
  bool ambiguous = false;  ///< the readings differ
};

PrueferReading PrueferPasses(const Mat6& U0, const Mat6& V0, const Mat6& U1, const Mat6& V1,
                             double ell, bool odd) {
  PrueferReading out;
  const Vec6 d = Units(ell);
  const Mat6 Us0 = d.asDiagonal() * U0, Vs0 = d.cwiseInverse().asDiagonal() * V0;
  const Mat6 Us1 = d.asDiagonal() * U1, Vs1 = d.cwiseInverse().asDiagonal() * V1;
  // The eigenvalues μ of sym(H) at each node.
  Mat6 H0, H1;
  if (!ScaledStiffness(U0, V0, ell, &H0) || !ScaledStiffness(U1, V1, ell, &H1)) return out;
  const Vec6 mu0 = Eigen::SelfAdjointEigenSolver<Mat6>(H0, Eigen::EigenvaluesOnly).eigenvalues();
  const Vec6 mu1 = Eigen::SelfAdjointEigenSolver<Mat6>(H1, Eigen::EigenvaluesOnly).eigenvalues();
  using CMat6 = Eigen::Matrix<std::complex<double>, 6, 6>;
  const std::complex<double> i(0.0, 1.0);
  auto det = [&](const Mat6& Us, const Mat6& Vs, double c) {
    const CMat6 P = Us.cast<std::complex<double>>() + i * (Vs / c).cast<std::complex<double>>();
    return P.partialPivLu().determinant();
  };
  std::vector<double> trials;
  const double c0 = Us0.norm() > 0 && Vs0.norm() > 0 ? Vs0.norm() / Us0.norm() : 1.0;
  for (int j = 0; j <= 64; ++j)  // c0, then c0 · 10^(±1/2), c0 · 10^(±1), … alternating
    trials.push_back(c0 * std::pow(10.0, (j % 2 == 0 ? 1.0 : -1.0) * ((j + 1) / 2) / 2.0));
  std::vector<double> sizes;
  for (int k = 0; k < 6; ++k) {
    if (mu0(k) != 0.0) sizes.push_back(std::abs(mu0(k)));
    if (mu1(k) != 0.0) sizes.push_back(std::abs(mu1(k)));
  }
  std::sort(sizes.begin(), sizes.end());
  for (std::size_t k = 0; k + 1 < sizes.size(); ++k) {
    if (sizes[k + 1] > 4.0 * sizes[k]) trials.push_back(std::sqrt(sizes[k] * sizes[k + 1]));
  }
  for (const double c : trials) {
    if (!std::isfinite(c) || c <= 0.0) continue;
    double dpsi = 0.0;
    for (int k = 0; k < 6; ++k) dpsi += 2.0 * (std::atan(mu1(k) / c) - std::atan(mu0(k) / c));
    const double dphi = 2.0 * std::arg(det(Us1, Vs1, c) / det(Us0, Vs0, c));
    if (!std::isfinite(dphi) || std::abs(dphi) > 0.5 * M_PI) continue;
    const double passes = (dpsi - dphi) / (2.0 * M_PI);
    const double whole = std::round(passes);
    if (std::abs(passes - whole) >= 0.05 || whole < 0) continue;
    const int n = static_cast<int>(whole);
    if ((n % 2 == 1) != odd) continue;
    if (out.first < 0) out.first = n;
    out.ambiguous = out.ambiguous || n != out.first;
  }
  return out;
}

// The Jacobi frame at a node: U = [δθ_B; δp_B] and V = [δm − m × δθ; δn − n × δθ] (body frame)
// of the 6 directions of T, at the node's rotation R and wrench W = [m; n].
void JacobiFrame(const Mat3& R, const Vec6& W, const ShotTangent& T, Mat6* U, Mat6* V) {
  constexpr int kP = 0, kR = 3, kM = 12, kN = 15;  // rows of a ShotTangent
  const Vec3 m = W.head<3>(), f = W.tail<3>();
  for (int c = 0; c < 6; ++c) {
    // A = Rᵀ dR is skew to first order: δθ_B = vee(A), from its antisymmetric part.
    Mat3 A;
    for (int j = 0; j < 3; ++j) A.col(j) = R.transpose() * T.block<3, 1>(kR + 3 * j, c);
    const Vec3 dtheta(0.5 * (A(2, 1) - A(1, 2)), 0.5 * (A(0, 2) - A(2, 0)),
                      0.5 * (A(1, 0) - A(0, 1)));
    U->col(c) << dtheta, R.transpose() * T.block<3, 1>(kP, c);
    V->col(c) << T.block<3, 1>(kM, c) - m.cross(dtheta), T.block<3, 1>(kN, c) - f.cross(dtheta);
  }
}

// A node of the sweep along s: its Jacobi frame, the number of negative eigenvalues of sym(H)
// there (`negative`, set by the caller) and the sign of det U.
struct SweepNode {
  Mat6 U, V;
  int negative = 0;
  bool det_positive = true;
};

// The node's frame and det U's sign; false where det U is exactly zero (no count).
bool FrameAt(const Mat3& R, const Vec6& W, const ShotTangent& T, SweepNode* node) {
  JacobiFrame(R, W, T, &node->U, &node->V);
  const double det_u = node->U.determinant();
  node->det_positive = det_u > 0;
  return det_u != 0.0;
}

// The conjugate points between two neighbouring nodes of the sweep: looked for only where the
// count or det U's sign changes; where the readings differ, `refined` counts them on a
// refinement of the segment (−1: it cannot, and the first reading stands). −1 when there is no
// reading.
int PassesBetween(const SweepNode& a, const SweepNode& b, double ell,
                  const std::function<int()>& refined) {
  if (a.negative == b.negative && a.det_positive == b.det_positive) return 0;
  const PrueferReading r =
      PrueferPasses(a.U, a.V, b.U, b.V, ell, a.det_positive != b.det_positive);
  if (r.first < 0) return -1;
  const int on_refinement = r.ambiguous && refined ? refined() : -1;
  return on_refinement >= 0 ? on_refinement : r.first;
}

// Refinement of an ambiguous segment: its steps.
constexpr int kRefinedParts = 16;

// The passes in segment i from its refinement, each sub-interval read as PassesBetween reads
// (its first reading if still ambiguous). −1 when the refinement cannot be made or a
// sub-interval has no reading.
int PassesOnRefinement(const RefineSegment& refine, int i, double ell) {
  RodState states;
  std::vector<ShotTangent> tangents;
  if (!refine || !refine(i, kRefinedParts, &states, &tangents) ||
      static_cast<int>(tangents.size()) != kRefinedParts + 1)
    return -1;
  int passes = 0;
  SweepNode previous, node;
  for (int k = 0; k <= kRefinedParts; ++k) {
    if (!FrameAt(states.rotation_WB[k], states.wrench_B[k], tangents[k], &node)) return -1;
    node.negative = NegativeEigenvaluesFast(node.U, node.V);
    if (node.negative < 0) return -1;
    if (k > 0) {
      const int n = PassesBetween(previous, node, ell, nullptr);
      if (n < 0) return -1;
      passes += n;
    }
    previous = node;
  }
  return passes;
}

}  // namespace

int MorseIndexOfShot(const RodState& record, const std::vector<ShotTangent>& nodes,
                     const TipVariations& tip, double length, double zero,
                     const RefineSegment& refine) {
  const int n = static_cast<int>(nodes.size());
  int conjugate = 0, negative = 0;
  SweepNode previous, node;
  for (int i = 1; i < n; ++i) {
    // U singular to rounding at a node (det U exactly zero, or no inertia): no count.
    if (!FrameAt(record.rotation_WB[i], record.wrench_B[i], nodes[i], &node)) return -1;
    // The count on all of η (at the tip with the threshold) says where to look for conjugate
    // points; the tip term counts on the admissible variations.
    const bool at_tip = i + 1 == n;
    Mat6 Hs;
    if (at_tip && !ScaledStiffness(node.U, node.V, length, &Hs)) return -1;
    node.negative = at_tip ? NegativeEigenvalues(Hs, TipVariations::Identity(6, 6), length, zero)
                           : NegativeEigenvaluesFast(node.U, node.V);
    if (node.negative < 0) return -1;
    if (i > 1) {
      const int passes = PassesBetween(previous, node, length,
                                       [&] { return PassesOnRefinement(refine, i - 1, length); });
      if (passes < 0) return -1;
      conjugate += passes;
    }
    previous = node;
    negative = node.negative;
    if (at_tip && tip.cols() < 6) negative = NegativeEigenvalues(Hs, tip, length, zero);
  }
  return conjugate + negative;
}

}  // namespace cosserat
