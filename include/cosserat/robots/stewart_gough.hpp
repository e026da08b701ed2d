#pragma once
/// \file
/// The continuum Stewart–Gough robot (Bryson & Rucker 2014; Till, Aloi & Rucker 2019): six
/// rods pass through holes of a base plate, each free to spin about itself in its hole
/// (torsion-free), and are clamped to a platform; their lengths above the base are the
/// actuators. The holes lie on a circle in three pairs: at the base the two holes of a pair are
/// 120° − alpha apart and the pairs alpha; at the platform the other way round, so each rod leans
/// across to a hole of the neighbouring pair. The defaults are those
/// of Till, Aloi & Rucker's example code: spring steel rods of 1.3 mm, a circle of 87 mm,
/// alpha = 100°, 0.4 m, 40 nodes.

#include "cosserat/assembly/assembly.hpp"

namespace cosserat {

struct StewartGoughParameters {
  double youngs_modulus = 207e9;  ///< Pa
  double poisson_ratio = 0.305;
  double density = 8000.0;        ///< kg/m³
  double rod_radius = 0.00065;    ///< m
  double circle_radius = 0.087;   ///< of both hole patterns, m
  double alpha = 100.0 * M_PI / 180.0;  ///< the base's angle between pairs, rad
  double rod_length = 0.4;        ///< the rods' model length and the platform's start height, m
  int nodes = 40;
  double platform_mass = 0.0;     ///< kg
};

/// Six rods and the platform (body 0, its frame at the centre of its hole circle, z up). Rods
/// start at z = 0 along +z.
Assembly ContinuumStewartGough(const StewartGoughParameters& p = {});

}  // namespace cosserat
