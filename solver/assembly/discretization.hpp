// Scene parameters (docs/contract.md) and the space discretization they define: mesh, A, the
// variant's mass matrix, and the split of the dofs into free and clamped (top edge) ones.
#pragma once

#include <string>
#include <vector>

#include "assembly/assembly.hpp"
#include "util/tangents.hpp"

namespace contactbody {

// The four situations of the paper's Fig. 7, and (4) redistributed_implicit_contact:
// the redistributed normal mass with contact at the end of the step, which cannot gain energy
// at contact (the paper's midpoint contact can, for near-incompressible materials).
enum class MassVariant : int {
    standard = 0,
    redistributed_normal = 1,
    redistributed_both = 2,
    standard_implicit_contact = 3,
    redistributed_implicit_contact = 4,
};
constexpr int num_mass_variants = 5;

// Whether the variant's y block is M_r, and whether it imposes contact on u^{k+1}, v^{k+1}.
// With contact at the end of the step the normal contact work lambda_N (u_N^{k+1} - u_N^k)
// is lambda_N (gap - u_N^k) <= 0 at every active node: contact can only take energy out.
bool redistributes_normal(MassVariant v);
bool contact_at_end_of_step(MassVariant v);
struct SceneParameters;
// Whether the reduced body of p keeps its contact x dofs with mass (reduced_edge resolved).
bool reduced_edge_has_tangential_mass(const SceneParameters& p);
// Throws std::invalid_argument where a reduced body's reduced_edge asks for a mass the variant
// has not (check_parameters calls it for modes > 0; a reduced body of any p, itself).
void check_reduced_edge(const SceneParameters& p);

// The reduced body's contact edge (docs/decisions.md, "The reduced body's contact edge"):
// massless (the residual attachment modes of every contact dof, MacNeal), or with the contact
// x dofs as coordinates of their own that carry the variant's tangential mass (Craig-Bampton
// constraint modes; the normal dofs stay massless). by_variant takes the measured default.
enum class ReducedEdge : int { by_variant = 0, massless = 1, tangential_mass = 2 };

// Whether a scene parameter changes the Discretization (A, M, C, the unknowns) and so the
// factors, or only what a run does with them.
enum class Reuse { rebuilds_discretization, keeps_discretization };

struct SceneParameters {
    // The body's mesh: empty for the rectangle of width, height, nx, ny; else a Gmsh file
    // (solver/mesh/gmsh.hpp), whose path the FMU resolves against its resources/ folder.
    std::string mesh;
    double width = 0.1, height = 0.1;
    int nx = 20, ny = 20;
    double density = 1000, lambda = 300e6, mu = 150e6;
    double friction_coefficient = 1.2;
    // A node that sticks needs static_friction_ratio x F to break loose; a slipping node feels
    // F. 1 is Coulomb's law; above 1 the friction drops at the onset of slip (stick-slip).
    double static_friction_ratio = 1;
    // Slip-rate dependence: F(v) = F_d + (F_s - F_d) exp(-|v| / stribeck_velocity)
    // + viscous_friction |v|, F_d = friction_coefficient, F_s = static_friction_ratio x F_d,
    // v the discrete slip rate, taken implicitly. 0 and 0: today's law (with the stick memory
    // of static_friction_ratio).
    double stribeck_velocity = 0;  // m/s
    double viscous_friction = 0;   // s/m
    // The supernodal factor's kernels: the fastest this CPU has (false), or the architecture's
    // baseline ones, which compute the same bits on every machine (linalg/supernodal_kernels.hpp).
    bool baseline_kernels = false;
    int threads = 1;  // of a supernodal factor's numeric factorization (the same bits for any)
    MassVariant mass_matrix = MassVariant::redistributed_normal;
    double internal_step = 4e-6;
    double min_internal_step = 1e-9;  // failed contact solves halve a substep down to this
    // Substeps chosen by a local error estimate (relative, in the energy norm; 0: fixed substeps
    // of at most internal_step, the same bits as before it existed): simulation/substep_control.cpp.
    double tolerance = 0;
    double contact_tolerance = 1e-10;
    double initial_gap = 0;
    // Rayleigh damping C = damping_mass M + damping_stiffness A (M: the variant's mass matrix).
    double damping_mass = 0, damping_stiffness = 0;
    // The top edge: clamped to top_displacement, or a rigid plate of mass top_mass (kg/m) with
    // u_x = 0, pressed down by the force top_force.
    bool force_control = false;
    double top_mass = 1.0;
    // Uniform initial velocity of the body (and of the plate), m/s, per component (z: a 3D
    // body's).
    PerComponent initial_velocity{};
    // Initial displacement: the paper's linear profile, or the static equilibrium under the
    // initial top displacement with the foundation at rest (displacement control only).
    bool static_initial_state = false;
    // The blow-up guard (J/m, and a multiple of E(0) + the work put in); 0 turns each off.
    double max_energy = 0, max_energy_ratio = 1e6;
    // The body: 0 the full mesh; m > 0 the reduced body (docs/decisions.md, "The reduced
    // body"): the contact edge exact and massless, the interior reduced to its m lowest modes.
    int modes = 0;
    ReducedEdge reduced_edge = ReducedEdge::by_variant;
    // The body dimension its user expects (not a variable: an FMU's units are those of one
    // dimension, N/m for 2D and N for 3D). A mesh of the other dimension is refused.
    int dimension = 2;
    bool damped() const { return damping_mass != 0 || damping_stiffness != 0; }

    // Every field once: f(name, reuse, the field of each p...) with the FMU variable that sets
    // it (a bool or an enumeration takes the variable's integer value) and whether the
    // discretization, and so its factors, depend on it. same_discretization follows this list,
    // and the FMU's Values::scene() fills the fields through it (refusing a parameter that
    // reaches no field and is not declared FMU-only).
    template <class F, class... P>
    static void for_each(F&& f, P&... p) {
        constexpr Reuse rebuild = Reuse::rebuilds_discretization, keep = Reuse::keeps_discretization;
        f("mesh", rebuild, p.mesh...);
        f("width", rebuild, p.width...);
        f("height", rebuild, p.height...);
        f("nx", rebuild, p.nx...);
        f("ny", rebuild, p.ny...);
        f("density", rebuild, p.density...);
        f("lambda", rebuild, p.lambda...);
        f("mu", rebuild, p.mu...);
        f("friction_coefficient", keep, p.friction_coefficient...);
        f("static_friction_ratio", keep, p.static_friction_ratio...);
        f("stribeck_velocity", keep, p.stribeck_velocity...);
        f("viscous_friction", keep, p.viscous_friction...);
        f("mass_matrix", rebuild, p.mass_matrix...);
        f("internal_step", keep, p.internal_step...);  // factors are kept per substep size
        f("min_internal_step", keep, p.min_internal_step...);
        f("tolerance", keep, p.tolerance...);
        f("contact_tolerance", keep, p.contact_tolerance...);
        f("initial_gap", keep, p.initial_gap...);
        f("damping_mass", rebuild, p.damping_mass...);
        f("damping_stiffness", rebuild, p.damping_stiffness...);
        f("top_control", rebuild, p.force_control...);
        f("top_mass", rebuild, p.top_mass...);
        f("initial_velocity_x", keep, p.initial_velocity[0]...);
        f("initial_velocity_y", keep, p.initial_velocity[1]...);
        f("initial_velocity_z", keep, p.initial_velocity[2]...);
        f("initial_state", keep, p.static_initial_state...);
        f("max_energy", keep, p.max_energy...);
        f("max_energy_ratio", keep, p.max_energy_ratio...);
        f("modes", rebuild, p.modes...);  // the basis is built from the discretization
        f("reduced_edge", rebuild, p.reduced_edge...);
        f("baseline_kernels", rebuild, p.baseline_kernels...);  // the factors are made with them
        f("threads", rebuild, p.threads...);
    }
};

// Limits shared by the solver and the FMI layer (which also writes them as min/max).
constexpr int max_cells_per_direction = 4096;
constexpr long max_nodes = 4'000'000;
// Measured static/kinetic ratios of dry friction stay below 3; larger ones only make the
// contact step stiffer (and F x ratio must stay finite).
constexpr double max_static_friction_ratio = 10;
// Measured dry friction coefficients stay below about 3 (clean metals in vacuum excepted); a
// hundred means a bond, not friction, and only stiffens the contact step.
constexpr double max_friction_coefficient = 100;
// The reduced body's modes: every mode of bodies up to 2000 free dofs (solved densely), at
// most 500 of larger ones (modal_basis.hpp).
constexpr int max_reduced_modes = 2000;
// c_v |v| adds 1 to F at |v| = 1 / c_v: 100 s/m does so at 1 cm/s.
constexpr double max_viscous_friction = 100;

// Throws std::invalid_argument naming the first offending parameter (the FMU's variable names).
void check_parameters(const SceneParameters& p);
// What a body of this mesh's dimension cannot take yet (3D: friction and the reduced body);
// throws std::invalid_argument naming it. friction_coefficient is checked again wherever it
// changes after the discretization (it does not rebuild it).
void check_dimension(const Mesh& mesh, const SceneParameters& p);

struct Discretization {
    Mesh mesh;
    std::vector<std::string> mesh_notes;  // what reading the mesh did that the log should say
    bool contact_at_end_of_step = false;  // else on u^{k+1/2} (the paper's midpoint)
    SparseMatrix A;                       // all dofs
    StrainEnergy strain_energy;           // 1/2 u^T A u, >= 0 and exact for translations
    SparseMatrix M;                       // the variant's mass matrix, all dofs
    // The unknowns ("free", n_f of them): every dof that is neither clamped nor tied to the
    // top plate, then, under force control, the plate's vertical displacement w (plate_index).
    // expand (all dofs x free) maps them to all dofs: its transpose sums the plate's rows.
    std::vector<int> free_dofs;     // ascending: the dofs that are unknowns themselves
    std::vector<int> clamped_dofs;  // top edge x, and y under displacement control; ascending
    std::vector<int> moving_dofs;   // all but the clamped ones (free and tied), ascending
    std::vector<int> top_dofs;      // top edge, x and y, ascending: the reaction's rows
    std::vector<int> free_index;    // dof -> its unknown (the plate's for tied dofs), or -1
    int plate_index = -1;           // force control: the unknown w
    double plate_mass = 0;          // kg/m, force control
    SparseMatrix expand;
    // Blocks used by the stepper: rows free / top, columns all / clamped.
    RowMajorSparseMatrix M_free_rows, A_free_rows;  // row-major: every substep multiplies by them
    SparseMatrix A_free_clamped, M_free_clamped;
    RowMajorSparseMatrix M_top_rows, A_top_rows;  // few rows, read row by row
    SparseMatrix A_free, M_free;                  // free x free (M_free with the plate's mass)
    // Rayleigh damping C = alpha M + beta A and the same blocks of it; all empty (no
    // entries) when undamped, so that the undamped scheme is computed exactly as before.
    SparseMatrix C;
    RowMajorSparseMatrix C_free_rows;
    SparseMatrix C_free_clamped, C_free;
    // Contact node c: free positions of its y (normal) dof and of its tangent t's
    // (contact_tangential[t]: x, and in 3D z; empty past the body's tangents).
    std::vector<int> contact_y;
    PerTangent<std::vector<int>> contact_tangential;
    // The free positions of the contact unknowns in multiplier order: y dofs (N), then each
    // tangent's (T: x, then in 3D z).
    std::vector<int> contact_unknowns() const;
    // A top node's y dof: all of them move together (the clamp's value, or the plate's w).
    int top_y_dof() const { return mesh.dof(mesh.top_nodes.front(), Mesh::normal); }
    // out = u minus the translation of node 0. A annihilates translations, but the product
    // A u rounds |A| |u|: a body far from where it started would feel forces of that size
    // from nowhere. A (u - t) is the same force without them.
    void remove_translation(const Eigen::VectorXd& u, Eigen::VectorXd& out) const;
};

Discretization discretize(const SceneParameters& p);

// Whether a and b define the same Discretization (and so the same factors): they agree on
// every parameter SceneParameters::for_each marks as rebuilding it.
bool same_discretization(const SceneParameters& a, const SceneParameters& b);

}  // namespace contactbody
