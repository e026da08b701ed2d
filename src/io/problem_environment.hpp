#pragma once
/// \file
/// The "environment" of a problem file: the fluid around the rod (buoyancy, Morison drag, added
/// mass, a uniform or sheared flow) and the rigid surfaces it touches. Keys in
/// docs/problem-format.md.

#include "cosserat/io/json_reader.hpp"
#include "cosserat/io/problem.hpp"
#include "cosserat/loads/contact.hpp"
#include "cosserat/loads/fluid.hpp"

namespace cosserat::io::detail {

/// Reads "environment" into *fluid and *contact; errors go to o's report, naming the key.
void ParseEnvironment(const ObjectReader& o, Fluid* fluid, FluidGust* gust,
                      ContactSurfaces* contact);

/// The unloaded rod does not start past a contact surface, and no bore is narrower than it;
/// errors into *report, naming the surface.
void CheckStartsOutsideSurfaces(const Problem& p, ErrorReport* report);

}  // namespace cosserat::io::detail
