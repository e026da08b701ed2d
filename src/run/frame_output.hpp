#pragma once
// The frames of a dynamics run for the VTK time series (Result::frames, io/vtk_series.hpp).

#include <vector>

#include "cosserat/io/result_writer.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run::detail {

/// The outer radius of `model` at each arc length of `s` (m), for `actuation`.
std::vector<double> NodeRadius(const RodModel& model, const std::vector<double>& s,
                               const Actuation& actuation);

/// Moves a single rod's recorded frames (run->frame_states at run->frame_t) into
/// result->frames, with the rod's node radii.
void MoveFrames(const RodModel& model, const Actuation& actuation, io::DynamicRun* run,
                Result* result);

}  // namespace cosserat::run::detail
