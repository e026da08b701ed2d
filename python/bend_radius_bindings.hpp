#pragma once
// The minimum bend radius of an eversion robot (analysis/bend_radius.hpp) for
// cosserat.minimum_bend_radius (bend_radius_bindings.cpp).

#include <pybind11/pybind11.h>

namespace cosserat::python {

void BindBendRadius(pybind11::module_& m);

}  // namespace cosserat::python
