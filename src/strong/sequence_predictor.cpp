#include "cosserat/strong/sequence_predictor.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <limits>

namespace cosserat {

namespace {

constexpr int kMaxDegree = SequencePredictor::kMaxDegree;

/// Solves A x = b for a symmetric positive definite A of fixed size N (lower triangle read) by
/// LDLᵀ without pivoting. Written out for the recurrence's 10 × 10 normal equations, which are
/// solved in exactly the transient steps that set the stepper's p99: Eigen's LLT took ~540 ns
/// there, this ~300 ns (the divisions' latency chain is most of it), which moved the peer
/// problem's p99 / median by ~0.03 (docs/performance.md). A non-positive pivot
/// gives a non-finite x, which the caller rejects.
template <int N>
Eigen::Matrix<double, N, 1> SolveSpd(const Eigen::Matrix<double, N, N>& A,
                                     const Eigen::Matrix<double, N, 1>& b) {
  double L[N][N];  // unit lower factor, strictly below the diagonal
  double d[N], inv_d[N];
  for (int j = 0; j < N; ++j) {
    double v[N];  // L(j, k) d(k)
    double dj = A(j, j);
    for (int k = 0; k < j; ++k) {
      v[k] = L[j][k] * d[k];
      dj -= L[j][k] * v[k];
    }
    d[j] = dj;
    inv_d[j] = 1.0 / dj;
    if (!(dj > 0)) inv_d[j] = std::numeric_limits<double>::quiet_NaN();
    for (int i = j + 1; i < N; ++i) {
      double t = A(i, j);
      for (int k = 0; k < j; ++k) t -= L[i][k] * v[k];
      L[i][j] = t * inv_d[j];
    }
  }
  double y[N];  // L y = b
  for (int i = 0; i < N; ++i) {
    double t = b(i);
    for (int k = 0; k < i; ++k) t -= L[i][k] * y[k];
    y[i] = t;
  }
  Eigen::Matrix<double, N, 1> x;  // D Lᵀ x = y
  for (int i = N - 1; i >= 0; --i) {
    double t = y[i] * inv_d[i];
    for (int k = i + 1; k < N; ++k) t -= L[k][i] * x(k);
    x(i) = t;
  }
  return x;
}

// kWeights[p][j] = (−1)^j C(p+1, j+1): the extrapolation of degree p one step ahead from the
// p + 1 latest terms, newest first. A table: Push() scores every degree every step, and
// computing the binomials there took as many instructions as the rest of the predictor.
struct WeightTable {
  double w[kMaxDegree + 1][kMaxDegree + 1] = {};
  constexpr WeightTable() {
    for (int p = 0; p <= kMaxDegree; ++p) {
      double c = 1.0;  // C(p+1, j+1), built up in j
      for (int j = 0; j <= p; ++j) {
        c = j == 0 ? p + 1 : c * (p + 1 - j) / (j + 1);
        w[p][j] = (j % 2 == 0 ? 1.0 : -1.0) * c;
      }
    }
  }
};
constexpr WeightTable kWeights;

}  // namespace

SequencePredictor::SequencePredictor(int min_degree, bool recurrence)
    : min_degree_(std::clamp(min_degree, 0, kMaxDegree)), recurrence_(recurrence) {
  score_.fill(-1.0);
}

void SequencePredictor::ResetRecurrence() {
  use_recurrence_ = false;
  differences_ = 0;
  lags_gram_valid_ = false;
  gram_.setZero();
  rhs_.setZero();
  recurrence_ready_ = false;
  recurrence_score_ = -1.0;
}

void SequencePredictor::Reset(const Vec6& x) {
  terms_[0] = x;
  count_ = 1;
  spacing_ = 0.0;
  degree_ = 0;
  score_.fill(-1.0);
  ResetRecurrence();
}

Vec6 SequencePredictor::Extrapolate(int p, int first) const {
  Vec6 out = Vec6::Zero();
  for (int j = 0; j <= p; ++j) out += kWeights.w[p][j] * terms_[first + j];
  return out;
}

void SequencePredictor::Push(const Vec6& x, double spacing, const Mat6* weight) {
  if (count_ == 0) {
    Reset(x);
    return;
  }
  if (count_ >= 2 && spacing != spacing_) {
    count_ = 1;  // the older terms lie at another spacing: keep only the latest
    degree_ = 0;
    score_.fill(-1.0);
    ResetRecurrence();
  }
  spacing_ = spacing;
  for (int j = static_cast<int>(terms_.size()) - 1; j > 0; --j) terms_[j] = terms_[j - 1];
  terms_[0] = x;
  if (count_ < static_cast<int>(terms_.size())) ++count_;
  // Score every degree that had enough terms to predict x from the ones before it: an
  // exponential average of its squared errors, so that one lucky prediction in a transient does
  // not decide alone.
  double best = std::numeric_limits<double>::infinity();
  const int lowest = std::min(min_degree_, count_ - 2);
  degree_ = lowest;
  for (int p = 0; p <= kMaxDegree; ++p) {
    if (p + 2 > count_) {
      score_[p] = -1.0;  // not yet scored
      continue;
    }
    const Vec6 miss = Extrapolate(p, 1) - x;
    const double error = weight ? (*weight * miss).squaredNorm() : miss.squaredNorm();
    score_[p] = score_[p] < 0 ? error : 0.5 * (score_[p] + error);
    if (p >= lowest && score_[p] < best) {
      best = score_[p];
      degree_ = p;
    }
  }
  if (recurrence_) PushRecurrence(x, weight, best);
}

void SequencePredictor::PushRecurrence(const Vec6& x, const Mat6* weight, double best) {
  // Score the prediction made for x, then add x's equation to the fit and predict the next.
  if (recurrence_ready_) {
    const Vec6 miss = recurrence_prediction_ - x;
    const double error = weight ? (*weight * miss).squaredNorm() : miss.squaredNorm();
    recurrence_score_ = recurrence_score_ < 0 ? error : 0.5 * (recurrence_score_ + error);
  }
  // Only while the degrees predict poorly is the recurrence's solve worth its cost
  // (kRecurrenceFrom); its normal equations are kept up to date all the same.
  const bool active = best > kRecurrenceFrom;
  if (!active) recurrence_score_ = -1.0;  // scored afresh when it is next needed
  use_recurrence_ = active && recurrence_score_ >= 0 && recurrence_score_ < best;
  recurrence_ready_ = false;
  if (count_ < 3) return;
  const Vec6 d = x - 2 * terms_[1] + terms_[2];
  if (differences_ == 0)
    fit_scale_ = weight ? Vec6(weight->colwise().norm().transpose()) : Vec6::Ones();
  for (int k = kLags; k > 0; --k) weighted_[k] = weighted_[k - 1];
  weighted_[0] = fit_scale_.cwiseProduct(d);
  if (differences_ < kLags + 1) ++differences_;
  if (differences_ < kLags + 1) return;  // the fit needs the lags of its newest equation
  // The newest equation: weighted_[0] ≈ Σ_i a_i weighted_[1 + i]. Its Gram matrix of the lags
  // is the last one's shifted by one, with a new first row and column.
  VecL dots;
  for (int i = 0; i < kLags; ++i) dots(i) = weighted_[1 + i].dot(weighted_[0]);
  if (lags_gram_valid_) {
    lags_gram_.bottomRightCorner<kLags - 1, kLags - 1>() =
        lags_gram_.topLeftCorner<kLags - 1, kLags - 1>().eval();
    for (int l = 0; l < kLags; ++l)
      lags_gram_(0, l) = lags_gram_(l, 0) = weighted_[1].dot(weighted_[1 + l]);
  } else {
    for (int i = 0; i < kLags; ++i)
      for (int l = 0; l <= i; ++l)
        lags_gram_(i, l) = lags_gram_(l, i) = weighted_[1 + i].dot(weighted_[1 + l]);
    lags_gram_valid_ = true;
  }
  gram_ = kRecurrenceMemory * gram_ + lags_gram_;
  rhs_ = kRecurrenceMemory * rhs_ + dots;
  if (!active) return;
  // A little ridge: the lags are nearly dependent once the slow modes dominate.
  MatL A = gram_;
  A.diagonal().array() += 1e-12 * gram_.trace() / kLags + 1e-300;
  const VecL a = SolveSpd<kLags>(A, rhs_);
  if (!a.allFinite()) return;
  // d_{k+1} from the same coefficients and the unweighted differences (terms_ holds the
  // kLags + 2 terms they need); x_{k+1} = d_{k+1} + 2 x_k − x_{k−1}.
  Vec6 next = 2 * terms_[0] - terms_[1];
  for (int i = 0; i < kLags; ++i) next += a(i) * (terms_[i] - 2 * terms_[i + 1] + terms_[i + 2]);
  recurrence_prediction_ = next;
  recurrence_ready_ = true;
}

Vec6 SequencePredictor::Predict(double spacing) const {
  if (count_ == 0) return Vec6::Zero();
  if (count_ < 2 || spacing != spacing_) return terms_[0];
  if (use_recurrence_ && recurrence_ready_) return recurrence_prediction_;
  return Extrapolate(degree_, 0);
}

}  // namespace cosserat
