// The exported FMI 2.0 Co-Simulation functions. Each checks its state and pointers in its
// first lines (BEGIN / REQUIRE), then runs its body through `guarded`, which turns the
// model's exceptions into fmi2Status and a log message naming the function.
#include <cmath>
#include <cstring>
#include <sstream>
#include <memory>
#include <new>

#include "instance.hpp"
#include "resource_start_values.hpp"

using namespace contactbody;
using namespace contactbody::fmu;

namespace {

constexpr unsigned any_state =
    Instantiated | InitializationMode | StepComplete | StepFailed | Terminated | Error;
constexpr unsigned readable = InitializationMode | StepComplete | StepFailed | Terminated | Error;
constexpr unsigned settable = Instantiated | InitializationMode | StepComplete;
// FMI 2.0.5's co-simulation state table: a state may be taken from Instantiated on, and set
// back after a discard or an error too (that is how a master recovers).
constexpr unsigned saveable = Instantiated | InitializationMode | StepComplete | StepFailed | Terminated;
constexpr unsigned restorable = saveable | Error;

template <class Body>
fmi2Status guarded(Instance* instance, const char* function, Body&& body) {
    try {
        return body();
    } catch (const StepError& e) {
        instance->error(function, e.what());
        instance->state = Error;  // the state is the step's start: fmi2SetFMUstate may go on
        return fmi2Error;
    } catch (const ModelError& e) {
        instance->error(function, e.what());
        return fmi2Error;
    } catch (const std::bad_alloc&) {
        instance->error(function, "out of memory");
    } catch (const std::exception& e) {
        instance->error(function, e.what());
    } catch (...) {
        instance->error(function, "unknown failure");
    }
    instance->state = Error;  // unexpected: fmi2SetFMUstate, fmi2Reset or fmi2FreeInstance help
    return fmi2Error;
}

bool initialized(const Instance* instance) {
    return instance->state & (StepComplete | StepFailed | Terminated | Error);
}

// The simulation's warnings (docs/contract.md, "Warnings"), each once, as logStatusWarning.
void log_warnings(Instance* instance, const char* function, Simulation& sim) {
    for (const std::string& warning : sim.take_warnings())
        instance->log(fmi2Warning, LogCategory::warning, std::string(function) + ": " + warning);
}

// Events (a new factorization) and the contact solver's statistics of the last step.
void log_step(Instance* instance, Simulation& sim) {
    log_warnings(instance, "fmi2DoStep", sim);
    const int factorizations = sim.stepper().factorizations();
    if (factorizations != instance->factorizations_logged) {
        instance->factorizations_logged = factorizations;
        instance->log(fmi2OK, LogCategory::events,
                      "factorized 4/dt^2 M + A (factorization " + std::to_string(factorizations) + ")");
    }
    const StepStatistics& s = sim.statistics();
    if (s.refinements > 0) {
        std::ostringstream msg;
        msg << "step to t = " << sim.time() << ": " << s.refinements
            << " substeps redone as halves after a failed contact solve (smallest substep "
            << s.smallest_substep << " s)";
        instance->log(fmi2OK, LogCategory::events, msg.str());
    }
    instance->log(fmi2OK, LogCategory::contact_solver,
                  "substeps " + std::to_string(s.substeps) + ", contact solves " +
                      std::to_string(s.contact_solves) + ", Newton iterations " +
                      std::to_string(s.contact_iterations) + " (max " +
                      std::to_string(s.max_contact_iterations) + " in one substep), Gauss-Seidel "
                      "sweeps " + std::to_string(s.gauss_seidel_sweeps));
}

const Variable& variable(unsigned vr) {
    const Variable* v = find_variable(vr);
    if (!v) throw ModelError("unknown value reference " + std::to_string(vr));
    return *v;
}

FmuState* known_state(Instance* instance, fmi2FMUstate s) {
    auto* state = static_cast<FmuState*>(s);
    if (!instance->states.count(state))
        throw ModelError("FMUstate was not made by this instance, or was freed");
    return state;
}

}  // namespace

#define BEGIN(function, states)                                   \
    if (!c) return fmi2Error;                                     \
    auto* instance = static_cast<Instance*>(c);                   \
    if (!instance->allowed(function, states)) return fmi2Error;
#define REQUIRE(function, pointer, count)                                              \
    if ((count) > 0 && !(pointer)) {                                                    \
        instance->error(function, std::string(#pointer) + " is NULL but its size is " + \
                                      std::to_string(count));                          \
        return fmi2Error;                                                               \
    }
#define NOT_SUPPORTED(function, what)                                      \
    BEGIN(function, any_state)                                             \
    instance->error(function, std::string("not supported: ") + (what));    \
    return fmi2Error;

namespace {

// The body of every get/set: state and pointer checks, then `each` on every (variable, value).
template <class Value, class Each>
fmi2Status for_each_variable(fmi2Component c, const char* function, unsigned states,
                             const fmi2ValueReference vr[], size_t nvr, Value* value, Each&& each) {
    BEGIN(function, states)
    REQUIRE(function, vr, nvr) REQUIRE(function, value, nvr)
    return guarded(instance, function, [&] {
        for (size_t k = 0; k < nvr; ++k) each(instance, variable(vr[k]), value[k]);
        return fmi2OK;
    });
}

auto refuse(const char* type) {
    return [type](Instance*, const Variable& v, const auto&) {
        throw ModelError(std::string("variable ") + v.name + " is not of type " + type +
                         " (this FMU has no " + type + " variables)");
    };
}

}  // namespace

extern "C" {

const char* fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char* fmi2GetVersion(void) { return fmi2Version; }

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions* functions, fmi2Boolean /*visible*/,
                              fmi2Boolean loggingOn) {
    if (!functions) return nullptr;
    auto fail = [&](const char* message) -> fmi2Component {
        if (functions->logger)
            functions->logger(functions->componentEnvironment, instanceName ? instanceName : "",
                              fmi2Error, "logStatusError", "fmi2Instantiate: %s", message);
        return nullptr;
    };
    if (!instanceName || !*instanceName) return fail("instanceName is missing");
    if (fmuType != fmi2CoSimulation) return fail("only fmi2CoSimulation is supported");
    if (!fmuGUID || std::strcmp(fmuGUID, guid) != 0)
        return fail("fmuGUID does not match this FMU's modelDescription.xml");
    try {
        auto instance = std::make_unique<Instance>(instanceName, functions, loggingOn);
        // A configured copy's start values (contactbody.system's SSP components).
        instance->model.set_defaults(read_start_values(start_values_path(fmuResourceLocation)));
        return instance.release();
    } catch (const std::exception& e) {
        return fail(e.what());
    } catch (...) {
        return fail("out of memory");
    }
}

void fmi2FreeInstance(fmi2Component c) { delete static_cast<Instance*>(c); }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    BEGIN("fmi2SetDebugLogging", any_state)
    return instance->set_debug_logging(loggingOn, nCategories, categories);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean /*toleranceDefined*/,
                               fmi2Real /*tolerance*/, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    BEGIN("fmi2SetupExperiment", Instantiated)
    return guarded(instance, "fmi2SetupExperiment", [&] {
        if (stopTimeDefined && !(stopTime >= startTime))
            throw ModelError("stopTime must be >= startTime");
        instance->model.set_start_time(startTime);
        instance->last_successful_time = startTime;
        return fmi2OK;
    });
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    BEGIN("fmi2EnterInitializationMode", Instantiated)
    instance->state = InitializationMode;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    BEGIN("fmi2ExitInitializationMode", InitializationMode)
    return guarded(instance, "fmi2ExitInitializationMode", [&] {
        instance->model.initialize();
        instance->state = StepComplete;
        // Factorizations are counted over the discretization's life (it outlives fmi2Reset):
        // the steps log the ones they make.
        instance->factorizations_logged = instance->model.simulation()->stepper().factorizations();
        instance->log(fmi2OK, LogCategory::events, "initialized");
        log_warnings(instance, "fmi2ExitInitializationMode", *instance->model.simulation());
        return fmi2OK;
    });
}

fmi2Status fmi2Terminate(fmi2Component c) {
    BEGIN("fmi2Terminate", StepComplete | StepFailed)
    instance->state = Terminated;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
    BEGIN("fmi2Reset", any_state)
    instance->model.reset();
    instance->last_successful_time = 0;
    instance->state = Instantiated;
    return fmi2OK;
}

// ---- getters and setters ----

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
    return for_each_variable(c, "fmi2GetReal", readable, vr, nvr, value,
                             [](Instance* i, const Variable& v, fmi2Real& x) {
                                 x = i->model.get_real(v);
                             });
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[]) {
    return for_each_variable(c, "fmi2GetInteger", readable, vr, nvr, value,
                             [](Instance* i, const Variable& v, fmi2Integer& x) {
                                 x = i->model.get_integer(v);
                             });
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) {
    return for_each_variable(c, "fmi2SetReal", settable, vr, nvr, value,
                             [](Instance* i, const Variable& v, const fmi2Real& x) {
                                 i->model.set_real(v, x, initialized(i));
                             });
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[]) {
    return for_each_variable(c, "fmi2SetInteger", settable, vr, nvr, value,
                             [](Instance* i, const Variable& v, const fmi2Integer& x) {
                                 i->model.set_integer(v, x, initialized(i));
                             });
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[]) {
    return for_each_variable(c, "fmi2GetString", readable, vr, nvr, value,
                             [](Instance* i, const Variable& v, fmi2String& x) {
                                 x = i->model.get_string(v);
                             });
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[]) {
    return for_each_variable(c, "fmi2SetString", settable, vr, nvr, value,
                             [](Instance* i, const Variable& v, const fmi2String& x) {
                                 i->model.set_string(v, x, initialized(i));
                             });
}

// This FMU has no Boolean variables: any value reference is refused.
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[]) {
    return for_each_variable(c, "fmi2GetBoolean", readable, vr, nvr, value, refuse("Boolean"));
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[]) {
    return for_each_variable(c, "fmi2SetBoolean", settable, vr, nvr, value, refuse("Boolean"));
}


// ---- stepping and status ----

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean /*noSetFMUStatePriorToCurrentPoint*/) {
    BEGIN("fmi2DoStep", StepComplete)
    const fmi2Status status = guarded(instance, "fmi2DoStep", [&] {
        instance->model.do_step(currentCommunicationPoint, communicationStepSize);
        instance->last_successful_time = instance->model.time();
        return fmi2OK;
    });
    if (Simulation* sim = instance->model.simulation()) log_step(instance, *sim);
    return status;
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    NOT_SUPPORTED("fmi2CancelStep", "steps are never asynchronous")
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind /*s*/, fmi2Status* /*value*/) {
    NOT_SUPPORTED("fmi2GetStatus", "steps are never asynchronous")
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real* value) {
    BEGIN("fmi2GetRealStatus", StepComplete | StepFailed | Terminated)
    REQUIRE("fmi2GetRealStatus", value, 1)
    if (s != fmi2LastSuccessfulTime) {
        instance->error("fmi2GetRealStatus", "only fmi2LastSuccessfulTime is available");
        return fmi2Error;
    }
    *value = instance->last_successful_time;
    return fmi2OK;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind /*s*/,
                                fmi2Integer* /*value*/) {
    NOT_SUPPORTED("fmi2GetIntegerStatus", "no integer status is defined")
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean* value) {
    BEGIN("fmi2GetBooleanStatus", StepComplete | StepFailed | Terminated)
    REQUIRE("fmi2GetBooleanStatus", value, 1)
    if (s != fmi2Terminated) {
        instance->error("fmi2GetBooleanStatus", "only fmi2Terminated is available");
        return fmi2Error;
    }
    // After a discarded step the slave asks to end the simulation: retrying the same step
    // would fail the same way.
    *value = instance->state == StepFailed ? fmi2True : fmi2False;
    return fmi2OK;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind /*s*/,
                               fmi2String* /*value*/) {
    NOT_SUPPORTED("fmi2GetStringStatus", "no string status is defined")
}

// ---- capabilities this FMU does not declare ----

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[],
                                       size_t nvr, const fmi2Integer order[],
                                       const fmi2Real value[]) {
    BEGIN("fmi2SetRealInputDerivatives", InitializationMode | StepComplete)
    REQUIRE("fmi2SetRealInputDerivatives", vr, nvr)
    REQUIRE("fmi2SetRealInputDerivatives", order, nvr)
    REQUIRE("fmi2SetRealInputDerivatives", value, nvr)
    return guarded(instance, "fmi2SetRealInputDerivatives", [&] {
        for (size_t k = 0; k < nvr; ++k)
            instance->model.set_input_derivative(variable(vr[k]), order[k], value[k]);
        return fmi2OK;
    });
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2Integer[], fmi2Real[]) {
    NOT_SUPPORTED("fmi2GetRealOutputDerivatives", "maxOutputDerivativeOrder is 0")
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2ValueReference[], size_t, const fmi2Real[],
                                        fmi2Real[]) {
    NOT_SUPPORTED("fmi2GetDirectionalDerivative", "providesDirectionalDerivative is false")
}

// ---- FMU state: plain data owned by the instance, bytes with a versioned header ----

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
    BEGIN("fmi2GetFMUstate", saveable)
    REQUIRE("fmi2GetFMUstate", FMUstate, 1)
    return guarded(instance, "fmi2GetFMUstate", [&] {
        FmuState* target = static_cast<FmuState*>(*FMUstate);
        if (target && !instance->states.count(target))
            throw ModelError("*FMUstate is not a state of this instance (pass NULL for a new one)");
        FmuState saved{instance->state, instance->last_successful_time, instance->model.save()};
        if (target) {
            *target = std::move(saved);  // overwrite, as FMI 2.0 asks for a non-NULL state
        } else {
            auto fresh = std::make_unique<FmuState>(std::move(saved));
            instance->states.insert(fresh.get());
            *FMUstate = fresh.release();
        }
        return fmi2OK;
    });
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
    BEGIN("fmi2SetFMUstate", restorable)
    REQUIRE("fmi2SetFMUstate", FMUstate, 1)
    return guarded(instance, "fmi2SetFMUstate", [&] {
        const FmuState* s = known_state(instance, FMUstate);
        instance->model.load(s->model);
        instance->state = static_cast<FmiState>(s->instance_state);
        instance->last_successful_time = s->last_successful_time;
        return fmi2OK;
    });
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
    BEGIN("fmi2FreeFMUstate", any_state)
    REQUIRE("fmi2FreeFMUstate", FMUstate, 1)
    if (!*FMUstate) return fmi2OK;
    return guarded(instance, "fmi2FreeFMUstate", [&] {
        FmuState* s = known_state(instance, *FMUstate);
        instance->states.erase(s);
        delete s;
        *FMUstate = nullptr;
        return fmi2OK;
    });
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t* size) {
    BEGIN("fmi2SerializedFMUstateSize", any_state)
    REQUIRE("fmi2SerializedFMUstateSize", FMUstate, 1)
    REQUIRE("fmi2SerializedFMUstateSize", size, 1)
    return guarded(instance, "fmi2SerializedFMUstateSize", [&] {
        *size = serialize(*known_state(instance, FMUstate)).size();
        return fmi2OK;
    });
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte bytes[],
                                 size_t size) {
    BEGIN("fmi2SerializeFMUstate", any_state)
    REQUIRE("fmi2SerializeFMUstate", FMUstate, 1)
    REQUIRE("fmi2SerializeFMUstate", bytes, 1)
    return guarded(instance, "fmi2SerializeFMUstate", [&] {
        const std::vector<char> data = serialize(*known_state(instance, FMUstate));
        if (size != data.size())
            throw ModelError("size is " + std::to_string(size) + ", the state needs " +
                             std::to_string(data.size()) + " (fmi2SerializedFMUstateSize)");
        std::memcpy(bytes, data.data(), data.size());
        return fmi2OK;
    });
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[],
                                   size_t size, fmi2FMUstate* FMUstate) {
    BEGIN("fmi2DeSerializeFMUstate", any_state)
    REQUIRE("fmi2DeSerializeFMUstate", serializedState, 1)
    REQUIRE("fmi2DeSerializeFMUstate", FMUstate, 1)
    return guarded(instance, "fmi2DeSerializeFMUstate", [&] {
        FmuState parsed = deserialize(serializedState, size);
        if (*FMUstate) {  // reuse the given state, as FMI 2.0 allows
            *known_state(instance, *FMUstate) = std::move(parsed);
            return fmi2OK;
        }
        auto fresh = std::make_unique<FmuState>(std::move(parsed));
        instance->states.insert(fresh.get());
        *FMUstate = fresh.release();
        return fmi2OK;
    });
}

}  // extern "C"
