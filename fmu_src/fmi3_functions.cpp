// The exported FMI 3.0 Co-Simulation functions: a second thin layer over the same Instance,
// model and variable table as fmi2_functions.cpp. Each checks its state and pointers in its
// first lines (BEGIN / REQUIRE), then runs its body through the shared shim (shim.hpp).
// The FMU has no event mode, no clocks, no intermediate updates and no early return; the
// contact-edge arrays hold edge_nodes values each (the structural parameter, nx + 1).
#include <climits>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <type_traits>

extern "C" {
#include "fmi3Functions.h"
}

#include "instance.hpp"
#include "resource_start_values.hpp"
#include "shim.hpp"

using namespace contactbody;
using namespace contactbody::fmu;

namespace {

constexpr unsigned any_state =
    Instantiated | ConfigurationMode | InitializationMode | StepComplete | Terminated | Error;
constexpr unsigned readable = ConfigurationMode | InitializationMode | StepComplete | Terminated | Error;
constexpr unsigned settable = Instantiated | ConfigurationMode | InitializationMode | StepComplete;
constexpr unsigned saveable = Instantiated | InitializationMode | StepComplete | Terminated;
constexpr unsigned restorable = saveable | Error;

template <class Body>
fmi3Status fmi3_guarded(Instance* instance, const char* function, Body&& body) {
    return static_cast<fmi3Status>(guarded(instance, function, [&] { return static_cast<int>(body()); }));
}

bool initialized(const Instance* instance) { return instance->state & (StepComplete | Terminated | Error); }

// The variable of `vr` when it has FMI 3.0 type `type` (time: vr 0, Float64, has none).
const Variable* variable(unsigned vr, const char* type) {
    if (vr == time_value_reference) {
        if (std::strcmp(type, "Float64") != 0)
            throw ModelError("variable time (value reference 0) is of type Float64, not " +
                             std::string(type));
        return nullptr;
    }
    const Variable* v = find_variable(vr, Standard::fmi3);
    if (!v) throw ModelError("unknown value reference " + std::to_string(vr));
    if (std::strcmp(fmi3_type(*v), type) != 0)
        throw ModelError(std::string("variable ") + v->name + " is of type " + fmi3_type(*v) + ", not " +
                         type);
    return v;
}

// In Configuration Mode only the structural parameters are read and written.
void check_configuration(const Instance* instance, const Variable* v) {
    if (instance->state == ConfigurationMode && !(v && v->structural))
        throw ModelError(std::string("variable ") + (v ? v->name : "time") +
                         " is not a structural parameter: only those in Configuration Mode");
}

// An integer value as the model's int, or an error naming the variable and its limits (the
// model checks the limits of the values that fit).
template <class T>
int as_int(const Variable& v, T x) {
    bool fits;
    if constexpr (std::is_unsigned_v<T>)
        fits = x <= static_cast<T>(INT_MAX);
    else
        fits = x >= INT_MIN && x <= INT_MAX;
    if (!fits)
        throw ModelError(std::string("variable ") + v.name + " = " + std::to_string(x) +
                         " is out of range: must be >= " + std::to_string(static_cast<long long>(v.min)) +
                         " and <= " + std::to_string(static_cast<long long>(v.max)));
    return static_cast<int>(x);
}

}  // namespace

#define BEGIN(function, states)                         \
    if (!instance_) return fmi3Error;                   \
    auto* instance = static_cast<Instance*>(instance_); \
    if (!instance->allowed(function, states)) return fmi3Error;
#define REQUIRE(function, pointer, count)                                                             \
    if ((count) > 0 && !(pointer)) {                                                                  \
        instance->error(function,                                                                     \
                        std::string(#pointer) + " is NULL but its size is " + std::to_string(count)); \
        return fmi3Error;                                                                             \
    }
#define NOT_SUPPORTED(function, what)                                   \
    BEGIN(function, any_state)                                          \
    instance->error(function, std::string("not supported: ") + (what)); \
    return fmi3Error;

namespace {

// fmi3Get{Type}: state and pointer checks, then each variable's values in turn (size(v) of
// them: edge_nodes for an array), exactly nValues in all.
template <class T>
fmi3Status get_values(fmi3Instance instance_, const char* function, const char* type,
                      const fmi3ValueReference vr[], size_t nvr, T values[], size_t nValues) {
    BEGIN(function, readable)
    REQUIRE(function, vr, nvr)
    REQUIRE(function, values, nValues) return fmi3_guarded(instance, function, [&] {
        ContactBodyModel& model = instance->model;
        size_t needed = 0;
        for (size_t k = 0; k < nvr; ++k) {
            const Variable* v = variable(vr[k], type);
            check_configuration(instance, v);
            needed += v ? model.size(*v) : 1;
        }
        if (needed != nValues) {
            size_t array_size = 0;
            for (size_t k = 0; k < nvr; ++k)
                if (const Variable* v = variable(vr[k], type); v && v->is_array())
                    array_size = model.size(*v);
            throw ModelError(
                "nValues is " + std::to_string(nValues) + ", the variables hold " + std::to_string(needed) +
                (array_size ? " (each edge array holds edge_nodes = " + std::to_string(array_size) +
                                  " values, nx + 1 for the "
                                  "rectangle, a mesh's contact nodes; an importer that sizes "
                                  "arrays from the "
                                  "modelDescription needs the start of edge_nodes changed too)"
                            : std::string()));
        }
        T* out = values;
        for (size_t k = 0; k < nvr; ++k) {
            const Variable* v = variable(vr[k], type);
            if constexpr (std::is_same_v<T, fmi3Float64>) {
                if (!v)
                    *out++ = model.time();
                else if (v->is_array())
                    model.get_edge(*v, out), out += model.size(*v);
                else
                    *out++ = model.get_real(*v);
            } else if constexpr (std::is_same_v<T, fmi3Int64>) {
                if (v->is_array())
                    model.get_edge(*v, out), out += model.size(*v);
                else
                    *out++ = model.get_integer(*v);
            } else if constexpr (std::is_same_v<T, fmi3String>) {
                *out++ = model.get_string(*v);
            } else {
                *out++ = static_cast<T>(model.get_integer(*v));  // Int32, UInt64
            }
        }
        return fmi3OK;
    });
}

// fmi3Set{Type}: scalars only (the arrays are outputs), one value per variable.
template <class T>
fmi3Status set_values(fmi3Instance instance_, const char* function, const char* type,
                      const fmi3ValueReference vr[], size_t nvr, const T values[], size_t nValues) {
    BEGIN(function, settable)
    REQUIRE(function, vr, nvr)
    REQUIRE(function, values, nValues) return fmi3_guarded(instance, function, [&] {
        if (nValues != nvr)
            throw ModelError("nValues is " + std::to_string(nValues) + ", the variables hold " +
                             std::to_string(nvr));
        for (size_t k = 0; k < nvr; ++k) {
            const Variable* v = variable(vr[k], type);
            if (!v) throw ModelError("variable time is the independent variable and cannot be set");
            check_configuration(instance, v);
            if (v->causality == Causality::output)
                throw ModelError(std::string("variable ") + v->name + " is an output and cannot be set");
            ContactBodyModel& model = instance->model;
            const bool after = initialized(instance);
            if constexpr (std::is_same_v<T, fmi3Float64>)
                model.set_real(*v, values[k], after);
            else if constexpr (std::is_same_v<T, fmi3String>)
                model.set_string(*v, values[k], after);
            else
                model.set_integer(*v, as_int(*v, values[k]), after);
        }
        return fmi3OK;
    });
}

// Types of which this FMU has no variables: any value reference is refused, and so is
// nValues > 0 without one, as get_values and set_values refuse a count that is not the
// variables' (no value references hold no values).
fmi3Status no_variables(fmi3Instance instance_, const char* function, unsigned states, const char* type,
                        const fmi3ValueReference vr[], size_t nvr, size_t nValues) {
    BEGIN(function, states)
    REQUIRE(function, vr, nvr)
    if (nvr == 0 && nValues != 0) {
        instance->error(function, "nValues is " + std::to_string(nValues) +
                                      ", the variables hold 0 (no value references)");
        return fmi3Error;
    }
    if (nvr == 0) return fmi3OK;
    instance->error(function, "value reference " + std::to_string(vr[0]) + " is not of type " + type +
                                  " (this FMU has no " + type + " variables)");
    return fmi3Error;
}

}  // namespace

extern "C" {

const char* fmi3GetVersion(void) { return fmi3Version; }

fmi3Status fmi3SetDebugLogging(fmi3Instance instance_, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[]) {
    BEGIN("fmi3SetDebugLogging", any_state)
    return static_cast<fmi3Status>(
        instance->set_debug_logging("fmi3SetDebugLogging", loggingOn, nCategories, categories));
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String instanceName, fmi3String instantiationToken,
                                         fmi3String resourcePath, fmi3Boolean /*visible*/,
                                         fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
                                         fmi3Boolean /*earlyReturnAllowed: this FMU never returns early*/,
                                         const fmi3ValueReference /*requiredIntermediateVariables*/[],
                                         size_t nRequiredIntermediateVariables,
                                         fmi3InstanceEnvironment instanceEnvironment,
                                         fmi3LogMessageCallback logMessage,
                                         fmi3IntermediateUpdateCallback /*intermediateUpdate*/) {
    auto fail = [&](const std::string& message) -> fmi3Instance {
        if (logMessage && loggingOn)  // FMI 3.0: no call while logging is off
            logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                       ("fmi3InstantiateCoSimulation: " + message).c_str());
        return nullptr;
    };
    if (!instanceName || !*instanceName) return fail("instanceName is missing");
    if (!instantiationToken || std::strcmp(instantiationToken, guid) != 0)
        return fail("instantiationToken does not match this FMU's modelDescription.xml");
    if (eventModeUsed) return fail("this FMU has no event mode (hasEventMode = false)");
    if (nRequiredIntermediateVariables > 0)
        return fail("this FMU provides no intermediate variables (providesIntermediateUpdate = false)");
    try {
        Logger logger;
        if (logMessage)
            logger = [logMessage, instanceEnvironment](int status, const char* category,
                                                       const char* message) {
                logMessage(instanceEnvironment, static_cast<fmi3Status>(status), category, message);
            };
        auto instance = std::make_unique<Instance>(instanceName, std::move(logger), loggingOn,
                                                   LogRule::fmi3_settings_only);
        // A configured copy's start values (resources/start_values.txt), after the folder that
        // a relative mesh among them is taken from.
        instance->model.set_resources(resourcePath ? resourcePath : "", /*edge_arrays=*/true);
        if (resourcePath && *resourcePath)
            instance->model.set_defaults(read_start_values(std::string(resourcePath) + "/start_values.txt"));
        return instance.release();
    } catch (const std::exception& e) {
        return fail(e.what());
    } catch (...) {
        return fail("out of memory");
    }
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String, fmi3String, fmi3Boolean,
                                          fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage) {
    if (logMessage && loggingOn)
        logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                   "fmi3InstantiateModelExchange: this FMU supports Co-Simulation only");
    (void)instanceName;
    return nullptr;
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String, fmi3String, fmi3String, fmi3Boolean,
                                               fmi3Boolean loggingOn,
                                               fmi3InstanceEnvironment instanceEnvironment,
                                               fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback,
                                               fmi3LockPreemptionCallback, fmi3UnlockPreemptionCallback) {
    if (logMessage && loggingOn)
        logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                   "fmi3InstantiateScheduledExecution: this FMU supports Co-Simulation only");
    return nullptr;
}

void fmi3FreeInstance(fmi3Instance instance) { delete static_cast<Instance*>(instance); }

// ---- configuration, initialization, termination ----

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance_) {
    // From Instantiated only: no structural parameter is tunable, so there is no
    // Reconfiguration Mode.
    BEGIN("fmi3EnterConfigurationMode", Instantiated)
    instance->state = ConfigurationMode;
    return fmi3OK;
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance_) {
    BEGIN("fmi3ExitConfigurationMode", ConfigurationMode)
    return fmi3_guarded(instance, "fmi3ExitConfigurationMode", [&] {
        instance->model.check_structure();
        instance->state = Instantiated;
        return fmi3OK;
    });
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance_, fmi3Boolean /*toleranceDefined*/,
                                       fmi3Float64 /*tolerance*/, fmi3Float64 startTime,
                                       fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    BEGIN("fmi3EnterInitializationMode", Instantiated)
    return fmi3_guarded(instance, "fmi3EnterInitializationMode", [&] {
        if (stopTimeDefined && !(stopTime >= startTime)) throw ModelError("stopTime must be >= startTime");
        instance->model.set_start_time(startTime);
        instance->last_successful_time = startTime;
        instance->state = InitializationMode;
        return fmi3OK;
    });
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance_) {
    BEGIN("fmi3ExitInitializationMode", InitializationMode)
    return fmi3_guarded(instance, "fmi3ExitInitializationMode", [&] {
        instance->model.initialize();
        instance->state = StepComplete;
        log_initialized(instance, "fmi3ExitInitializationMode");
        return fmi3OK;
    });
}

fmi3Status fmi3Terminate(fmi3Instance instance_) {
    BEGIN("fmi3Terminate", StepComplete)
    instance->state = Terminated;
    return fmi3OK;
}

fmi3Status fmi3Reset(fmi3Instance instance_) {
    BEGIN("fmi3Reset", any_state)
    instance->model.reset();
    instance->last_successful_time = 0;
    instance->state = Instantiated;
    return fmi3OK;
}

// ---- getters and setters ----

#define GETTER(Type, T)                                                                                    \
    fmi3Status fmi3Get##Type(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, T values[], \
                             size_t nValues) {                                                             \
        return get_values(instance, "fmi3Get" #Type, #Type, vr, nvr, values, nValues);                     \
    }
#define SETTER(Type, T)                                                                        \
    fmi3Status fmi3Set##Type(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, \
                             const T values[], size_t nValues) {                               \
        return set_values(instance, "fmi3Set" #Type, #Type, vr, nvr, values, nValues);         \
    }
#define NO_VARIABLES(Type, T)                                                                             \
    fmi3Status fmi3Get##Type(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, T[],       \
                             size_t nValues) {                                                            \
        return no_variables(instance, "fmi3Get" #Type, readable, #Type, vr, nvr, nValues);                \
    }                                                                                                     \
    fmi3Status fmi3Set##Type(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const T[], \
                             size_t nValues) {                                                            \
        return no_variables(instance, "fmi3Set" #Type, settable, #Type, vr, nvr, nValues);                \
    }

GETTER(Float64, fmi3Float64)
SETTER(Float64, fmi3Float64)
GETTER(Int32, fmi3Int32)
SETTER(Int32, fmi3Int32)
GETTER(UInt64, fmi3UInt64)
SETTER(UInt64, fmi3UInt64)
GETTER(Int64, fmi3Int64)
SETTER(Int64, fmi3Int64)
GETTER(String, fmi3String)
SETTER(String, fmi3String)
NO_VARIABLES(Float32, fmi3Float32)
NO_VARIABLES(Int8, fmi3Int8)
NO_VARIABLES(UInt8, fmi3UInt8)
NO_VARIABLES(Int16, fmi3Int16)
NO_VARIABLES(UInt16, fmi3UInt16)
NO_VARIABLES(UInt32, fmi3UInt32)
NO_VARIABLES(Boolean, fmi3Boolean)

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, size_t[],
                         fmi3Binary[], size_t nValues) {
    return no_variables(instance, "fmi3GetBinary", readable, "Binary", vr, nvr, nValues);
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr, const size_t[],
                         const fmi3Binary[], size_t nValues) {
    return no_variables(instance, "fmi3SetBinary", settable, "Binary", vr, nvr, nValues);
}

// ---- stepping ----

fmi3Status fmi3DoStep(fmi3Instance instance_, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize, fmi3Boolean /*noSetFMUStatePriorToCurrentPoint*/,
                      fmi3Boolean* eventHandlingNeeded, fmi3Boolean* terminateSimulation,
                      fmi3Boolean* earlyReturn, fmi3Float64* lastSuccessfulTime) {
    BEGIN("fmi3DoStep", StepComplete)
    REQUIRE("fmi3DoStep", eventHandlingNeeded, 1)
    REQUIRE("fmi3DoStep", terminateSimulation, 1)
    REQUIRE("fmi3DoStep", earlyReturn, 1)
    REQUIRE("fmi3DoStep", lastSuccessfulTime, 1)
    // No events and no early return; a failed step ends in Error at the step's start, which
    // fmi3SetFMUState can leave.
    *eventHandlingNeeded = fmi3False;
    *terminateSimulation = fmi3False;
    *earlyReturn = fmi3False;
    const fmi3Status status = fmi3_guarded(instance, "fmi3DoStep", [&] {
        instance->model.do_step(currentCommunicationPoint, communicationStepSize);
        instance->last_successful_time = instance->model.time();
        return fmi3OK;
    });
    *lastSuccessfulTime = instance->last_successful_time;
    if (Simulation* sim = instance->model.simulation()) log_step(instance, "fmi3DoStep", *sim);
    return status;
}

// ---- FMU state: the same plain data and bytes as the FMI 2.0 layer ----

fmi3Status fmi3GetFMUState(fmi3Instance instance_, fmi3FMUState* FMUState) {
    BEGIN("fmi3GetFMUState", saveable)
    REQUIRE("fmi3GetFMUState", FMUState, 1)
    return static_cast<fmi3Status>(get_fmu_state(instance, "fmi3GetFMUState", FMUState));
}

fmi3Status fmi3SetFMUState(fmi3Instance instance_, fmi3FMUState FMUState) {
    BEGIN("fmi3SetFMUState", restorable)
    REQUIRE("fmi3SetFMUState", FMUState, 1)
    return static_cast<fmi3Status>(set_fmu_state(instance, "fmi3SetFMUState", FMUState));
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance_, fmi3FMUState* FMUState) {
    BEGIN("fmi3FreeFMUState", any_state)
    REQUIRE("fmi3FreeFMUState", FMUState, 1)
    return static_cast<fmi3Status>(free_fmu_state(instance, "fmi3FreeFMUState", FMUState));
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance_, fmi3FMUState FMUState, size_t* size) {
    BEGIN("fmi3SerializedFMUStateSize", any_state)
    REQUIRE("fmi3SerializedFMUStateSize", FMUState, 1)
    REQUIRE("fmi3SerializedFMUStateSize", size, 1)
    return static_cast<fmi3Status>(
        serialized_fmu_state_size(instance, "fmi3SerializedFMUStateSize", FMUState, size));
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance_, fmi3FMUState FMUState, fmi3Byte serializedState[],
                                 size_t size) {
    BEGIN("fmi3SerializeFMUState", any_state)
    REQUIRE("fmi3SerializeFMUState", FMUState, 1)
    REQUIRE("fmi3SerializeFMUState", serializedState, 1)
    return static_cast<fmi3Status>(serialize_fmu_state(instance, "fmi3SerializeFMUState", FMUState,
                                                       reinterpret_cast<char*>(serializedState), size));
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance_, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState* FMUState) {
    BEGIN("fmi3DeserializeFMUState", any_state)
    REQUIRE("fmi3DeserializeFMUState", serializedState, 1)
    REQUIRE("fmi3DeserializeFMUState", FMUState, 1)
    return static_cast<fmi3Status>(deserialize_fmu_state(
        instance, "fmi3DeserializeFMUState", reinterpret_cast<const char*>(serializedState), size, FMUState));
}

// ---- capabilities this FMU does not declare ----

fmi3Status fmi3EnterEventMode(fmi3Instance instance_){
    NOT_SUPPORTED("fmi3EnterEventMode", "hasEventMode is false")} fmi3Status
    fmi3EnterStepMode(fmi3Instance instance_){
        NOT_SUPPORTED("fmi3EnterStepMode", "hasEventMode is false")} fmi3Status
    fmi3EvaluateDiscreteStates(fmi3Instance instance_){
        NOT_SUPPORTED("fmi3EvaluateDiscreteStates", "hasEventMode is false")} fmi3Status
    fmi3UpdateDiscreteStates(fmi3Instance instance_, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*,
                             fmi3Boolean*, fmi3Float64*){
        NOT_SUPPORTED("fmi3UpdateDiscreteStates", "hasEventMode is false")} fmi3Status
    fmi3GetClock(fmi3Instance instance_, const fmi3ValueReference[], size_t,
                 fmi3Clock[]){NOT_SUPPORTED("fmi3GetClock", "this FMU has no clocks")} fmi3Status
    fmi3SetClock(fmi3Instance instance_, const fmi3ValueReference[], size_t,
                 const fmi3Clock[]){NOT_SUPPORTED("fmi3SetClock", "this FMU has no clocks")} fmi3Status
    fmi3GetIntervalDecimal(fmi3Instance instance_, const fmi3ValueReference[], size_t, fmi3Float64[],
                           fmi3IntervalQualifier[]){
        NOT_SUPPORTED("fmi3GetIntervalDecimal", "this FMU has no clocks")} fmi3Status
    fmi3GetIntervalFraction(fmi3Instance instance_, const fmi3ValueReference[], size_t, fmi3UInt64[],
                            fmi3UInt64[], fmi3IntervalQualifier[]){
        NOT_SUPPORTED("fmi3GetIntervalFraction", "this FMU has no clocks")} fmi3Status
    fmi3GetShiftDecimal(fmi3Instance instance_, const fmi3ValueReference[], size_t, fmi3Float64[]){
        NOT_SUPPORTED("fmi3GetShiftDecimal", "this FMU has no clocks")} fmi3Status
    fmi3GetShiftFraction(fmi3Instance instance_, const fmi3ValueReference[], size_t, fmi3UInt64[],
                         fmi3UInt64[]){
        NOT_SUPPORTED("fmi3GetShiftFraction", "this FMU has no clocks")} fmi3Status
    fmi3SetIntervalDecimal(fmi3Instance instance_, const fmi3ValueReference[], size_t, const fmi3Float64[]){
        NOT_SUPPORTED("fmi3SetIntervalDecimal", "this FMU has no clocks")} fmi3Status
    fmi3SetIntervalFraction(fmi3Instance instance_, const fmi3ValueReference[], size_t, const fmi3UInt64[],
                            const fmi3UInt64[]){
        NOT_SUPPORTED("fmi3SetIntervalFraction", "this FMU has no clocks")} fmi3Status
    fmi3SetShiftDecimal(fmi3Instance instance_, const fmi3ValueReference[], size_t, const fmi3Float64[]){
        NOT_SUPPORTED("fmi3SetShiftDecimal", "this FMU has no clocks")} fmi3Status
    fmi3SetShiftFraction(fmi3Instance instance_, const fmi3ValueReference[], size_t, const fmi3UInt64[],
                         const fmi3UInt64[]){
        NOT_SUPPORTED("fmi3SetShiftFraction", "this FMU has no clocks")} fmi3Status
    fmi3ActivateModelPartition(fmi3Instance instance_, fmi3ValueReference, fmi3Float64){
        NOT_SUPPORTED("fmi3ActivateModelPartition", "Co-Simulation only")} fmi3Status
    fmi3GetNumberOfVariableDependencies(fmi3Instance instance_, fmi3ValueReference, size_t*){
        NOT_SUPPORTED("fmi3GetNumberOfVariableDependencies",
                      "providesPerElementDependencies is false")} fmi3Status
    fmi3GetVariableDependencies(fmi3Instance instance_, fmi3ValueReference, size_t[], fmi3ValueReference[],
                                size_t[], fmi3DependencyKind[], size_t){
        NOT_SUPPORTED("fmi3GetVariableDependencies", "providesPerElementDependencies is false")} fmi3Status
    fmi3GetDirectionalDerivative(fmi3Instance instance_, const fmi3ValueReference[], size_t,
                                 const fmi3ValueReference[], size_t, const fmi3Float64[], size_t,
                                 fmi3Float64[], size_t){
        NOT_SUPPORTED("fmi3GetDirectionalDerivative", "providesDirectionalDerivatives is false")} fmi3Status
    fmi3GetAdjointDerivative(fmi3Instance instance_, const fmi3ValueReference[], size_t,
                             const fmi3ValueReference[], size_t, const fmi3Float64[], size_t, fmi3Float64[],
                             size_t){
        NOT_SUPPORTED("fmi3GetAdjointDerivative", "providesAdjointDerivatives is false")} fmi3Status
    fmi3GetOutputDerivatives(fmi3Instance instance_, const fmi3ValueReference[], size_t, const fmi3Int32[],
                             fmi3Float64[], size_t){
        NOT_SUPPORTED("fmi3GetOutputDerivatives", "maxOutputDerivativeOrder is 0")}
// Model Exchange: this FMU is Co-Simulation only.
fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance_){
    NOT_SUPPORTED("fmi3EnterContinuousTimeMode", "Co-Simulation only")} fmi3Status
    fmi3CompletedIntegratorStep(fmi3Instance instance_, fmi3Boolean, fmi3Boolean*, fmi3Boolean*){
        NOT_SUPPORTED("fmi3CompletedIntegratorStep", "Co-Simulation only")} fmi3Status
    fmi3SetTime(fmi3Instance instance_,
                fmi3Float64){NOT_SUPPORTED("fmi3SetTime", "Co-Simulation only")} fmi3Status
    fmi3SetContinuousStates(fmi3Instance instance_, const fmi3Float64[],
                            size_t){NOT_SUPPORTED("fmi3SetContinuousStates", "Co-Simulation only")} fmi3Status
    fmi3GetContinuousStateDerivatives(fmi3Instance instance_, fmi3Float64[], size_t){
        NOT_SUPPORTED("fmi3GetContinuousStateDerivatives", "Co-Simulation only")} fmi3Status
    fmi3GetEventIndicators(fmi3Instance instance_, fmi3Float64[],
                           size_t){NOT_SUPPORTED("fmi3GetEventIndicators", "Co-Simulation only")} fmi3Status
    fmi3GetContinuousStates(fmi3Instance instance_, fmi3Float64[],
                            size_t){NOT_SUPPORTED("fmi3GetContinuousStates", "Co-Simulation only")} fmi3Status
    fmi3GetNominalsOfContinuousStates(fmi3Instance instance_, fmi3Float64[], size_t){
        NOT_SUPPORTED("fmi3GetNominalsOfContinuousStates", "Co-Simulation only")} fmi3Status
    fmi3GetNumberOfEventIndicators(fmi3Instance instance_, size_t*){
        NOT_SUPPORTED("fmi3GetNumberOfEventIndicators", "Co-Simulation only")} fmi3Status
    fmi3GetNumberOfContinuousStates(fmi3Instance instance_, size_t*) {
    NOT_SUPPORTED("fmi3GetNumberOfContinuousStates", "Co-Simulation only")
}

}  // extern "C"
