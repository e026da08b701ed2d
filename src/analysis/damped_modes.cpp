// The damped modes of a quaternion-FD linearisation: the pairs of λ² M + λ C + K = 0, each
// matched to the undamped mode it belongs to (damped_modes.hpp).
#include "damped_modes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

namespace cosserat::detail {

namespace {

constexpr double kTwoPi = 6.283185307179586;

/// A damped pair λ (Im λ > 0) of a first-order form and, when its coordinates are the undamped
/// modal ones z = [Ω η; η̇], the share of its energy in each undamped mode j:
/// (Ω_j² + |λ|²) |η_j|², normalised.
struct DampedPair {
  DampedMode mode;
  Eigen::VectorXd share;  ///< empty when the coordinates are not modal
};

/// The shares of the pair λ of the modal form [[0, Ω], [−Ω, −D]]: its η solves
/// (λ² I + λ D + Ω²) η = 0, found by inverse iteration at λ (an eigenvalue to round-off, so
/// two solves converge; where the matrix is singular to the bit, at λ moved by 1e-12 |λ|). One
/// complex LU of the modal size per pair, for 2n + 6 pairs: all the first-order form's
/// eigenvectors took 3.7 times as long as its eigenvalues alone, these LUs 1.2–2.5 times.
Eigen::VectorXd ModalShares(const Eigen::MatrixXd& companion, std::complex<double> l) {
  const Eigen::Index k = companion.rows() / 2;
  const Eigen::VectorXd om = companion.topRightCorner(k, k).diagonal();
  for (const double shift : {0.0, 1e-12}) {
    const std::complex<double> at = l * (1.0 + shift);
    Eigen::MatrixXcd Q = -at * companion.bottomRightCorner(k, k).cast<std::complex<double>>();
    Q.diagonal().array() += at * at + om.array().square();
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(Q);
    Eigen::VectorXcd eta = Eigen::VectorXcd::Ones(k);
    for (int sweep = 0; sweep < 2; ++sweep) eta = lu.solve(eta).normalized();
    const Eigen::VectorXd e = (om.array().square() + std::norm(l)) * eta.cwiseAbs2().array();
    if (e.allFinite() && e.sum() > 0) return e / e.sum();
  }
  return Eigen::VectorXd();
}

/// The eigenvalues λ of a plain companion matrix [[0, I], [K, C]], accurate at its low end. A
/// rod's K spans its stiffness's whole range (1e3 to 4e13 1/s² on a 1 mm wire), and the
/// eigensolver's error, ε times that norm, moved a damped frequency of 4.2 Hz by 2.5 % with
/// the equilibrium's round-off (and made a 313 Hz pair grow). With λ = γ μ, γ = sqrt(‖K‖)
/// (Fan, Lin & Van Dooren 2004), [[0, I], [K', C']] = [[0, I], [K/γ², C/γ]] has blocks of one
/// size; its low pairs, the ones the modes take, are the largest eigenvalues ν = 1/μ of its
/// inverse [[−K'⁻¹C', K'⁻¹], [I, 0]], where they keep their relative accuracy (the same rod
/// turned 90° about its axis gave the first pair to 4e-4 from the scaled matrix, to 1e-9 so). A
/// singular K (a rod at a critical load) is solved in the scaled form.
Eigen::VectorXcd CompanionEigenvalues(const Eigen::MatrixXd& companion) {
  const Eigen::Index m = companion.rows() / 2;
  const double stiffness = companion.bottomLeftCorner(m, m).norm();
  const double gamma = stiffness > 0 && std::isfinite(stiffness) ? std::sqrt(stiffness) : 1.0;
  const Eigen::MatrixXd K = companion.bottomLeftCorner(m, m) / (gamma * gamma),
                        C = companion.bottomRightCorner(m, m) / gamma;
  const Eigen::MatrixXd K_inverse = K.partialPivLu().inverse();
  if (K_inverse.allFinite()) {
    Eigen::MatrixXd inverse = Eigen::MatrixXd::Zero(2 * m, 2 * m);
    inverse.topLeftCorner(m, m) = -K_inverse * C;
    inverse.topRightCorner(m, m) = K_inverse;
    inverse.bottomLeftCorner(m, m).setIdentity();
    const Eigen::EigenSolver<Eigen::MatrixXd> es(inverse, false);
    return gamma * es.eigenvalues().cwiseInverse();  // ν = 0 (no pair) becomes infinite
  }
  Eigen::MatrixXd scaled(2 * m, 2 * m);
  scaled << Eigen::MatrixXd::Zero(m, m), Eigen::MatrixXd::Identity(m, m), K, C;
  const Eigen::EigenSolver<Eigen::MatrixXd> es(scaled, false);
  return gamma * es.eigenvalues();
}

/// The lowest `count` pairs of `companion` by |λ|, with their shares when its coordinates are
/// `modal` (SymmetricSpectrum's form, nearly normal: its eigenvalues are taken as they are).
std::vector<DampedPair> DampedPairs(const Eigen::MatrixXd& companion, bool modal, int count) {
  const Eigen::VectorXcd lambda = modal
                                      ? Eigen::VectorXcd(Eigen::EigenSolver<Eigen::MatrixXd>(
                                                             companion, false)
                                                             .eigenvalues())
                                      : CompanionEigenvalues(companion);
  // An overdamped mode's slow root sits near −1/τ for every mode damped as τ K: hundreds of
  // equal real roots, which the eigensolver splits into pairs with Im λ up to 1e-5 |λ| (a wire
  // on 41 and 161 nodes). Below a mode's |λ| they took the places of its pair (ζ = 0.7 came out
  // overdamped). A pair needs Im λ > 1e-3 |λ|: ζ < 0.9999995, beyond which a mode is taken as
  // critically damped.
  std::vector<std::complex<double>> roots;
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    const std::complex<double> l = lambda(i);
    if (std::isfinite(std::abs(l)) && l.imag() > 1e-3 * std::abs(l)) roots.push_back(l);
  }
  std::sort(roots.begin(), roots.end(),
            [](const auto& a, const auto& b) { return std::abs(a) < std::abs(b); });
  if (static_cast<int>(roots.size()) > count) roots.resize(count);
  std::vector<DampedPair> pairs;
  for (const std::complex<double> l : roots) {
    DampedPair p;
    p.mode.omega_n = std::abs(l);
    p.mode.damped_frequency_hz = l.imag() / kTwoPi;
    p.mode.damping_ratio = 0.0 - l.real() / p.mode.omega_n;  // an undamped mode's 0, not −0
    if (modal) p.share = ModalShares(companion, l);
    pairs.push_back(std::move(p));
  }
  return pairs;
}

/// The undamped modes closer than this fraction of ω form one cluster: a pair's share is counted
/// over its cluster, since the damping turns a degenerate pair (a round rod's two bending planes,
/// split by round-off) at will. A physical split, a rubber bar's 3.5 % or a curled finger's 1 %,
/// is far wider.
constexpr double kClusterGap = 1e-3;

/// The damped pair of each undamped mode, in the modes' order; none (NaN frequency and ratio)
/// for an overdamped mode, a divergent one (ω² < 0) or one no pair is found for. A growing
/// oscillation's pair is listed (ζ < 0).
/// - Modal coordinates (`omega`: their ω, ascending): by shape. A pair is the cluster's that
///   holds more than half its energy, and a cluster's pairs go to its modes in the order of
///   |λ|. A curled pneumatic finger damped in bending only mixes its bending and torsion modes:
///   its third mode's pair holds 2/3 of its energy there and 1/3 in the torsion mode, at |λ|
///   13 % above ω, where matching by |λ| finds none. Damped hard enough, its bending modes are
///   overdamped and the pairs left are modes of the rod with its bending held by the dampers,
///   with under half their energy in any one undamped mode: nobody's.
/// - Otherwise by |λ|: the unused pair nearest the mode's ω, within 2 % (damping proportional to
///   the stiffness keeps |λ| = ω; light damping of other forms moves it by O(ζ²)).
std::vector<DampedMode> AlignDamped(const std::vector<Mode>& modes,
                                    const std::vector<DampedPair>& pairs,
                                    const Eigen::VectorXd& omega) {
  const int n = static_cast<int>(modes.size());
  std::vector<int> pair_of(n, -1);
  if (omega.size() > 0) {
    const int k = static_cast<int>(omega.size());
    std::vector<int> first_of{0};  // the first coordinate of each cluster, and k at the end
    for (int j = 1; j < k; ++j)
      if (omega(j) - omega(j - 1) > kClusterGap * std::abs(omega(j))) first_of.push_back(j);
    first_of.push_back(k);
    for (size_t c = 0; c + 1 < first_of.size() && first_of[c] < n; ++c) {
      const int from = first_of[c], to = first_of[c + 1];
      int next = from;  // pairs come by |λ|: the cluster's modes take them in that order
      for (int j = 0; j < static_cast<int>(pairs.size()) && next < std::min(to, n); ++j)
        if (pairs[j].share.size() == k && pairs[j].share.segment(from, to - from).sum() > 0.5)
          pair_of[next++] = j;
    }
  } else {
    std::vector<bool> used(pairs.size(), false);
    for (int i = 0; i < n; ++i) {
      const double w = modes[i].omega;
      for (int j = 0; j < static_cast<int>(pairs.size()); ++j) {
        const double gap = std::abs(pairs[j].mode.omega_n - w);
        if (!used[j] && w > 0 && gap <= 0.02 * w &&
            (pair_of[i] < 0 || gap < std::abs(pairs[pair_of[i]].mode.omega_n - w)))
          pair_of[i] = j;
      }
      if (pair_of[i] >= 0) used[pair_of[i]] = true;
    }
  }
  std::vector<DampedMode> aligned;
  for (int i = 0; i < n; ++i) {
    DampedMode d;
    d.omega_n = modes[i].omega;
    d.damped_frequency_hz = d.damping_ratio = std::numeric_limits<double>::quiet_NaN();
    aligned.push_back(pair_of[i] >= 0 ? pairs[pair_of[i]].mode : d);
  }
  return aligned;
}

/// The pairs of λ² M + λ C + K = 0, through a first-order form: the modal one SymmetricSpectrum
/// left in *companion, or the plain companion matrix [[0, I], [Ar, Br]] when the stiffness is not
/// symmetric.
std::vector<DampedPair> DampedSpectrum(bool symmetric, const Eigen::MatrixXd& Ar,
                                       const Eigen::MatrixXd& Br, int count,
                                       Eigen::MatrixXd* companion) {
  if (!symmetric) {
    const Eigen::Index m = Ar.rows();
    *companion = Eigen::MatrixXd::Zero(2 * m, 2 * m);
    companion->topRightCorner(m, m).setIdentity();
    companion->bottomLeftCorner(m, m) = Ar;
    companion->bottomRightCorner(m, m) = Br;
  }
  return DampedPairs(*companion, symmetric, count);
}

}  // namespace

bool DampedOfModes(bool symmetric, const Eigen::MatrixXd& Ar, const Eigen::MatrixXd& Br,
                   const std::vector<Mode>& modes, double judged_above,
                   Eigen::MatrixXd* companion, std::vector<DampedMode>* out) {
  const std::vector<DampedPair> pairs =
      DampedSpectrum(symmetric, Ar, Br, 2 * static_cast<int>(modes.size()) + 6, companion);
  const Eigen::VectorXd modal_omega =
      symmetric ? Eigen::VectorXd(companion->topRightCorner(companion->rows() / 2,
                                                            companion->cols() / 2)
                                      .diagonal())
                : Eigen::VectorXd();
  *out = AlignDamped(modes, pairs, modal_omega);
  for (const DampedPair& p : pairs)  // a growing pair, whichever mode it belongs to
    if (p.mode.omega_n > judged_above && p.mode.damping_ratio < -1e-9) return true;
  return false;
}

}  // namespace cosserat::detail
