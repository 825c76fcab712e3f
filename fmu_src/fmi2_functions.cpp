// The exported FMI 2.0 Co-Simulation functions. Each checks its state and pointers in its
// first lines (BEGIN / REQUIRE), then runs its body through the shared shim (shim.hpp), which
// turns the model's exceptions into fmi2Status and a log message naming the function.
#include <cmath>
#include <cstring>
#include <memory>
#include <new>

extern "C" {
#include "fmi2Functions.h"
}

#include "instance.hpp"
#include "resource_start_values.hpp"
#include "shim.hpp"

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

// The shared shim, returning fmi2Status.
template <class Body>
fmi2Status fmi2_guarded(Instance* instance, const char* function, Body&& body) {
    return static_cast<fmi2Status>(guarded(instance, function, [&] { return static_cast<int>(body()); }));
}

bool initialized(const Instance* instance) {
    return instance->state & (StepComplete | StepFailed | Terminated | Error);
}

const Variable& variable(unsigned vr) {
    const Variable* v = find_variable(vr, Standard::fmi2);
    if (!v) throw ModelError("unknown value reference " + std::to_string(vr));
    return *v;
}

}  // namespace

#define BEGIN(function, states)                 \
    if (!c) return fmi2Error;                   \
    auto* instance = static_cast<Instance*>(c); \
    if (!instance->allowed(function, states)) return fmi2Error;
#define REQUIRE(function, pointer, count)                                                             \
    if ((count) > 0 && !(pointer)) {                                                                  \
        instance->error(function,                                                                     \
                        std::string(#pointer) + " is NULL but its size is " + std::to_string(count)); \
        return fmi2Error;                                                                             \
    }
#define NOT_SUPPORTED(function, what)                                   \
    BEGIN(function, any_state)                                          \
    instance->error(function, std::string("not supported: ") + (what)); \
    return fmi2Error;

namespace {

// The body of every get/set: state and pointer checks, then `each` on every (variable, value).
template <class Value, class Each>
fmi2Status for_each_variable(fmi2Component c, const char* function, unsigned states,
                             const fmi2ValueReference vr[], size_t nvr, Value* value, Each&& each) {
    BEGIN(function, states)
    REQUIRE(function, vr, nvr)
    REQUIRE(function, value, nvr) return fmi2_guarded(instance, function, [&] {
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
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions* functions,
                              fmi2Boolean /*visible*/, fmi2Boolean loggingOn) {
    if (!functions) return nullptr;
    auto fail = [&](const char* message) -> fmi2Component {
        if (functions->logger)
            functions->logger(functions->componentEnvironment, instanceName ? instanceName : "", fmi2Error,
                              "logStatusError", "fmi2Instantiate: %s", message);
        return nullptr;
    };
    if (!instanceName || !*instanceName) return fail("instanceName is missing");
    if (fmuType != fmi2CoSimulation) return fail("only fmi2CoSimulation is supported");
    if (!fmuGUID || std::strcmp(fmuGUID, guid) != 0)
        return fail("fmuGUID does not match this FMU's modelDescription.xml");
    try {
        // The message goes through "%s": the host formats the logger's message printf-style.
        Logger logger;
        if (functions->logger)
            logger = [log = functions->logger, env = functions->componentEnvironment,
                      name = std::string(instanceName)](int status, const char* category,
                                                        const char* message) {
                log(env, name.c_str(), static_cast<fmi2Status>(status), category, "%s", message);
            };
        auto instance = std::make_unique<Instance>(instanceName, std::move(logger), loggingOn);
        // A configured copy's start values (contactbody.system's SSP components), after the
        // folder that a relative mesh among them is taken from.
        instance->model.set_resources(resources_directory(fmuResourceLocation), /*edge_arrays=*/false);
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
    return static_cast<fmi2Status>(
        instance->set_debug_logging("fmi2SetDebugLogging", loggingOn, nCategories, categories));
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean /*toleranceDefined*/, fmi2Real /*tolerance*/,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    BEGIN("fmi2SetupExperiment", Instantiated)
    return fmi2_guarded(instance, "fmi2SetupExperiment", [&] {
        if (stopTimeDefined && !(stopTime >= startTime)) throw ModelError("stopTime must be >= startTime");
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
    return fmi2_guarded(instance, "fmi2ExitInitializationMode", [&] {
        instance->model.initialize();
        instance->state = StepComplete;
        log_initialized(instance, "fmi2ExitInitializationMode");
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

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    return for_each_variable(c, "fmi2GetReal", readable, vr, nvr, value,
                             [](Instance* i, const Variable& v, fmi2Real& x) { x = i->model.get_real(v); });
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    return for_each_variable(
        c, "fmi2GetInteger", readable, vr, nvr, value,
        [](Instance* i, const Variable& v, fmi2Integer& x) { x = i->model.get_integer(v); });
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    return for_each_variable(
        c, "fmi2SetReal", settable, vr, nvr, value,
        [](Instance* i, const Variable& v, const fmi2Real& x) { i->model.set_real(v, x, initialized(i)); });
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[]) {
    return for_each_variable(c, "fmi2SetInteger", settable, vr, nvr, value,
                             [](Instance* i, const Variable& v, const fmi2Integer& x) {
                                 i->model.set_integer(v, x, initialized(i));
                             });
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[]) {
    return for_each_variable(
        c, "fmi2GetString", readable, vr, nvr, value,
        [](Instance* i, const Variable& v, fmi2String& x) { x = i->model.get_string(v); });
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[]) {
    return for_each_variable(c, "fmi2SetString", settable, vr, nvr, value,
                             [](Instance* i, const Variable& v, const fmi2String& x) {
                                 i->model.set_string(v, x, initialized(i));
                             });
}

// This FMU has no Boolean variables: any value reference is refused.
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
    return for_each_variable(c, "fmi2GetBoolean", readable, vr, nvr, value, refuse("Boolean"));
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[]) {
    return for_each_variable(c, "fmi2SetBoolean", settable, vr, nvr, value, refuse("Boolean"));
}

// ---- stepping and status ----

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean /*noSetFMUStatePriorToCurrentPoint*/) {
    BEGIN("fmi2DoStep", StepComplete)
    const fmi2Status status = fmi2_guarded(instance, "fmi2DoStep", [&] {
        instance->model.do_step(currentCommunicationPoint, communicationStepSize);
        instance->last_successful_time = instance->model.time();
        return fmi2OK;
    });
    if (Simulation* sim = instance->model.simulation()) log_step(instance, "fmi2DoStep", *sim);
    return status;
}

fmi2Status fmi2CancelStep(fmi2Component c){NOT_SUPPORTED("fmi2CancelStep", "steps are never asynchronous")}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind /*s*/, fmi2Status* /*value*/){
    NOT_SUPPORTED("fmi2GetStatus", "steps are never asynchronous")}

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

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind /*s*/, fmi2Integer* /*value*/){
    NOT_SUPPORTED("fmi2GetIntegerStatus", "no integer status is defined")}

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

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind /*s*/, fmi2String* /*value*/){
    NOT_SUPPORTED("fmi2GetStringStatus", "no string status is defined")}

// ---- capabilities this FMU does not declare ----

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    BEGIN("fmi2SetRealInputDerivatives", InitializationMode | StepComplete)
    REQUIRE("fmi2SetRealInputDerivatives", vr, nvr)
    REQUIRE("fmi2SetRealInputDerivatives", order, nvr)
    REQUIRE("fmi2SetRealInputDerivatives", value, nvr)
    return fmi2_guarded(instance, "fmi2SetRealInputDerivatives", [&] {
        for (size_t k = 0; k < nvr; ++k)
            instance->model.set_input_derivative(variable(vr[k]), order[k], value[k]);
        return fmi2OK;
    });
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2Integer[], fmi2Real[]){
    NOT_SUPPORTED("fmi2GetRealOutputDerivatives", "maxOutputDerivativeOrder is 0")}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2ValueReference[], size_t, const fmi2Real[], fmi2Real[]){
    NOT_SUPPORTED("fmi2GetDirectionalDerivative", "providesDirectionalDerivative is false")}

// ---- FMU state: plain data owned by the instance, bytes with a versioned header ----

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
    BEGIN("fmi2GetFMUstate", saveable)
    REQUIRE("fmi2GetFMUstate", FMUstate, 1)
    return static_cast<fmi2Status>(get_fmu_state(instance, "fmi2GetFMUstate", FMUstate));
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
    BEGIN("fmi2SetFMUstate", restorable)
    REQUIRE("fmi2SetFMUstate", FMUstate, 1)
    return static_cast<fmi2Status>(set_fmu_state(instance, "fmi2SetFMUstate", FMUstate));
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
    BEGIN("fmi2FreeFMUstate", any_state)
    REQUIRE("fmi2FreeFMUstate", FMUstate, 1)
    return static_cast<fmi2Status>(free_fmu_state(instance, "fmi2FreeFMUstate", FMUstate));
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t* size) {
    BEGIN("fmi2SerializedFMUstateSize", any_state)
    REQUIRE("fmi2SerializedFMUstateSize", FMUstate, 1)
    REQUIRE("fmi2SerializedFMUstateSize", size, 1)
    return static_cast<fmi2Status>(
        serialized_fmu_state_size(instance, "fmi2SerializedFMUstateSize", FMUstate, size));
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte bytes[], size_t size) {
    BEGIN("fmi2SerializeFMUstate", any_state)
    REQUIRE("fmi2SerializeFMUstate", FMUstate, 1)
    REQUIRE("fmi2SerializeFMUstate", bytes, 1)
    return static_cast<fmi2Status>(
        serialize_fmu_state(instance, "fmi2SerializeFMUstate", FMUstate, bytes, size));
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate* FMUstate) {
    BEGIN("fmi2DeSerializeFMUstate", any_state)
    REQUIRE("fmi2DeSerializeFMUstate", serializedState, 1)
    REQUIRE("fmi2DeSerializeFMUstate", FMUstate, 1)
    return static_cast<fmi2Status>(
        deserialize_fmu_state(instance, "fmi2DeSerializeFMUstate", serializedState, size, FMUstate));
}

}  // extern "C"
