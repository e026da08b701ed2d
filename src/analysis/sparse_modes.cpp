#include "sparse_modes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "banded_inertia.hpp"

namespace cosserat::detail {
namespace {

/// Start vectors with entries in [−1, 1] from a fixed linear congruential sequence: the same
/// modes on every run.
Eigen::MatrixXd StartVectors(int m, int p) {
  Eigen::MatrixXd X(m, p);
  std::uint64_t state = 88172645463325252ull;
  for (int j = 0; j < p; ++j)
    for (int i = 0; i < m; ++i) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      X(i, j) = static_cast<double>(state >> 11) / 9007199254740992.0 * 2.0 - 1.0;
    }
  return X;
}

/// An orthonormal basis of X's columns (thin QR).
Eigen::MatrixXd Orthonormal(const Eigen::MatrixXd& X) {
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(X);
  return qr.householderQ() * Eigen::MatrixXd::Identity(X.rows(), X.cols());
}

/// Subspace iterations before giving up (each gains a factor ω²_k / ω²_{p+1} per mode k; the
/// slowest of a cable's near-double pairs took 60).
constexpr int kMaxIterations = 400;
/// The relative change of the lowest ω² between iterations that ends them.
constexpr double kSettled = 1e-12;
/// How far above the last ω² found (relative) Sylvester's count must agree with the modes found.
constexpr double kSylvesterMargin = 1e-6;

}  // namespace

Eigen::SparseMatrix<double> SparseMassPower(const Reduction& red, double e) {
  const int m = static_cast<int>(red.mass.size());
  std::vector<bool> in_block(m, false);
  std::vector<Eigen::Triplet<double>> entries;
  for (const VertexMassBlock& b : red.mass_blocks) {
    const Mat3 P = b.Power(e);
    for (int i = 0; i < 3; ++i) {
      in_block[b.column + i] = true;
      for (int j = 0; j < 3; ++j) entries.emplace_back(b.column + i, b.column + j, P(i, j));
    }
  }
  for (int i = 0; i < m; ++i)
    if (!in_block[i]) entries.emplace_back(i, i, std::pow(red.mass(i), e));
  Eigen::SparseMatrix<double> M(m, m);
  M.setFromTriplets(entries.begin(), entries.end());
  return M;
}

bool LowestModesSparse(const Eigen::SparseMatrix<double>& K, const Reduction& red, int count,
                       bool shapes, std::vector<std::pair<double, Eigen::VectorXd>>* eig) {
  eig->clear();
  const int m = static_cast<int>(K.rows());
  const std::vector<int> order = AlongTheRod(red.vertex_column, red.segment_column, m);
  if (count < 1 || m < count || order.empty()) return false;
  const Eigen::SparseMatrix<double> root = SparseMassPower(red, -0.5);  // M^−½
  const Eigen::SparseMatrix<double> Kt = K.transpose();
  const Eigen::SparseMatrix<double> H = root * (0.5 * (K + Kt)) * root;
  const SymmetricBand band = BandInOrder(H, order);
  BandedLdlt ldlt;
  if (!ldlt.Factorize(band, 0.0, 0.0) || ldlt.negative_pivots() > 0) return false;
  // In the banded order throughout; μ = 1/ω², the largest first.
  const int p = std::min(m, 2 * count + 8);
  Eigen::MatrixXd X = StartVectors(m, p), Q, Y(m, p);
  Eigen::VectorXd mu, previous;
  bool settled = false;
  for (int it = 0; it < kMaxIterations && !settled; ++it) {
    Q = Orthonormal(X);
    Y = Q;
    for (int j = 0; j < p; ++j) ldlt.Solve(Y.col(j));  // H⁻¹ Q
    Eigen::MatrixXd T = Q.transpose() * Y;
    T = 0.5 * (T + T.transpose()).eval();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(T);
    mu = es.eigenvalues().reverse();  // descending: the lowest modes first
    const Eigen::MatrixXd V = es.eigenvectors().rowwise().reverse();
    X = Y * V;  // the next power step of the Ritz vectors
    if (it > 0) {
      double change = 0.0;
      for (int k = 0; k < count; ++k)
        change = std::max(change, std::abs(mu(k) - previous(k)) / std::abs(mu(k)));
      settled = change <= kSettled;
    }
    previous = mu;
    if (settled) X = Q * V;  // the Ritz vectors of this basis
  }
  if (!settled || !(mu(count - 1) > 0)) return false;
  // Sylvester: as many eigenvalues of H below the last ω² found (and its repeats) as found.
  // The margin stands clear of what either spectrum resolves on the most slender rods (1e-7 of
  // ω² for a 0.1 mm wire: the count at 1e-8 above it missed a pair).
  const double top = 1.0 / mu(count - 1) * (1.0 + kSylvesterMargin);
  int found = 0;
  while (found < p && 1.0 / mu(found) <= top) ++found;
  if (!ldlt.Factorize(band, -top, 0.0) || ldlt.negative_pivots() != found) return false;
  for (int k = 0; k < count; ++k) {
    Eigen::VectorXd shape;
    if (shapes) {
      Eigen::VectorXd psi(m);  // back from the banded order
      const Eigen::VectorXd x = X.col(k).normalized();
      for (int i = 0; i < m; ++i) psi(order[i]) = x(i);
      shape = root * psi;
    }
    eig->emplace_back(1.0 / mu(k), std::move(shape));
  }
  return true;
}

}  // namespace cosserat::detail
