#include "cosserat/run/solver_options.hpp"

#include <algorithm>
#include <cmath>

namespace cosserat::run {

StaticShootingOptions StaticOptions(const io::Problem& problem) {
  StaticShootingOptions options;
  options.tolerance = problem.solver.tolerance;
  options.max_iterations = problem.solver.max_iterations;
  return options;
}

quatfd::QuatFdStaticsOptions QuatFdStaticOptions(const io::Problem& problem) {
  quatfd::QuatFdStaticsOptions options;
  options.tolerance = problem.solver.tolerance;
  options.floor_tolerance = std::max(options.floor_tolerance, options.tolerance);
  options.max_iterations = problem.solver.max_iterations;
  return options;
}

quatfd::QuatFdStaticsOptions QuatFdLoadedPathOptions(const io::Problem& problem) {
  quatfd::QuatFdStaticsOptions options = QuatFdStaticOptions(problem);
  options.direct_solve = false;
  options.max_load_step = 1.0 / 16.0;
  options.keep_path_direction = true;
  return options;
}

quatfd::QuatFdOptions QuatFdModelOptions(const io::Problem& problem) {
  quatfd::QuatFdOptions options;
  options.segments = problem.nodes - 1;
  options.base_end = quatfd::EndCondition::kClamped;
  if (problem.boundary == io::Boundary::kAnchored) {
    if (!problem.anchor.base_clamped) {
      options.base_end = quatfd::EndCondition::kPinned;
      options.base_twist_held = true;
    }
    options.tip_end = problem.anchor.tip_clamped ? quatfd::EndCondition::kClamped
                                                 : quatfd::EndCondition::kPinned;
    options.tip_position_W = problem.anchor.position;
    options.tip_rotation_W = problem.anchor.rotation;
    if (problem.analysis == io::Analysis::kDynamics && problem.anchor.motion_period > 0) {
      options.tip_motion_amplitude = problem.anchor.motion_amplitude;
      options.tip_motion_angular_frequency = 2 * M_PI / problem.anchor.motion_period;
    }
  }
  return options;
}

Bdf2Options DynamicsOptions(const io::Problem& problem) {
  Bdf2Options options;
  options.dt = problem.dynamics.dt;
  options.ends = problem.boundary == io::Boundary::kFreeFree ? EndConditions::kFreeFree
                                                             : EndConditions::kCantilever;
  options.tolerance = problem.solver.tolerance;
  options.tip_mass = problem.dynamics.tip_mass;
  options.tip_inertia_B = problem.dynamics.tip_inertia;
  options.max_iterations = problem.solver.max_iterations;
  options.shooting_segments = problem.dynamics.shooting_segments;
  options.spatial_scheme = ToSpatialScheme(problem.dynamics.spatial_scheme);
  return options;
}

SpatialScheme ToSpatialScheme(io::ShotScheme scheme) {
  switch (scheme) {
    case io::ShotScheme::kHeun:
      return SpatialScheme::kHeun;
    case io::ShotScheme::kRk4Pairs:
      return SpatialScheme::kRk4Pairs;
    case io::ShotScheme::kRk4:
      break;
  }
  return SpatialScheme::kRk4;
}

TipHold GuidedTipHold(io::Boundary boundary) {
  return boundary == io::Boundary::kClampedClamped ? TipHold::kGuidedClamped
         : boundary == io::Boundary::kClampedPinned ? TipHold::kGuidedPinned
                                                     : TipHold::kFree;
}

bool ToColumnEnds(io::Boundary boundary, ColumnEnds* ends) {
  switch (boundary) {
    case io::Boundary::kCantilever:
      *ends = ColumnEnds::kClampedFree;
      return true;
    case io::Boundary::kPinnedPinned:
      *ends = ColumnEnds::kPinnedPinned;
      return true;
    case io::Boundary::kClampedClamped:
      *ends = ColumnEnds::kClampedClamped;
      return true;
    case io::Boundary::kClampedPinned:
      *ends = ColumnEnds::kClampedPinned;
      return true;
    case io::Boundary::kFreeFree:
    case io::Boundary::kAnchored:
      break;
  }
  return false;
}

}  // namespace cosserat::run
