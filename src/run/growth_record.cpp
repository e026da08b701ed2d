#include "growth_record.hpp"

#include <cmath>
#include <utility>

#include "frame_output.hpp"

namespace cosserat::run::detail {

void GrowthRecord::Add(const EversionRobot& robot, const EversionSolveSummary& step) {
  const RodState& state = robot.state();
  length_.push_back(robot.length());
  tip_.push_back(state.tip_position_W());
  ratio_.push_back(step.kink.max_ratio);
  if (!frames_) return;
  io::VtkFrame frame;
  frame.t = robot.length();  // m: ParaView's time controls play the growth
  frame.rods = {state};
  // The body at this length: a band it has everted only in part ends at its tip.
  frame.radius = {NodeRadius(robot.ModelAt(robot.length()), state.s, robot.actuation())};
  frames_kept_.push_back(std::move(frame));
}

nlohmann::ordered_json GrowthRecord::Json() const {
  nlohmann::ordered_json tips = nlohmann::ordered_json::array();
  nlohmann::ordered_json ratios = nlohmann::ordered_json::array();
  for (const Vec3& p : tip_) tips.push_back({p.x(), p.y(), p.z()});
  for (const double r : ratio_)
    ratios.push_back(std::isfinite(r) ? nlohmann::ordered_json(r) : nlohmann::ordered_json());
  nlohmann::ordered_json out;
  out["length"] = length_;
  out["tip"] = std::move(tips);
  out["max_moment_ratio"] = std::move(ratios);
  return out;
}

void GrowthRecord::MoveFramesInto(Result* result) {
  if (!frames_ || frames_kept_.empty()) return;
  result->frames = std::move(frames_kept_);
  frames_kept_.clear();
}

}  // namespace cosserat::run::detail
