#include "cosserat/assembly/rod_shot.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/rod/grid.hpp"

namespace cosserat {

RodShot::RodShot(const RodModel& model, int nodes) : model_length_(model.length) {
  std::string why;
  if (!model.IsValid(&why)) throw std::invalid_argument("RodModel: " + why);
  if (!model.tendons.empty())
    throw std::invalid_argument("RodShot: rods with tendons are not joined in assemblies yet");
  if (nodes < 2) throw std::invalid_argument("RodShot: at least 2 nodes are needed");
  const std::vector<double> grid = ModelGrid(model, nodes);
  sigma_.resize(grid.size());
  for (size_t i = 0; i < grid.size(); ++i) sigma_[i] = grid[i] / model.length;
  samples_.resize(2 * grid.size() - 1);
  for (size_t q = 0; q < samples_.size(); ++q) {
    const size_t i = q / 2;
    const double s = q % 2 == 0 ? grid[i] : 0.5 * (grid[i] + grid[i + 1]);
    const SectionLaw law = SectionLaw::At(model, s, Actuation{});
    Sample& smp = samples_[q];
    smp.rest_strain = law.rest_strain;
    smp.compliance = law.stiffness.cwiseInverse();
    smp.mass_per_length = law.mass_per_length();
    smp.outer_diameter = law.outer_diameter;
    smp.s = s;
  }
  const SectionProperties p = model.section->At(0.0, Actuation{});
  bending_stiffness_ = std::max(p.stiffness(0, 0), p.stiffness(1, 1));
}

void RodShot::SetLoads(const StaticLoads& loads) {
  for (Sample& smp : samples_)
    smp.force_W =
        TotalDistributedForce_W(loads, {smp.s, 1.0, smp.mass_per_length, smp.outer_diameter});
}

void RodShot::Record(const Point<double>& start, double length, RodState* state) const {
  state->Resize(nodes());
  Point<double> y = start;
  auto record = [&](int i, const Point<double>& at) {
    Vec6 xi;
    rhs::LinearStrain<double>(samples_[2 * i].rest_strain, samples_[2 * i].compliance, at.m, at.n,
                              &xi);
    state->s[i] = sigma_[i] * length;
    state->position_W[i] = at.p;
    state->rotation_WB[i] = at.R;
    state->wrench_B[i] << at.m, at.n;
    state->strain[i] = xi;
    state->twist_B[i].setZero();
  };
  record(0, y);
  for (int i = 0; i + 1 < nodes(); ++i) {
    y = Step<double>(i, y, length);
    record(i + 1, y);
  }
}

}  // namespace cosserat
