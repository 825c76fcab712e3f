#include "scheme_warnings.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>

#include "stability_map_data.hpp"

namespace contactbody {

namespace {

double p_wave_speed(const SceneParameters& p) { return std::sqrt((p.lambda + 2 * p.mu) / p.density); }

// The maps' body: the paper's 0.1 m square, lambda = 300 MPa, mu = 150 MPa, rho = 1000 kg/m3.
constexpr double paper_height = 0.1, paper_lambda = 300e6, paper_mu = 150e6, paper_density = 1000;

// The measured mesh nearest (in log) to the body's cells across its height.
int nearest_column(int cells) {
    int best = 0;
    for (int k = 1; k < static_cast<int>(std::size(stability_map::damped_nx)); ++k)
        if (std::abs(std::log(double(stability_map::damped_nx[k]) / cells)) <
            std::abs(std::log(double(stability_map::damped_nx[best]) / cells)))
            best = k;
    return best;
}

// Smallest stabilizing beta (paper's units) on column c for friction F: the larger of the
// measured F's around it (the map is not monotone in F about the admissible steady state, so
// no interpolation is safe); inf where one of them has no stabilizing beta, or beyond the
// measured F.
double stabilizing_beta(int c, double friction) {
    const stability_map::DampedRow* below = nullptr;
    for (const auto& row : stability_map::damped) {
        if (row.beta[c] == stability_map::unmeasured) continue;
        if (row.friction < friction) {
            below = &row;
            continue;
        }
        if (row.friction == friction || !below) return row.beta[c];
        return std::max(below->beta[c], row.beta[c]);
    }
    return stability_map::inf;
}

// Largest measured F on column c that some beta of the map stabilizes.
double largest_stabilized_friction(int c) {
    double largest = 0;
    for (const auto& row : stability_map::damped)
        if (row.beta[c] != stability_map::unmeasured && std::isfinite(row.beta[c]))
            largest = std::max(largest, row.friction);
    return largest;
}

std::string friction_warning(const SceneParameters& p) {
    // beta scales with the time H / c_p (the problem's only time at fixed lambda/mu and mesh)
    const double paper_time =
        paper_height / std::sqrt((paper_lambda + 2 * paper_mu) / paper_density);
    const double scale = p.height / p_wave_speed(p) / paper_time;
    const int c = nearest_column(p.ny);
    if (p.friction_coefficient >= wedging_friction(p)) {
        std::ostringstream msg;
        msg << "friction_coefficient = " << p.friction_coefficient << ": no steady sliding state "
            << "exists here (foundation_velocity != 0): the clamped body wedges, its normal force "
            << "grows without bound, for F >= " << stability_map::damped_no_steady_state[c]
            << " on the damped stability map (nx = " << stability_map::damped_nx[c]
            << " cells across the height; measured on the paper's body, lambda/mu = 2)";
        return msg.str();
    }
    const double needed = stabilizing_beta(c, p.friction_coefficient) * scale;
    if (p.damping_stiffness >= needed) return "";
    std::ostringstream msg;
    msg << "friction_coefficient = " << p.friction_coefficient << " with damping_stiffness = "
        << p.damping_stiffness << " s: steady sliding (foundation_velocity != 0) is unstable "
        << "here (the damped stability map, nx = " << stability_map::damped_nx[c] << " cells ";
    if (std::isfinite(needed)) {
        msg << "across the height): set damping_stiffness >= " << needed << " s";
    } else {
        const double largest = largest_stabilized_friction(c);
        msg << "across the height): no damping_stiffness up to "
            << stability_map::damped_largest_beta * scale << " s stabilizes it; F <= " << largest
            << " is stable with damping_stiffness >= " << stabilizing_beta(c, largest) * scale
            << " s";
    }
    msg << " (measured on the paper's body, lambda/mu = 2; beta scaled by H / c_p";
    if (std::abs(p.lambda / p.mu - 2) > 0.5)
        msg << "; lambda/mu here = " << p.lambda / p.mu << ", not measured";
    msg << ")";
    return msg.str();
}

std::string frictionless_warning(const SceneParameters& p) {
    const int variant = static_cast<int>(p.mass_matrix);
    if (p.mass_matrix != MassVariant::standard && p.mass_matrix != MassVariant::redistributed_normal &&
        p.mass_matrix != MassVariant::redistributed_both)
        return "";
    const double h = std::min(p.width / p.nx, p.height / p.ny);
    const double courant = p_wave_speed(p) * p.internal_step / h;
    const double ratio = p.lambda / p.mu;
    // The measured lambda/mu at or below this one (growth rises with it), the nearest Courant.
    double row = -1, column = 0;
    for (const auto& cell : stability_map::frictionless) {
        if (cell.lambda_over_mu <= ratio) row = std::max(row, cell.lambda_over_mu);
        if (column == 0 || std::abs(std::log(cell.courant / courant)) <
                               std::abs(std::log(column / courant)))
            column = cell.courant;
    }
    double growth = 1, smaller_stable_courant = 0;
    for (const auto& cell : stability_map::frictionless) {
        if (cell.variant != variant || cell.lambda_over_mu != row) continue;
        if (cell.courant == column) growth = cell.max_energy_ratio;
        if (cell.courant < column && cell.max_energy_ratio <= frictionless_growth_limit)
            smaller_stable_courant = std::max(smaller_stable_courant, cell.courant);
    }
    if (!(growth > frictionless_growth_limit)) return "";
    std::ostringstream msg;
    msg << "without friction, mass_matrix = " << variant << " gains energy at the contact here: "
        << "lambda/mu = " << ratio << ", Courant number c_p internal_step / h = " << courant
        << "; the frictionless map (lambda/mu = " << row << ", Courant " << column
        << ") measured max E / E(0) = " << growth << " in 20 ms with nothing put in. Use "
        << "mass_matrix = 4 (redistributed_implicit_contact: it cannot gain energy at contact)";
    if (smaller_stable_courant > 0)
        msg << ", or internal_step <= " << smaller_stable_courant * h / p_wave_speed(p) << " s";
    return msg.str();
}

}  // namespace

double wedging_friction(const SceneParameters& p) {
    return stability_map::damped_no_steady_state[nearest_column(p.ny)];
}

std::string scheme_warning(const SceneParameters& p) {
    const std::string why = p.friction_coefficient > 0 ? friction_warning(p) : frictionless_warning(p);
    return why.empty() ? why : "settings in a measured unstable region: " + why;
}

}  // namespace contactbody
