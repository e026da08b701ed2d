#include "cosserat/numerics/banded_matrix.hpp"

#include <algorithm>
#include <vector>
#include <cmath>
#include <utility>

namespace cosserat {

void BandedMatrix::Resize(int n, int kl, int ku) {
  n_ = n;
  kl_ = kl;
  ku_ = ku;
  kv_ = kl + ku;          // row of the diagonal in the band storage
  ld_ = 2 * kl + ku + 1;  // kl rows of fill-in above the ku + kl + 1 band rows
  data_.assign(static_cast<size_t>(ld_) * std::max(n, 0), 0.0);
  pivot_.assign(std::max(n, 0), 0);
  row_end_.assign(std::max(n, 0), 0);
  u_top_.assign(std::max(n, 0), 0);
}

void BandedMatrix::SetZero() { std::fill(data_.begin(), data_.end(), 0.0); }

void BandedMatrix::Multiply(const Eigen::Ref<const Eigen::VectorXd>& x,
                            Eigen::Ref<Eigen::VectorXd> y) const {
  y.setZero();
  for (int j = 0; j < n_; ++j) {
    const double xj = x[j];
    const int i0 = std::max(0, j - ku_), i1 = std::min(n_ - 1, j + kl_);
    const double* col = &data_[kv_ - j + j * ld_];
    for (int i = i0; i <= i1; ++i) y[i] += col[i] * xj;
  }
}

Eigen::SparseMatrix<double> BandedMatrix::ToSparse() const {
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < n_; ++j)
    for (int i = std::max(0, j - ku_); i <= std::min(n_ - 1, j + kl_); ++i)
      if ((*this)(i, j) != 0.0) entries.emplace_back(i, j, (*this)(i, j));
  Eigen::SparseMatrix<double> A(n_, n_);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

Eigen::MatrixXd BandedMatrix::ToDense() const {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n_, n_);
  for (int j = 0; j < n_; ++j)
    for (int i = std::max(0, j - ku_); i <= std::min(n_ - 1, j + kl_); ++i) A(i, j) = (*this)(i, j);
  return A;
}

namespace {
// Row i of U can be non-zero only up to column row_end[i] (the last column the interchanges up to
// step i have touched, non-decreasing in i); every other fill-in entry stays exactly zero. So
// column j of U is non-zero only from row u_top[j] = min{i : row_end[i] ≥ j} down, which is
// j − ku when no rows were interchanged instead of j − kl − ku: the back substitution skips the
// zero entries (the same result, bit for bit, for finite values).
void UpperTops(const std::vector<int>& row_end, std::vector<int>* u_top) {
  int i = 0;
  for (size_t j = 0; j < u_top->size(); ++j) {
    while (row_end[i] < static_cast<int>(j)) ++i;
    (*u_top)[j] = i;
  }
}
}  // namespace

bool BandedMatrix::Factorize() {
  // dgbtf2: column j of L below the diagonal is stored in place; U gets up to kl + ku
  // super-diagonals because of the row interchanges. The fill-in rows must start at zero.
  for (int j = 0; j < n_; ++j)
    for (int r = 0; r < kl_; ++r) data_[r + j * ld_] = 0.0;
  int ju = 0;  // last column touched by the interchanges so far
  for (int j = 0; j < n_; ++j) {
    const int km = std::min(kl_, n_ - 1 - j);
    double* colj = &data_[kv_ + j * ld_];  // colj[i] = A(j + i, j)
    int jp = 0;
    double best = std::abs(colj[0]);
    for (int i = 1; i <= km; ++i)
      if (std::abs(colj[i]) > best) best = std::abs(colj[i]), jp = i;
    pivot_[j] = j + jp;
    if (colj[jp] == 0.0) return false;
    ju = std::max(ju, std::min(j + ku_ + jp, n_ - 1));
    row_end_[j] = ju;
    if (jp != 0)
      for (int c = j; c <= ju; ++c) std::swap((*this)(j, c), (*this)(j + jp, c));
    if (km > 0) {
      const double inv = 1.0 / colj[0];
      for (int i = 1; i <= km; ++i) colj[i] *= inv;
      for (int c = j + 1; c <= ju; ++c) {
        const double ajc = (*this)(j, c);
        if (ajc == 0.0) continue;
        double* colc = &data_[kv_ + j - c + c * ld_];  // colc[i] = A(j + i, c)
        for (int i = 1; i <= km; ++i) colc[i] -= colj[i] * ajc;
      }
    }
  }
  UpperTops(row_end_, &u_top_);
  return true;
}

void BandedMatrix::Solve(Eigen::Ref<Eigen::VectorXd> rhs) const {
  double* __restrict b = rhs.data();
  const double* __restrict d = data_.data();
  // L y = P b.
  for (int j = 0; j < n_; ++j) {
    if (pivot_[j] != j) std::swap(b[j], b[pivot_[j]]);
    const int km = std::min(kl_, n_ - 1 - j);
    const double* colj = d + kv_ + j * ld_;  // colj[i] = L(j + i, j)
    const double bj = b[j];
    for (int i = 1; i <= km; ++i) b[j + i] -= colj[i] * bj;
  }
  // U x = y; column j of U is non-zero from row u_top_[j] (at most kl + ku above the diagonal).
  for (int j = n_ - 1; j >= 0; --j) {
    const double* colj = d + kv_ - j + j * ld_;  // colj[i] = U(i, j)
    b[j] /= colj[j];
    const double bj = b[j];
    for (int i = u_top_[j]; i < j; ++i) b[i] -= colj[i] * bj;
  }
}

void ComplexBandedMatrix::Resize(int n, int kl, int ku) {
  n_ = n;
  kl_ = kl;
  ku_ = ku;
  kv_ = kl + ku;
  ld_ = 2 * kl + ku + 1;
  re_.assign(static_cast<size_t>(ld_) * std::max(n, 0), 0.0);
  im_.assign(static_cast<size_t>(ld_) * std::max(n, 0), 0.0);
  pivot_.assign(std::max(n, 0), 0);
  row_end_.assign(std::max(n, 0), 0);
  u_top_.assign(std::max(n, 0), 0);
  inv_re_.assign(std::max(n, 0), 0.0);
  inv_im_.assign(std::max(n, 0), 0.0);
}

Eigen::MatrixXcd ComplexBandedMatrix::ToDense() const {
  Eigen::MatrixXcd A = Eigen::MatrixXcd::Zero(n_, n_);
  for (int j = 0; j < n_; ++j)
    for (int i = std::max(0, j - ku_); i <= std::min(n_ - 1, j + kl_); ++i) A(i, j) = (*this)(i, j);
  return A;
}

// Plain complex arithmetic on the parts: std::complex's operators carry the C99 Annex G inf/NaN
// recovery (a branch per product, a library call per division); the iteration matrices here are
// finite, and a NaN still propagates. Products (a + ib)(c + id) = (ac − bd) + i(ad + bc).

bool ComplexBandedMatrix::Factorize() {
  // BandedMatrix::Factorize with complex entries.
  double* __restrict re = re_.data();
  double* __restrict im = im_.data();
  for (int j = 0; j < n_; ++j)
    for (int r = 0; r < kl_; ++r) re[r + j * ld_] = im[r + j * ld_] = 0.0;
  int ju = 0;
  for (int j = 0; j < n_; ++j) {
    const int km = std::min(kl_, n_ - 1 - j);
    double* cr = re + kv_ + j * ld_;  // cr[i] + i ci[i] = A(j + i, j)
    double* ci = im + kv_ + j * ld_;
    int jp = 0;
    double best = std::abs(cr[0]) + std::abs(ci[0]);
    for (int i = 1; i <= km; ++i) {
      const double a = std::abs(cr[i]) + std::abs(ci[i]);
      if (a > best) best = a, jp = i;
    }
    pivot_[j] = j + jp;
    if (cr[jp] == 0.0 && ci[jp] == 0.0) return false;
    ju = std::max(ju, std::min(j + ku_ + jp, n_ - 1));
    row_end_[j] = ju;
    if (jp != 0)
      for (int c = j; c <= ju; ++c) {
        const size_t k0 = (kv_ + j - c) + static_cast<size_t>(c) * ld_, k1 = k0 + jp;
        std::swap(re[k0], re[k1]);
        std::swap(im[k0], im[k1]);
      }
    const double d = 1.0 / (cr[0] * cr[0] + ci[0] * ci[0]);
    const double ir = cr[0] * d, ii = -ci[0] * d;
    inv_re_[j] = ir;
    inv_im_[j] = ii;
    if (km > 0) {
      for (int i = 1; i <= km; ++i) {
        const double xr = cr[i], xi = ci[i];
        cr[i] = xr * ir - xi * ii;
        ci[i] = xr * ii + xi * ir;
      }
      for (int c = j + 1; c <= ju; ++c) {
        const size_t k = (kv_ + j - c) + static_cast<size_t>(c) * ld_;  // A(j, c)
        const double ar = re[k], ai = im[k];
        if (ar == 0.0 && ai == 0.0) continue;
        double* __restrict ur = re + k;  // ur[i] + i ui[i] = A(j + i, c)
        double* __restrict ui = im + k;
        for (int i = 1; i <= km; ++i) {
          ur[i] -= cr[i] * ar - ci[i] * ai;
          ui[i] -= cr[i] * ai + ci[i] * ar;
        }
      }
    }
  }
  UpperTops(row_end_, &u_top_);
  return true;
}

void ComplexBandedMatrix::Solve(Eigen::Ref<Eigen::VectorXd> re,
                                Eigen::Ref<Eigen::VectorXd> im) const {
  double* __restrict br = re.data();
  double* __restrict bi = im.data();
  const double* __restrict dr = re_.data();
  const double* __restrict di = im_.data();
  for (int j = 0; j < n_; ++j) {
    if (pivot_[j] != j) {
      std::swap(br[j], br[pivot_[j]]);
      std::swap(bi[j], bi[pivot_[j]]);
    }
    const int km = std::min(kl_, n_ - 1 - j);
    const double* cr = dr + kv_ + j * ld_;
    const double* ci = di + kv_ + j * ld_;
    const double xr = br[j], xi = bi[j];
    for (int i = 1; i <= km; ++i) {
      br[j + i] -= cr[i] * xr - ci[i] * xi;
      bi[j + i] -= cr[i] * xi + ci[i] * xr;
    }
  }
  for (int j = n_ - 1; j >= 0; --j) {
    const double yr = br[j], yi = bi[j];
    const double xr = yr * inv_re_[j] - yi * inv_im_[j];
    const double xi = yr * inv_im_[j] + yi * inv_re_[j];
    br[j] = xr;
    bi[j] = xi;
    const double* cr = dr + kv_ - j + j * ld_;  // cr[i] + i ci[i] = U(i, j)
    const double* ci = di + kv_ - j + j * ld_;
    for (int i = u_top_[j]; i < j; ++i) {
      br[i] -= cr[i] * xr - ci[i] * xi;
      bi[i] -= cr[i] * xi + ci[i] * xr;
    }
  }
}

void ComplexBandedMatrix::Solve(Eigen::Ref<Eigen::VectorXcd> b) const {
  Eigen::VectorXd re = b.real(), im = b.imag();
  Solve(re, im);
  b.real() = re;
  b.imag() = im;
}

}  // namespace cosserat
