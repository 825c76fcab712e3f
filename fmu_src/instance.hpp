// One FMU instance, for either FMI layer: the Co-Simulation state machine, logging, and the
// model.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <set>
#include <string>

#include "fmu_state.hpp"

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

// Status codes as both standards number them (fmi2Status and fmi3Status agree on 0-4).
struct Status {
    enum : int { ok = 0, warning = 1, discard = 2, error = 3, fatal = 4 };
};

// The host's logger, whatever its standard's signature: (status, category, message).
using Logger = std::function<void(int, const char*, const char*)>;

enum class LogCategory { events, warning, error, all, contact_solver };

struct Instance {
    Instance(std::string name, Logger logger, bool logging_on);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    // Errors are always passed to the logger; other messages per the enabled categories.
    void log(int status, LogCategory category, const std::string& message) const;
    void error(const char* function, const std::string& message) const {
        log(Status::error, LogCategory::error, std::string(function) + ": " + message);
    }
    // Checks that `function` may be called in the current state; logs and returns false if not.
    bool allowed(const char* function, unsigned states) const;
    // Returns a Status; `function` names the caller in errors.
    int set_debug_logging(const char* function, bool on, size_t n, const char* const categories[]);

    std::string name;
    Logger logger;
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
