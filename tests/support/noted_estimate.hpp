#pragma once
// A log's estimate of an error, checked against the error measured: the coarse-grid notes and
// warnings print "<marker><number>", a per cent or a fraction.

#include <gtest/gtest.h>

#include <string>

namespace cosserat::testing {

/// Expects `log` to state after `marker` an estimate (in per cent when `percent`) within
/// [lo, hi] times `measured`, the fraction the test measured.
inline void ExpectEstimateWithin(const std::string& log, const std::string& marker, bool percent,
                                 double measured, double lo, double hi) {
  const size_t at = log.find(marker);
  ASSERT_NE(at, std::string::npos) << marker << " is not in:\n" << log;
  const double noted = std::stod(log.substr(at + marker.size())) / (percent ? 100.0 : 1.0);
  EXPECT_GT(noted, lo * measured) << log;
  EXPECT_LT(noted, hi * measured) << log;
}

}  // namespace cosserat::testing
