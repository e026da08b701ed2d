// The snapshots of the BDF2 stepper: what identifies the rod a run belongs to, and a saved run
// restored.
#include <cstdint>
#include <stdexcept>

#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat {

std::uint64_t Bdf2ShootingStepper::ModelFingerprint() const {
  // FNV-1a over the bytes of what a run's state depends on.
  std::uint64_t h = 1469598103934665603ull;
  auto add = [&h](const void* data, std::size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  const int ends = static_cast<int>(options_.ends),
            scheme = static_cast<int>(options_.spatial_scheme);
  add(&ends, sizeof ends);
  add(&scheme, sizeof scheme);
  add(pair_start_.data(), pair_start_.size());  // where the stage slots are (PlanSteps)
  for (const double s : grid_) {
    const SectionProperties p = model_.section->At(s, Actuation{});
    const Vec6 k = p.stiffness.diagonal(), m = p.mass.diagonal(), d = p.damping.diagonal();
    add(&s, sizeof s);
    add(k.data(), sizeof(double) * 6);
    add(m.data(), sizeof(double) * 6);
    add(d.data(), sizeof(double) * 6);  // Kelvin–Voigt: the same state steps on differently
  }
  // The actuators: a snapshot of a tendon or chamber robot continues only on the same robot.
  for (const Tendon& t : model_.tendons) {
    const int kind = static_cast<int>(t.route.kind);
    const double numbers[] = {t.route.offset_base.x(), t.route.offset_base.y(),
                              t.route.offset_tip.x(),  t.route.offset_tip.y(),
                              t.route.radius,          t.route.pitch,
                              t.route.phase,           t.anchor};
    add(&kind, sizeof kind);
    add(numbers, sizeof numbers);
  }
  for (const Chamber& c : model_.chambers) {
    const double numbers[] = {c.offset.x(), c.offset.y(), c.area, c.start, c.end};
    add(numbers, sizeof numbers);
  }
  const std::size_t counts[] = {model_.tendons.size(), model_.chambers.size()};
  add(counts, sizeof counts);
  return h;
}

bool Bdf2ShootingStepper::PiecesCanFollow(const Snapshot& s) const {
  return automatic_pieces_ && s.junction_unknowns.size() % 18 == 0 &&
         static_cast<int>(s.junction_unknowns.size() / 18) < MaxAutomaticPieces();
}

void Bdf2ShootingStepper::RequireRestorable(const Snapshot& s) const {
  // First: an empty snapshot (saved before InitializeAtRest, or default-constructed) also has
  // other sizes, and its reason is that it holds no run.
  if (!s.initialized)
    throw std::invalid_argument("Snapshot was saved before InitializeAtRest: it holds no run");
  const bool pieces_fit =
      s.junction_unknowns.size() == run_.junction_unknowns.size() || PiecesCanFollow(s);
  if (s.strain1.size() != run_.strain1.size() || s.state.size() != run_.state.size() ||
      !pieces_fit)
    throw std::invalid_argument(
        "Snapshot is from a stepper with another grid or another plan of the shot's steps (its "
        "dt and spatial scheme decide where segments are paired)");
  if (s.model_fingerprint != run_.model_fingerprint)
    throw std::invalid_argument(
        "Snapshot is from a stepper of another rod, grid, end conditions or plan of the shot's "
        "steps (dt, spatial scheme)");
}

void Bdf2ShootingStepper::Restore(const Snapshot& s) {
  RequireRestorable(s);
  // Automatic pieces may have changed since the snapshot: shoot in its pieces again.
  if (s.junction_unknowns.size() != run_.junction_unknowns.size())
    SetShootingPieces(1 + static_cast<int>(s.junction_unknowns.size() / 18));
  run_ = s;  // equal sizes: vectors copy into their existing storage (the factors included)
  history_ready_ = false;
  stage_strains_current_ = false;
  initialized_ = true;
}

}  // namespace cosserat
