#pragma once
/// \file
/// A square banded matrix and its LU factorisation with partial pivoting (the LAPACK dgbtf2
/// algorithm, written out so no LAPACK is needed). Storage is column-major band storage with
/// kl extra rows on top for the fill-in of row interchanges, so a matrix can be factorised in
/// place. Cost: factorisation O(n kl (kl + ku)), solve O(n (2 kl + ku)).

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <complex>
#include <vector>

namespace cosserat {

class BandedMatrix {
 public:
  BandedMatrix() = default;
  /// n × n with kl sub- and ku super-diagonals, zero.
  BandedMatrix(int n, int kl, int ku) { Resize(n, kl, ku); }
  void Resize(int n, int kl, int ku);
  void SetZero();

  int rows() const { return n_; }
  int lower() const { return kl_; }
  int upper() const { return ku_; }
  /// True when (i, j) lies in the band kl, ku (the only entries that may be non-zero).
  bool InBand(int i, int j) const { return i - j <= kl_ && j - i <= ku_ && i >= 0 && j >= 0; }
  /// Entry (i, j); only valid InBand(i, j).
  double& operator()(int i, int j) { return data_[(kv_ + i - j) + j * ld_]; }
  double operator()(int i, int j) const { return data_[(kv_ + i - j) + j * ld_]; }

  /// y = A x.
  void Multiply(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const;
  /// The dense copy (for tests and small checks).
  Eigen::MatrixXd ToDense() const;
  /// The sparse copy: the band's non-zero entries.
  Eigen::SparseMatrix<double> ToSparse() const;

  /// Factorises in place into P A = L U. Returns false when a pivot is exactly zero (the matrix is
  /// singular); Solve must not be called then.
  bool Factorize();
  /// Solves A x = b in place with the factors of Factorize().
  void Solve(Eigen::Ref<Eigen::VectorXd> b) const;

 private:
  int n_ = 0, kl_ = 0, ku_ = 0, kv_ = 0, ld_ = 1;
  std::vector<double> data_;
  std::vector<int> pivot_;
  std::vector<int> row_end_;  ///< per row of U: its last possibly non-zero column
  std::vector<int> u_top_;    ///< per column of U: its first possibly non-zero row
};

/// The complex counterpart of BandedMatrix's storage, factorisation and solve (same dgbtf2
/// algorithm, pivoting on |Re| + |Im| as LAPACK's zgbtf2 does): for the complex iteration matrix
/// of the Radau IIA integrator (radau.hpp). Only what that needs: fill, factorise, solve.
/// Real and imaginary parts are stored in two separate band arrays (and the fast solve takes the
/// right-hand side as two real vectors), so the inner loops are plain real loops the compiler
/// vectorises; interleaved std::complex storage made the complex LU and solve ~20 % of a step.
class ComplexBandedMatrix {
 public:
  using Scalar = std::complex<double>;
  /// Entry (i, j) as an assignable value (the parts live in two arrays).
  class Entry {
   public:
    Entry(double* re, double* im) : re_(re), im_(im) {}
    Entry& operator=(const Scalar& z) {
      *re_ = z.real();
      *im_ = z.imag();
      return *this;
    }
    operator Scalar() const { return Scalar(*re_, *im_); }

   private:
    double *re_, *im_;
  };
  ComplexBandedMatrix() = default;
  ComplexBandedMatrix(int n, int kl, int ku) { Resize(n, kl, ku); }
  void Resize(int n, int kl, int ku);

  int rows() const { return n_; }
  int lower() const { return kl_; }
  int upper() const { return ku_; }
  /// Entry (i, j); only valid in the band (|i − j| within kl, ku).
  Entry operator()(int i, int j) {
    const size_t k = (kv_ + i - j) + static_cast<size_t>(j) * ld_;
    return Entry(&re_[k], &im_[k]);
  }
  Scalar operator()(int i, int j) const {
    const size_t k = (kv_ + i - j) + static_cast<size_t>(j) * ld_;
    return Scalar(re_[k], im_[k]);
  }
  /// Sets entry (i, j) from its parts.
  void Set(int i, int j, double re, double im) {
    const size_t k = (kv_ + i - j) + static_cast<size_t>(j) * ld_;
    re_[k] = re;
    im_[k] = im;
  }
  /// The dense copy (for tests).
  Eigen::MatrixXcd ToDense() const;

  /// P A = L U in place; false when a pivot is exactly zero.
  bool Factorize();
  /// A x = b in place with the factors of Factorize(), b = re + i im as two real vectors.
  void Solve(Eigen::Ref<Eigen::VectorXd> re, Eigen::Ref<Eigen::VectorXd> im) const;
  /// The same for a complex vector (copies through two temporaries: allocates; for tests).
  void Solve(Eigen::Ref<Eigen::VectorXcd> b) const;

 private:
  int n_ = 0, kl_ = 0, ku_ = 0, kv_ = 0, ld_ = 1;
  std::vector<double> re_, im_;  ///< the band storage of BandedMatrix, one array per part
  std::vector<int> pivot_;
  std::vector<int> row_end_, u_top_;  ///< as in BandedMatrix
  std::vector<double> inv_re_, inv_im_;  ///< 1/U(j, j), so the solve multiplies
};

}  // namespace cosserat
