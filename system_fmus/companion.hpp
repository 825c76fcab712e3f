// The companion FMUs of examples/system (BeltDrive, Press): small ODE models behind one
// generic FMI 2.0 co-simulation layer (companion_fmi2.cpp). A model is data: its variable
// table, its states and three functions; the layer integrates the states with classic RK4
// at a fixed internal step and does the rest (state machine, checks, FMU state).
#pragma once

#include <algorithm>
#include <vector>

namespace companion {

enum class Causality { parameter, input, output };

struct Variable {
    const char* name;
    unsigned value_reference;  // also the index into the values array
    Causality causality;
    double start;
    const char* unit;
    const char* description;
    bool positive = false;  // a parameter that must be > 0
};

struct Model {
    const char* name;
    const char* guid;
    const char* description;
    std::vector<Variable> variables;  // value_reference == position
    int num_states;
    double internal_step;  // s: RK4 step inside doStep (the last one shortened)
    // x(t0) from the parameters
    void (*initial_states)(const double* values, double* x);
    // dx/dt at time t; values holds the parameters and the inputs at t
    void (*derivatives)(const double* values, const double* x, double t, double* dx);
    // the outputs from the states at time t
    void (*outputs)(double* values, const double* x, double t);
};

const Model& model();  // defined by each model's file

// A load ramped linearly from 0 at t = 0 to 1 at ramp_time, then held (ramp_time 0: a step).
inline double ramp(double t, double ramp_time) { return ramp_time > 0 ? std::min(1.0, t / ramp_time) : 1.0; }

}  // namespace companion
