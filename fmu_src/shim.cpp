#include "shim.hpp"

#include <cstring>
#include <memory>

#include "util/text.hpp"

namespace contactbody::fmu {

namespace {

FmuState* known_state(Instance* instance, void* s) {
    auto* state = static_cast<FmuState*>(s);
    if (!instance->states.count(state))
        throw ModelError("FMU state was not made by this instance, or was freed");
    return state;
}

}  // namespace

void log_warnings(Instance* instance, const char* function, Simulation& sim) {
    for (const std::string& warning : sim.take_warnings())
        instance->log(Status::warning, LogCategory::warning, std::string(function) + ": " + warning);
}

void log_step(Instance* instance, const char* function, Simulation& sim) {
    log_warnings(instance, function, sim);
    const int factorizations = sim.body().factorizations();
    if (factorizations != instance->factorizations_logged) {
        instance->factorizations_logged = factorizations;
        instance->log(
            Status::ok, LogCategory::events,
            std::string(sim.body().operator_name()) + " (operator " + std::to_string(factorizations) + ")");
    }
    const StepStatistics& s = sim.statistics();
    if (s.declined_growths > 0) {
        Text msg;
        msg << "step to t = " << sim.time() << ": " << s.declined_growths
            << " pairs of substeps kept their span where the estimate allowed doubling it: the doubled "
               "span's step operator costs about "
            << s.new_operator_solves << " solves, more than the declined doublings have saved so far";
        instance->log(Status::ok, LogCategory::events, msg.str());
    }
    if (s.refinements > 0) {
        Text msg;
        msg << "step to t = " << sim.time() << ": " << s.refinements
            << (sim.body().parameters().tolerance > 0
                    ? " pairs of substeps redone at half their span, their estimate above tolerance or "
                      "a contact solve failed (smallest substep "
                    : " substeps redone as halves after a failed contact solve (smallest substep ")
            << s.smallest_substep << " s)";
        instance->log(Status::ok, LogCategory::events, msg.str());
    }
    instance->log(Status::ok, LogCategory::contact_solver,
                  "substeps " + std::to_string(s.substeps) + ", contact solves " +
                      std::to_string(s.contact_solves) + ", Newton iterations " +
                      std::to_string(s.contact_iterations) + " (max " +
                      std::to_string(s.max_contact_iterations) +
                      " in one substep), Gauss-Seidel "
                      "sweeps " +
                      std::to_string(s.gauss_seidel_sweeps));
}

void log_initialized(Instance* instance, const char* function) {
    Simulation& sim = *instance->model.simulation();
    // Factorizations are counted over the discretization's life (it outlives a reset): the
    // steps log the ones they make.
    instance->factorizations_logged = sim.body().factorizations();
    if (std::string summary = sim.body().summary(); !summary.empty())
        instance->log(Status::ok, LogCategory::events, summary);
    for (const std::string& note : sim.body().discretization().mesh_notes)
        instance->log(Status::ok, LogCategory::events, note);
    instance->log(Status::ok, LogCategory::events, "initialized");
    log_warnings(instance, function, sim);
}

int get_fmu_state(Instance* instance, const char* function, void** state) {
    return guarded(instance, function, [&] {
        FmuState* target = static_cast<FmuState*>(*state);
        if (target && !instance->states.count(target))
            throw ModelError("*FMUState is not a state of this instance (pass NULL for a new one)");
        FmuState saved{instance->state, instance->last_successful_time, instance->model.save()};
        if (target) {
            *target = std::move(saved);  // overwrite, as both standards ask for a non-NULL state
        } else {
            auto fresh = std::make_unique<FmuState>(std::move(saved));
            instance->states.insert(fresh.get());
            *state = fresh.release();
        }
        return Status::ok;
    });
}

int set_fmu_state(Instance* instance, const char* function, void* state) {
    return guarded(instance, function, [&] {
        const FmuState* s = known_state(instance, state);
        instance->model.load(s->model);
        instance->state = static_cast<FmiState>(s->instance_state);
        instance->last_successful_time = s->last_successful_time;
        return Status::ok;
    });
}

int free_fmu_state(Instance* instance, const char* function, void** state) {
    if (!*state) return Status::ok;
    return guarded(instance, function, [&] {
        FmuState* s = known_state(instance, *state);
        instance->states.erase(s);
        delete s;
        *state = nullptr;
        return Status::ok;
    });
}

int serialized_fmu_state_size(Instance* instance, const char* function, void* state, size_t* size) {
    return guarded(instance, function, [&] {
        *size = serialize(*known_state(instance, state)).size();
        return Status::ok;
    });
}

int serialize_fmu_state(Instance* instance, const char* function, void* state, char bytes[], size_t size) {
    return guarded(instance, function, [&] {
        const std::vector<char> data = serialize(*known_state(instance, state));
        if (size != data.size())
            throw ModelError("size is " + std::to_string(size) + ", the state needs " +
                             std::to_string(data.size()) + " (the serialized state size)");
        std::memcpy(bytes, data.data(), data.size());
        return Status::ok;
    });
}

int deserialize_fmu_state(Instance* instance, const char* function, const char bytes[], size_t size,
                          void** state) {
    return guarded(instance, function, [&] {
        FmuState parsed = deserialize(bytes, size);
        if (*state) {  // reuse the given state, as both standards allow
            *known_state(instance, *state) = std::move(parsed);
            return Status::ok;
        }
        auto fresh = std::make_unique<FmuState>(std::move(parsed));
        instance->states.insert(fresh.get());
        *state = fresh.release();
        return Status::ok;
    });
}

}  // namespace contactbody::fmu
