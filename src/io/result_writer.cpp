#include "cosserat/io/result_writer.hpp"

#include <iomanip>
#include <limits>

namespace cosserat::io {
namespace {

using json = nlohmann::ordered_json;

template <typename Vector>
json ToArray(const Vector& v) {
  json out = json::array();
  for (int i = 0; i < v.size(); ++i) out.push_back(v(i));
  return out;
}

/// Row-major nested array [[r00, r01, r02], [r10, ...], ...].
json ToRows(const Mat3& m) {
  json out = json::array();
  for (int i = 0; i < 3; ++i) out.push_back(ToArray(Vec3(m.row(i).transpose())));
  return out;
}

json NodesToJson(const RodState& state) {
  json s = json::array(), position = json::array(), curvature = json::array();
  json moment = json::array(), force = json::array();
  for (int i = 0; i < state.size(); ++i) {
    s.push_back(state.s[i]);
    position.push_back(ToArray(state.position_W[i]));
    curvature.push_back(ToArray(Vec3(state.strain[i].head<3>())));
    moment.push_back(ToArray(Vec3(state.wrench_B[i].head<3>())));
    force.push_back(ToArray(Vec3(state.wrench_B[i].tail<3>())));
  }
  return {{"s", s},
          {"position", position},
          {"curvature", curvature},
          {"moment_body", moment},
          {"force_body", force}};
}

}  // namespace

json StaticResultToJson(const StaticShootingSummary& summary, const RodState& state) {
  json out;
  out["status"] = ToString(summary.status);
  out["iterations"] = summary.iterations;
  out["shots"] = summary.shots;
  out["load_steps"] = summary.load_steps;
  out["residual"] = summary.residual;
  out["wall_time_s"] = summary.wall_time_s;
  if (state.size() > 0) {
    out["tip"] = {{"position", ToArray(state.tip_position_W())},
                  {"rotation", ToRows(state.tip_rotation_WB())}};
    const Vec6 reaction = state.BaseReaction_W();
    out["base_wrench"] = {{"moment", ToArray(Vec3(reaction.head<3>()))},
                          {"force", ToArray(Vec3(reaction.tail<3>()))}};
  }
  out["nodes"] = NodesToJson(state);
  return out;
}

void WriteNodesCsv(std::ostream& out, const RodState& state) {
  const auto old_precision = out.precision(std::numeric_limits<double>::max_digits10);
  out << "s,x,y,z,k1,k2,k3\n";
  for (int i = 0; i < state.size(); ++i) {
    const Vec3& p = state.position_W[i];
    const Vec6& xi = state.strain[i];
    out << state.s[i] << ',' << p.x() << ',' << p.y() << ',' << p.z() << ',' << xi(0) << ','
        << xi(1) << ',' << xi(2) << '\n';
  }
  out.precision(old_precision);
}

}  // namespace cosserat::io
