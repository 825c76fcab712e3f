// Exceptions of the FMI layer; fmi2_functions.cpp and fmi3_functions.cpp map them to a status.
#pragma once

#include <stdexcept>

namespace contactbody::fmu {

// Bad input or call: fmi2Error / fmi3Error, the instance stays as it was.
struct ModelError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// A step that cannot be completed even with refined substeps, or whose outputs are not
// finite: fmi2Error / fmi3Error, the state restored to the step's start, the instance in the
// Error state (setting a saved FMU state, reset and freeing remain).
struct StepError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace contactbody::fmu
