// One FMU instance, for either FMI layer: the Co-Simulation state machine, logging, and the
// model.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <set>
#include <string>

#include "fmi_states.hpp"
#include "fmu_state.hpp"

namespace contactbody::fmu {

// Status codes as both standards number them (fmi2Status and fmi3Status agree on 0-4).
struct Status {
    enum : int { ok = 0, warning = 1, discard = 2, error = 3, fatal = 4 };
};

// The host's logger, whatever its standard's signature: (status, category, message).
using Logger = std::function<void(int, const char*, const char*)>;

enum class LogCategory { events, warning, error, all, contact_solver };

// Which messages reach the logger while logging is off or a category is disabled. FMI 2.0
// says the logger "should" not be called then, and an error or warning nobody sees would be a
// silent one: they always reach it. FMI 3.0 says logMessage is not called at all while
// loggingOn is false, and only for enabled categories, errors included (2.3.1, "respecting
// the current logging settings").
enum class LogRule { fmi2_errors_always, fmi3_settings_only };

struct Instance {
    Instance(std::string name, Logger logger, bool logging_on, LogRule rule = LogRule::fmi2_errors_always);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    // Per the LogRule: FMI 2.0 passes errors and warnings always, other messages per the
    // enabled categories; FMI 3.0 passes every message per the enabled categories only.
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
    LogRule rule;
    std::array<bool, 5> category_on;
    double last_successful_time = 0;
    ContactBodyModel model;
    // FMU states handed out by this instance: only these pointers are accepted back.
    std::set<FmuState*> states;
    int factorizations_logged = 0;
};

}  // namespace contactbody::fmu
