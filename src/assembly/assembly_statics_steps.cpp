// AssemblyStaticsSolver's steps: a trial step, chord steps after a full Newton step that raised
// the residual, and the tolerance the balance's round-off allows.
#include <algorithm>
#include <limits>

#include "cosserat/assembly/assembly_statics.hpp"

namespace cosserat {

namespace {

// Chord steps tried after a full Newton step that raised the residual (TryStep).
constexpr int kChordSteps = 4;

}  // namespace

bool AssemblyStaticsSolver::TryStep(const StaticLoads& loads, double norm, bool chord_steps) {
  // Chord steps: taut rods held at both ends: a tip position residual (over L) is tiny against
  // the moment rows a good Newton step disturbs, so the full step can raise the norm where the
  // chord steps after it bring it below (a plate on 1 mm wires, off its centre of mass, pushed
  // sideways: its load steps stalled at 2e-6 under damped steps that each gained 1e-3).
  Store(&saved_);
  Apply(dz_, 1.0);
  bool ok = dz_.allFinite() && ShootAll();
  for (int k = 0; ok; ++k) {
    Residual(loads, &r_trial_);
    if (!r_trial_.allFinite()) break;
    if (r_trial_.norm() < norm) return true;
    if (k == (chord_steps ? kChordSteps : 0)) break;
    dz_ = lu_.solve(-r_trial_);
    Apply(dz_, 1.0);
    ok = dz_.allFinite() && ShootAll();
  }
  // Back to the state before the step, and to its shots: the rods' tips are what the Jacobian
  // reads (a step that blew up left them NaN, and the next Jacobian with them).
  Load(saved_);
  ShootAll();
  return false;
}

double AssemblyStaticsSolver::Tolerance(const StaticLoads& loads, double* stall_floor) const {
  // The largest force the balance adds up (N): the bodies' weights and forces, the rods' weights
  // and distributed loads. Each term carries round-off ε of itself, amplified through the
  // shots: a 10 kg plate on four 1 mm wires (625 times the force scale) stalls at 2.6e-10 to
  // 5e-10, 2e3–4e3 ε of it; 1e4 ε bounds that.
  //
  // A rod's held end is placed to ε of its coordinates (~ε L), an axial force of ~EA ε: a taut
  // wire's balance may not resolve its tension below that. The same plate off its centre of
  // mass and pushed sideways stalled at 2–6e-9 of the force scale. A solve that stops making
  // progress below 10 ε ΣEA (at most 1e-6 of the loads) has converged as far as the rods allow;
  // one that still progresses goes on to the tolerance.
  const double g = loads.gravity_W.norm();
  double force = 0.0, axial_stiffness = 0.0;
  for (const RigidBody& b : assembly_.bodies) force += b.mass * g + b.force_W.norm();
  for (const AssemblyRod& a : assembly_.rods) {
    const SectionProperties p = a.model.section->At(0.0, Actuation{});
    force += (p.mass(3, 3) * g + loads.distributed_force_W.norm()) * a.model.length;
    axial_stiffness += p.stiffness(5, 5);  // EA, N
  }
  const double scale = body_force_scale_.empty() ? rods_.front().force_scale
                                                 : body_force_scale_.front();
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  const double tolerance = std::max(options_.tolerance, 1e4 * kEpsilon * force / scale);
  if (stall_floor)
    *stall_floor =
        std::max(tolerance, std::min(10 * kEpsilon * axial_stiffness, 1e-6 * force) / scale);
  return tolerance;
}

}  // namespace cosserat
