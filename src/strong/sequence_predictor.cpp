#include "cosserat/strong/sequence_predictor.hpp"

#include <algorithm>
#include <limits>

namespace cosserat {

namespace {

constexpr int kMaxDegree = SequencePredictor::kMaxDegree;

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

SequencePredictor::SequencePredictor(int min_degree)
    : min_degree_(std::clamp(min_degree, 0, kMaxDegree)) {
  score_.fill(-1.0);
}

void SequencePredictor::Reset(const Vec6& x) {
  terms_[0] = x;
  count_ = 1;
  spacing_ = 0.0;
  degree_ = 0;
  score_.fill(-1.0);
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
}

Vec6 SequencePredictor::Predict(double spacing) const {
  if (count_ == 0) return Vec6::Zero();
  if (count_ < 2 || spacing != spacing_) return terms_[0];
  return Extrapolate(degree_, 0);
}

}  // namespace cosserat
