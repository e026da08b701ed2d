#include "cosserat/quatfd/quatfd_statics.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosserat/loads/contact_entry.hpp"
#include "cosserat/loads/obstacle_core.hpp"
#include "cosserat/numerics/banded_matrix.hpp"
#include "cosserat/quatfd/quatfd_kernels.hpp"

namespace cosserat::quatfd {
namespace {

using L = QuatFdLayout;

struct Workspace {
  explicit Workspace(int n)
      : A(n, L::kBandwidth, L::kBandwidth),
        B(n, L::kBandwidth, L::kBandwidth),
        a(n),
        dq(n),
        zero(Eigen::VectorXd::Zero(n)) {}
  BandedMatrix A, B;
  Eigen::VectorXd a, dq, zero;
  Eigen::VectorXd step;  ///< the limited step, for the contact entry check
  double residual = 0;
};

/// β for the solve: β² J_min = EI/L, so the constraint rows (β² (|p|² − 1)/2) and the tangential
/// rows (torque / J, torques of the order EI/L) have comparable size for pivoting. Only a row
/// scale: any β > 0 gives the same equilibrium.
/// A rod held at both ends takes the larger of EI/L and the moments its loads and tension make
/// over a segment: a cable's EI/L is far below them, and a Baumgarte row that weak leaves the
/// quaternions' gauge nearly singular beside the torques, which spoils Newton's step.
double StaticBeta(const QuatFdModel& model, const StaticLoads& loads,
                  const Eigen::Ref<const Eigen::VectorXd>& q) {
  double moment = model.moment_scale();
  if (model.options().TipHeld()) {
    const double h = model.length() / model.layout().segments;
    const double weight = model.Mass() * loads.gravity_W.norm() +
                          loads.distributed_force_W.norm() * model.length() +
                          loads.tip_force.norm();
    moment = std::max({moment, model.MaxSegmentForce(q) * h, weight * h});
  }
  return std::sqrt(moment / model.min_rotational_inertia());
}

/// The vertex positions of q (world, m), and of q + dq when dq is given.
std::vector<Vec3> VertexPositions(const QuatFdModel& model,
                                  const Eigen::Ref<const Eigen::VectorXd>& q,
                                  const Eigen::VectorXd* dq = nullptr) {
  std::vector<Vec3> x(model.layout().segments + 1);
  for (size_t v = 0; v < x.size(); ++v) {
    x[v] = q.segment<3>(L::X(static_cast<int>(v)));
    if (dq) x[v] += dq->segment<3>(L::X(static_cast<int>(v)));
  }
  return x;
}

/// Whether the surfaces hold the rod back at q: no vertex, segment or vertex path from `from`
/// reaches into an obstacle's core (obstacle_core.hpp). Always true without obstacles.
bool HeldBack(const QuatFdModel& model, const ContactSurfaces& surfaces,
              const Eigen::Ref<const Eigen::VectorXd>& from,
              const Eigen::Ref<const Eigen::VectorXd>& q) {
  return !HasObstacleCore(surfaces) ||
         !ReachesObstacleCore(surfaces, VertexPositions(model, from), VertexPositions(model, q));
}

/// The fraction of the step dq from q after which the first vertex clear of a contact surface
/// has entered it by its outer radius (contact_entry.hpp); 1 without surfaces.
double ContactEntry(const QuatFdModel& model, const Eigen::Ref<const Eigen::VectorXd>& q,
                    const Eigen::VectorXd& dq) {
  const ContactSurfaces& surfaces = model.loads().contact;
  if (surfaces.count == 0) return 1.0;
  std::vector<double> diameter(model.layout().segments + 1);
  for (size_t v = 0; v < diameter.size(); ++v)
    diameter[v] = model.VertexSite(static_cast<int>(v)).outer_diameter;
  return ContactEntryFraction(surfaces, VertexPositions(model, q), VertexPositions(model, q, &dq),
                              diameter);
}

/// The round-off floor of StaticResidual at q: a vertex force is C_Γ times a strain formed from
/// differences of positions of size |x| over a segment h = L/N, so its round-off is about
/// ε C_Γ |x| N / L; over the force scale, with a factor 10 for the sums that form the residual.
/// A 1 m steel rod of r = 5 mm on 30 000 segments reaches 1e-6 (it failed there); on 1 000,
/// 4e-8.
double RoundOffFloor(const QuatFdModel& model, const Eigen::Ref<const Eigen::VectorXd>& q) {
  const int N = model.layout().segments;
  double reach = model.length();
  for (int v = 0; v <= N; ++v) reach = std::max(reach, q.segment<3>(L::X(v)).norm());
  const double force_scale = std::max(model.force_scale(), model.MaxSegmentForce(q));
  return 10.0 * std::numeric_limits<double>::epsilon() * model.MaxStrainStiffness() * reach * N /
         (model.length() * force_scale);
}

/// Newton at fixed loads from q. Returns true on convergence; counts iterations.
bool Newton(const QuatFdModel& model, const QuatFdStaticsOptions& opt, double beta,
            Eigen::Ref<Eigen::VectorXd> q, Workspace* w, QuatFdStaticsSummary* summary) {
  const int n = model.size();
  const double L = model.length();
  for (int it = 0; it < opt.max_iterations; ++it) {
    w->residual = StaticResidual(model, q);
    summary->residual = w->residual;
    if (!std::isfinite(w->residual)) return false;
    if (w->residual < opt.tolerance) return true;
    model.Jacobian(q, w->zero, 0.0, beta, &w->A, &w->B, &w->a);
    ++summary->iterations;
    // A fixed coordinate's row becomes dq_i = 0, scaled like the row it replaces: a unit row
    // among a stiff contact's (k = 1e20 N/m², entries ~1e20) is eliminated by the pivoting
    // into round-off, which moved a clamped base node by 88 mm over the iterations.
    for (int i = 0; i < n; ++i) {
      if (!model.IsFixed(i)) continue;
      double row_scale = 0.0;
      for (int j = std::max(0, i - L::kBandwidth); j <= std::min(n - 1, i + L::kBandwidth); ++j) {
        row_scale = std::max(row_scale, std::abs(w->A(i, j)));
        w->A(i, j) = 0.0;
      }
      w->A(i, i) = row_scale > 0.0 ? row_scale : 1.0;
      w->a[i] = 0.0;
    }
    if (!w->A.Factorize()) return false;
    w->dq = -w->a;
    w->A.Solve(w->dq);
    for (int i = 0; i < n; ++i)
      if (model.IsFixed(i)) w->dq[i] = 0.0;  // exactly: the end stays where it is held
    if (!w->dq.allFinite()) return false;
    // Limit a step to a rotation increment of about 0.5 rad per quaternion and a displacement of
    // L/2 (full Newton steps far from the solution can flip quaternions).
    double scale = 1.0;
    for (int s = 0; s < model.layout().segments; ++s)
      scale = std::min(scale, 0.25 / std::max(1e-300, w->dq.segment<4>(L::P(s)).norm()));
    for (int v = 0; v <= model.layout().segments; ++v)
      scale = std::min(scale, 0.5 * L / std::max(1e-300, w->dq.segment<3>(L::X(v)).norm()));
    w->step = scale * w->dq;
    scale *= ContactEntry(model, q, w->step);
    q += scale * w->dq;
    for (int s = 0; s < model.layout().segments; ++s) q.segment<4>(L::P(s)).normalize();
    double step_x = 0.0, step_p = 0.0;
    for (int i = 0; i < n; ++i) {
      const bool is_x = (i % 7) < 3;
      (is_x ? step_x : step_p) = std::max(is_x ? step_x : step_p, std::abs(scale * w->dq[i]));
    }
    if (scale == 1.0 && step_x < 1e-13 * L && step_p < 1e-13) {
      w->residual = StaticResidual(model, q);
      summary->residual = w->residual;
      return w->residual < std::max(opt.floor_tolerance, RoundOffFloor(model, q));
    }
  }
  w->residual = StaticResidual(model, q);
  summary->residual = w->residual;
  return w->residual < opt.tolerance;
}

/// The loads as statics solves them. Newton drives the accelerations M⁻¹ f to zero; a fluid's
/// added mass makes M turn with each vertex's tangent, which adds ∂M⁻¹/∂q · f to the Jacobian:
/// zero at the equilibrium, but far from it enough to turn a riser's steps on the sea bed
/// astray. At rest the added mass does nothing, so it is left out.
StaticLoads AtRest(const StaticLoads& loads) {
  StaticLoads out = loads;
  out.fluid.added_mass = 0.0;
  return out;
}

/// Throws std::invalid_argument for a q not of the model's size or options out of range.
void RequireStaticsInputs(const QuatFdModel& model, const Eigen::Ref<Eigen::VectorXd>& q,
                          const QuatFdStaticsOptions& options) {
  if (q.size() != model.size())
    throw std::invalid_argument("quatfd::SolveStatics: q has " + std::to_string(q.size()) +
                                " entries, the model's state " + std::to_string(model.size()));
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("QuatFdStaticsOptions: " + why);
}

}  // namespace

bool TurnsBack(const QuatFdModel& model, const Eigen::VectorXd& a, const Eigen::VectorXd& b,
               const Eigen::VectorXd& c) {
  double along = 0.0;  // m²; fixed vertices do not move and add nothing
  for (int n = 0; n <= model.layout().segments; ++n) {
    const int i = L::X(n);
    along += (c.segment<3>(i) - b.segment<3>(i)).dot(b.segment<3>(i) - a.segment<3>(i));
  }
  return along < 0.0;
}

bool QuatFdStaticsOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (!(tolerance > 0 && std::isfinite(tolerance))) return fail("tolerance: expected > 0");
  if (!(floor_tolerance >= tolerance && std::isfinite(floor_tolerance)))
    return fail("floor_tolerance: expected >= tolerance");
  if (max_iterations < 1) return fail("max_iterations: expected at least 1");
  if (!(min_load_step > 0 && min_load_step <= 1)) return fail("min_load_step: expected in (0, 1]");
  if (max_load_steps < 1) return fail("max_load_steps: expected at least 1");
  if (!(max_load_step > 0 && max_load_step <= 1)) return fail("max_load_step: expected in (0, 1]");
  return true;
}

double StaticResidual(const QuatFdModel& model, const Eigen::Ref<const Eigen::VectorXd>& q) {
  const int N = model.layout().segments, n = model.size();
  Eigen::VectorXd forces(n);
  model.Forces(q, Eigen::VectorXd::Zero(n), forces);
  const double f_max = model.MaxSegmentForce(q);
  const double force_scale = std::max(model.force_scale(), f_max);
  const double moment_scale = std::max(model.moment_scale(), f_max * model.length() / N);
  double r = 0.0;
  for (int v = 0; v <= N; ++v)
    r = std::max(r, forces.segment<3>(L::X(v)).norm() / force_scale);
  for (int s = 0; s < N; ++s) {
    r = std::max(r, forces.segment<3>(L::P(s) + 1).norm() / moment_scale);
    r = std::max(r, std::abs(q.segment<4>(L::P(s)).squaredNorm() - 1.0));
  }
  return r;
}

QuatFdStaticsSummary SolveStatics(QuatFdModel* model, const StaticLoads& given,
                                  Eigen::Ref<Eigen::VectorXd> q,
                                  const QuatFdStaticsOptions& options) {
  const StaticLoads loads = AtRest(given);  // the model gets the given loads back at the end
  const auto start = std::chrono::steady_clock::now();
  RequireStaticsInputs(*model, q, options);
  QuatFdStaticsSummary summary;
  Workspace w(model->size());
  const double beta = StaticBeta(*model, loads, q);
  auto finish = [&](SolveStatus status) {
    model->set_loads(given);
    summary.status = status;
    summary.wall_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
  };
  if (!loads.IsValid(nullptr) || !q.allFinite()) return finish(SolveStatus::kNonFinite);

  model->set_loads(loads);
  const Eigen::VectorXd q_start = q;
  // A direct solve that lands beyond an obstacle jumped through it: the continuation then.
  if (options.direct_solve && Newton(*model, options, beta, q, &w, &summary) &&
      HeldBack(*model, loads.contact, q_start, q))
    return finish(SolveStatus::kConverged);
  if (!options.load_stepping) return finish(SolveStatus::kMaxIterations);

  // Continuation in λ along at(λ) from a solution q_ok at λ = 0 (q_before: the point before it):
  // grow the increment after a success, halve it after a failure. False when the increment
  // falls below its floor or the load steps run out.
  Eigen::VectorXd q_ok(model->size()), v(model->size()), q_before(model->size());
  model->RestState(q_ok, v);
  const auto follow = [&](const std::function<StaticLoads(double)>& at) {
    q_before = q_ok;  // each path starts without a direction
    double lambda = 0.0, step = std::min(0.25, options.max_load_step);
    while (lambda < 1.0) {
      if (summary.load_steps >= options.max_load_steps || step < options.min_load_step)
        return false;
      ++summary.load_steps;
      const double target = std::min(1.0, lambda + step);
      model->set_loads(at(target));
      q = q_ok;
      if (Newton(*model, options, beta, q, &w, &summary) &&
          HeldBack(*model, loads.contact, q_ok, q) &&
          !(options.keep_path_direction && TurnsBack(*model, q_before, q_ok, q))) {
        lambda = target;
        q_before = q_ok;
        q_ok = q;
        step = std::min(2.0 * step, options.max_load_step);
      } else {
        step *= 0.5;
      }
    }
    return true;
  };
  // A rod held at both ends starts from a shape hanging in gravity, which is no equilibrium of
  // the other loads when the rod is slack: there the rod hanging under gravity (and buoyancy)
  // comes first, and the continuation adds the other loads to it. The hanging shape does not
  // depend on the size of gravity, so gravity itself is followed from zero when needed.
  bool ok;
  if (model->options().TipHeld() && !loads.gravity_W.isZero()) {
    StaticLoads hanging = loads.Scaled(0.0);
    hanging.gravity_W = loads.gravity_W;
    model->set_loads(hanging);
    q = q_ok;
    ok = Newton(*model, options, beta, q, &w, &summary) &&
         HeldBack(*model, loads.contact, q_ok, q);
    if (ok)
      q_ok = q;
    else
      ok = follow([&](double l) { return hanging.Scaled(l); });
    if (ok && hanging != loads)
      ok = follow([&](double l) { return StaticLoads::Blend(hanging, loads, l); });
  } else {
    ok = follow([&](double l) { return loads.Scaled(l); });
  }
  if (!ok) return finish(SolveStatus::kLoadSteppingFailed);
  q = q_ok;
  model->set_loads(loads);
  summary.residual = StaticResidual(*model, q);
  return finish(SolveStatus::kConverged);
}

}  // namespace cosserat::quatfd
