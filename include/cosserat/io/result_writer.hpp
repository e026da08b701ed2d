#pragma once
/// \file
/// Results of a solve as JSON (the "Result" of docs/problem-format.md) and as a CSV of the nodes.

#include <limits>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "cosserat/io/load_envelope.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat::io {

/// A vector as [x, y, z]; a rotation matrix row-major, [[r00, r01, r02], [r10, ...], ...].
nlohmann::ordered_json ToJson(const Vec3& v);
nlohmann::ordered_json ToJson(const Mat3& m);

/// The nodes' s (m), position (m, world), curvature (1/m), moment_body (N·m) and force_body (N):
/// the internal wrench in the section frame, the part (s, L] acting on [0, s].
nlohmann::ordered_json NodesToJson(const RodState& state);

/// tip {position (m), rotation (R_WB, row-major)} and base_wrench {moment (N·m), force (N)} of a
/// state: the support's reaction on the rod, world frame, the moment about the base point.
void AddTipAndBaseWrench(const RodState& state, nlohmann::ordered_json* out);

/// The statics result:
///   status (ToString of the status), iterations, shots, load_steps, residual, wall_time_s,
///   tip {position (m), rotation (R_WB, row-major 3×3)},
///   base_wrench {moment (N·m), force (N)}: the reaction of the support on the rod, world frame,
///     moment about the base point (RodState::BaseReaction_W),
///   nodes {s, position, curvature (body-frame [k1, k2, k3], 1/m),
///          moment_body, force_body (internal wrench W = [m; n] in the section frame)}.
/// Keys keep this order (status first). Non-finite numbers (only possible when the solve failed)
/// are written as null.
nlohmann::ordered_json StaticResultToJson(const StaticShootingSummary& summary,
                                          const RodState& state);

/// One row per node, header `s,x,y,z,k1,k2,k3` (m; 1/m), full double precision.
void WriteNodesCsv(std::ostream& out, const RodState& state);

/// A dynamics run as the `cosserat` command records it, for DynamicResultToJson and
/// WriteTrajectoryCsv.
struct DynamicRun {
  SolveStatus status = SolveStatus::kNotRun;  ///< converged: the initial state and every step
  bool initial_state_ok = false;  ///< false: the initial equilibrium failed, there is no state
  /// The statics' count of the start's unstable directions (−1: not counted).
  int initial_unstable_directions = -1;
  double failed_at_t = std::numeric_limits<double>::quiet_NaN();  ///< end time of the failed step
  int steps = 0;                                                  ///< steps that converged
  int halved_steps = 0;  ///< of those, steps that needed step halving
  int shooting_segments = 0;  ///< SE(3) path: the most pieces a step was shot in (0: not reported)
  /// SE(3) path: the steps of the shot in s, the grid's segments less the pairs of the default
  /// scheme (Bdf2ShootingStepper::shot_steps; 0: not reported)
  int shot_steps = 0;
  int iterations = 0;    ///< all solves, the initial one included
  /// The largest final residual of those solves (each solver's own norm; quaternion FD: the
  /// initial equilibrium's, its Radau steps being controlled by their error estimate).
  double residual = 0.0;
  int shots = 0;
  double wall_time_s = 0;           ///< initial state and stepping loop
  double stepping_wall_time_s = 0;  ///< the stepping loop alone
  double simulated_time_s = 0;      ///< time of the final state
  std::vector<double> step_time_s;  ///< wall time of each Step() call, the failed one included
  RodEnergy energy;                 ///< of the final state, under the loads for t > 0
  /// The total energy of the initial state under the loads for t > 0 (J; NaN: not run), and the
  /// largest kinetic energy over the recorded frames (J): what the log's energy note compares.
  double initial_total_energy = std::numeric_limits<double>::quiet_NaN();
  double peak_kinetic_energy = 0.0;
  // Recorded frames: t = 0, every output interval, and the final state.
  std::vector<double> frame_t;
  std::vector<Vec3> frame_tip;        ///< tip position of each frame
  /// The tip's spin about its own axis (body z, rad/s) of each frame: recorded and written as the
  /// trajectory's tip_spin when `report_tip_spin` (a drill string).
  std::vector<double> frame_tip_spin;
  bool report_tip_spin = false;
  /// trajectory's table_speed (rad/s) and table_torque (the string's torque on the table, m₃(0),
  /// N·m) when `report_table` (a motor-driven rotary table).
  std::vector<double> frame_table_speed, frame_table_torque;
  bool report_table = false;
  /// The rod's internal force at the tip of each frame (N, world): for a rod held at an anchor the
  /// force the anchor exerts on it, a riser's top tension in time; written as the trajectory's
  /// anchor_force when `report_anchor_force`.
  std::vector<Vec3> frame_anchor_force;
  bool report_anchor_force = false;
  /// A rod held at both ends: the position of its node nearest mid-length at each frame (m,
  /// world), where the tip's is the anchor's. Empty otherwise.
  std::vector<Vec3> frame_midspan;
  /// The touchdown point of each frame (m of s: the end of the first stretch pressing into a
  /// contact surface, from the base; NaN when none does), written as the trajectory's
  /// touchdown_s when `report_touchdown` (a riser on the sea bed).
  std::vector<double> frame_touchdown_s;
  bool report_touchdown = false;
  std::vector<Vec3> frame_positions;  ///< all node positions, frame after frame (may be empty)
  /// The section forces' envelope over the recorded frames, written as "envelope".
  LoadEnvelope envelope;
  /// The whole state of each frame, when `record_states` (for the VTK time series).
  std::vector<RodState> frame_states;
  bool record_states = false;
};

/// The dynamics result: status, failed_at_t (only on failure), steps, halved_steps, iterations,
/// shots, wall_time_s, simulated_time_s, real_time_ratio (simulated time / stepping loop wall
/// time), step_time_us {median, p99, max}, then for the final state (when the initial one
/// converged) tip, base_wrench, energy {kinetic, elastic, potential}, trajectory {t, tip_position}
/// and nodes as in StaticResultToJson. Non-finite numbers are written as null.
nlohmann::ordered_json DynamicResultToJson(const DynamicRun& run, const RodState& final_state);

/// The recorded frames in long format: header `t,node,s,x,y,z`, one row per node per frame
/// (node counts from 0; s from `grid`), full double precision. Needs run.frame_positions.
void WriteTrajectoryCsv(std::ostream& out, const DynamicRun& run, const std::vector<double>& grid);

}  // namespace cosserat::io
