#include "assembly_json.hpp"

#include "cosserat/io/result_writer.hpp"

namespace cosserat::run::detail {

using json = nlohmann::ordered_json;

json AssemblyJson(const Assembly& assembly, const char* kind, const std::vector<lie::SE3>& poses,
                  const std::vector<const RodState*>& rods, const std::vector<double>& lengths) {
  json bodies = json::array(), rod_blocks = json::array();
  for (std::size_t b = 0; b < assembly.bodies.size() && b < poses.size(); ++b)
    bodies.push_back({{"name", assembly.bodies[b].name},
                      {"position", io::ToJson(poses[b].p)},
                      {"rotation", io::ToJson(poses[b].R)}});
  for (std::size_t i = 0; i < rods.size(); ++i) {
    const RodState& state = *rods[i];
    json rod;
    rod["name"] = assembly.rods[i].name;
    rod["length"] = lengths[i];
    io::AddTipAndBaseWrench(state, &rod);  // base_wrench: [moment about the base point; force]
    // As a single rod's: the member's internal forces and moments along it too.
    rod["nodes"] = io::NodesToJson(state);
    rod_blocks.push_back(rod);
  }
  return {{"kind", kind}, {"bodies", bodies}, {"rods", rod_blocks}};
}

}  // namespace cosserat::run::detail
