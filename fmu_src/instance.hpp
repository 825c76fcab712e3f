// One FMU instance: the FMI 2.0 Co-Simulation state machine, logging, and the model.
#pragma once

#include <array>
#include <memory>
#include <set>
#include <string>

extern "C" {
#include "fmi2Functions.h"
}

#include "fmu_state.hpp"

namespace contactbody::fmu {

// States of the FMI 2.0 Co-Simulation state machine, as bits so that each entry point
// names the set it is allowed in.
enum FmiState : unsigned {
    Instantiated = 1u << 0,
    InitializationMode = 1u << 1,
    StepComplete = 1u << 2,
    StepFailed = 1u << 3,
    Terminated = 1u << 4,
    Error = 1u << 5,
};

enum class LogCategory { events, warning, error, all, contact_solver };

struct Instance {
    Instance(std::string name, const fmi2CallbackFunctions* callbacks, bool logging_on);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    // Errors are always passed to the logger; other messages per the enabled categories.
    void log(fmi2Status status, LogCategory category, const std::string& message) const;
    void error(const char* function, const std::string& message) const {
        log(fmi2Error, LogCategory::error, std::string(function) + ": " + message);
    }
    // Checks that `function` may be called in the current state; logs and returns false if not.
    bool allowed(const char* function, unsigned states) const;
    fmi2Status set_debug_logging(bool on, size_t n, const fmi2String categories[]);

    std::string name;
    fmi2CallbackFunctions callbacks;
    FmiState state = Instantiated;
    bool logging_on;
    std::array<bool, 5> category_on;
    double last_successful_time = 0;
    ContactBodyModel model;
    // FMU states handed out by this instance: only these pointers are accepted back.
    std::set<FmuState*> states;
    int factorizations_logged = 0;
};

}  // namespace contactbody::fmu
