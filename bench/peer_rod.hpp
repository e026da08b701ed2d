#pragma once
// The peer problem (bench_dynamics.cpp, examples/cantilever_release.json): a steel
// cantilever, E = 200 GPa, G = 80 GPa, ρ = 8000 kg/m³, r = 1 mm, L = 0.5 m, clamped along +z,
// gravity 9.81 m/s² along −x, held in equilibrium under an extra tip force equal to the weight
// of 0.02 kg and released at t = 0.

#include "cosserat/strong/bdf2_stepper.hpp"

namespace cosserat::bench {

inline RodModel PeerRod() {
  return RodModel::Uniform(0.5, CrossSection::Circle(0.001),
                           Material::FromShearModulus(200e9, 80e9, 8000));
}

/// Gravity and the extra tip weight; set tip_force to zero for the release.
inline StepInput PeerPreload() {
  StepInput in;
  in.loads.gravity_W = Vec3(-9.81, 0, 0);
  in.loads.tip_force = Vec3(-0.02 * 9.81, 0, 0);
  return in;
}

}  // namespace cosserat::bench
