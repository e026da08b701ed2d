#pragma once
// Shots per step of a run of Bdf2ShootingStepper, binned 1, 2, 3, 4, >= 5, with the exact
// Jacobians taken: what startup_shots and kick_shots print for a window of steps.
#include <cstdio>

#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat::bench {

struct ShotHistogram {
  long steps_with[6] = {};  ///< [k]: steps that took k shots (k = 1 … 4), [5]: 5 or more
  long steps = 0, shots = 0, jacobians = 0;

  void Add(const StepSummary& s) {
    ++steps_with[s.shots >= 5 ? 5 : s.shots];
    ++steps;
    shots += s.shots;
    jacobians += s.jacobians;
  }
  void Print(const char* name) const {
    std::printf("%-18s 1: %ld  2: %ld  3: %ld  4: %ld  >=5: %ld  shots/step %.4f  exact J %ld\n",
                name, steps_with[1], steps_with[2], steps_with[3], steps_with[4], steps_with[5],
                steps ? double(shots) / steps : 0.0, jacobians);
  }
};

}  // namespace cosserat::bench
