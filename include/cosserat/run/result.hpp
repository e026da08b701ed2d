#pragma once
/// \file
/// What running a problem produces (run.hpp): the result document, the node table and the
/// summary, as `cosserat solve` writes them and `cosserat.solve` returns them.

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cosserat/io/vtk_series.hpp"
#include "cosserat/lie/types.hpp"

namespace cosserat::run {

/// What a run asks for beyond the result document.
struct RunOptions {
  /// Fill Result::nodes_csv. Dynamics then records every node of every output frame, not only
  /// the tip.
  bool nodes_csv = false;
  /// Fill Result::frames: every rod's whole state at every output frame of a dynamics run, for
  /// the VTK time series (io/vtk_series.hpp; `cosserat solve --vtk DIR`).
  bool frames = false;
  /// Called during a long run with how far it got and where it ends: a dynamics run's simulated
  /// time and duration (s), after every step (SE(3), assemblies) or output frame (quaternion
  /// FD); an SE(3) buckling search's load reached and its maximum; an SE(3) modes scan's modes
  /// found and asked. May be empty; may throw to stop the run (Python's Ctrl-C). The `cosserat`
  /// command draws a progress line with it on a terminal.
  std::function<void(double reached, double end)> progress;
};

/// The outcome of a run. A run that did not converge still has a full result document, whose
/// "status" says why.
struct Result {
  /// True when every solve converged (for buckling: the load path could be followed).
  bool converged = false;
  /// The result document (docs/problem-format.md, "Result"): "status" first, then the keys of
  /// the analysis run (io/result_writer.hpp).
  nlohmann::ordered_json json;
  /// Statics: one row per node, `s,x,y,z,k1,k2,k3`; dynamics: every recorded frame,
  /// `t,node,s,x,y,z`. Empty unless RunOptions::nodes_csv.
  std::string nodes_csv;
  /// The one-line summary and any hints, each line ending in '\n'.
  std::string log;
  /// Dynamics: each node's centreline velocity in the final state (m/s, world frame), for the
  /// velocity-dependent parts of the contact report; empty otherwise.
  std::vector<Vec3> node_velocity_W;
  /// Dynamics with RunOptions::frames: the recorded frames (the times of the result's
  /// trajectory), and each rod's outer radius at its nodes (m).
  std::vector<io::VtkFrame> frames;
  std::vector<std::vector<double>> node_radius;
};

}  // namespace cosserat::run
