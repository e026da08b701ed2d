#pragma once
// Test support: a 6 × 6 Jacobian of a shot (dimensionless residual in dimensionless unknowns)
// against central differences at h = 1e-6, column by column. Truncation h² times the third
// derivative (amplified by the shot's gain) and round-off 1e-16/h stay below 1e-6 of a column's
// norm (or of 1) for the shots the tests use; a wrong term is O(1) of it.

#include <gtest/gtest.h>

#include <algorithm>

#include "cosserat/lie/types.hpp"

namespace cosserat::testing {

template <typename Residual>
void ExpectJacobianMatchesCentralDifferences(Residual&& residual, const Vec6& x, const Mat6& J) {
  const double h = 1e-6;
  for (int k = 0; k < 6; ++k) {
    Vec6 xp = x, xm = x;
    xp(k) += h;
    xm(k) -= h;
    const Vec6 fd = (residual(xp) - residual(xm)) / (2 * h);
    EXPECT_LT((fd - J.col(k)).norm(), 1e-6 * std::max(1.0, J.col(k).norm())) << "column " << k;
  }
}

}  // namespace cosserat::testing
