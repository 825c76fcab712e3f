// Exceptions of the FMI layer; fmi2_functions.cpp maps them to fmi2Status.
#pragma once

#include <stdexcept>

namespace contactbody::fmu {

// Bad input or call: fmi2Error, the instance stays as it was.
struct ModelError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// A step that cannot be completed even with refined substeps, or whose outputs are not
// finite: fmi2Error, the state restored to the step's start, the instance in the Error
// state (fmi2SetFMUstate, fmi2Reset and fmi2FreeInstance remain).
struct StepError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace contactbody::fmu
