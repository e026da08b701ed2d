#include "cosserat/strong/batch_stepper.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cosserat {

BatchStepper::BatchStepper(const RodModel& model, int nodes, const Bdf2Options& options,
                           int count, int threads)
    : team_(std::clamp(threads, 1, std::max(count, 1))) {  // no more threads than rods
  if (count < 1) throw std::invalid_argument("BatchStepper: count must be at least 1");
  if (threads < 1) throw std::invalid_argument("BatchStepper: threads must be at least 1");
  for (int i = 0; i < count; ++i)
    rods_.push_back(std::make_unique<Bdf2ShootingStepper>(model, nodes, options));
  summaries_.resize(count);
}

int BatchStepper::InitializeAtRest(const StepInput& input) {
  rods_[0]->RequireValidInput(input);  // one model: what one rod refuses, all do
  return EachRod([&](std::size_t i) { return rods_[i]->InitializeAtRest(input); });
}

int BatchStepper::InitializeAtRest(const StepInput& input, const RodState& equilibrium) {
  rods_[0]->RequireValidInput(input);
  return EachRod([&](std::size_t i) { return rods_[i]->InitializeAtRest(input, equilibrium); });
}

int BatchStepper::Step(const StepInput* inputs) {
  // Every input is checked before any rod moves: a refused call changes nothing.
  for (std::size_t i = 0; i < rods_.size(); ++i) rods_[i]->RequireValidInput(inputs[i]);
  return EachRod([&](std::size_t i) { return rods_[i]->Step(inputs[i]); });
}

std::vector<Bdf2ShootingStepper::Snapshot> BatchStepper::Save() const {
  std::vector<Bdf2ShootingStepper::Snapshot> out;
  out.reserve(rods_.size());
  for (const auto& rod : rods_) out.push_back(rod->Save());
  return out;
}

void BatchStepper::Restore(const std::vector<Bdf2ShootingStepper::Snapshot>& snapshots) {
  if (snapshots.size() != rods_.size())
    throw std::invalid_argument("BatchStepper::Restore: expected " +
                                std::to_string(rods_.size()) + " snapshots, got " +
                                std::to_string(snapshots.size()));
  // One model: a snapshot rod 0 accepts, every rod accepts.
  for (const auto& s : snapshots) rods_[0]->RequireRestorable(s);
  for (std::size_t i = 0; i < rods_.size(); ++i) rods_[i]->Restore(snapshots[i]);
}

void BatchStepper::RestoreAll(const Bdf2ShootingStepper::Snapshot& snapshot) {
  rods_[0]->RequireRestorable(snapshot);
  for (const auto& rod : rods_) rod->Restore(snapshot);
}

}  // namespace cosserat
