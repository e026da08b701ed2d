#pragma once
// The steps of a grown eversion robot, for its result and its VTK series.

#include <nlohmann/json.hpp>
#include <vector>

#include "cosserat/io/vtk_series.hpp"
#include "cosserat/robots/eversion_robot.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run::detail {

/// Each converged growth step of an eversion robot: its everted length (m), tip position (world,
/// m) and largest wrinkling ratio (the kink check's), for the result's robot.growth; and, when
/// `frames`, its body as a VTK frame whose time is the length (m), with the radii of the body at
/// that length at its nodes (the grid grows with the body).
class GrowthRecord {
 public:
  explicit GrowthRecord(bool frames) : frames_(frames) {}
  /// After a converged step, with the robot holding its equilibrium.
  void Add(const EversionRobot& robot, const EversionSolveSummary& step);
  /// {"length": […], "tip": [[x, y, z], …], "max_moment_ratio": […]}, one entry per step; an
  /// infinite ratio (a collapsed wall) is null.
  nlohmann::ordered_json Json() const;
  /// The steps' frames, when recorded, into result->frames (replacing the final state's one).
  void MoveFramesInto(Result* result);

 private:
  bool frames_;
  std::vector<double> length_, ratio_;
  std::vector<Vec3> tip_;
  std::vector<io::VtkFrame> frames_kept_;
};

}  // namespace cosserat::run::detail
