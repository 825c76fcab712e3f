#include "instance.hpp"

namespace contactbody::fmu {

namespace {

const char* state_name(FmiState s) {
    switch (s) {
        case Instantiated: return "Instantiated";
        case InitializationMode: return "InitializationMode";
        case StepComplete: return "StepComplete";
        case StepFailed: return "StepFailed";
        case Terminated: return "Terminated";
        case Error: return "Error";
    }
    return "unknown";
}

}  // namespace

Instance::Instance(std::string n, const fmi2CallbackFunctions* cb, bool on)
    : name(std::move(n)), callbacks(*cb), logging_on(on) {
    category_on.fill(on);
}

void Instance::log(fmi2Status status, LogCategory category, const std::string& message) const {
    if (!callbacks.logger) return;
    const auto index = static_cast<size_t>(category);
    // Errors and warnings reach the user whatever the logging settings: a warning nobody sees
    // would be a silent one.
    const bool always = status != fmi2OK;
    if (!always && !(logging_on && category_on[index])) return;
    // The message goes through "%s": the host formats the logger's message printf-style.
    callbacks.logger(callbacks.componentEnvironment, name.c_str(), status,
                     log_categories()[index].c_str(), "%s", message.c_str());
}

Instance::~Instance() {
    for (FmuState* s : states) delete s;
}

bool Instance::allowed(const char* function, unsigned states) const {
    if (state & states) return true;
    error(function, std::string("not allowed in state ") + state_name(state));
    return false;
}

fmi2Status Instance::set_debug_logging(bool on, size_t n, const fmi2String categories[]) {
    if (n > 0 && !categories) {
        error("fmi2SetDebugLogging", "categories is NULL but nCategories > 0");
        return fmi2Error;
    }
    std::array<bool, 5> requested{};
    for (size_t k = 0; k < n; ++k) {
        const std::string wanted = categories[k] ? categories[k] : "";
        bool found = false;
        for (size_t c = 0; c < log_categories().size(); ++c) {
            if (log_categories()[c] == wanted) requested[c] = found = true;
        }
        if (!found) {
            error("fmi2SetDebugLogging", "unknown log category '" + wanted + "'");
            return fmi2Error;
        }
    }
    logging_on = on;
    for (size_t c = 0; c < category_on.size(); ++c) {
        if (n == 0) category_on[c] = on;  // no categories: all of them
        else if (requested[c]) category_on[c] = on;
    }
    if (on && n > 0 && requested[static_cast<size_t>(LogCategory::all)]) category_on.fill(true);
    return fmi2OK;
}

}  // namespace contactbody::fmu
