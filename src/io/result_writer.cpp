#include "cosserat/io/result_writer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cosserat/io/csv_line.hpp"
#include "cosserat/lie/nearest_rotation.hpp"

namespace cosserat::io {
namespace {

using json = nlohmann::ordered_json;

/// The value below which a fraction q of `sorted` lies (nearest rank); NaN when empty.
double Percentile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
  return sorted[std::min(sorted.size(), std::max<std::size_t>(rank, 1)) - 1];
}

/// {median, p99, max} in microseconds.
json StepTimeStats(std::vector<double> times_s) {
  std::sort(times_s.begin(), times_s.end());
  const double max = times_s.empty() ? std::numeric_limits<double>::quiet_NaN() : times_s.back();
  return {{"median", 1e6 * Percentile(times_s, 0.5)},
          {"p99", 1e6 * Percentile(times_s, 0.99)},
          {"max", 1e6 * max}};
}

}  // namespace

json NodesToJson(const RodState& state) {
  json s = json::array(), position = json::array(), curvature = json::array();
  json moment = json::array(), force = json::array();
  for (int i = 0; i < state.size(); ++i) {
    s.push_back(state.s[i]);
    position.push_back(ToJson(state.position_W[i]));
    curvature.push_back(ToJson(Vec3(state.strain[i].head<3>())));
    moment.push_back(ToJson(Vec3(state.wrench_B[i].head<3>())));
    force.push_back(ToJson(Vec3(state.wrench_B[i].tail<3>())));
  }
  return {{"s", s},
          {"position", position},
          {"curvature", curvature},
          {"moment_body", moment},
          {"force_body", force}};
}

json ToJson(const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

json ToJson(const Mat3& m) {
  json out = json::array();
  for (int i = 0; i < 3; ++i) out.push_back(ToJson(Vec3(m.row(i).transpose())));
  return out;
}

void AddTipAndBaseWrench(const RodState& state, json* out) {
  // RK4 in s leaves the frames off SO(3) by about its error in the shape (3e-3 for a rod curled
  // 3 turns on 41 nodes, whose tip is off by 4e-4 L): the written rotation is the nearest one,
  // so that it can be given back as a pose.
  const Mat3 R = state.tip_rotation_WB();
  (*out)["tip"] = {{"position", ToJson(state.tip_position_W())},
                   {"rotation", ToJson(R.allFinite() ? lie::NearestRotation(R) : R)}};
  const Vec6 reaction = state.BaseReaction_W();
  (*out)["base_wrench"] = {{"moment", ToJson(Vec3(reaction.head<3>()))},
                           {"force", ToJson(Vec3(reaction.tail<3>()))}};
}

json StaticResultToJson(const StaticShootingSummary& summary, const RodState& state) {
  json out;
  out["status"] = ToString(summary.status);
  out["iterations"] = summary.iterations;
  out["shots"] = summary.shots;
  out["load_steps"] = summary.load_steps;
  out["residual"] = summary.residual;
  if (summary.stability_index >= 0) out["stability_index"] = summary.stability_index;
  if (std::isfinite(summary.load_fraction)) out["load_reached"] = summary.load_fraction;
  out["wall_time_s"] = summary.wall_time_s;
  if (state.size() > 0) AddTipAndBaseWrench(state, &out);
  out["nodes"] = NodesToJson(state);
  return out;
}

json DynamicResultToJson(const DynamicRun& run, const RodState& final_state) {
  json out;
  out["status"] = ToString(run.status);
  if (run.status != SolveStatus::kConverged) out["failed_at_t"] = run.failed_at_t;
  out["steps"] = run.steps;
  out["halved_steps"] = run.halved_steps;
  if (run.shooting_segments > 0) out["shooting_segments"] = run.shooting_segments;
  if (run.shot_steps > 0) out["shot_steps"] = run.shot_steps;
  out["iterations"] = run.iterations;
  out["residual"] = run.residual;
  out["shots"] = run.shots;
  out["wall_time_s"] = run.wall_time_s;
  out["simulated_time_s"] = run.simulated_time_s;
  out["real_time_ratio"] = run.simulated_time_s / run.stepping_wall_time_s;
  out["step_time_us"] = StepTimeStats(run.step_time_s);
  if (!run.initial_state_ok || final_state.size() == 0) return out;
  AddTipAndBaseWrench(final_state, &out);
  out["energy"] = {{"kinetic", run.energy.kinetic},
                   {"elastic", run.energy.elastic},
                   {"potential", run.energy.potential}};
  // The start's total under the same loads: the run's energy balance (quaternion FD: not kept).
  if (std::isfinite(run.initial_total_energy))
    out["energy"]["initial_total"] = run.initial_total_energy;
  json tip = json::array();
  for (const Vec3& p : run.frame_tip) tip.push_back(ToJson(p));
  out["trajectory"] = {{"t", run.frame_t}, {"tip_position", std::move(tip)}};
  if (run.report_tip_spin) out["trajectory"]["tip_spin"] = run.frame_tip_spin;
  if (run.report_table) {
    out["trajectory"]["table_speed"] = run.frame_table_speed;
    out["trajectory"]["table_torque"] = run.frame_table_torque;
  }
  if (run.report_touchdown) out["trajectory"]["touchdown_s"] = run.frame_touchdown_s;
  if (run.report_anchor_force) {
    json force = json::array();
    for (const Vec3& f : run.frame_anchor_force) force.push_back(ToJson(f));
    out["trajectory"]["anchor_force"] = std::move(force);
  }
  if (!run.frame_midspan.empty()) {
    json midspan = json::array();
    for (const Vec3& p : run.frame_midspan) midspan.push_back(ToJson(p));
    out["trajectory"]["midspan_position"] = std::move(midspan);
  }
  out["nodes"] = NodesToJson(final_state);
  if (run.envelope.frames > 0)
    out["envelope"] = {{"tension_max", run.envelope.tension_max},
                       {"tension_min", run.envelope.tension_min},
                       {"moment_max", run.envelope.moment_max}};
  return out;
}

void WriteNodesCsv(std::ostream& out, const RodState& state) {
  out << "s,x,y,z,k1,k2,k3\n";
  CsvLine line;
  for (int i = 0; i < state.size(); ++i) {
    const Vec3& p = state.position_W[i];
    const Vec6& xi = state.strain[i];
    line << state.s[i] << p.x() << p.y() << p.z() << xi(0) << xi(1) << xi(2);
    line.WriteTo(out);
  }
}

void WriteTrajectoryCsv(std::ostream& out, const DynamicRun& run, const std::vector<double>& grid) {
  out << "t,node,s,x,y,z\n";
  const std::size_t n = grid.size();
  const std::size_t frames =
      n == 0 ? 0 : std::min(run.frame_t.size(), run.frame_positions.size() / n);
  CsvLine line;
  for (std::size_t f = 0; f < frames; ++f) {
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& p = run.frame_positions[f * n + i];
      line << run.frame_t[f] << i << grid[i] << p.x() << p.y() << p.z();
      line.WriteTo(out);
    }
  }
}

}  // namespace cosserat::io
