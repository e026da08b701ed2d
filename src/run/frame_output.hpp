#pragma once
// The frames of a dynamics run for the VTK time series (Result::frames, io/vtk_series.hpp).

#include <vector>

#include "cosserat/io/problem.hpp"
#include "cosserat/io/result_writer.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run::detail {

/// A fixed-step run of `dynamics`: its steps, round(duration / dt), and the steps between
/// recorded frames, round(output_interval / dt) and at least 1.
struct FixedSteps {
  int steps;
  int stride;
};
FixedSteps StepsOf(const io::Problem::Dynamics& dynamics);

/// The outer radius of `model` at each arc length of `s` (m), for `actuation`.
std::vector<double> NodeRadius(const RodModel& model, const std::vector<double>& s,
                               const Actuation& actuation);

/// With RunOptions::frames, the one frame of a static answer (statics, and the equilibrium of
/// modes and buckling): `state` at t = 0, with its node radii, for the VTK series.
void KeepStaticFrame(const io::Problem& problem, const RodState& state, const RunOptions& options,
                     Result* result);

/// Moves a single rod's recorded frames (run->frame_states at run->frame_t) into
/// result->frames, with the rod's node radii.
void MoveFrames(const RodModel& model, const Actuation& actuation, io::DynamicRun* run,
                Result* result);

}  // namespace cosserat::run::detail
