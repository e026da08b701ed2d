#include "cosserat/state/rod_state.hpp"

#include <algorithm>

namespace cosserat {

void RodState::Resize(int n) {
  s.resize(n);
  position_W.resize(n);
  rotation_WB.resize(n);
  strain.resize(n);
  wrench_B.resize(n);
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

}  // namespace cosserat
