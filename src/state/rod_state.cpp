#include "cosserat/state/rod_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cosserat {

void RodState::Resize(int n) {
  // Entries nobody has computed are NaN (written out as null), never uninitialised memory.
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  s.resize(n, nan);
  position_W.assign(n, Vec3::Constant(nan));
  rotation_WB.assign(n, Mat3::Constant(nan));
  strain.assign(n, Vec6::Constant(nan));
  wrench_B.assign(n, Vec6::Constant(nan));
  twist_B.assign(n, Vec6::Zero());
}

Vec6 RodState::BaseReaction_W() const {
  Vec6 out;
  const Mat3& R = rotation_WB.front();
  out.head<3>() = -R * wrench_B.front().head<3>();
  out.tail<3>() = -R * wrench_B.front().tail<3>();
  return out;
}

double RodState::MaxForce() const {
  double force = 0.0;
  for (const Vec6& w : wrench_B) force = std::max(force, w.tail<3>().norm());
  return force;
}

bool RodState::RanAway() const {
  for (const Mat3& R : rotation_WB)
    if (FrameRanAway(R)) return true;
  return SegmentsRanAway();
}

bool RodState::SegmentsRanAway() const {
  // The turn first, squared: a step's hot path (most segments turn far less than 1 rad).
  for (int i = 0; i + 1 < size(); ++i) {
    const double h = s[i + 1] - s[i];
    const double k2 =
        std::max(strain[i].head<3>().squaredNorm(), strain[i + 1].head<3>().squaredNorm());
    if (k2 * h * h > 1.0 &&
        SegmentRanAway(h, (position_W[i + 1] - position_W[i]).norm(), std::sqrt(k2) * h))
      return true;
  }
  return false;
}

}  // namespace cosserat
