#pragma once
// Test support: the frequency of a sampled signal's largest spectral peak, shared by the tests
// that measure free-vibration frequencies (SE(3) stepper, quaternion FD).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace cosserat::testing {

/// Frequency (Hz) of the largest spectral peak of x (sampled every dt s) in [f_lo, f_hi]:
/// Hann-windowed discrete-time Fourier transform, scanned then refined by golden section. Fails
/// the calling test if the peak sits on the edge of the bracket (then the bracket, not the
/// signal, decided the answer).
inline double PeakFrequency(const std::vector<double>& x, double dt, double f_lo, double f_hi) {
  constexpr double kPi = 3.14159265358979323846;
  const int n = static_cast<int>(x.size());
  double mean = 0;
  for (double v : x) mean += v / n;
  auto power = [&](double f) {
    std::complex<double> sum = 0;
    for (int k = 0; k < n; ++k) {
      const double w = 0.5 - 0.5 * std::cos(2 * kPi * k / (n - 1));
      sum += w * (x[k] - mean) * std::polar(1.0, -2 * kPi * f * k * dt);
    }
    return std::norm(sum);
  };
  const int scan = 400;
  int best = 0;
  double best_p = -1;
  for (int i = 0; i <= scan; ++i) {
    const double p = power(f_lo + (f_hi - f_lo) * i / scan);
    if (p > best_p) best_p = p, best = i;
  }
  EXPECT_GT(best, 0) << "peak at the lower edge of the bracket";
  EXPECT_LT(best, scan) << "peak at the upper edge of the bracket";
  double a = f_lo + (f_hi - f_lo) * std::max(best - 1, 0) / scan;
  double b = f_lo + (f_hi - f_lo) * std::min(best + 1, scan) / scan;
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  for (int it = 0; it < 60; ++it) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    (power(c) > power(d) ? b : a) = (power(c) > power(d) ? d : c);
  }
  return 0.5 * (a + b);
}

}  // namespace cosserat::testing
