#pragma once
/// \file
/// The "assembly" object of a problem file: rods and rigid bodies joined into one structure,
/// solved forward (the bodies' poses for given lengths) or inverse (the lengths for given poses)
/// (docs/problem-format.md#assembly, docs/assemblies.md).

#include <string>
#include <vector>

#include "cosserat/io/json_reader.hpp"
#include "cosserat/io/problem.hpp"

namespace cosserat::io::detail {

/// Sets problem->assembly and problem->has_assembly from `assembly`, reporting every error by
/// its path (a joint naming a missing body, a name used twice, an inverse problem without six
/// rods per body, a body no rod holds, ...).
void ParseAssembly(const ObjectReader& assembly, Problem* problem);

/// The top-level keys of a single-rod problem, refused beside "assembly" (each rod of
/// assembly.rods has its own "rod" and "base").
const std::vector<std::string>& SingleRodKeys();

/// The loads an assembly does not apply ("tip_force", "tip_moment", "bit_friction": its rods'
/// tips are joined to bodies, which carry their own force and moment), reported if given.
void CheckAssemblyLoads(const ObjectReader& loads);

/// The keys of "dynamics" that belong to a single rod ("tip_mass", "base_spin", ...), reported
/// if given beside "assembly".
void CheckAssemblyDynamics(const ObjectReader& dynamics);

/// What this version cannot run of an assembly problem (UnsupportedFeatures): an analysis other
/// than "statics" or "dynamics", a formulation other than "se3-shooting", and in dynamics an
/// inverse problem, given lengths or a torsion-free base. One line each.
std::vector<std::string> UnsupportedAssemblyFeatures(const Problem& problem);

}  // namespace cosserat::io::detail
