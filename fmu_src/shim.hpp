// What the FMI 2.0 and FMI 3.0 layers share: the model's exceptions turned into a status and
// a message naming the function, the step's log messages, and the FMU state functions. Both
// standards number their status codes alike (fmu::Status), and their FMU states are both
// opaque pointers to an FmuState, serialized to the same bytes.
#pragma once

#include <cstddef>
#include <new>

#include "instance.hpp"

namespace contactbody::fmu {

// Runs body (which returns a Status) and turns the model's exceptions into Status::error, logged
// with the function's name. A failed step leaves the instance in Error at the step's start
// (fmiXSetFMUState may go on); anything unexpected leaves it in Error too.
template <class Body>
int guarded(Instance* instance, const char* function, Body&& body) {
    try {
        return body();
    } catch (const StepError& e) {
        instance->error(function, e.what());
        instance->state = Error;
        return Status::error;
    } catch (const ModelError& e) {
        instance->error(function, e.what());
        return Status::error;
    } catch (const std::bad_alloc&) {
        instance->error(function, "out of memory");
    } catch (const std::exception& e) {
        instance->error(function, e.what());
    } catch (...) {
        instance->error(function, "unknown failure");
    }
    instance->state = Error;
    return Status::error;
}

// The simulation's warnings (docs/contract.md, "Warnings"), each once, as logStatusWarning.
void log_warnings(Instance* instance, const char* function, Simulation& sim);
// After a step: its warnings, events (a new factorization, refined substeps) and the contact
// solver's statistics.
void log_step(Instance* instance, const char* function, Simulation& sim);
// After initialization: the events and warnings of the initial state.
void log_initialized(Instance* instance, const char* function);

// The FMU state functions, with their names for the messages. `state` is the standard's
// opaque FMU state pointer.
int get_fmu_state(Instance* instance, const char* function, void** state);
int set_fmu_state(Instance* instance, const char* function, void* state);
int free_fmu_state(Instance* instance, const char* function, void** state);
int serialized_fmu_state_size(Instance* instance, const char* function, void* state, size_t* size);
int serialize_fmu_state(Instance* instance, const char* function, void* state, char bytes[], size_t size);
int deserialize_fmu_state(Instance* instance, const char* function, const char bytes[], size_t size,
                          void** state);

}  // namespace contactbody::fmu
