#pragma once
// The module's batch objects: cosserat.BatchStepper and cosserat._core.sweep (batch_bindings.cpp).

#include <pybind11/pybind11.h>

namespace cosserat::python {

void BindBatches(pybind11::module_& m);

}  // namespace cosserat::python
