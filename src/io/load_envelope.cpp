#include "cosserat/io/load_envelope.hpp"

#include <algorithm>
#include <cmath>

namespace cosserat::io {

void LoadEnvelope::Add(const RodState& state) {
  const std::size_t n = static_cast<std::size_t>(state.size());
  if (frames == 0) {
    tension_max.assign(n, -INFINITY);
    tension_min.assign(n, INFINITY);
    moment_max.assign(n, 0.0);
  }
  if (tension_max.size() != n) return;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec6& W = state.wrench_B[i];
    tension_max[i] = std::max(tension_max[i], W(5));
    tension_min[i] = std::min(tension_min[i], W(5));
    moment_max[i] = std::max(moment_max[i], std::hypot(W(0), W(1)));
  }
  ++frames;
}

}  // namespace cosserat::io
