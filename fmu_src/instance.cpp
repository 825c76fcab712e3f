#include "instance.hpp"

namespace contactbody::fmu {

namespace {

const char* state_name(FmiState s) {
    switch (s) {
        case Instantiated:
            return "Instantiated";
        case InitializationMode:
            return "InitializationMode";
        case StepComplete:
            return "StepComplete";
        case StepFailed:
            return "StepFailed";
        case Terminated:
            return "Terminated";
        case Error:
            return "Error";
        case ConfigurationMode:
            return "ConfigurationMode";
    }
    return "unknown";
}

}  // namespace

Instance::Instance(std::string n, Logger l, bool on, LogRule r)
    : name(std::move(n)), logger(std::move(l)), logging_on(on), rule(r) {
    category_on.fill(on);
}

void Instance::log(int status, LogCategory category, const std::string& message) const {
    if (!logger) return;
    const auto index = static_cast<size_t>(category);
    const bool always = rule == LogRule::fmi2_errors_always && status != Status::ok;
    if (!always && !(logging_on && category_on[index])) return;
    logger(status, log_categories()[index].c_str(), message.c_str());
}

Instance::~Instance() {
    for (FmuState* s : states) delete s;
}

bool Instance::allowed(const char* function, unsigned states) const {
    if (state & states) return true;
    error(function, std::string("not allowed in state ") + state_name(state));
    return false;
}

int Instance::set_debug_logging(const char* function, bool on, size_t n, const char* const categories[]) {
    if (n > 0 && !categories) {
        error(function, "categories is NULL but nCategories > 0");
        return Status::error;
    }
    std::array<bool, 5> requested{};
    for (size_t k = 0; k < n; ++k) {
        const std::string wanted = categories[k] ? categories[k] : "";
        bool found = false;
        for (size_t c = 0; c < log_categories().size(); ++c) {
            if (log_categories()[c] == wanted) requested[c] = found = true;
        }
        if (!found) {
            error(function, "unknown log category '" + wanted + "'");
            return Status::error;
        }
    }
    // Logging on for listed categories: those, and only those (not what instantiation's
    // loggingOn enabled before); off for listed ones: those off. No categories: all of them.
    logging_on = on;
    for (size_t c = 0; c < category_on.size(); ++c) {
        if (n == 0)
            category_on[c] = on;
        else if (on)
            category_on[c] = requested[c];
        else if (requested[c])
            category_on[c] = false;
    }
    if (on && n > 0 && requested[static_cast<size_t>(LogCategory::all)]) category_on.fill(true);
    return Status::ok;
}

}  // namespace contactbody::fmu
