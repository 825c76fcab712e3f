#include "variables.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

#include "mesh/gmsh.hpp"
#include "util/text.hpp"

#ifndef CONTACTBODY_ONE_MODEL_TABLE
#define CONTACTBODY_ONE_MODEL_TABLE 0
#endif

namespace contactbody::fmu {

std::string mesh_path(const std::string& mesh, const std::string& resources) {
    const bool absolute = (!mesh.empty() && (mesh[0] == '/' || mesh[0] == '\\')) ||
                          (mesh.size() > 2 && std::isalpha(static_cast<unsigned char>(mesh[0])) &&
                           mesh[1] == ':' && (mesh[2] == '/' || mesh[2] == '\\'));
    return mesh.empty() || absolute ? mesh : resources + mesh;
}

namespace {

constexpr double none = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

using T = Type;
using C = Causality;
using V = Variability;

Variable declare(const char* name, unsigned vr, Type type, Causality causality, Variability variability,
                 const char* unit, double start, double min, double max, const char* description) {
    Variable v{name, vr, type, causality, variability, unit, description, start, min, max};
    return v;
}

Variable real(const char* name, unsigned vr, double Values::* field, const char* unit, double start,
              double min, double max, const char* description) {
    Variable v = declare(name, vr, T::Real, C::parameter, V::fixed, unit, start, min, max, description);
    v.real = [field](Values& values) -> double& { return values.*field; };
    return v;
}

// A component of a per-tangent or per-component field (foundation_velocity_z: tangent 1).
template <size_t N>
Variable real(const char* name, unsigned vr, std::array<double, N> Values::* field, size_t component,
              const char* unit, double start, double min, double max, const char* description) {
    Variable v = declare(name, vr, T::Real, C::parameter, V::fixed, unit, start, min, max, description);
    v.real = [field, component](Values& values) -> double& { return (values.*field)[component]; };
    return v;
}

Variable integer(const char* name, unsigned vr, int Values::* field, double start, double min, double max,
                 const char* description) {
    Variable v = declare(name, vr, T::Integer, C::parameter, V::fixed, "", start, min, max, description);
    v.integer = [field](Values& values) -> int& { return values.*field; };
    return v;
}

Variable enumeration(const char* name, unsigned vr, int Values::* field, const char* type, double start,
                     const char* description) {
    Variable v = integer(name, vr, field, start, 0, 0, description);
    v.type = T::Enumeration;
    v.enumeration = type;
    v.max = static_cast<double>(enumeration_type(v).items.size() - 1);
    return v;
}

Variable string(const char* name, unsigned vr, std::string Values::* field, const char* description) {
    Variable v = declare(name, vr, T::String, C::parameter, V::fixed, "", 0, none, none, description);
    v.string = [field](Values& values) -> std::string& { return values.*field; };
    return v;
}

// The field of `out` that Observables::for_each names `name`, as T&.
template <class T>
T& observable(Observables& out, const std::string& name) {
    T* found = nullptr;
    Observables::for_each(
        [&](const char* field_name, auto& x) {
            if constexpr (std::is_same_v<std::decay_t<decltype(x)>, T>)
                if (name == field_name) found = &x;
        },
        out);
    if (!found) throw std::logic_error("no observable " + name + " of this type");
    return *found;
}

// An output: Observables' field of the same name (Real and continuous for a double, Integer
// and discrete for an int).
Variable output(const char* name, unsigned vr, const char* unit, const char* description) {
    bool is_integer = false, found = false;
    Observables probe;
    Observables::for_each(
        [&](const char* field_name, const auto& x) {
            if (std::string(field_name) != name) return;
            found = true;
            is_integer = std::is_same_v<std::decay_t<decltype(x)>, int>;
        },
        probe);
    if (!found) throw std::logic_error(std::string("output ") + name + " is no Observables field");
    Variable v = declare(name, vr, is_integer ? T::Integer : T::Real, C::output,
                         is_integer ? V::discrete : V::continuous, unit, none, none, none, description);
    const std::string key = name;
    if (is_integer)
        v.integer = [key](Values& values) -> int& { return observable<int>(values.out, key); };
    else
        v.real = [key](Values& values) -> double& { return observable<double>(values.out, key); };
    return v;
}

// FMI 3.0 outputs along the contact edge.
// An edge array's field: the snapshot's `field`, or tangent t's of a per-tangent one.
template <auto field, int t = -1>
const Eigen::VectorXd& edge_field(const EdgeSnapshot& e) {
    if constexpr (t < 0)
        return e.*field;
    else
        return (e.*field)[t];
}

Variable edge_output(const char* name, unsigned vr, const char* unit,
                     const Eigen::VectorXd& (*field)(const EdgeSnapshot&), const char* description) {
    Variable v = declare(name, vr, T::Real, C::output, V::continuous, unit, none, none, none, description);
    v.edge_real = field;
    v.standard = Standard::fmi3;
    return v;
}

Variable edge_state_output(const char* name, unsigned vr, const char* description) {
    Variable v = declare(name, vr, T::Enumeration, C::output, V::discrete, "", none, none, none, description);
    v.enumeration = "ContactState";
    v.edge_state = true;
    v.standard = Standard::fmi3;
    return v;
}

// The edge arrays follow the body: nx + 1 for the rectangle, a mesh's contact nodes (a mesh
// that cannot be read leaves edge_nodes as it is: initialization refuses the file, naming why).
[[maybe_unused]] void follow_nx(Values& v, const std::string&) {
    if (v.mesh.empty()) v.edge_nodes = v.nx + 1;
}
void follow_mesh(Values& v, const std::string& resources) {
    if (v.mesh.empty()) {
        v.edge_nodes = v.nx + 1;
        return;
    }
    try {
        std::vector<std::string> notes;
        const Mesh mesh = read_gmsh_mesh(mesh_path(v.mesh, resources), max_nodes, notes);
        v.edge_nodes = static_cast<int>(mesh.contact_nodes.size());
    } catch (const std::invalid_argument&) {
    }
}
void retune_friction(Simulation& s, double friction) { s.set_friction_coefficient(friction); }

std::vector<Variable> checked(std::vector<Variable> rows) {
    check_variable_table(rows, !CONTACTBODY_ONE_MODEL_TABLE);
    return rows;
}

}  // namespace

void check_variable_table(const std::vector<Variable>& rows, bool every_field) {
    const auto fail = [](const std::string& what) { throw std::logic_error("variable table: " + what); };
    const auto named = [&](const std::string& name) -> const Variable* {
        for (const Variable& v : rows)
            if (name == v.name) return &v;
        return nullptr;
    };
    // Within each model a reference and a name are one variable's; a row of one model may
    // share them with the other's (the 3D model's mesh has its own description), and the same
    // name is the same reference in both.
    const auto together = [](const Variable& a, const Variable& b) {
        return a.dimension == 0 || b.dimension == 0 || a.dimension == b.dimension;
    };
    for (size_t i = 0; i < rows.size(); ++i)
        for (size_t j = 0; j < i; ++j) {
            const Variable &a = rows[i], &b = rows[j];
            const bool same_name = std::strcmp(a.name, b.name) == 0;
            if (same_name && a.value_reference != b.value_reference)
                fail(std::string(a.name) + " has two value references");
            if (!together(a, b)) continue;
            if (a.value_reference == b.value_reference && !same_name)
                fail(std::string(a.name) + " repeats the value reference of " + b.name);
            if (same_name) fail(std::string(a.name) + " is declared twice for one model");
        }
    SceneParameters scene;
    std::vector<std::string> scene_names;
    SceneParameters::for_each(
        [&](const char* name, Reuse, const auto&) {
            const Variable* v = named(name);
            if (every_field && (!v || v->causality != C::parameter || v->fmu_only))
                fail(std::string("SceneParameters' ") + name + " is set by no parameter");
            scene_names.push_back(name);
        },
        scene);
    for (const Variable& v : rows)
        if (v.causality == C::parameter && !v.fmu_only &&
            std::find(scene_names.begin(), scene_names.end(), v.name) == scene_names.end())
            fail(std::string("parameter ") + v.name +
                 " reaches no SceneParameters field (SceneParameters::for_each) and is not "
                 "declared FMU-only");
    Observables probe;
    Observables::for_each(
        [&](const char* name, const auto&) {
            const Variable* v = named(name);
            if (every_field && (!v || v->causality != C::output))
                fail(std::string("Observables' ") + name + " is no output");
        },
        probe);
}

Variable& Variable::as_input(Input slot) {
    causality = C::input;
    variability = V::continuous;
    input = slot;
    return *this;
}
Variable& Variable::as_tunable(void (*apply)(Simulation&, double)) {
    variability = V::tunable;
    tune = apply;
    return *this;
}
Variable& Variable::as_structural(Standard in) {
    structural = true;
    standard = in;
    return *this;
}
Variable& Variable::as_fmu_only() {
    fmu_only = true;
    return *this;
}
Variable& Variable::as_discrete() {
    variability = V::discrete;
    return *this;
}
Variable& Variable::then(void (*follow)(Values&, const std::string& resources)) {
    after_set = follow;
    return *this;
}
Variable& Variable::only_in(int model) {
    dimension = model;
    return *this;
}
Variable& Variable::starting_at(const char* text) {
    string_start = text;
    return *this;
}

namespace {

// A row of one model (Variable::dimension). A platform build's binary holds its own model's rows
// only (CONTACTBODY_ONE_MODEL_TABLE: the other's would take room in the FMU, the 5 MB limit);
// the native build's hold both, and its table test checks them together.
#if !CONTACTBODY_ONE_MODEL_TABLE || CONTACTBODY_MODEL_DIMENSION == 2
#define PLANAR_ROW(...) __VA_ARGS__.only_in(2),
#else
#define PLANAR_ROW(...)
#endif
#if !CONTACTBODY_ONE_MODEL_TABLE || CONTACTBODY_MODEL_DIMENSION == 3
#define SOLID_ROW(...) __VA_ARGS__.only_in(3),
#else
#define SOLID_ROW(...)
#endif

// The rows. FMI limits are inclusive: where a value must be > 0, min is the smallest meaningful
// positive value. Enumerations take their range from their type.
const std::vector<Variable>& all_rows() {
    static const std::vector<Variable> rows = checked({
        // Parameters (docs/variables.md lists them). A row marked only_in(2) or only_in(3)
        // belongs to one model (variables.hpp's model_dimension).
        PLANAR_ROW(
            string("mesh", 35, &Values::mesh,
                   "The body's mesh: empty = the rectangle of width, height, nx and ny; else a Gmsh file "
                   "(MSH 4.1 or 2.2, ASCII) of first-order triangles in the x-y plane, in metres, with "
                   "physical groups of boundary lines named contact (may touch the foundation, which lies "
                   "under its lowest node by initial_gap) and clamp (driven as the top edge); its path "
                   "absolute or relative to the FMU's resources folder. width, height, nx and ny are then "
                   "unused; setting it sets edge_nodes to its number of contact nodes")
                .as_structural(Standard::both)
                .then(follow_mesh))
            SOLID_ROW(
                string(
                    "mesh", 35, &Values::mesh,
                    "The body's mesh: a Gmsh file (MSH 4.1 or 2.2, ASCII) of first-order tetrahedra, in "
                    "metres, with physical groups of boundary surfaces named contact (may touch the "
                    "foundation, the plane y = const under its lowest node by initial_gap, which slides in x "
                    "and z) and clamp (driven as the top: u_x = u_z = 0, u_y = top_displacement); its path "
                    "absolute or relative to the FMU's resources folder. The default block.msh (in "
                    "resources/) is a 0.1 m cube of 6 x 6 x 6 Kuhn-split cells, its bottom face in contact "
                    "and its top face clamped. Setting it sets edge_nodes to its number of contact nodes")
                    .as_structural(Standard::both)
                    .then(follow_mesh)
                    .starting_at(solid_default_mesh))
        PLANAR_ROW(real("width", 1, &Values::width, "m", 0.1, 1e-6, inf, "Width W of the body"))
            PLANAR_ROW(real("height", 2, &Values::height, "m", 0.1, 1e-6, inf, "Height H of the body"))
                PLANAR_ROW(integer("nx", 3, &Values::nx, 20, 1, max_cells_per_direction, "Cells along x")
                               .as_structural(Standard::both)
                               .then(follow_nx))
                    PLANAR_ROW(integer("ny", 4, &Values::ny, 20, 1, max_cells_per_direction, "Cells along y")
                                   .as_structural(Standard::both))
                        integer("edge_nodes", 31, &Values::edge_nodes,
                                solid_model ? solid_default_mesh_contact_nodes : 21, solid_model ? 3 : 2,
                                solid_model ? static_cast<double>(max_nodes) : max_cells_per_direction + 1,
                                "Contact nodes, the size of the edge arrays: nx + 1 for the rectangle "
                                "(setting nx sets it; another value is refused when Configuration Mode ends "
                                "and at initialization); with a mesh its number of contact nodes (setting "
                                "mesh sets it; another value is refused at initialization, naming it)")
                            .as_structural(Standard::fmi3)
                            .as_fmu_only(),
        real("density", 5, &Values::density, "kg/m3", 1000, 1e-3, inf, "Density rho"),
        real("lambda", 6, &Values::lambda, "Pa", 300e6, none, none,
             "First Lame coefficient (lambda + mu > 0)"),
        real("mu", 7, &Values::mu, "Pa", 150e6, 1, inf, "Shear modulus"),
        real("friction_coefficient", 8, &Values::friction_coefficient, "", 1.2, 0, max_friction_coefficient,
             "Coulomb friction coefficient F")
            .as_tunable(retune_friction),
        enumeration("mass_matrix", 9, &Values::mass_matrix, "MassMatrix", 1,
                    "Mass matrix and contact treatment: 0 standard, 1 redistributed_normal (the paper), 2 "
                    "redistributed_both, 3 standard_implicit_contact, 4 redistributed_implicit_contact (M_r, "
                    "contact at the end of the step: cannot gain energy at contact)"),
        real("internal_step", 10, &Values::internal_step, "s", 4e-6, 1e-12, inf, "Largest midpoint substep"),
        real("contact_tolerance", 11, &Values::contact_tolerance, "", 1e-10,
             std::numeric_limits<double>::epsilon(), 0.5,
             "Relative tolerance of each substep's contact solve (at least the resolution of a double, "
             "2.2e-16)"),
        real("initial_gap", 12, &Values::initial_gap, "m", 0, 0, inf,
             "Initial gap between the body and the foundation"),
        string("result_directory", 13, &Values::result_directory,
               "Directory for field output (.vtu files and a .pvd collection); empty = none")
            .as_fmu_only(),
        real("field_output_interval", 14, &Values::field_output_interval, "s", 1e-4, 1e-9, inf,
             "Time between field output files (written at the first communication point at or after each "
             "multiple)")
            .as_fmu_only(),
        real("edge_output_interval", 28, &Values::edge_output_interval, "s", 0, 0, inf,
             "Time between the records of the edge history (result_directory/contactbody_edge.npy: per "
             "bottom node and output time, the step-averaged contact pressure and friction density, slip "
             "velocity, gap and state); 0 = none")
            .as_fmu_only(),
        real("damping_mass", 15, &Values::damping_mass, "1/s", 0, 0, inf,
             "Rayleigh damping: alpha of C = alpha M + beta A (M: the variant's mass matrix)"),
        real("damping_stiffness", 16, &Values::damping_stiffness, "s", 0, 0, inf,
             "Rayleigh damping: beta of C = alpha M + beta A"),
        real("min_internal_step", 17, &Values::min_internal_step, "s", 1e-9, 1e-15, inf,
             "Smallest substep: a substep whose contact solve fails is redone as two halves, recursively, "
             "down to this size (at most 20 halvings)"),
        real("tolerance", 41, &Values::tolerance, "", 0, 0, 0.5,
             "Substeps chosen by error: the relative local error of each pair of substeps, estimated by "
             "step doubling (two substeps against four of half their size) in the energy norm of "
             "displacement and velocity; a pair then spans at most internal_step, and its substeps "
             "are at least min_internal_step. 0 = fixed substeps of at most internal_step"),
        enumeration(
            "input_interpolation", 18, &Values::input_interpolation, "InputInterpolation", 0,
            "How an input set without a derivative enters the step: hold (its value, FMI 2.0) or ramp "
            "(linearly from its value at the previous communication point: one step of delay, no jumps)")
            .as_fmu_only(),
        enumeration("top_control", 19, &Values::top_control, "TopControl", 0,
                    per_body("Top edge: displacement (clamped to the input top_displacement) or force (a "
                             "rigid plate of mass top_mass with u_x = 0, pushed down by the input top_force; "
                             "top_displacement then only sets the initial position)",
                             "Clamp group: displacement (clamped to the input top_displacement) or force (a "
                             "rigid plate of mass top_mass with u_x = u_z = 0, pushed down by the input "
                             "top_force; top_displacement then only sets the initial position)")),
        real("top_mass", 23, &Values::top_mass, per_body("kg/m", "kg"), 1.0, 1e-9, inf,
             "Mass of the top plate (top_control = force)"),
        real("initial_velocity_x", 24, &Values::initial_velocity, 0, "m/s", 0, none, none,
             "Uniform initial velocity of the body, x (the clamped dofs excepted)"),
        real("initial_velocity_y", 25, &Values::initial_velocity, 1, "m/s", 0, none, none,
             "Uniform initial velocity of the body, y (with the plate under force control)"),
        SOLID_ROW(real("initial_velocity_z", 37, &Values::initial_velocity, 2, "m/s", 0, none, none,
                       "Uniform initial velocity of the body, z (the clamped dofs excepted)"))
        enumeration("initial_state", 26, &Values::initial_state, "InitialState", 0,
                    "Initial displacement: paper (u_y = top_displacement y / H, not an equilibrium: a "
                    "free vibration follows) or static (the static equilibrium under the initial "
                    "top_displacement, or under top_force > 0 with top_control = force, with the "
                    "foundation at rest, reached by a quasi-static frictional load path)"),
        real("max_energy", 29, &Values::max_energy, per_body("J/m", "J"), 0, 0, inf,
             "Blow-up guard: a step that ends with the energy E above this fails with an error status, "
             "naming the time, E, the works and the likely cause; 0 = no absolute limit"),
        real("max_energy_ratio", 30, &Values::max_energy_ratio, "", 1e6, 0, inf,
             "Blow-up guard: a step that ends with E above max_energy_ratio x (E(0) + |clamp_work| + "
             "|foundation_work|) fails with an error status, naming the time, E, the works and the likely "
             "cause; 0 = off. The default 1e6 is above the growth of every run of the paper's Figs. 7-8 but "
             "variant 0 at internal_step 1e-6 s, whose growth is chaotic and crosses it in some draws (the "
             "examples that measure growth set 0)"),
        real("static_friction_ratio", 27, &Values::static_friction_ratio, "", 1, 1, max_static_friction_ratio,
             "Static over kinetic friction: a node that stuck in the last substep breaks loose only at "
             "static_friction_ratio x F x pressure; a slipping node feels F (1 = Coulomb's law; above 1 the "
             "friction drops at the onset of slip, which gives stick-slip; at most 10)"),
        real("stribeck_velocity", 32, &Values::stribeck_velocity, "m/s", 0, 0, inf,
             "Slip-rate law: F(v) = F_d + (F_s - F_d) exp(-|v| / stribeck_velocity) + viscous_friction |v| "
             "with F_d = friction_coefficient, F_s = static_friction_ratio x F_d and v the scheme's slip "
             "rate, taken implicitly in the step; 0 = no Stribeck term (F_s is then the stick memory of "
             "static_friction_ratio)"),
        real("viscous_friction", 33, &Values::viscous_friction, "s/m", 0, 0, max_viscous_friction,
             "Slip-rate law: the viscous term c_v |v| of F(v) (see stribeck_velocity); 0 = none"),
        integer(
            "modes", 34, &Values::modes, 0, 0, max_reduced_modes,
            per_body("The body: 0 = the full mesh; m > 0 = the reduced body: the contact edge kept exact, "
                     "the interior reduced to its m lowest modes plus the edge's residual attachment modes "
                     "(massless boundary component mode synthesis; reduced_edge chooses whether the edge's x "
                     "dofs keep their mass); under top_control = force the plate's translation is one more "
                     "coordinate. At most the body's finite modes (free dofs less massless ones), and of a "
                     "body above 2000 free dofs at most 500 and at most a quarter of them. The basis is "
                     "built at initialization and kept over a reset",
                     "The body: 0 = the full mesh; m > 0 = the reduced body: the contact edge kept exact, "
                     "the interior reduced to its m lowest modes plus the edge's residual attachment modes "
                     "(massless boundary component mode synthesis; reduced_edge chooses whether the edge's x "
                     "and z dofs keep their mass); under top_control = force the plate's translation is one "
                     "more coordinate. At most the body's finite modes (free dofs less massless ones), and "
                     "of a body above 2000 free dofs at most 500 and at most a quarter of them. The basis is "
                     "built at initialization and kept over a reset")),
        enumeration(
            "reduced_edge", 36, &Values::reduced_edge, "ReducedEdge", 0,
            per_body(
                "The reduced body's contact edge (modes > 0): massless (every contact dof a massless "
                "residual coordinate) or tangential_mass (the contact x dofs kept as coordinates that carry "
                "the variant's tangential mass, the normal dofs massless: the paper's principle; not with "
                "redistributed_both, whose x dofs have no mass); by_variant takes the default measured for "
                "each mass_matrix: tangential_mass for 0, 3 and 4, massless for 1 and 2",
                "The reduced body's contact edge (modes > 0): massless (every contact dof a massless "
                "residual coordinate) or tangential_mass (the contact x and z dofs kept as coordinates that "
                "carry the variant's tangential mass, the normal dofs massless: the paper's principle; not "
                "with redistributed_both, whose tangential dofs have no mass); by_variant takes the default "
                "measured for each mass_matrix: tangential_mass for 0, 3 and 4, massless for 1 and 2")),
        SOLID_ROW(integer("baseline_kernels", 39, &Values::baseline_kernels, 0, 0, 1,
                          "Where the body's factor is supernodal (a tetrahedral body's from 1e8 flops of "
                          "factorization, about a thousand nodes; others' from 1e9), its dense kernels: 0 = the fastest "
                          "this CPU has (x86-64-v4 with AVX-512, or x86-64-v3 with AVX2 and FMA, where the CPU "
                          "reports it; the log names the set), whose last bits depend on the CPU; 1 = the architecture's baseline "
                          "ones, the same bits on every machine of an architecture"))
        SOLID_ROW(integer("threads", 40, &Values::threads, 1, 1, 64,
                          "Threads of a supernodal factor's numeric factorization (see baseline_kernels): "
                          "independent subtrees and blocks of the large panels side by side. The outputs are "
                          "the same bit for bit for any number; 1 by default, because importers often run "
                          "many instances side by side"))
        // Inputs
        real("foundation_velocity", 20, &Values::foundation_velocity, 0, "m/s", 20, none, none,
             per_body("Horizontal velocity V of the rigid foundation",
                      "Velocity of the rigid foundation in its plane, x component"))
            .as_input(Input::foundation_velocity),
        SOLID_ROW(real("foundation_velocity_z", 38, &Values::foundation_velocity, 1, "m/s", 0, none, none,
                       "Velocity of the rigid foundation in its plane, z component")
                      .as_input(Input::foundation_velocity_z))
        real("top_displacement", 21, &Values::top_displacement, "m", -2.5e-5, none, none,
             per_body("Prescribed vertical displacement of the top edge",
                      "Prescribed vertical (y) displacement of the clamp group"))
            .as_input(Input::top_displacement),
        real("top_force", 22, &Values::top_force, per_body("N/m", "N"), 0, none, none,
             "Force pressing the top plate down (top_control = force), positive downwards")
            .as_input(Input::top_force),
        // Outputs
        output(
            "energy", 100, per_body("J/m", "J"),
            per_body(
                "Total energy E = kinetic + strain (paper eq. 19, with the variant's mass matrix; the "
                "plate's kinetic energy under force control), per metre of thickness, at the end of the step",
                "Total energy E = kinetic + strain (paper eq. 19, with the variant's mass matrix; the "
                "plate's kinetic energy under force control) at the end of the step")),
        output("kinetic_energy", 101, per_body("J/m", "J"), "Kinetic part of E"),
        output("strain_energy", 102, per_body("J/m", "J"), "Strain part of E"),
        output("friction_work", 103, per_body("J/m", "J"), "Work xi of friction on the body since the start"),
        output("energy_minus_friction_work", 104, per_body("J/m", "J"), "E - xi (paper Fig. 8)"),
        output("normal_force", 105, per_body("N/m", "N"),
               "Total normal contact force on the body, a magnitude (>= 0): the average over the last "
               "communication step of its substeps' forces"),
        output("friction_force", 106, per_body("N/m", "N"),
               "Total friction force on the body, signed x component (> 0: the foundation drags the body "
               "towards +x): the average over the last communication step"),
        SOLID_ROW(output("friction_force_z", 125, "N",
                         "Total friction force on the body, signed z component: the average over the last "
                         "communication step"))
        output("corner_pressure", 107, "Pa",
               per_body("Contact pressure at node (0,0), averaged over the last step",
                        "Contact pressure at the first contact node (least x, then least z), averaged "
                        "over the last step")),
        output("corner_friction", 108, "Pa",
               per_body("Friction force density at node (0,0), averaged over the last step",
                        "Friction force density at the first contact node, x component, averaged over the "
                        "last step")),
        output("top_reaction_x", 109, per_body("N/m", "N"),
               "Force of the clamp (or plate) on the body, signed x component, averaged over the last "
               "communication step"),
        output("top_reaction_y", 110, per_body("N/m", "N"),
               "Force of the clamp (or plate) on the body, signed y component (< 0 while it presses the body "
               "down), averaged over the last communication step"),
        SOLID_ROW(output("top_reaction_z", 126, "N",
                         "Force of the clamp (or plate) on the body, signed z component, averaged over the "
                         "last communication step"))
        output("active_contact_nodes", 111, "", "Contact nodes in contact at the last substep"),
        output("slipping_contact_nodes", 112, "", "Contact nodes slipping at the last substep"),
        output("max_penetration", 113, "m",
               "Largest penetration of the bottom nodes at the ends u^{k+1} of the last step's substeps. "
               "Contact is imposed at the midpoints u^{k+1/2}, so this is the scheme's overshoot between "
               "midpoints (about dt/2 x the normal velocity), not a violated contact condition"),
        output("damping_work", 114, per_body("J/m", "J"),
               "Energy dissipated by the Rayleigh damping since the start (>= 0)"),
        output("clamp_work", 115, per_body("J/m", "J"),
               "Work of the clamp's reaction on the body since the start, jumps of a held top_displacement "
               "included"),
        output("normal_contact_work", 116, per_body("J/m", "J"),
               "Work of the normal contact forces on the body since the start"),
        output("friction_dissipation", 117, per_body("J/m", "J"),
               "Energy dissipated by friction at the interface since the start (foundation_work - "
               "friction_work)"),
        output("foundation_work", 118, per_body("J/m", "J"),
               "Work of the foundation's motion against friction since the start (what its drive pays)"),
        output("top_position", 119, "m",
               per_body("Vertical displacement u_y of the top edge (the plate under force control)",
                        "Vertical displacement u_y of the clamp group (the plate under force control)")),
        output("top_velocity", 120, "m/s",
               per_body("Vertical velocity of the top edge", "Vertical velocity of the clamp group")),
        output("substeps", 121, "",
               "Midpoint substeps taken in the last communication step (ceil(step / internal_step), plus one "
               "per refinement)"),
        output("substep_refinements", 122, "",
               "Substeps of the last communication step redone as two halves after a failed contact solve"),
        output("contact_iterations", 123, "",
               "Semi-smooth Newton iterations of the contact solves in the last communication step, summed"),
        output("gauss_seidel_sweeps", 124, "",
               "Sweeps of the contact solver's Gauss-Seidel fallback in the last communication step, summed "
               "(0 when Newton always converged)"),
        // Outputs along the contact edge (FMI 3.0: arrays of edge_nodes values, ordered by x)
        edge_output("edge_x", 130, "m", edge_field<&EdgeSnapshot::x>,
                    "Position x of each bottom node (reference configuration)")
            .as_discrete(),
        SOLID_ROW(edge_output("edge_z", 136, "m", edge_field<&EdgeSnapshot::z>,
                              "Position z of each contact node (reference configuration)")
                      .as_discrete())
        edge_output("edge_pressure", 131, "Pa", edge_field<&EdgeSnapshot::pressure>,
                    "Contact pressure at each bottom node, averaged over the last communication step "
                    "like normal_force (node shares x pressures sum to normal_force)"),
        edge_output("edge_friction", 132, "Pa", edge_field<&EdgeSnapshot::friction, 0>,
                    "Friction force density at each bottom node, signed x component, averaged like "
                    "friction_force (node shares x densities sum to friction_force)"),
        SOLID_ROW(edge_output("edge_friction_z", 137, "Pa", edge_field<&EdgeSnapshot::friction, 1>,
                              "Friction force density at each contact node, signed z component, averaged "
                              "like friction_force_z (node shares x densities sum to friction_force_z)"))
        edge_output("edge_slip_velocity", 133, "m/s", edge_field<&EdgeSnapshot::slip_velocity, 0>,
                    "Velocity x of each bottom node relative to the foundation over the last substep"),
        SOLID_ROW(
            edge_output("edge_slip_velocity_z", 138, "m/s", edge_field<&EdgeSnapshot::slip_velocity, 1>,
                        "Velocity z of each contact node relative to the foundation over the last substep"))
        edge_output("edge_gap", 134, "m", edge_field<&EdgeSnapshot::gap>,
                    "Height of each bottom node above the foundation at the end of the step (< 0: "
                    "penetration, see max_penetration)"),
        edge_state_output("edge_state", 135,
                          "Contact state of each bottom node in the last substep: open, stick or slip "
                          "(counts: active_contact_nodes = stick + slip, slipping_contact_nodes = slip)"),
    });
    return rows;
}

// This model's rows.
const std::vector<Variable>& table() {
    static const std::vector<Variable> rows = [] {
        std::vector<Variable> mine;
        for (const Variable& v : all_rows())
            if (v.dimension == 0 || v.dimension == model_dimension) mine.push_back(v);
        return mine;
    }();
    return rows;
}

}  // namespace

// Each SceneParameters field from this model's parameter of its name (checked: every field
// has one in some model; one the model has not keeps its default: the 3D model has no
// rectangle), and the model's dimension.
SceneParameters Values::scene() const {
    Values values = *this;  // the accessors take Values&
    SceneParameters p;
    p.dimension = model_dimension;
    SceneParameters::for_each(
        [&](const char* name, Reuse, auto& field) {
            const Variable* found = find_variable(name);
            if (!found) return;
            const Variable& v = *found;
            using Field = std::decay_t<decltype(field)>;
            if constexpr (std::is_same_v<Field, std::string>)
                field = v.string(values);
            else if constexpr (std::is_floating_point_v<Field>)
                field = v.real(values);
            else  // int, a bool (0 or 1) or an enumeration
                field = static_cast<Field>(v.integer(values));
        },
        p);
    return p;
}

const std::vector<Variable>& all_model_variables() { return all_rows(); }
const std::vector<Variable>& variables() { return table(); }

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
    Text msg;
    msg.precision(17);
    if (!std::isfinite(value)) {
        msg << "variable " << v.name << " must be finite (got " << value << ")";
        throw std::invalid_argument(msg.str());
    }
    if (value < v.min || value > v.max) {
        msg << "variable " << v.name << " = " << value << " is out of range: must be >= " << v.min
            << " and <= " << v.max;
        throw std::invalid_argument(msg.str());
    }
}

const char* fmi3_type(const Variable& v) {
    switch (v.type) {
        case Type::Real:
            return "Float64";
        case Type::Integer:
            return v.structural ? "UInt64" : "Int32";
        case Type::Enumeration:
            return "Int64";
        case Type::String:
            return "String";
    }
    return "";
}

const Variable* find_variable(unsigned value_reference, Standard standard) {
    static const std::unordered_map<unsigned, const Variable*> index = [] {
        std::unordered_map<unsigned, const Variable*> m;
        for (const Variable& v : table()) m.emplace(v.value_reference, &v);
        return m;
    }();
    const auto it = index.find(value_reference);
    return it == index.end() || !it->second->in(standard) ? nullptr : it->second;
}

const Variable* find_variable(const std::string& name) {
    for (const Variable& v : table())
        if (name == v.name) return &v;
    return nullptr;
}

Values start_values() {
    Values values{};
    for (const Variable& v : table()) {
        if (v.causality == Causality::output) continue;
        if (v.real)
            v.real(values) = v.start;
        else if (v.integer)
            v.integer(values) = static_cast<int>(v.start);
        else if (v.string)
            v.string(values) = v.string_start;
    }
    return values;
}

const std::vector<EnumerationType>& enumeration_types() {
    static const std::vector<EnumerationType> types = {
        {"MassMatrix",
         {"standard", "redistributed_normal", "redistributed_both", "standard_implicit_contact",
          "redistributed_implicit_contact"}},
        {"InputInterpolation", {"hold", "ramp"}},
        {"TopControl", {"displacement", "force"}},
        {"InitialState", {"paper", "static"}},
        {"ReducedEdge", {"by_variant", "massless", "tangential_mass"}},
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
    static const std::vector<std::string> categories = {"logEvents", "logStatusWarning", "logStatusError",
                                                        "logAll", "logContactSolver"};
    return categories;
}

}  // namespace contactbody::fmu
