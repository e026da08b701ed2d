#include "contact_report.hpp"

#include <vector>

#include "cosserat/loads/contact.hpp"

namespace cosserat::run::detail {

void AddContactReport(const io::Problem& problem, Result* result) {
  if (problem.loads.contact.count == 0) return;
  auto& json = result->json;
  if (!json.contains("nodes") || !json["nodes"].contains("position")) return;
  const auto& s = json["nodes"]["s"];
  const auto& position = json["nodes"]["position"];
  const PenaltyContact contact(problem.loads.contact);
  nlohmann::ordered_json per_node = nlohmann::ordered_json::array();
  nlohmann::ordered_json intervals = nlohmann::ordered_json::array();
  Vec3 total = Vec3::Zero(), previous = Vec3::Zero();
  double s_previous = 0.0, start = -1.0;
  const std::size_t n = s.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double si = s[i].get<double>();
    const Vec3 p(position[i][0].get<double>(), position[i][1].get<double>(),
                 position[i][2].get<double>());
    const double d = problem.rod.section->At(si, problem.robot.actuation).outer_diameter;
    const Vec3 f =
        contact.MotionForce_W({si, 1.0, 0.0, d}, {p, Vec3::UnitZ(), Vec3::Zero()}, nullptr);
    per_node.push_back({f.x(), f.y(), f.z()});
    if (i > 0) total += 0.5 * (si - s_previous) * (f + previous);
    const bool touching = !f.isZero(0.0);
    if (touching && start < 0) start = si;
    if (!touching && start >= 0) {
      intervals.push_back({start, s_previous});
      start = -1.0;
    }
    previous = f;
    s_previous = si;
  }
  if (start >= 0) intervals.push_back({start, s_previous});
  json["nodes"]["contact_force"] = per_node;
  json["contact"] = {{"total_force", {total.x(), total.y(), total.z()}}, {"intervals", intervals}};
}

}  // namespace cosserat::run::detail
