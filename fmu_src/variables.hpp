// The FMU's variables, declared once (docs/variables.md is generated from them). The FMI layer reads and writes through this
// table and generate_model_description writes modelDescription.xml from it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "simulation/simulation.hpp"

namespace contactbody::fmu {

// The body dimension of this binary's model: 2 for ContactBody (plane strain: forces in N/m,
// energies in J/m), 3 for ContactBody3D (N, J). fmu_src/ is compiled once per model
// (cmake/fmu_binaries.cmake); both read this one table, whose rows and units follow it.
#ifndef CONTACTBODY_MODEL_DIMENSION
#define CONTACTBODY_MODEL_DIMENSION 2
#endif
constexpr int model_dimension = CONTACTBODY_MODEL_DIMENSION;
static_assert(model_dimension == 2 || model_dimension == 3, "CONTACTBODY_MODEL_DIMENSION is 2 or 3");
constexpr bool solid_model = model_dimension == 3;
constexpr const char* model_identifier = solid_model ? "ContactBody3D" : "ContactBody";
constexpr const char* guid =
    solid_model ? "{b1d7e3a4-6c2f-4e9a-8b05-3f7a9c1d2e68}" : "{6f1c2a8e-4b7d-4e21-9c3a-5d8e0b7f2c41}";
// What a value of the 2D model's body, per metre of thickness, is for the 3D model's.
constexpr const char* per_body(const char* planar, const char* solid) { return solid_model ? solid : planar; }
// The 3D model's default body, in its FMU's resources folder (the rectangle is 2D).
constexpr const char* solid_default_mesh = "block.msh";
constexpr int solid_default_mesh_contact_nodes = 49;

// Everything the variables read and write, as plain data.
struct Values {
    std::string mesh;  // empty: the rectangle; else a Gmsh file (resources/-relative or absolute)
    double width, height, density, lambda, mu, friction_coefficient;
    int nx, ny, mass_matrix;
    int edge_nodes;  // contact nodes (the rectangle's nx + 1): the size of the FMI 3.0 edge arrays
    double internal_step, contact_tolerance, initial_gap;
    double damping_mass, damping_stiffness, min_internal_step;
    double tolerance;  // 0: fixed substeps
    int input_interpolation;  // InputInterpolation
    int top_control;          // TopControl
    int initial_state;        // InitialState
    double top_mass;
    PerComponent initial_velocity;  // initial_velocity_x, _y and (the 3D model's) the z one
    double static_friction_ratio;
    double stribeck_velocity, viscous_friction;
    double max_energy, max_energy_ratio;
    int modes;                     // 0: the full body
    int reduced_edge;              // ReducedEdge
    int baseline_kernels;          // 0 or 1
    int threads;                   // of a supernodal factor, >= 1
    std::string result_directory;  // field output; empty = none
    double field_output_interval;
    double edge_output_interval;     // 0: no edge history
    Tangential foundation_velocity;  // foundation_velocity and (the 3D model's) the z one
    double top_displacement, top_force;
    Observables out;

    SceneParameters scene() const;
};

enum class Type { Real, Integer, Enumeration, String };
enum class Causality { parameter, input, output };
enum class Variability { fixed, tunable, continuous, discrete };
// Which FMUs declare a variable: both, or only the FMI 3.0 one (the contact-edge arrays and
// the structural parameter that sizes them).
enum class Standard : unsigned { fmi2 = 1, fmi3 = 2, both = 3 };

// The inputs, in the order of StepInputs' values (Variable::input).
// (foundation_velocity_z: the 3D model's only; the 2D model's stays 0.)
enum class Input : int {
    none = -1,
    foundation_velocity = 0,
    top_displacement = 1,
    top_force = 2,
    foundation_velocity_z = 3
};
constexpr int num_inputs = 4;

// One variable, declared once in variables.cpp's table with the builders there (real,
// integer, enumeration, string, output, edge_output and the as_... modifiers). Everything else
// follows from it: the modelDescriptions, docs/variables.md, get/set and range checks, the
// saved state (every non-array variable, in table order), the SceneParameters it sets (by
// name: SceneParameters::for_each), the output it reads (by name: Observables::for_each).
struct Variable {
    const char* name;
    unsigned value_reference;
    Type type;
    Causality causality;
    Variability variability;
    const char* unit;  // "" for none
    const char* description;
    double start;     // for parameters and inputs (String variables: string_start)
    double min, max;  // inclusive limits written to the XML; NaN for none
    // Exactly one of real / integer / string is set, by type (none for the arrays).
    std::function<double&(Values&)> real;
    std::function<int&(Values&)> integer;
    std::function<std::string&(Values&)> string;
    const char* enumeration = nullptr;  // the EnumerationType's name, for Enumeration variables
    // FMI 3.0: causality structuralParameter, type UInt64 (FMI 2.0: an Integer parameter).
    bool structural = false;
    Standard standard = Standard::both;
    const char* string_start = "";
    // The model that declares it: 0 both, 2 ContactBody only, 3 ContactBody3D only.
    int dimension = 0;
    // FMI 3.0 arrays along the contact edge, edge_nodes values each: a field of the edge
    // snapshot (Float64), or its contact states (edge_state: an Enumeration array).
    const Eigen::VectorXd& (*edge_real)(const EdgeSnapshot&) = nullptr;
    bool edge_state = false;
    Input input = Input::none;
    // A parameter that no SceneParameters field takes (it configures the FMU layer).
    bool fmu_only = false;
    // A tunable parameter: how a running simulation takes a new value.
    void (*tune)(Simulation&, double) = nullptr;
    // What else changes with this variable (nx and mesh set edge_nodes), given the FMU's
    // resources folder (a mesh's relative path is taken from there).
    void (*after_set)(Values&, const std::string& resources) = nullptr;

    bool settable_after_initialization() const {
        return causality == Causality::input || variability == Variability::tunable;
    }
    bool in(Standard s) const { return static_cast<unsigned>(standard) & static_cast<unsigned>(s); }
    bool is_array() const { return edge_real || edge_state; }

    // Modifiers for the table's rows.
    Variable& as_input(Input slot);
    Variable& as_tunable(void (*apply)(Simulation&, double));
    Variable& as_structural(Standard in);
    Variable& as_fmu_only();
    Variable& as_discrete();
    Variable& then(void (*follow)(Values&, const std::string& resources));
    Variable& only_in(int model_dimension);
    Variable& starting_at(const char* text);
};

// This model's variables (rows of its dimension), in table order.
const std::vector<Variable>& variables();
// Every row of both models (the table's checks run on them).
const std::vector<Variable>& all_model_variables();
// The file `mesh` names: as it is where absolute (/..., \\server\..., C:/... or C:\...), else
// in the FMU's resources folder; "" (the rectangle) stays "".
std::string mesh_path(const std::string& mesh, const std::string& resources);
// The table's consistency, checked when it is built: value references unique, every parameter
// reaching a SceneParameters field or declared FMU-only, and with every_field (the rows of both
// models) every SceneParameters field set by a parameter, every Observables field an output.
// Throws std::logic_error naming what is wrong.
void check_variable_table(const std::vector<Variable>& rows, bool every_field = true);
// Throws std::invalid_argument naming the variable if value is not finite or out of range.
void check_range(const Variable& v, double value);
// Longest accepted String value (bytes).
constexpr size_t max_string_length = 4096;
// Throws std::invalid_argument naming the variable if value is NULL, too long or not printable.
void check_string(const Variable& v, const char* value);

// The input's index in StepInputs' order, -1 for other variables.
inline int input_index(const Variable& v) { return static_cast<int>(v.input); }

// The variable's FMI 3.0 type: Float64, Int32, UInt64 (structural parameters), Int64
// (enumerations, as FMI 3.0 accesses them) or String.
const char* fmi3_type(const Variable& v);
// FMI 3.0's independent variable, which the variable table leaves to the layers.
constexpr unsigned time_value_reference = 0;

// nullptr when no variable of this standard has this reference.
const Variable* find_variable(unsigned value_reference, Standard standard);
// nullptr when no variable has this name.
const Variable* find_variable(const std::string& name);
// Values with every start value.
Values start_values();

// How held inputs enter a step: at their value (FMI 2.0 without derivatives), or ramped from
// the value at the previous communication point (one step of delay, no jumps).
enum class InputInterpolation : int { hold = 0, ramp = 1 };
// The top edge: clamped to top_displacement, or a rigid plate pushed by top_force.
enum class TopControl : int { displacement = 0, force = 1 };
// The initial displacement: the paper's linear profile, or the static equilibrium.
enum class InitialState : int { paper = 0, static_equilibrium = 1 };
// A contact node's state in the last substep (EdgeSnapshot::state, the edge_state array).
enum class ContactState : int { open = 0, stick = 1, slip = 2 };

// The enumeration types: XML name and item names in value order. Each Enumeration variable
// names its type (Variable::enumeration).
struct EnumerationType {
    const char* name;
    std::vector<std::string> items;
};
const std::vector<EnumerationType>& enumeration_types();
const EnumerationType& enumeration_type(const Variable& v);
// Log categories, in the order of the XML.
const std::vector<std::string>& log_categories();

}  // namespace contactbody::fmu
