#pragma once
/// \file
/// Several rods and rigid bodies joined into one structure: a parallel continuum robot (rods
/// holding a platform), a guided beam, a multi-backbone robot. The model only: which rods, which
/// bodies, and how each rod's ends are held. Solved by AssemblyStaticsSolver
/// (assembly_statics.hpp).
///
/// Each rod's base is held at a given pose (its tangent along the pose's z), in the world or on a
/// rigid body (a frame's corner, a multi-backbone robot's disk), either clamped or torsion-free
/// (free to spin about its own tangent, as a rod passing through a hole of a base plate). Its tip
/// is free, or joined to a point of a rigid body:
///   clamped       the tip's frame is the body's attachment frame;
///   torsion_free  the tip's tangent is the attachment frame's z, the spin about it free;
///   pinned        only the tip's position is held: a ball joint.
/// A rod with a torsion-free base and a torsion-free tip could spin freely about itself and is
/// refused. A body's pose is unknown; its weight acts at its origin, with the loads' gravity.

#include <string>
#include <vector>

#include "cosserat/lie/se3.hpp"
#include "cosserat/rod/rod_model.hpp"

namespace cosserat {

/// A rigid body: its weight and the load applied at its origin.
struct RigidBody {
  std::string name;
  double mass = 0.0;                ///< kg
  Mat3 inertia_B = Mat3::Zero();    ///< about its origin, body frame (kg·m²; for dynamics)
  lie::SE3 pose;                    ///< the start of the solve (world), then its solution
  Vec3 force_W = Vec3::Zero();      ///< applied at the origin, N
  Vec3 moment_W = Vec3::Zero();     ///< N·m
};

enum class BaseJoint { kClamped, kTorsionFree };
enum class TipJoint { kFree, kClamped, kTorsionFree, kPinned };

struct AssemblyRod {
  std::string name;
  RodModel model;        ///< its length is the rod's length (the actuator of a parallel robot)
  int nodes = 41;        ///< grid points, ends included
  lie::SE3 base;         ///< pose of s = 0 in the world, or in base_body's frame; tangent z
  int base_body = -1;    ///< the body the base is held on (index; −1: the world)
  BaseJoint base_joint = BaseJoint::kClamped;
  TipJoint tip_joint = TipJoint::kFree;
  int body = -1;         ///< the body the tip is joined to (index; −1 with kFree)
  lie::SE3 attachment;   ///< the attachment frame in the body's frame
};

struct Assembly {
  std::vector<AssemblyRod> rods;
  std::vector<RigidBody> bodies;

  /// Checks the rods, bodies and joints; on failure writes "<what>: <why>", naming the rod or
  /// body (e.g. "rods[2] (leg3).body: names body 4, but there are 1").
  bool IsValid(std::string* why) const;
};

}  // namespace cosserat
