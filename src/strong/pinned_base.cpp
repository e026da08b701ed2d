// The pinned base's twist axis. J_r(θ)⁻¹ = I + θ^/2 + (1/t² − (1 + cos t)/(2t sin t)) θ^²
// (t = |θ|), and with θ₃ = 0 its third row is [−b/2, a/2, g(t)], g(t) = (t/2) cot(t/2).
#include "cosserat/strong/pinned_base.hpp"

#include <cmath>

namespace cosserat {

Vec3 PinnedTwistAxis(double a, double b) {
  const double t = std::hypot(a, b);
  // Below t = 1e-2, g's series 1 − t²/12 − t⁴/720 (next term t⁶/30240, below 1e-16).
  const double g = t < 1e-2 ? 1.0 - t * t / 12.0 - t * t * t * t / 720.0
                            : 0.5 * t / std::tan(0.5 * t);
  return Vec3(-0.5 * b, 0.5 * a, g);
}

}  // namespace cosserat
