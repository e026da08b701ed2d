#include "cosserat/state/resampled_state.hpp"

#include <algorithm>
#include <stdexcept>

#include "cosserat/lie/so3.hpp"

namespace cosserat {

RodState ResampledState(const RodState& from, const std::vector<double>& s) {
  const int n = from.size();
  if (n < 2) throw std::invalid_argument("ResampledState: the state has fewer than 2 nodes");
  for (size_t j = 0; j < s.size(); ++j)
    if (!(s[j] >= from.s.front()) || (j > 0 && !(s[j] > s[j - 1])))
      throw std::invalid_argument("ResampledState: s must increase from the state's first node");
  RodState out;
  out.Resize(static_cast<int>(s.size()));
  int i = 0;  // from's segment [s_i, s_{i+1}] holding s[j]; s increases, so i only moves on
  for (size_t j = 0; j < s.size(); ++j) {
    out.s[j] = s[j];
    if (s[j] > from.s.back()) {
      const Mat3& R = from.rotation_WB.back();
      out.position_W[j] = from.position_W.back() + (s[j] - from.s.back()) * R.col(2);
      out.rotation_WB[j] = R;
      out.strain[j] = from.strain.back();
      out.wrench_B[j] = from.wrench_B.back();
      out.twist_B[j] = from.twist_B.back();
      continue;
    }
    while (i < n - 2 && s[j] > from.s[i + 1]) ++i;
    const double t = (s[j] - from.s[i]) / (from.s[i + 1] - from.s[i]);
    auto lerp = [t](const auto& a, const auto& b) { return ((1.0 - t) * a + t * b).eval(); };
    out.position_W[j] = lerp(from.position_W[i], from.position_W[i + 1]);
    const Mat3& Ri = from.rotation_WB[i];
    const Vec3 turn = lie::SO3Log(Ri.transpose() * from.rotation_WB[i + 1]);  // rad, body
    out.rotation_WB[j] = Ri * lie::SO3Exp(Vec3(t * turn));
    out.strain[j] = lerp(from.strain[i], from.strain[i + 1]);
    out.wrench_B[j] = lerp(from.wrench_B[i], from.wrench_B[i + 1]);
    out.twist_B[j] = lerp(from.twist_B[i], from.twist_B[i + 1]);
  }
  return out;
}

}  // namespace cosserat
