// The ContactBody model as an ordinary C++ class: values by variable, the simulation, and
// errors as exceptions (the FMI shim in fmi2_functions.cpp turns them into fmi2Status).
#pragma once

#include <memory>
#include <stdexcept>

#include "variables.hpp"

namespace contactbody::fmu {

// Bad input or call: fmi2Error.
struct ModelError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// A step that cannot be completed (the state stays at the step's start): fmi2Discard.
struct StepDiscarded : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class ContactBodyModel {
public:
    ContactBodyModel() : values_(start_values()) {}

    void reset();
    void set_start_time(double t);
    // `initialized` is true after fmi2ExitInitializationMode: only inputs and tunable
    // parameters may then change.
    void set_real(const Variable& v, double value, bool initialized);
    void set_integer(const Variable& v, int value, bool initialized);
    double get_real(const Variable& v);
    int get_integer(const Variable& v);

    // Builds the simulation from the parameters if they changed (throws ModelError).
    void initialize();
    void do_step(double current_time, double step_size);
    double time() const;
    Simulation* simulation() { return sim_.get(); }

private:
    void check_value(const Variable& v, double value, bool initialized) const;
    void refresh_outputs();

    Values values_;
    std::unique_ptr<Simulation> sim_;
    bool rebuild_ = true;
    double start_time_ = 0;
};

}  // namespace contactbody::fmu
