#pragma once
// The sweep functions of the `soak` Python module (SweepPython.cpp).
#include <pybind11/pybind11.h>

void addSweepFunctions(pybind11::module_& m);
