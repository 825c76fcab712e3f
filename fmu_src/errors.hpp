// Exceptions of the FMI layer; fmi2_functions.cpp maps them to fmi2Status.
#pragma once

#include <stdexcept>

namespace contactbody::fmu {

// Bad input or call: fmi2Error, the instance stays as it was.
struct ModelError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// A step that cannot be completed (the state stays at the step's start): fmi2Discard.
struct StepDiscarded : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace contactbody::fmu
