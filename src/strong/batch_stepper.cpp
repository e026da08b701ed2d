#include "cosserat/strong/batch_stepper.hpp"

#include <algorithm>
#include <stdexcept>

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
  auto job = [&](std::size_t i) { summaries_[i] = rods_[i]->InitializeAtRest(input); };
  team_.For(rods_.size(), job);
  int converged = 0;
  for (const StepSummary& s : summaries_) converged += s.converged();
  return converged;
}

int BatchStepper::InitializeAtRest(const StepInput& input, const RodState& equilibrium) {
  auto job = [&](std::size_t i) { summaries_[i] = rods_[i]->InitializeAtRest(input, equilibrium); };
  team_.For(rods_.size(), job);
  int converged = 0;
  for (const StepSummary& s : summaries_) converged += s.converged();
  return converged;
}

int BatchStepper::Step(const StepInput* inputs) {
  auto job = [&](std::size_t i) { summaries_[i] = rods_[i]->Step(inputs[i]); };
  team_.For(rods_.size(), job);
  int converged = 0;
  for (const StepSummary& s : summaries_) converged += s.converged();
  return converged;
}

}  // namespace cosserat
