#include "variables.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace contactbody::fmu {

namespace {

constexpr double none = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

// Argument order of Variable after the description: start, min, max, accessors. FMI limits are
// inclusive: where a value must be > 0, min is the smallest meaningful positive value.
#define ACCESS_REAL(field) [](Values& v) -> double& { return v.field; }, nullptr
#define ACCESS_INT(field) nullptr, [](Values& v) -> int& { return v.field; }
#define ACCESS_STRING(field) nullptr, nullptr, [](Values& v) -> std::string& { return v.field; }
#define ACCESS_ENUM(field, type) \
    nullptr, [](Values& v) -> int& { return v.field; }, nullptr, type
// FMI 3.0 structural parameters (UInt64), in both FMUs or in the FMI 3.0 one only.
#define ACCESS_STRUCTURAL(field, standard) \
    nullptr, [](Values& v) -> int& { return v.field; }, nullptr, nullptr, true, standard
// FMI 3.0 outputs along the contact edge.
#define ACCESS_EDGE(field) \
    nullptr, nullptr, nullptr, nullptr, false, Standard::fmi3, \
        [](const EdgeSnapshot& e) -> const Eigen::VectorXd& { return e.field; }
#define ACCESS_EDGE_STATE \
    nullptr, nullptr, nullptr, "ContactState", false, Standard::fmi3, nullptr, true

using T = Type;
using C = Causality;
using V = Variability;

const std::vector<Variable> table = {
    // Parameters (docs/variables.md lists them)
    {"width", 1, T::Real, C::parameter, V::fixed, "m", "Width W of the body", 0.1, 1e-6, inf, ACCESS_REAL(width)},
    {"height", 2, T::Real, C::parameter, V::fixed, "m", "Height H of the body", 0.1, 1e-6, inf, ACCESS_REAL(height)},
    {"nx", 3, T::Integer, C::parameter, V::fixed, "", "Cells along x", 20, 1, max_cells_per_direction, ACCESS_STRUCTURAL(nx, Standard::both)},
    {"ny", 4, T::Integer, C::parameter, V::fixed, "", "Cells along y", 20, 1, max_cells_per_direction, ACCESS_STRUCTURAL(ny, Standard::both)},
    {"edge_nodes", 31, T::Integer, C::parameter, V::fixed, "", "Bottom nodes on the contact edge, the size of the edge arrays: always nx + 1 (setting nx sets it; another value is refused when Configuration Mode ends and at initialization)", 21, 2, max_cells_per_direction + 1, ACCESS_STRUCTURAL(edge_nodes, Standard::fmi3)},
    {"density", 5, T::Real, C::parameter, V::fixed, "kg/m3", "Density rho", 1000, 1e-3, inf, ACCESS_REAL(density)},
    {"lambda", 6, T::Real, C::parameter, V::fixed, "Pa", "First Lame coefficient (lambda + mu > 0)", 300e6, none, none, ACCESS_REAL(lambda)},
    {"mu", 7, T::Real, C::parameter, V::fixed, "Pa", "Shear modulus", 150e6, 1, inf, ACCESS_REAL(mu)},
    {"friction_coefficient", 8, T::Real, C::parameter, V::tunable, "", "Coulomb friction coefficient F", 1.2, 0, max_friction_coefficient, ACCESS_REAL(friction_coefficient)},
    {"mass_matrix", 9, T::Enumeration, C::parameter, V::fixed, "", "Mass matrix and contact treatment: 0 standard, 1 redistributed_normal (the paper), 2 redistributed_both, 3 standard_implicit_contact, 4 redistributed_implicit_contact (M_r, contact at the end of the step: cannot gain energy at contact)", 1, 0, num_mass_variants - 1, ACCESS_ENUM(mass_matrix, "MassMatrix")},
    {"internal_step", 10, T::Real, C::parameter, V::fixed, "s", "Largest midpoint substep", 4e-6, 1e-12, inf, ACCESS_REAL(internal_step)},
    {"contact_tolerance", 11, T::Real, C::parameter, V::fixed, "", "Relative tolerance of each substep's contact solve (at least the resolution of a double, 2.2e-16)", 1e-10, std::numeric_limits<double>::epsilon(), 0.5, ACCESS_REAL(contact_tolerance)},
    {"initial_gap", 12, T::Real, C::parameter, V::fixed, "m", "Initial gap between the body and the foundation", 0, 0, inf, ACCESS_REAL(initial_gap)},
    {"result_directory", 13, T::String, C::parameter, V::fixed, "", "Directory for field output (.vtu files and a .pvd collection); empty = none", 0, none, none, ACCESS_STRING(result_directory)},
    {"field_output_interval", 14, T::Real, C::parameter, V::fixed, "s", "Time between field output files (written at the first communication point at or after each multiple)", 1e-4, 1e-9, inf, ACCESS_REAL(field_output_interval)},
    {"edge_output_interval", 28, T::Real, C::parameter, V::fixed, "s", "Time between the records of the edge history (result_directory/contactbody_edge.npy: per bottom node and output time, the step-averaged contact pressure and friction density, slip velocity, gap and state); 0 = none", 0, 0, inf, ACCESS_REAL(edge_output_interval)},
    {"damping_mass", 15, T::Real, C::parameter, V::fixed, "1/s", "Rayleigh damping: alpha of C = alpha M + beta A (M: the variant's mass matrix)", 0, 0, inf, ACCESS_REAL(damping_mass)},
    {"damping_stiffness", 16, T::Real, C::parameter, V::fixed, "s", "Rayleigh damping: beta of C = alpha M + beta A", 0, 0, inf, ACCESS_REAL(damping_stiffness)},
    {"min_internal_step", 17, T::Real, C::parameter, V::fixed, "s", "Smallest substep: a substep whose contact solve fails is redone as two halves, recursively, down to this size (at most 20 halvings)", 1e-9, 1e-15, inf, ACCESS_REAL(min_internal_step)},
    {"input_interpolation", 18, T::Enumeration, C::parameter, V::fixed, "", "How an input set without a derivative enters the step: hold (its value, FMI 2.0) or ramp (linearly from its value at the previous communication point: one step of delay, no jumps)", 0, 0, 1, ACCESS_ENUM(input_interpolation, "InputInterpolation")},
    {"top_control", 19, T::Enumeration, C::parameter, V::fixed, "", "Top edge: displacement (clamped to the input top_displacement) or force (a rigid plate of mass top_mass with u_x = 0, pushed down by the input top_force; top_displacement then only sets the initial position)", 0, 0, 1, ACCESS_ENUM(top_control, "TopControl")},
    {"top_mass", 23, T::Real, C::parameter, V::fixed, "kg/m", "Mass of the top plate (top_control = force)", 1.0, 1e-9, inf, ACCESS_REAL(top_mass)},
    {"initial_velocity_x", 24, T::Real, C::parameter, V::fixed, "m/s", "Uniform initial velocity of the body, x (the clamped dofs excepted)", 0, none, none, ACCESS_REAL(initial_velocity_x)},
    {"initial_velocity_y", 25, T::Real, C::parameter, V::fixed, "m/s", "Uniform initial velocity of the body, y (with the plate under force control)", 0, none, none, ACCESS_REAL(initial_velocity_y)},
    {"initial_state", 26, T::Enumeration, C::parameter, V::fixed, "", "Initial displacement: paper (u_y = top_displacement y / H, not an equilibrium: a free vibration follows) or static (the static equilibrium under the initial top_displacement, or under top_force > 0 with top_control = force, with the foundation at rest, reached by a quasi-static frictional load path)", 0, 0, 1, ACCESS_ENUM(initial_state, "InitialState")},
    {"max_energy", 29, T::Real, C::parameter, V::fixed, "J/m", "Blow-up guard: a step that ends with the energy E above this fails with an error status, naming the time, E, the works and the likely cause; 0 = no absolute limit", 0, 0, inf, ACCESS_REAL(max_energy)},
    {"max_energy_ratio", 30, T::Real, C::parameter, V::fixed, "", "Blow-up guard: a step that ends with E above max_energy_ratio x (E(0) + |clamp_work| + |foundation_work|) fails with an error status, naming the time, E, the works and the likely cause; 0 = off. The default 1e6 is 4x above the largest growth in the paper's Figs. 7-8 (2.3e5: variant 0, F = 1.2, internal_step 1e-6 s)", 1e6, 0, inf, ACCESS_REAL(max_energy_ratio)},
    {"static_friction_ratio", 27, T::Real, C::parameter, V::fixed, "", "Static over kinetic friction: a node that stuck in the last substep breaks loose only at static_friction_ratio x F x pressure; a slipping node feels F (1 = Coulomb's law; above 1 the friction drops at the onset of slip, which gives stick-slip; at most 10)", 1, 1, max_static_friction_ratio, ACCESS_REAL(static_friction_ratio)},
    {"stribeck_velocity", 32, T::Real, C::parameter, V::fixed, "m/s", "Slip-rate law: F(v) = F_d + (F_s - F_d) exp(-|v| / stribeck_velocity) + viscous_friction |v| with F_d = friction_coefficient, F_s = static_friction_ratio x F_d and v the scheme's slip rate, taken implicitly in the step; 0 = no Stribeck term (F_s is then the stick memory of static_friction_ratio)", 0, 0, inf, ACCESS_REAL(stribeck_velocity)},
    {"viscous_friction", 33, T::Real, C::parameter, V::fixed, "s/m", "Slip-rate law: the viscous term c_v |v| of F(v) (see stribeck_velocity); 0 = none", 0, 0, max_viscous_friction, ACCESS_REAL(viscous_friction)},
    // Inputs
    {"foundation_velocity", 20, T::Real, C::input, V::continuous, "m/s", "Horizontal velocity V of the rigid foundation", 20, none, none, ACCESS_REAL(foundation_velocity)},
    {"top_displacement", 21, T::Real, C::input, V::continuous, "m", "Prescribed vertical displacement of the top edge", -2.5e-5, none, none, ACCESS_REAL(top_displacement)},
    {"top_force", 22, T::Real, C::input, V::continuous, "N/m", "Force pressing the top plate down (top_control = force), positive downwards", 0, none, none, ACCESS_REAL(top_force)},
    // Outputs
    {"energy", 100, T::Real, C::output, V::continuous, "J/m", "Total energy E = kinetic + strain (paper eq. 19, with the variant's mass matrix; the plate's kinetic energy under force control), per metre of thickness, at the end of the step", none, none, none, ACCESS_REAL(out.energy)},
    {"kinetic_energy", 101, T::Real, C::output, V::continuous, "J/m", "Kinetic part of E", none, none, none, ACCESS_REAL(out.kinetic_energy)},
    {"strain_energy", 102, T::Real, C::output, V::continuous, "J/m", "Strain part of E", none, none, none, ACCESS_REAL(out.strain_energy)},
    {"friction_work", 103, T::Real, C::output, V::continuous, "J/m", "Work xi of friction on the body since the start", none, none, none, ACCESS_REAL(out.friction_work)},
    {"energy_minus_friction_work", 104, T::Real, C::output, V::continuous, "J/m", "E - xi (paper Fig. 8)", none, none, none, ACCESS_REAL(out.energy_minus_friction_work)},
    {"normal_force", 105, T::Real, C::output, V::continuous, "N/m", "Total normal contact force on the body, a magnitude (>= 0): the average over the last communication step of its substeps' forces", none, none, none, ACCESS_REAL(out.normal_force)},
    {"friction_force", 106, T::Real, C::output, V::continuous, "N/m", "Total friction force on the body, signed x component (> 0: the foundation drags the body towards +x): the average over the last communication step", none, none, none, ACCESS_REAL(out.friction_force)},
    {"corner_pressure", 107, T::Real, C::output, V::continuous, "Pa", "Contact pressure at node (0,0), averaged over the last step", none, none, none, ACCESS_REAL(out.corner_pressure)},
    {"corner_friction", 108, T::Real, C::output, V::continuous, "Pa", "Friction force density at node (0,0), averaged over the last step", none, none, none, ACCESS_REAL(out.corner_friction)},
    {"top_reaction_x", 109, T::Real, C::output, V::continuous, "N/m", "Force of the clamp (or plate) on the body, signed x component, averaged over the last communication step", none, none, none, ACCESS_REAL(out.top_reaction_x)},
    {"top_reaction_y", 110, T::Real, C::output, V::continuous, "N/m", "Force of the clamp (or plate) on the body, signed y component (< 0 while it presses the body down), averaged over the last communication step", none, none, none, ACCESS_REAL(out.top_reaction_y)},
    {"active_contact_nodes", 111, T::Integer, C::output, V::discrete, "", "Contact nodes in contact at the last substep", none, none, none, ACCESS_INT(out.active_contact_nodes)},
    {"slipping_contact_nodes", 112, T::Integer, C::output, V::discrete, "", "Contact nodes slipping at the last substep", none, none, none, ACCESS_INT(out.slipping_contact_nodes)},
    {"max_penetration", 113, T::Real, C::output, V::continuous, "m", "Largest penetration of the bottom nodes at the ends u^{k+1} of the last step's substeps. Contact is imposed at the midpoints u^{k+1/2}, so this is the scheme's overshoot between midpoints (about dt/2 x the normal velocity), not a violated contact condition", none, none, none, ACCESS_REAL(out.max_penetration)},
    {"damping_work", 114, T::Real, C::output, V::continuous, "J/m", "Energy dissipated by the Rayleigh damping since the start (>= 0)", none, none, none, ACCESS_REAL(out.damping_work)},
    {"clamp_work", 115, T::Real, C::output, V::continuous, "J/m", "Work of the clamp's reaction on the body since the start, jumps of a held top_displacement included", none, none, none, ACCESS_REAL(out.clamp_work)},
    {"normal_contact_work", 116, T::Real, C::output, V::continuous, "J/m", "Work of the normal contact forces on the body since the start", none, none, none, ACCESS_REAL(out.normal_contact_work)},
    {"friction_dissipation", 117, T::Real, C::output, V::continuous, "J/m", "Energy dissipated by friction at the interface since the start (foundation_work - friction_work)", none, none, none, ACCESS_REAL(out.friction_dissipation)},
    {"foundation_work", 118, T::Real, C::output, V::continuous, "J/m", "Work of the foundation's motion against friction since the start (what its drive pays)", none, none, none, ACCESS_REAL(out.foundation_work)},
    {"top_position", 119, T::Real, C::output, V::continuous, "m", "Vertical displacement u_y of the top edge (the plate under force control)", none, none, none, ACCESS_REAL(out.top_position)},
    {"top_velocity", 120, T::Real, C::output, V::continuous, "m/s", "Vertical velocity of the top edge", none, none, none, ACCESS_REAL(out.top_velocity)},
    {"substeps", 121, T::Integer, C::output, V::discrete, "", "Midpoint substeps taken in the last communication step (ceil(step / internal_step), plus one per refinement)", none, none, none, ACCESS_INT(out.substeps)},
    {"substep_refinements", 122, T::Integer, C::output, V::discrete, "", "Substeps of the last communication step redone as two halves after a failed contact solve", none, none, none, ACCESS_INT(out.substep_refinements)},
    {"contact_iterations", 123, T::Integer, C::output, V::discrete, "", "Semi-smooth Newton iterations of the contact solves in the last communication step, summed", none, none, none, ACCESS_INT(out.contact_iterations)},
    {"gauss_seidel_sweeps", 124, T::Integer, C::output, V::discrete, "", "Sweeps of the contact solver's Gauss-Seidel fallback in the last communication step, summed (0 when Newton always converged)", none, none, none, ACCESS_INT(out.gauss_seidel_sweeps)},
    // Outputs along the contact edge (FMI 3.0: arrays of edge_nodes values, ordered by x)
    {"edge_x", 130, T::Real, C::output, V::discrete, "m", "Position x of each bottom node (reference configuration)", none, none, none, ACCESS_EDGE(x)},
    {"edge_pressure", 131, T::Real, C::output, V::continuous, "Pa", "Contact pressure at each bottom node, averaged over the last communication step like normal_force (node shares x pressures sum to normal_force)", none, none, none, ACCESS_EDGE(pressure)},
    {"edge_friction", 132, T::Real, C::output, V::continuous, "Pa", "Friction force density at each bottom node, signed x component, averaged like friction_force (node shares x densities sum to friction_force)", none, none, none, ACCESS_EDGE(friction)},
    {"edge_slip_velocity", 133, T::Real, C::output, V::continuous, "m/s", "Velocity x of each bottom node relative to the foundation over the last substep", none, none, none, ACCESS_EDGE(slip_velocity)},
    {"edge_gap", 134, T::Real, C::output, V::continuous, "m", "Height of each bottom node above the foundation at the end of the step (< 0: penetration, see max_penetration)", none, none, none, ACCESS_EDGE(gap)},
    {"edge_state", 135, T::Enumeration, C::output, V::discrete, "", "Contact state of each bottom node in the last substep: open, stick or slip (counts: active_contact_nodes = stick + slip, slipping_contact_nodes = slip)", none, none, none, ACCESS_EDGE_STATE},
};

}  // namespace

SceneParameters Values::scene() const {
    SceneParameters p;
    p.width = width;
    p.height = height;
    p.nx = nx;
    p.ny = ny;
    p.density = density;
    p.lambda = lambda;
    p.mu = mu;
    p.friction_coefficient = friction_coefficient;
    p.static_friction_ratio = static_friction_ratio;
    p.stribeck_velocity = stribeck_velocity;
    p.viscous_friction = viscous_friction;
    p.mass_matrix = static_cast<MassVariant>(mass_matrix);
    p.internal_step = internal_step;
    p.contact_tolerance = contact_tolerance;
    p.initial_gap = initial_gap;
    p.damping_mass = damping_mass;
    p.damping_stiffness = damping_stiffness;
    p.min_internal_step = min_internal_step;
    p.force_control = top_control == static_cast<int>(TopControl::force);
    p.top_mass = top_mass;
    p.initial_velocity_x = initial_velocity_x;
    p.initial_velocity_y = initial_velocity_y;
    p.max_energy = max_energy;
    p.max_energy_ratio = max_energy_ratio;
    p.static_initial_state = initial_state == static_cast<int>(InitialState::static_equilibrium);
    return p;
}

const std::vector<Variable>& variables() { return table; }

void check_string(const Variable& v, const char* value) {
    if (!value) throw std::invalid_argument(std::string("variable ") + v.name + " cannot be NULL");
    const size_t n = std::strlen(value);
    if (n > max_string_length)
        throw std::invalid_argument(std::string("variable ") + v.name + " is longer than " +
                                    std::to_string(max_string_length) + " bytes");
    for (size_t i = 0; i < n; ++i)
        if (static_cast<unsigned char>(value[i]) < 0x20)
            throw std::invalid_argument(std::string("variable ") + v.name +
                                        " contains a control character at byte " + std::to_string(i));
}

void check_range(const Variable& v, double value) {
    std::ostringstream msg;
    msg.precision(17);
    if (!std::isfinite(value)) {
        msg << "variable " << v.name << " must be finite (got " << value << ")";
        throw std::invalid_argument(msg.str());
    }
    if (value < v.min || value > v.max) {
        msg << "variable " << v.name << " = " << value << " is out of range: must be >= "
            << v.min << " and <= " << v.max;
        throw std::invalid_argument(msg.str());
    }
}

int input_index(const Variable& v) {
    if (v.causality != Causality::input) return -1;
    const std::string name = v.name;
    return name == "foundation_velocity" ? 0 : name == "top_displacement" ? 1 : 2;
}

const char* fmi3_type(const Variable& v) {
    switch (v.type) {
        case Type::Real: return "Float64";
        case Type::Integer: return v.structural ? "UInt64" : "Int32";
        case Type::Enumeration: return "Int64";
        case Type::String: return "String";
    }
    return "";
}

const Variable* find_variable(unsigned value_reference, Standard standard) {
    static const std::unordered_map<unsigned, const Variable*> index = [] {
        std::unordered_map<unsigned, const Variable*> m;
        for (const Variable& v : table) m.emplace(v.value_reference, &v);
        return m;
    }();
    const auto it = index.find(value_reference);
    return it == index.end() || !it->second->in(standard) ? nullptr : it->second;
}

Values start_values() {
    Values values{};
    for (const Variable& v : table) {
        if (v.causality == Causality::output) continue;
        if (v.real) v.real(values) = v.start;
        else if (v.integer) v.integer(values) = static_cast<int>(v.start);
    }
    return values;
}

const std::vector<EnumerationType>& enumeration_types() {
    static const std::vector<EnumerationType> types = {
        {"MassMatrix", {"standard", "redistributed_normal", "redistributed_both",
                        "standard_implicit_contact", "redistributed_implicit_contact"}},
        {"InputInterpolation", {"hold", "ramp"}},
        {"TopControl", {"displacement", "force"}},
        {"InitialState", {"paper", "static"}},
        {"ContactState", {"open", "stick", "slip"}},
    };
    return types;
}

const EnumerationType& enumeration_type(const Variable& v) {
    for (const EnumerationType& t : enumeration_types())
        if (v.enumeration && std::string(v.enumeration) == t.name) return t;
    throw std::logic_error(std::string("variable ") + v.name + " has no enumeration type");
}

const std::vector<std::string>& log_categories() {
    static const std::vector<std::string> categories = {
        "logEvents", "logStatusWarning", "logStatusError", "logAll", "logContactSolver"};
    return categories;
}

}  // namespace contactbody::fmu
