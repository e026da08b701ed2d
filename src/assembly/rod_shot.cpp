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

namespace {

using rhs::StaticTangent;

StaticTangent Axpy(const StaticTangent& y, double a, const StaticTangent& d) {
  StaticTangent out;
  out.p = y.p + a * d.p;
  for (int j = 0; j < 3; ++j) out.R[j] = y.R[j] + a * d.R[j];
  out.m = y.m + a * d.m;
  out.n = y.n + a * d.n;
  return out;
}

}  // namespace

RodShot::Point<double> RodShot::ShootTangent(const Point<double>& start,
                                             const rhs::StaticTangent& start_tangent,
                                             double length, rhs::StaticTangent* tip_tangent) const {
  auto axpy = [](const Point<double>& y, double a, const Point<double>& k) {
    return Point<double>{y.p + a * k.p, y.R + a * k.R, y.m + a * k.m, y.n + a * k.n};
  };
  Point<double> y = start;
  StaticTangent dy = start_tangent;
  const double stage_step[4] = {0.0, 0.5, 0.5, 1.0};
  for (int i = 0; i + 1 < nodes(); ++i) {
    const double h = sigma_[i + 1] - sigma_[i];
    const Sample* smp[4] = {&samples_[2 * i], &samples_[2 * i + 1], &samples_[2 * i + 1],
                            &samples_[2 * i + 2]};
    Point<double> k[4];
    StaticTangent t[4];
    for (int j = 0; j < 4; ++j) {
      const Point<double> yj = j == 0 ? y : axpy(y, stage_step[j] * h, k[j - 1]);
      const StaticTangent dyj = j == 0 ? dy : Axpy(dy, stage_step[j] * h, t[j - 1]);
      Vec6 xi;
      k[j] = rhs::StaticDerivative<double>(smp[j]->rest_strain, smp[j]->compliance,
                                           smp[j]->force_W, yj, &xi);
      t[j] = rhs::StaticTangentDerivative(smp[j]->compliance, smp[j]->force_W, yj, dyj, xi);
      // dy/dσ = L y'(s): the rates and their tangents scale with the length.
      k[j].p *= length;
      k[j].R *= length;
      k[j].m *= length;
      k[j].n *= length;
      t[j].p *= length;
      for (auto& c : t[j].R) c *= length;
      t[j].m *= length;
      t[j].n *= length;
    }
    const double a = h / 6, b = h / 3;
    y.p += a * (k[0].p + k[3].p) + b * (k[1].p + k[2].p);
    y.R += a * (k[0].R + k[3].R) + b * (k[1].R + k[2].R);
    y.m += a * (k[0].m + k[3].m) + b * (k[1].m + k[2].m);
    y.n += a * (k[0].n + k[3].n) + b * (k[1].n + k[2].n);
    dy.p += a * (t[0].p + t[3].p) + b * (t[1].p + t[2].p);
    for (int c = 0; c < 3; ++c) dy.R[c] += a * (t[0].R[c] + t[3].R[c]) + b * (t[1].R[c] + t[2].R[c]);
    dy.m += a * (t[0].m + t[3].m) + b * (t[1].m + t[2].m);
    dy.n += a * (t[0].n + t[3].n) + b * (t[1].n + t[2].n);
  }
  *tip_tangent = dy;
  return y;
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
