#include "assembly/discretization.hpp"

#include <cmath>
#include <stdexcept>
#include <tuple>

#include "mesh/gmsh.hpp"
#include "util/text.hpp"

namespace contactbody {

namespace {

[[noreturn]] void reject(const char* name, const std::string& rule, double value) {
    Text msg;
    msg << name << " must be " << rule << " (got " << value << ")";
    throw std::invalid_argument(msg.str());
}

void require_positive(const char* name, double value) {
    if (!(std::isfinite(value) && value > 0)) reject(name, "finite and > 0", value);
}

// Selection matrix: one row per listed index, picking that entry of a vector of size n.
SparseMatrix selector(const std::vector<int>& rows, int n) {
    SparseMatrix s(static_cast<int>(rows.size()), n);
    std::vector<Eigen::Triplet<double>> t;
    for (size_t r = 0; r < rows.size(); ++r) t.emplace_back(static_cast<int>(r), rows[r], 1.0);
    s.setFromTriplets(t.begin(), t.end());
    return s;
}

}  // namespace

bool redistributes_normal(MassVariant v) {
    return v == MassVariant::redistributed_normal || v == MassVariant::redistributed_both ||
           v == MassVariant::redistributed_implicit_contact;
}

bool contact_at_end_of_step(MassVariant v) {
    return v == MassVariant::standard_implicit_contact || v == MassVariant::redistributed_implicit_contact;
}

bool reduced_edge_has_tangential_mass(const SceneParameters& p) {
    switch (p.reduced_edge) {
        case ReducedEdge::massless:
            return false;
        case ReducedEdge::tangential_mass:
            return true;
        case ReducedEdge::by_variant:
            break;
    }
    // The tangential mass where the variant has mass at the contact (0, 3, 4), the massless
    // edge for variants 1 and 2 (docs/decisions.md, "The reduced body's contact edge").
    return p.mass_matrix == MassVariant::standard || contact_at_end_of_step(p.mass_matrix);
}

void check_parameters(const SceneParameters& p) {
    if (p.dimension != 2 && p.dimension != 3) reject("dimension", "2 or 3", p.dimension);
    if (p.dimension == 3 && p.mesh.empty())
        throw std::invalid_argument(
            "mesh is empty: a 3D body comes from a Gmsh file of first-order "
            "tetrahedra (the built-in rectangle is 2D)");
    require_positive("width", p.width);
    require_positive("height", p.height);
    if (p.mesh.empty()) {  // the rectangle's cells (a mesh file is checked as it is read)
        if (p.nx < 1 || p.nx > max_cells_per_direction)
            reject("nx", "between 1 and " + std::to_string(max_cells_per_direction), p.nx);
        if (p.ny < 1 || p.ny > max_cells_per_direction)
            reject("ny", "between 1 and " + std::to_string(max_cells_per_direction), p.ny);
        if (static_cast<long>(p.nx + 1) * (p.ny + 1) > max_nodes)
            reject("nx", "such that (nx+1)(ny+1) <= " + std::to_string(max_nodes), p.nx);
    }
    require_positive("density", p.density);
    require_positive("mu", p.mu);
    if (!(std::isfinite(p.lambda) && p.lambda + p.mu > 0))
        reject("lambda", "finite with lambda + mu > 0", p.lambda);
    if (!(p.friction_coefficient >= 0 && p.friction_coefficient <= max_friction_coefficient))
        reject("friction_coefficient", "in [0, 100] (a hundred means a bond, not friction)",
               p.friction_coefficient);
    if (!(std::isfinite(p.max_energy) && p.max_energy >= 0))
        reject("max_energy", "finite and >= 0 (0: no limit)", p.max_energy);
    if (!(std::isfinite(p.max_energy_ratio) && p.max_energy_ratio >= 0))
        reject("max_energy_ratio", "finite and >= 0 (0: no limit)", p.max_energy_ratio);
    if (!(p.static_friction_ratio >= 1 && p.static_friction_ratio <= max_static_friction_ratio))
        reject("static_friction_ratio", "in [1, 10]", p.static_friction_ratio);
    if (!(std::isfinite(p.stribeck_velocity) && p.stribeck_velocity >= 0))
        reject("stribeck_velocity", "finite and >= 0 (0: no Stribeck term)", p.stribeck_velocity);
    if (!(p.viscous_friction >= 0 && p.viscous_friction <= max_viscous_friction))
        reject("viscous_friction", "in [0, 100] s/m", p.viscous_friction);
    const int variant = static_cast<int>(p.mass_matrix);
    if (variant < 0 || variant >= num_mass_variants) reject("mass_matrix", "0, 1, 2, 3 or 4", variant);
    if (redistributes_normal(p.mass_matrix) && p.mesh.empty() && p.ny < 2)
        reject("ny", ">= 2 for a redistributed mass matrix", p.ny);
    require_positive("internal_step", p.internal_step);
    require_positive("min_internal_step", p.min_internal_step);
    if (!(p.tolerance >= 0 && p.tolerance <= 0.5))
        reject("tolerance", "in [0, 0.5] (0: fixed substeps)", p.tolerance);
    // docs/decisions.md "Substeps chosen by a tolerance": the standard variant's full body
    // blows up under changing substep sizes though every fixed size keeps it.
    if (p.tolerance > 0 && p.mass_matrix == MassVariant::standard && p.modes == 0)
        throw std::invalid_argument(
            "tolerance > 0 with mass_matrix = 0 (standard) on the full body: its contact nodes "
            "carry normal mass and their contact holds at the midpoint, and under the changing "
            "substep sizes of the controller that contact created energy without bound (damped "
            "sliding on the paper's body: 1e6 times E(0) within 1.6 ms, where every fixed "
            "internal_step from 16 us to 0.25 us ended 1.28 ms at E = 0.163 J/m); use "
            "mass_matrix = 1, 3 or 4, or modes > 0 (the reduced body's edge carries no normal "
            "mass), or tolerance = 0 with a fixed internal_step");
    if (!(p.contact_tolerance > 0 && p.contact_tolerance < 1))
        reject("contact_tolerance", "in (0, 1)", p.contact_tolerance);
    if (p.force_control) require_positive("top_mass", p.top_mass);
    bool moving = false;
    for (int c = 0; c < 3; ++c) {
        const std::string name = std::string("initial_velocity_") + component_letter(c);
        const double v = p.initial_velocity[static_cast<size_t>(c)];
        if (!std::isfinite(v)) reject(name.c_str(), "finite", v);
        if (c >= p.dimension && v != 0)
            reject(name.c_str(), "0 for a 2D body (plane strain in x-y has no z)", v);
        moving = moving || v != 0;
    }
    if (p.static_initial_state && moving) {
        Text msg;
        msg << "initial_state = static starts the body at rest, so ";
        for (int c = 0; c < p.dimension; ++c)
            msg << (c == 0                 ? ""
                    : c + 1 == p.dimension ? " and "
                                           : ", ")
                << "initial_velocity_" << component_letter(c);
        msg << " must be 0 (got ";
        for (int c = 0; c < p.dimension; ++c)
            msg << (c ? ", " : "") << p.initial_velocity[static_cast<size_t>(c)];
        msg << " m/s): set them to 0, or use initial_state = paper";
        throw std::invalid_argument(msg.str());
    }
    if (!(std::isfinite(p.initial_gap) && p.initial_gap >= 0))
        reject("initial_gap", "finite and >= 0", p.initial_gap);
    if (!(std::isfinite(p.damping_mass) && p.damping_mass >= 0))
        reject("damping_mass", "finite and >= 0", p.damping_mass);
    if (!(std::isfinite(p.damping_stiffness) && p.damping_stiffness >= 0))
        reject("damping_stiffness", "finite and >= 0", p.damping_stiffness);
    if (p.modes < 0) reject("modes", ">= 0 (0: the full body)", p.modes);
    const int edge = static_cast<int>(p.reduced_edge);
    if (edge < 0 || edge > 2)
        reject("reduced_edge", "0 (by_variant), 1 (massless) or 2 (tangential_mass)", edge);
    if (p.modes > 0) check_reduced_edge(p);  // (a full body does not use reduced_edge)
}

// What a mesh of each dimension holds, as messages name it.
constexpr const char* cells_of_dimension[] = {"", "", "triangles, a 2D body", "tetrahedra, a 3D body"};

void check_dimension(const Mesh& mesh, const SceneParameters& p) {
    if (mesh.dim != p.dimension) {
        Text msg;
        msg << "mesh " << mesh.source << ", line 0: it holds " << cells_of_dimension[mesh.dim]
            << "; this model's "
            << "bodies are " << p.dimension << "D"
            << (p.dimension == 2 ? " (plane strain, forces in N/m) and need a mesh with first-order "
                                   "triangles in the x-y plane"
                                 : " (forces in N) and need a mesh with first-order tetrahedra");
        throw std::invalid_argument(msg.str());
    }
    if (!(p.lambda + 2 * p.mu / mesh.dim > 0)) {  // (in 2D, lambda + mu > 0: checked above)
        Text rule;
        rule << "such that lambda + 2 mu / " << mesh.dim << " > 0 for a " << mesh.dim
             << "D body (a positive bulk modulus)";
        reject("lambda", rule.str(), p.lambda);
    }
}

void check_reduced_edge(const SceneParameters& p) {
    if (p.reduced_edge == ReducedEdge::tangential_mass && p.mass_matrix == MassVariant::redistributed_both)
        throw std::invalid_argument(
            "reduced_edge = tangential_mass keeps the contact x dofs' mass, and mass_matrix = "
            "redistributed_both has none there: use reduced_edge = massless (or by_variant)");
}

Discretization discretize(const SceneParameters& p) {
    check_parameters(p);
    Discretization d;
    d.mesh = p.mesh.empty() ? make_structured_mesh(p.width, p.height, p.nx, p.ny)
                            : read_gmsh_mesh(p.mesh, max_nodes, d.mesh_notes);
    check_dimension(d.mesh, p);
    d.A = stiffness_matrix(d.mesh, p.lambda, p.mu);
    d.strain_energy = StrainEnergy(d.mesh, p.lambda, p.mu);

    const SparseMatrix scalar = scalar_mass_matrix(d.mesh, p.density);
    SparseMatrix redistributed;
    if (redistributes_normal(p.mass_matrix)) redistributed = redistributed_mass(d.mesh, scalar, d.mesh_notes);
    const int dim = d.mesh.dim;
    if (p.mass_matrix == MassVariant::redistributed_both)
        d.M = vector_mass_matrix(dim, redistributed, redistributed);
    else if (redistributes_normal(p.mass_matrix))
        d.M = vector_mass_matrix(dim, scalar, redistributed);
    else
        d.M = vector_mass_matrix(dim, scalar, scalar);
    d.contact_at_end_of_step = contact_at_end_of_step(p.mass_matrix);

    const int n = d.mesh.num_dofs();
    std::vector<char> clamped(n, 0), tied(n, 0);
    for (int node : d.mesh.top_nodes)  // under force control the plate moves along y only
        for (int c = 0; c < dim; ++c)
            (p.force_control && c == Mesh::normal ? tied : clamped)[d.mesh.dof(node, c)] = 1;
    d.free_index.assign(n, -1);
    for (int dof = 0; dof < n; ++dof) {
        if (clamped[dof] || tied[dof]) d.top_dofs.push_back(dof);
        if (clamped[dof]) {
            d.clamped_dofs.push_back(dof);
            continue;
        }
        d.moving_dofs.push_back(dof);
        if (tied[dof]) continue;
        d.free_index[dof] = static_cast<int>(d.free_dofs.size());
        d.free_dofs.push_back(dof);
    }
    const int nf = static_cast<int>(d.free_dofs.size()) + (p.force_control ? 1 : 0);
    std::vector<Eigen::Triplet<double>> t;
    for (int k = 0; k < static_cast<int>(d.free_dofs.size()); ++k) t.emplace_back(d.free_dofs[k], k, 1.0);
    if (p.force_control) {
        d.plate_index = nf - 1;
        d.plate_mass = p.top_mass;
        for (int node : d.mesh.top_nodes) {
            t.emplace_back(d.mesh.dof(node, Mesh::normal), d.plate_index, 1.0);
            d.free_index[d.mesh.dof(node, Mesh::normal)] = d.plate_index;
        }
    }
    d.expand.resize(n, nf);
    d.expand.setFromTriplets(t.begin(), t.end());
    const SparseMatrix R = d.expand.transpose(), Pc = selector(d.clamped_dofs, n);
    const SparseMatrix PcT = Pc.transpose(), Pt = selector(d.top_dofs, n);
    d.M_free_rows = R * d.M;
    d.A_free_rows = R * d.A;
    d.M_top_rows = Pt * d.M;
    d.A_top_rows = Pt * d.A;
    d.A_free_clamped = R * d.A * PcT;
    d.M_free_clamped = d.M_free_rows * PcT;
    d.A_free = R * d.A * d.expand;
    d.M_free = d.M_free_rows * d.expand;
    if (p.force_control) d.M_free.coeffRef(d.plate_index, d.plate_index) += p.top_mass;
    d.C.resize(n, n);
    if (p.damped()) d.C = p.damping_mass * d.M + p.damping_stiffness * d.A;
    d.C_free_rows = R * d.C;
    d.C_free_clamped = d.C_free_rows * PcT;
    d.C_free = d.C_free_rows * d.expand;
    for (int node : d.mesh.contact_nodes) {
        d.contact_y.push_back(d.free_index[d.mesh.dof(node, Mesh::normal)]);
        for (int t = 0; t < d.mesh.tangents(); ++t)
            d.contact_tangential[static_cast<size_t>(t)].push_back(
                d.free_index[d.mesh.dof(node, tangent_component(t))]);
    }
    return d;
}

bool same_discretization(const SceneParameters& a, const SceneParameters& b) {
    bool same = true;
    SceneParameters::for_each(
        [&](const char*, Reuse reuse, const auto& x, const auto& y) {
            if (reuse == Reuse::rebuilds_discretization) same = same && x == y;
        },
        a, b);
    return same;
}

void Discretization::remove_translation(const Eigen::VectorXd& u, Eigen::VectorXd& out) const {
    const int dim = mesh.dim;
    out.resize(u.size());
    for (Eigen::Index dof = 0; dof < u.size(); dof += dim)
        for (int c = 0; c < dim; ++c) out[dof + c] = u[dof + c] - u[c];
}

std::vector<int> Discretization::contact_unknowns() const {
    std::vector<int> dofs(contact_y);
    for (const std::vector<int>& tangent : contact_tangential)
        dofs.insert(dofs.end(), tangent.begin(), tangent.end());
    return dofs;
}

}  // namespace contactbody
