#pragma once
// The modes of one cantilever under one set of loads in both formulations, on the same grid:
// SE(3) frequency shooting on `nodes` grid points and the quaternion-FD linearisation on
// nodes − 1 segments, for tests that hold them against each other or against the truth.

#include "cosserat/analysis/modes.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "rods.hpp"

namespace cosserat::testing {

struct ModesOfBothFormulations {
  ModalResult se3, quatfd;
};

inline ModesOfBothFormulations ModesInBothFormulations(const SteelRod& rod,
                                                       const StaticLoads& loads, int count,
                                                       int nodes = 41,
                                                       const lie::SE3& base = lie::SE3{}) {
  ModalOptions mo;
  mo.count = count;
  ShootingModalOptions so;
  so.modal = mo;
  ModesOfBothFormulations out;
  out.se3 = ComputeModesShooting(rod.model(), nodes, base, loads, so);
  quatfd::QuatFdOptions options;
  options.segments = nodes - 1;
  quatfd::QuatFdModel model(rod.model(), base, options);
  model.set_loads(loads);
  out.quatfd = ComputeModes(&model, loads, mo);
  return out;
}

}  // namespace cosserat::testing
