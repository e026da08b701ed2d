#include "cosserat/assembly/rod_shot.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/rod/grid.hpp"
#include "cosserat/strong/frame_tangent.hpp"

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
  // Each segment's own start, middle and end (from inside the segment, as the cantilever
  // solvers sample): a stiffness profile's end on a node belongs to the segment it bounds.
  const std::vector<double> points = SegmentSamplePoints(grid);
  samples_.resize(points.size());
  for (size_t q = 0; q < samples_.size(); ++q) {
    const double s = points[q];
    const SectionLaw law = SectionLaw::At(model, s, Actuation{});
    Sample& smp = samples_[q];
    smp.rest_strain = law.rest_strain;
    smp.compliance = law.stiffness.cwiseInverse();
    smp.mass_per_length = law.mass_per_length();
    smp.outer_diameter = law.outer_diameter;
    smp.s = s;
  }
  const SectionProperties p = model.section->At(0.0, Actuation{});
  bending_stiffness_ = p.max_bending_stiffness();
}

void RodShot::SetLoads(const StaticLoads& loads) {
  for (Sample& smp : samples_)
    smp.force_W =
        TotalDistributedForce_W(loads, {smp.s, 1.0, smp.mass_per_length, smp.outer_diameter});
}

namespace {

using rhs::StaticTangent;
using namespace internal;  // the tangent algebra of frame_tangent.hpp

/// The tangent of the carried state (RodShot's p, R, J, n_W), in StaticTangent's fields: m holds
/// dJ and n holds dn_W.
using CarriedTangent = StaticTangent;

CarriedTangent Axpy(const CarriedTangent& y, double a, const CarriedTangent& d) {
  CarriedTangent out;
  out.p = y.p + a * d.p;
  for (int j = 0; j < 3; ++j) out.R[j] = y.R[j] + a * d.R[j];
  out.m = y.m + a * d.m;
  out.n = y.n + a * d.n;
  return out;
}

/// The body-frame tangent (dm_B, dn_B) of the carried tangent at a stage's carried state
/// (p, R, J, n): n_B = Rᵀ n, m_B = Rᵀ (J − p × n), as AtStage converts.
StaticTangent BodyTangent(const Vec3& p, const Mat3& R, const Vec3& J, const Vec3& n,
                          const CarriedTangent& dc) {
  StaticTangent d;
  d.p = dc.p;
  d.R = dc.R;
  d.n = TransposeTimesFixed(dc.R, n) + R.transpose() * dc.n;
  d.m = TransposeTimesFixed(dc.R, J - p.cross(n)) +
        R.transpose() * (dc.m + Cross(n, dc.p) - Cross(p, dc.n));
  return d;
}

/// The same at the tip, where FromCarried converts with R⁻¹: n_B = R⁻¹ n, m_B = R⁻¹ u with
/// u = J − p × n, so dn_B = R⁻¹ (dn − dR n_B) and dm_B = R⁻¹ (du − dR m_B). RK4 leaves R off a
/// rotation by its truncation, which far from equilibrium is not small (|RᵀR − I| = 0.1 on a
/// taut wire bent hard by a first Newton step); with Rᵀ here, the derivative of the tip force
/// R n_B came out proportional to the tension where it is zero, and Newton stalled.
StaticTangent EndTangent(const Vec3& p, const Mat3& R, const Vec3& J, const Vec3& n,
                         const CarriedTangent& dc) {
  const Mat3 R_inv = R.inverse();
  const Vec3 n_B = R_inv * n, m_B = R_inv * (J - p.cross(n));
  const Mat36 zero = Mat36::Zero();
  StaticTangent d;
  d.p = dc.p;
  d.R = dc.R;
  d.n = R_inv * (dc.n - RotateTangent(R, dc.R, n_B, zero));
  d.m = R_inv * (dc.m + Cross(n, dc.p) - Cross(p, dc.n) - RotateTangent(R, dc.R, m_B, zero));
  return d;
}

}  // namespace

RodShot::Point<double> RodShot::ShootTangent(const Point<double>& start,
                                             const rhs::StaticTangent& start_tangent,
                                             double length, rhs::StaticTangent* tip_tangent) const {
  auto axpy = [](const Carried<double>& y, double a, const Carried<double>& k) {
    return Carried<double>{y.p + a * k.p, y.R + a * k.R, y.J + a * k.J, y.n + a * k.n};
  };
  Carried<double> c = ToCarried(start);
  // The start's tangent carried: dn_W = d(R n_B), dJ = d(R m_B) + dp × n_W + p × dn_W.
  CarriedTangent dc;
  dc.p = start_tangent.p;
  dc.R = start_tangent.R;
  dc.n = RotateTangent(start.R, start_tangent.R, start.n, start_tangent.n);
  dc.m = RotateTangent(start.R, start_tangent.R, start.m, start_tangent.m) - Cross(c.n, dc.p) +
         Cross(start.p, dc.n);
  const double stage_step[4] = {0.0, 0.5, 0.5, 1.0};
  for (int i = 0; i + 1 < nodes(); ++i) {
    const double h = sigma_[i + 1] - sigma_[i];
    const Sample* smp[4] = {&samples_[3 * i], &samples_[3 * i + 1], &samples_[3 * i + 1],
                            &samples_[3 * i + 2]};
    Carried<double> k[4];
    CarriedTangent t[4];
    for (int j = 0; j < 4; ++j) {
      const Carried<double> cj = j == 0 ? c : axpy(c, stage_step[j] * h, k[j - 1]);
      const CarriedTangent dcj = j == 0 ? dc : Axpy(dc, stage_step[j] * h, t[j - 1]);
      const Point<double> y = AtStage(cj);
      const StaticTangent dy = BodyTangent(cj.p, cj.R, cj.J, cj.n, dcj);
      const Vec3& f = smp[j]->force_W;
      Vec6 xi;
      const Point<double> rates =
          rhs::StaticDerivative<double>(smp[j]->rest_strain, smp[j]->compliance, f, y, &xi);
      const StaticTangent body = rhs::StaticTangentDerivative(smp[j]->compliance, f, y, dy, xi);
      // dc/dσ = L c'(s): J' = −p × f, n_W' = −f (f does not depend on the pose).
      k[j] = Carried<double>{length * rates.p, length * rates.R, -length * cj.p.cross(f),
                             -length * f};
      t[j].p = length * body.p;
      for (int a = 0; a < 3; ++a) t[j].R[a] = length * body.R[a];
      t[j].m = length * Cross(f, dcj.p);  // d(−p × f) = f × dp
      t[j].n.setZero();
    }
    const double a = h / 6, b = h / 3;
    c.p += a * (k[0].p + k[3].p) + b * (k[1].p + k[2].p);
    c.R += a * (k[0].R + k[3].R) + b * (k[1].R + k[2].R);
    c.J += a * (k[0].J + k[3].J) + b * (k[1].J + k[2].J);
    c.n += a * (k[0].n + k[3].n) + b * (k[1].n + k[2].n);
    dc.p += a * (t[0].p + t[3].p) + b * (t[1].p + t[2].p);
    for (int r = 0; r < 3; ++r) dc.R[r] += a * (t[0].R[r] + t[3].R[r]) + b * (t[1].R[r] + t[2].R[r]);
    dc.m += a * (t[0].m + t[3].m) + b * (t[1].m + t[2].m);
  }
  *tip_tangent = EndTangent(c.p, c.R, c.J, c.n, dc);
  return FromCarried(c);
}

void RodShot::Record(const Point<double>& start, double length, RodState* state) const {
  state->Resize(nodes());
  Carried<double> c = ToCarried(start);
  auto record = [&](int i, const Carried<double>& at) {
    const Point<double> y = FromCarried(at);
    Vec6 xi;
    // Node i's section: the start of segment i, the tip's the end of the last segment.
    const Sample& smp = samples_[i + 1 < nodes() ? 3 * i : 3 * i - 1];
    rhs::LinearStrain<double>(smp.rest_strain, smp.compliance, y.m, y.n, &xi);
    state->s[i] = sigma_[i] * length;
    state->position_W[i] = y.p;
    state->rotation_WB[i] = y.R;
    state->wrench_B[i] << y.m, y.n;
    state->strain[i] = xi;
    state->twist_B[i].setZero();
  };
  record(0, c);
  for (int i = 0; i + 1 < nodes(); ++i) {
    c = Step<double>(i, c, length);
    record(i + 1, c);
  }
}

Vec6 RodShot::LoadWrench_W(const Point<double>& start, double length) const {
  // The loads are what the carried wrench loses along the rod: J(0) − J(L), n_W(0) − n_W(L),
  // i.e. RK4's own sum of ∫ p × f and ∫ f.
  const Carried<double> c0 = ToCarried(start);
  Carried<double> c = c0;
  for (int i = 0; i + 1 < nodes(); ++i) c = Step<double>(i, c, length);
  Vec6 out;
  out << c0.J - c.J, c0.n - c.n;
  return out;
}

}  // namespace cosserat
