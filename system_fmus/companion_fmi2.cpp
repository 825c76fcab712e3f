// The FMI 2.0 co-simulation entry points of a companion model (companion.hpp): one explicit
// state machine, every entry point checks its pointer and its allowed states first, errors
// are logged with the function's name. The FMU state is plain data (values, states, time).
#include <fmi2Functions.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "companion.hpp"
#include "resource_start_values.hpp"
#include "util/text.hpp"

namespace {

using companion::Causality;
using companion::model;

enum class Phase : int32_t { instantiated, initialization, step_complete, terminated, error };
const char* phase_name(Phase p) {
    switch (p) {
        case Phase::instantiated:
            return "Instantiated";
        case Phase::initialization:
            return "InitializationMode";
        case Phase::step_complete:
            return "StepComplete";
        case Phase::terminated:
            return "Terminated";
        case Phase::error:
            return "Error";
    }
    return "?";
}

struct Snapshot {
    std::vector<double> values, rates, x;  // rates: of the inputs, across the next steps
    double time = 0;
    Phase phase = Phase::instantiated;
};

// RK4 buffers and the state a failed step goes back to: sized by the first step, reused.
struct Workspace {
    std::vector<double> v, start, k1, k2, k3, k4, y;
    Snapshot saved;
};

struct Instance {
    std::string name;
    fmi2CallbackFunctions callbacks;
    bool logging = false;
    Snapshot s;
    Workspace work;
    std::vector<double> defaults;  // start values: the table's, or this copy's resources'
};

constexpr uint32_t state_version = 1;

void log(Instance* inst, fmi2Status status, const char* function, const std::string& message) {
    if (!inst->callbacks.logger) return;
    if (status == fmi2OK && !inst->logging) return;
    inst->callbacks.logger(inst->callbacks.componentEnvironment, inst->name.c_str(), status,
                           status == fmi2OK ? "logEvents" : "logStatusError", "%s: %s", function,
                           message.c_str());
}

fmi2Status fail(Instance* inst, const char* function, const std::string& message) {
    log(inst, fmi2Error, function, message);
    return fmi2Error;
}

bool allowed(Instance* inst, const char* function, std::initializer_list<Phase> phases) {
    for (Phase p : phases)
        if (inst->s.phase == p) return true;
    fail(inst, function, std::string("not allowed in state ") + phase_name(inst->s.phase));
    return false;
}

#define ENTRY(function, ...)                    \
    if (!c) return fmi2Error;                   \
    Instance* inst = static_cast<Instance*>(c); \
    if (!allowed(inst, function, {__VA_ARGS__})) return fmi2Error

const companion::Variable* variable(fmi2ValueReference vr) {
    const auto& vars = model().variables;
    return vr < vars.size() ? &vars[vr] : nullptr;
}

void start_values(Snapshot& s) {
    const auto& vars = model().variables;
    s.values.resize(vars.size());
    for (size_t i = 0; i < vars.size(); ++i) s.values[i] = vars[i].start;
    s.rates.assign(vars.size(), 0.0);
    s.x.assign(static_cast<size_t>(model().num_states), 0.0);
    s.time = 0;
}

// Outputs of the initial states (during initialization) or of the current ones.
void update_outputs(Snapshot& s) {
    if (s.phase == Phase::instantiated || s.phase == Phase::initialization)
        model().initial_states(s.values.data(), s.x.data());
    model().outputs(s.values.data(), s.x.data(), s.time);
}

// Classic RK4 over [t, t + h] in substeps of at most internal_step, with the inputs moving
// along their rates; the inputs end at their values at t + h.
bool integrate(Snapshot& s, double h, Workspace& w) {
    const auto& m = model();
    const size_t n = m.variables.size(), k = static_cast<size_t>(m.num_states);
    const int steps = std::max(1, static_cast<int>(std::ceil(h / m.internal_step * (1 - 1e-9))));
    const double dt = h / steps, t0 = s.time;
    w.v = s.values;
    w.start = s.values;
    for (auto* buffer : {&w.k1, &w.k2, &w.k3, &w.k4, &w.y}) buffer->resize(k);
    auto &v = w.v, &start = w.start, &k1 = w.k1, &k2 = w.k2, &k3 = w.k3, &k4 = w.k4, &y = w.y;
    auto at = [&](double t) {
        for (size_t i = 0; i < n; ++i)
            if (m.variables[i].causality == Causality::input) v[i] = start[i] + s.rates[i] * (t - t0);
    };
    for (int j = 0; j < steps; ++j) {
        const double t = t0 + j * dt;
        at(t);
        m.derivatives(v.data(), s.x.data(), t, k1.data());
        for (size_t i = 0; i < k; ++i) y[i] = s.x[i] + 0.5 * dt * k1[i];
        at(t + 0.5 * dt);
        m.derivatives(v.data(), y.data(), t + 0.5 * dt, k2.data());
        for (size_t i = 0; i < k; ++i) y[i] = s.x[i] + 0.5 * dt * k2[i];
        m.derivatives(v.data(), y.data(), t + 0.5 * dt, k3.data());
        for (size_t i = 0; i < k; ++i) y[i] = s.x[i] + dt * k3[i];
        at(t + dt);
        m.derivatives(v.data(), y.data(), t + dt, k4.data());
        for (size_t i = 0; i < k; ++i) s.x[i] += dt / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
    at(t0 + h);
    for (size_t i = 0; i < n; ++i)
        if (m.variables[i].causality == Causality::input) s.values[i] = v[i];
    s.time = t0 + h;
    model().outputs(s.values.data(), s.x.data(), s.time);
    for (double x : s.x)
        if (!std::isfinite(x)) return false;
    for (double x : s.values)
        if (!std::isfinite(x)) return false;
    return true;
}

// Serialized state: version, counts, then the doubles.
std::vector<char> serialize(const Snapshot& s) {
    std::vector<char> out;
    auto put = [&](const void* p, size_t size) {
        const char* c = static_cast<const char*>(p);
        out.insert(out.end(), c, c + size);
    };
    const uint32_t version = state_version;
    const uint64_t nv = s.values.size(), nx = s.x.size();
    put(&version, 4);
    put(&s.phase, 4);
    put(&nv, 8);
    put(&nx, 8);
    put(&s.time, 8);
    put(s.values.data(), 8 * nv);
    put(s.rates.data(), 8 * nv);
    put(s.x.data(), 8 * nx);
    return out;
}

bool deserialize(const char* data, size_t size, Snapshot& s, std::string& why) {
    const uint64_t nv = model().variables.size(), nx = static_cast<uint64_t>(model().num_states);
    const size_t expected = 4 + 4 + 8 + 8 + 8 + 8 * (2 * nv + nx);
    if (size != expected) {
        why = "state has " + std::to_string(size) + " bytes, this FMU's has " + std::to_string(expected);
        return false;
    }
    uint32_t version;
    int32_t phase;
    uint64_t n1, n2;
    std::memcpy(&version, data, 4);
    std::memcpy(&phase, data + 4, 4);
    std::memcpy(&n1, data + 8, 8);
    std::memcpy(&n2, data + 16, 8);
    if (version != state_version || n1 != nv || n2 != nx || phase < 0 || phase > 4) {
        why = "state bytes of another FMU or version";
        return false;
    }
    s.phase = static_cast<Phase>(phase);
    std::memcpy(&s.time, data + 24, 8);
    s.values.resize(nv);
    s.rates.resize(nv);
    s.x.resize(nx);
    std::memcpy(s.values.data(), data + 32, 8 * nv);
    std::memcpy(s.rates.data(), data + 32 + 8 * nv, 8 * nv);
    std::memcpy(s.x.data(), data + 32 + 16 * nv, 8 * nx);
    return true;
}

}  // namespace

extern "C" {

const char* fmi2GetTypesPlatform() { return fmi2TypesPlatform; }
const char* fmi2GetVersion() { return fmi2Version; }

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String resource_location,
                              const fmi2CallbackFunctions* callbacks, fmi2Boolean, fmi2Boolean logging) {
    if (!name || !guid || !callbacks) return nullptr;
    if (type != fmi2CoSimulation || std::strcmp(guid, model().guid) != 0) {
        if (callbacks->logger)
            callbacks->logger(
                callbacks->componentEnvironment, name, fmi2Error, "logStatusError", "fmi2Instantiate: %s",
                type != fmi2CoSimulation ? "only co-simulation is supported" : "GUID does not match");
        return nullptr;
    }
    Instance* inst = new (std::nothrow) Instance;
    if (!inst) return nullptr;
    inst->name = name;
    inst->callbacks = *callbacks;
    inst->logging = logging;
    start_values(inst->s);
    try {  // a configured copy's start values (contactbody.system's SSP components)
        const auto& vars = model().variables;
        for (const auto& [name, text] :
             contactbody::fmu::read_start_values(contactbody::fmu::start_values_path(resource_location))) {
            auto v = std::find_if(vars.begin(), vars.end(),
                                  [&](const companion::Variable& x) { return name == x.name; });
            double x = 0;
            if (v == vars.end() || v->causality == Causality::output)
                throw std::runtime_error("resources/start_values.txt: " + name +
                                         " is not a parameter or input of this FMU");
            if (!contactbody::parse_number(text, x))
                throw std::runtime_error("resources/start_values.txt: " + name + " = '" + text +
                                         "' is not a finite number");
            inst->s.values[v->value_reference] = x;
        }
    } catch (const std::exception& e) {
        if (callbacks->logger)
            callbacks->logger(callbacks->componentEnvironment, name, fmi2Error, "logStatusError",
                              "fmi2Instantiate: %s", e.what());
        delete inst;
        return nullptr;
    }
    inst->defaults = inst->s.values;
    return inst;
}

void fmi2FreeInstance(fmi2Component c) { delete static_cast<Instance*>(c); }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t, const fmi2String[]) {
    ENTRY("fmi2SetDebugLogging", Phase::instantiated, Phase::initialization, Phase::step_complete,
          Phase::terminated, Phase::error);
    inst->logging = on;
    return fmi2OK;
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean, fmi2Real, fmi2Real start, fmi2Boolean,
                               fmi2Real) {
    ENTRY("fmi2SetupExperiment", Phase::instantiated);
    if (!std::isfinite(start)) return fail(inst, "fmi2SetupExperiment", "start time not finite");
    inst->s.time = start;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    ENTRY("fmi2EnterInitializationMode", Phase::instantiated);
    inst->s.phase = Phase::initialization;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    ENTRY("fmi2ExitInitializationMode", Phase::initialization);
    for (const auto& v : model().variables) {
        const double x = inst->s.values[v.value_reference];
        if (v.causality == Causality::parameter && (!std::isfinite(x) || (v.positive && !(x > 0))))
            return fail(inst, "fmi2ExitInitializationMode",
                        std::string("parameter ") + v.name + " = " + std::to_string(x) +
                            (v.positive ? ": must be finite and > 0" : ": must be finite"));
    }
    update_outputs(inst->s);
    inst->s.phase = Phase::step_complete;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) {
    ENTRY("fmi2Terminate", Phase::step_complete, Phase::error);
    inst->s.phase = Phase::terminated;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
    ENTRY("fmi2Reset", Phase::instantiated, Phase::initialization, Phase::step_complete, Phase::terminated,
          Phase::error);
    inst->s = Snapshot{};
    start_values(inst->s);
    inst->s.values = inst->defaults;
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real value[]) {
    ENTRY("fmi2GetReal", Phase::initialization, Phase::step_complete, Phase::terminated, Phase::error);
    if (n > 0 && (!vr || !value)) return fail(inst, "fmi2GetReal", "null array");
    if (inst->s.phase == Phase::initialization) update_outputs(inst->s);
    for (size_t i = 0; i < n; ++i) {
        if (!variable(vr[i]))
            return fail(inst, "fmi2GetReal", "unknown value reference " + std::to_string(vr[i]));
        value[i] = inst->s.values[vr[i]];
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real value[]) {
    ENTRY("fmi2SetReal", Phase::instantiated, Phase::initialization, Phase::step_complete);
    if (n > 0 && (!vr || !value)) return fail(inst, "fmi2SetReal", "null array");
    for (size_t i = 0; i < n; ++i) {  // all checked before any is set
        const companion::Variable* v = variable(vr[i]);
        if (!v) return fail(inst, "fmi2SetReal", "unknown value reference " + std::to_string(vr[i]));
        if (v->causality == Causality::output)
            return fail(inst, "fmi2SetReal", std::string(v->name) + " is an output");
        if (v->causality == Causality::parameter && inst->s.phase == Phase::step_complete)
            return fail(inst, "fmi2SetReal", std::string(v->name) + " is fixed after initialization");
        if (!std::isfinite(value[i]))
            return fail(inst, "fmi2SetReal", std::string(v->name) + " must be finite");
    }
    for (size_t i = 0; i < n; ++i) {
        inst->s.values[vr[i]] = value[i];
        inst->s.rates[vr[i]] = 0;  // a new value is held until a derivative is set
    }
    return fmi2OK;
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference[], size_t n, fmi2Integer[]) {
    ENTRY("fmi2GetInteger", Phase::instantiated, Phase::initialization, Phase::step_complete,
          Phase::terminated, Phase::error);
    return n == 0 ? fmi2OK : fail(inst, "fmi2GetInteger", "this FMU has no Integer variables");
}
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference[], size_t n, const fmi2Integer[]) {
    ENTRY("fmi2SetInteger", Phase::instantiated, Phase::initialization, Phase::step_complete);
    return n == 0 ? fmi2OK : fail(inst, "fmi2SetInteger", "this FMU has no Integer variables");
}
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference[], size_t n, fmi2Boolean[]) {
    ENTRY("fmi2GetBoolean", Phase::instantiated, Phase::initialization, Phase::step_complete,
          Phase::terminated, Phase::error);
    return n == 0 ? fmi2OK : fail(inst, "fmi2GetBoolean", "this FMU has no Boolean variables");
}
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference[], size_t n, const fmi2Boolean[]) {
    ENTRY("fmi2SetBoolean", Phase::instantiated, Phase::initialization, Phase::step_complete);
    return n == 0 ? fmi2OK : fail(inst, "fmi2SetBoolean", "this FMU has no Boolean variables");
}
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference[], size_t n, fmi2String[]) {
    ENTRY("fmi2GetString", Phase::instantiated, Phase::initialization, Phase::step_complete,
          Phase::terminated, Phase::error);
    return n == 0 ? fmi2OK : fail(inst, "fmi2GetString", "this FMU has no String variables");
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference[], size_t n, const fmi2String[]) {
    ENTRY("fmi2SetString", Phase::instantiated, Phase::initialization, Phase::step_complete);
    return n == 0 ? fmi2OK : fail(inst, "fmi2SetString", "this FMU has no String variables");
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* state) {
    ENTRY("fmi2GetFMUstate", Phase::instantiated, Phase::initialization, Phase::step_complete,
          Phase::terminated, Phase::error);
    if (!state) return fail(inst, "fmi2GetFMUstate", "null state pointer");
    Snapshot* s = *state ? static_cast<Snapshot*>(*state) : new (std::nothrow) Snapshot;
    if (!s) return fail(inst, "fmi2GetFMUstate", "out of memory");
    *s = inst->s;
    *state = s;
    return fmi2OK;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state) {
    ENTRY("fmi2SetFMUstate", Phase::instantiated, Phase::initialization, Phase::step_complete,
          Phase::terminated, Phase::error);
    if (!state) return fail(inst, "fmi2SetFMUstate", "null state");
    const Snapshot* s = static_cast<const Snapshot*>(state);
    if (s->values.size() != model().variables.size() ||
        s->x.size() != static_cast<size_t>(model().num_states))
        return fail(inst, "fmi2SetFMUstate", "state of another FMU");
    inst->s = *s;
    return fmi2OK;
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* state) {
    ENTRY("fmi2FreeFMUstate", Phase::instantiated, Phase::initialization, Phase::step_complete,
          Phase::terminated, Phase::error);
    if (!state) return fail(inst, "fmi2FreeFMUstate", "null state pointer");
    delete static_cast<Snapshot*>(*state);
    *state = nullptr;
    return fmi2OK;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t* size) {
    ENTRY("fmi2SerializedFMUstateSize", Phase::instantiated, Phase::initialization, Phase::step_complete,
          Phase::terminated, Phase::error);
    if (!state || !size) return fail(inst, "fmi2SerializedFMUstateSize", "null pointer");
    *size = serialize(*static_cast<const Snapshot*>(state)).size();
    return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[], size_t size) {
    ENTRY("fmi2SerializeFMUstate", Phase::instantiated, Phase::initialization, Phase::step_complete,
          Phase::terminated, Phase::error);
    if (!state || !bytes) return fail(inst, "fmi2SerializeFMUstate", "null pointer");
    const std::vector<char> data = serialize(*static_cast<const Snapshot*>(state));
    if (size < data.size()) return fail(inst, "fmi2SerializeFMUstate", "buffer too small");
    std::memcpy(bytes, data.data(), data.size());
    return fmi2OK;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], size_t size,
                                   fmi2FMUstate* state) {
    ENTRY("fmi2DeSerializeFMUstate", Phase::instantiated, Phase::initialization, Phase::step_complete,
          Phase::terminated, Phase::error);
    if (!bytes || !state) return fail(inst, "fmi2DeSerializeFMUstate", "null pointer");
    Snapshot parsed;
    std::string why;
    if (!deserialize(bytes, size, parsed, why))
        return fail(inst, "fmi2DeSerializeFMUstate", "rejected: " + why);
    Snapshot* s = *state ? static_cast<Snapshot*>(*state) : new (std::nothrow) Snapshot;
    if (!s) return fail(inst, "fmi2DeSerializeFMUstate", "out of memory");
    *s = parsed;
    *state = s;
    return fmi2OK;
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2ValueReference[], size_t, const fmi2Real[], fmi2Real[]) {
    ENTRY("fmi2GetDirectionalDerivative", Phase::initialization, Phase::step_complete);
    return fail(inst, "fmi2GetDirectionalDerivative", "not provided (see modelDescription)");
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    ENTRY("fmi2SetRealInputDerivatives", Phase::instantiated, Phase::initialization, Phase::step_complete);
    if (n > 0 && (!vr || !order || !value)) return fail(inst, "fmi2SetRealInputDerivatives", "null array");
    for (size_t i = 0; i < n; ++i) {
        const companion::Variable* v = variable(vr[i]);
        if (!v || v->causality != Causality::input)
            return fail(inst, "fmi2SetRealInputDerivatives",
                        "value reference " + std::to_string(vr[i]) + " is not an input");
        if (order[i] != 1 || !std::isfinite(value[i]))
            return fail(inst, "fmi2SetRealInputDerivatives", "only finite first derivatives are supported");
    }
    for (size_t i = 0; i < n; ++i) inst->s.rates[vr[i]] = value[i];
    return fmi2OK;
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2Integer[], fmi2Real[]) {
    ENTRY("fmi2GetRealOutputDerivatives", Phase::step_complete, Phase::terminated, Phase::error);
    return fail(inst, "fmi2GetRealOutputDerivatives", "maxOutputDerivativeOrder is 0");
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean) {
    ENTRY("fmi2DoStep", Phase::step_complete);
    if (!(h > 0) || !std::isfinite(h))
        return fail(inst, "fmi2DoStep", "communicationStepSize must be > 0 and finite");
    if (!(std::abs(t - inst->s.time) <= 1e-9 * std::max(1.0, std::abs(t)) + 1e-12))
        return fail(inst, "fmi2DoStep",
                    "currentCommunicationPoint " + std::to_string(t) + " does not match the FMU's time " +
                        std::to_string(inst->s.time));
    if (h / model().internal_step > 1e9) return fail(inst, "fmi2DoStep", "step too large");
    Snapshot& saved = inst->work.saved;
    saved = inst->s;
    if (!integrate(inst->s, h, inst->work)) {
        inst->s = saved;
        inst->s.phase = Phase::error;
        return fail(inst, "fmi2DoStep",
                    "the state became non-finite; state restored to t = " + std::to_string(saved.time));
    }
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c) {
    ENTRY("fmi2CancelStep", Phase::step_complete);
    return fail(inst, "fmi2CancelStep", "doStep is synchronous");
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind, fmi2Status*) {
    ENTRY("fmi2GetStatus", Phase::step_complete, Phase::terminated, Phase::error);
    return fmi2Discard;
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Real* value) {
    ENTRY("fmi2GetRealStatus", Phase::step_complete, Phase::terminated, Phase::error);
    if (kind != fmi2LastSuccessfulTime || !value) return fmi2Discard;
    *value = inst->s.time;
    return fmi2OK;
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind, fmi2Integer*) {
    ENTRY("fmi2GetIntegerStatus", Phase::step_complete, Phase::terminated, Phase::error);
    return fmi2Discard;
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Boolean* value) {
    ENTRY("fmi2GetBooleanStatus", Phase::step_complete, Phase::terminated, Phase::error);
    if (kind != fmi2Terminated || !value) return fmi2Discard;
    *value = fmi2False;
    return fmi2OK;
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind, fmi2String*) {
    ENTRY("fmi2GetStringStatus", Phase::step_complete, Phase::terminated, Phase::error);
    return fmi2Discard;
}

}  // extern "C"
