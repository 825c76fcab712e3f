// The ContactBody model as an ordinary C++ class: values by variable, the simulation, and
// errors as exceptions (the FMI shim in fmi2_functions.cpp turns them into fmi2Status).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "errors.hpp"
#include "output/edge_output.hpp"
#include "output/field_output.hpp"
#include "variables.hpp"

namespace contactbody::fmu {

// The model's whole state as plain data (fmi2GetFMUstate / fmi2SetFMUstate).
struct ModelState {
    Values values;
    double start_time = 0;
    std::array<double, num_inputs> input_rates{};      // d/dt of each input (input_index order)
    std::array<double, num_inputs> previous_inputs{};  // at the last communication point
    bool has_simulation = false;
    SimulationSnapshot simulation;
    // Field output so far: the times of the files written, and the index k of the next
    // output time start_time + k * field_output_interval.
    std::vector<double> field_output_times;
    uint64_t next_field_output = 0;
    // Edge history so far: records written, and the index of the next output time.
    uint64_t edge_rows = 0;
    uint64_t next_edge_output = 0;
};

class ContactBodyModel {
public:
    ContactBodyModel() : values_(start_values()), defaults_(values_) {}

    // Start values of this copy of the FMU (resources/start_values.txt: name, value as text),
    // which fmi2Reset returns to. Throws ModelError naming a bad name or value.
    void set_defaults(const std::vector<std::pair<std::string, std::string>>& values);
    void reset();
    // The FMU's resources folder (a relative mesh path is taken from it; "" if the importer
    // gave none) and whether the instance has the edge arrays (FMI 3.0), which then hold
    // edge_nodes values: a mesh's contact nodes must be that many. Without the arrays
    // (FMI 2.0) edge_nodes takes the mesh's count.
    void set_resources(std::string folder, bool edge_arrays);
    void set_start_time(double t);
    // `initialized` is true after fmi2ExitInitializationMode: only inputs and tunable
    // parameters may then change.
    void set_real(const Variable& v, double value, bool initialized);
    void set_integer(const Variable& v, int value, bool initialized);
    void set_string(const Variable& v, const char* value, bool initialized);
    double get_real(const Variable& v);
    // Values a variable holds: edge_nodes for the contact-edge arrays (FMI 3.0), else 1.
    size_t size(const Variable& v) const;
    // A contact-edge array's size(v) values: the Float64 fields, or the states (edge_state).
    void get_edge(const Variable& v, double* out);
    void get_edge(const Variable& v, int64_t* out);
    int get_integer(const Variable& v);
    const char* get_string(const Variable& v);

    // First time derivative of an input over the next steps (canInterpolateInputs); setting
    // the input's value again resets it to zero (held input).
    void set_input_derivative(const Variable& v, int order, double value);

    ModelState save() const;
    // Restores a saved state; refuses one saved with other fixed parameters (another mesh).
    void load(const ModelState& state);

    // Throws ModelError unless edge_nodes = nx + 1 (the FMI 3.0 arrays' size) for the
    // rectangle (a mesh's count is known once it is read, at initialization).
    void check_structure() const;
    // Builds the simulation from the parameters if they changed (throws ModelError).
    void initialize();
    void do_step(double current_time, double step_size);
    double time() const;
    Simulation* simulation() { return rebuild_ ? nullptr : sim_.get(); }

private:
    void check_writable(const Variable& v, bool initialized) const;
    void check_settable(const Variable& v, double value, bool initialized) const;
    void refresh_outputs();
    std::array<double, num_inputs> current_inputs() const;
    void build_simulation(const Values& values);
    void open_field_output();
    void write_due_fields();
    // Records due at this communication point (the edge history): true if one was written.
    void write_due_edge();

    Values values_;
    Values defaults_;  // the start values (the table's, or this copy's resources')
    std::array<double, num_inputs> input_rates_{};
    std::array<double, num_inputs> previous_inputs_{};  // where input_interpolation = ramp starts
    std::unique_ptr<Simulation> sim_;
    std::unique_ptr<FieldWriter> fields_;  // present while result_directory is set
    State field_state_;                    // the reduced body's state expanded for field output
    uint64_t next_field_output_ = 0;
    std::unique_ptr<EdgeWriter> edge_;  // present while edge_output_interval > 0
    uint64_t next_edge_output_ = 0;
    bool rebuild_ = true;
    double start_time_ = 0;
    std::string resources_;
    bool edge_arrays_ = false;
};

}  // namespace contactbody::fmu
