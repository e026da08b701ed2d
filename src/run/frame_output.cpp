#include "frame_output.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "cosserat/rod/section_profile.hpp"

namespace cosserat::run::detail {

FixedSteps StepsOf(const io::Problem::Dynamics& d) {
  return {static_cast<int>(std::lround(d.duration / d.dt)),
          std::max(1, static_cast<int>(std::lround(d.output_interval / d.dt)))};
}

std::vector<double> NodeRadius(const RodModel& model, const std::vector<double>& s,
                               const Actuation& actuation) {
  std::vector<double> radius;
  radius.reserve(s.size());
  for (double si : s) radius.push_back(0.5 * model.section->At(si, actuation).outer_diameter);
  return radius;
}

void KeepStaticFrame(const io::Problem& problem, const RodState& state, const RunOptions& options,
                     Result* result) {
  if (!options.frames || state.size() == 0) return;
  result->node_radius = {NodeRadius(problem.rod, state.s, problem.robot.actuation)};
  io::VtkFrame frame;
  frame.rods = {state};
  result->frames = {std::move(frame)};
}

void MoveFrames(const RodModel& model, const Actuation& actuation, io::DynamicRun* run,
                Result* result) {
  if (run->frame_states.empty()) return;
  result->node_radius = {NodeRadius(model, run->frame_states.front().s, actuation)};
  result->frames.reserve(run->frame_states.size());
  for (std::size_t k = 0; k < run->frame_states.size() && k < run->frame_t.size(); ++k) {
    io::VtkFrame frame;
    frame.t = run->frame_t[k];
    frame.rods.push_back(std::move(run->frame_states[k]));
    result->frames.push_back(std::move(frame));
  }
  run->frame_states.clear();
}

}  // namespace cosserat::run::detail
