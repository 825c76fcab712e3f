// The instance states, apart from the instance: the FMU state (fmu_state.cpp) stores one.
#pragma once

namespace contactbody::fmu {

// States of the Co-Simulation state machines, as bits so that each entry point names the set
// it is allowed in. FMI 2.0 and 3.0 share them: StepComplete is FMI 3.0's Step Mode, and
// ConfigurationMode and StepFailed each belong to one standard only.
enum FmiState : unsigned {
    Instantiated = 1u << 0,
    InitializationMode = 1u << 1,
    StepComplete = 1u << 2,
    StepFailed = 1u << 3,
    Terminated = 1u << 4,
    Error = 1u << 5,
    ConfigurationMode = 1u << 6,
};

}  // namespace contactbody::fmu
