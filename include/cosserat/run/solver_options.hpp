#pragma once
/// \file
/// The solvers' options a problem implies: the translation from the problem file's values
/// (io::Problem) to each solver's Options, shared by the runners, the command-line tool and the
/// Python module.

#include "cosserat/analysis/column.hpp"
#include "cosserat/io/problem.hpp"
#include "cosserat/quatfd/quatfd_statics.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/spatial_scheme.hpp"
#include "cosserat/strong/static_shooting.hpp"

namespace cosserat::run {

/// The static shooting solver's options: "solver" (tolerance, max_iterations), the rest at
/// their defaults.
StaticShootingOptions StaticOptions(const io::Problem& problem);

/// The quaternion-FD static solver's options: "solver" (tolerance, max_iterations), with the
/// round-off floor no tighter than the tolerance.
quatfd::QuatFdStaticsOptions QuatFdStaticOptions(const io::Problem& problem);
/// The same for following the loaded path from the rest state: no direct solve first, steps of
/// at most 1/16 of the load, small enough to see the path turn where the rod bends (a column
/// past its Euler load), none moving the rod against the last step's move.
quatfd::QuatFdStaticsOptions QuatFdLoadedPathOptions(const io::Problem& problem);

/// The quaternion-FD model's options: the grid (rod.nodes − 1 segments) and the ends (a clamped
/// cantilever, or the anchors of "anchored").
quatfd::QuatFdOptions QuatFdModelOptions(const io::Problem& problem);

/// The BDF2 shooting stepper's options for a dynamics problem: "dynamics" (dt, tip body,
/// shooting_segments, spatial_scheme), "boundary" (cantilever or free-free) and "solver"
/// (tolerance, max_iterations).
Bdf2Options DynamicsOptions(const io::Problem& problem);

/// The dynamic shot's scheme a problem file names.
SpatialScheme ToSpatialScheme(io::ShotScheme scheme);

/// The column ends of a boundary the column solvers run; false (and *ends unchanged) for
/// "free-free" and "anchored".
bool ToColumnEnds(io::Boundary boundary, ColumnEnds* ends);

/// How the SE(3) stepper holds a column's tip: guided along the axis, clamped or pinned, for
/// "clamped-clamped" and "clamped-pinned"; kFree for every other boundary.
TipHold GuidedTipHold(io::Boundary boundary);

}  // namespace cosserat::run
