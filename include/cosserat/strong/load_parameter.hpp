#pragma once
/// \file
/// The size of a static load case as a load parameter, for capping continuation steps: a
/// Newton-type solve from an equilibrium far from the loaded one can land on another branch
/// (the elastica has several for P L²/EI ≳ 10), so the loads are applied in increments of a
/// few units of this measure.

#include "cosserat/loads/static_loads.hpp"
#include "cosserat/rod/actuation.hpp"
#include "cosserat/rod/rod_model.hpp"

namespace cosserat {

/// The largest of |F_tip| L²/EI, |M_tip| L/EI and |f + ρA g| L³/EI (dead and follower parts
/// added; EI the larger bending stiffness, ρA and the outer diameter for the distributed loads,
/// all at s = 0 under the actuation). Dimensionless; 0 without loads.
double StaticLoadParameter(const RodModel& rod, const StaticLoads& loads,
                           const Actuation& actuation = {});

}  // namespace cosserat
