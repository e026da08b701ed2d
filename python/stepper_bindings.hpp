#pragma once
// The module's dynamics stepper: cosserat.Stepper, StepSummary and Snapshot (stepper_bindings.cpp).

#include <pybind11/pybind11.h>

namespace cosserat::python {

void BindStepper(pybind11::module_& m);

}  // namespace cosserat::python
