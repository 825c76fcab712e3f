
#include "simulation/scheme_warnings.hpp"
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <vector>
#include "contact/friction_law.hpp"
#include "simulation/stability_map_data.hpp"
#include "util/text.hpp"

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

// beta scales with the time H / c_p (the problem's only time at fixed lambda/mu and mesh)
double beta_scale(const SceneParameters& p) {
    const double paper_time = paper_height / std::sqrt((paper_lambda + 2 * paper_mu) / paper_density);
    return p.height / p_wave_speed(p) / paper_time;
}

std::string friction_warning(const SceneParameters& p) {
    const double scale = beta_scale(p);
    const int c = nearest_column(p.ny);
    if (p.friction_coefficient >= wedging_friction(p)) {
        Text msg;
        msg << "friction_coefficient = " << p.friction_coefficient << ": no steady sliding state "
            << "exists here (foundation_velocity != 0): the clamped body wedges, its normal force "
            << "grows without bound, for F >= " << stability_map::damped_no_steady_state[c]
            << " on the damped stability map (nx = " << stability_map::damped_nx[c]
            << " cells across the height; measured on the paper's body, lambda/mu = 2)";
        return msg.str();
    }
    const double needed = stabilizing_beta(c, p.friction_coefficient) * scale;
    if (p.damping_stiffness >= needed) return "";
    Text msg;
    msg << "friction_coefficient = " << p.friction_coefficient
        << " with damping_stiffness = " << p.damping_stiffness
        << " s: steady sliding (foundation_velocity != 0) is unstable "
        << "here (the damped stability map, nx = " << stability_map::damped_nx[c] << " cells ";
    if (std::isfinite(needed)) {
        msg << "across the height): set damping_stiffness >= " << needed << " s";
    } else {
        const double largest = largest_stabilized_friction(c);
        msg << "across the height): no damping_stiffness up to " << stability_map::damped_largest_beta * scale
            << " s stabilizes it; F <= " << largest
            << " is stable with damping_stiffness >= " << stabilizing_beta(c, largest) * scale << " s";
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
        if (column == 0 || std::abs(std::log(cell.courant / courant)) < std::abs(std::log(column / courant)))
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
    Text msg;
    msg << "without friction, mass_matrix = " << variant << " gains energy at the contact here: "
        << "lambda/mu = " << ratio << ", Courant number c_p internal_step / h = " << courant
        << "; the frictionless map (lambda/mu = " << row << ", Courant " << column
        << ") measured max E / E(0) = " << growth << " in 20 ms with nothing put in. Use "
        << "mass_matrix = 4 (redistributed_implicit_contact: it cannot gain energy at contact)";
    if (smaller_stable_courant > 0)
        msg << ", or internal_step <= " << smaller_stable_courant * h / p_wave_speed(p) << " s";
    return msg.str();
}

// The rate map's growth at (column nx, F, slope, beta index); nan where not measured.
double rate_growth(int nx, double friction, double slope, size_t beta) {
    for (const auto& row : stability_map::rate)
        if (row.nx == nx && row.friction == friction && row.slope == slope) return row.growth[beta];
    return std::numeric_limits<double>::quiet_NaN();
}

// Whether every measured point the setting lies between is stable: the measured F at or
// around it (the larger growth of the two, as for the damped map), the largest measured
// dF/dv at or below it and the largest measured beta at or below it (growth falls with both,
// so the point is judged no better than it is).
struct RatePlace {
    bool covered = false;
    int nx = 0;
    double f_below = 0, f_above = 0, slope = 0;
    size_t beta = 0;
};

RatePlace place_on_rate_map(const SceneParameters& p, double F, double dF, double beta) {
    RatePlace r;
    std::vector<int> columns;
    double f_min = stability_map::inf, f_max = -stability_map::inf;
    double s_min = stability_map::inf, s_max = -stability_map::inf;
    for (const auto& row : stability_map::rate) {
        if (std::find(columns.begin(), columns.end(), row.nx) == columns.end()) columns.push_back(row.nx);
        f_min = std::min(f_min, row.friction), f_max = std::max(f_max, row.friction);
        s_min = std::min(s_min, row.slope), s_max = std::max(s_max, row.slope);
    }
    r.nx = columns.front();
    for (int nx : columns)
        if (std::abs(std::log(double(nx) / p.ny)) < std::abs(std::log(double(r.nx) / p.ny))) r.nx = nx;
    if (!(F >= f_min && F <= f_max && dF >= s_min && dF <= s_max)) return r;
    r.f_below = f_min, r.f_above = f_max, r.slope = s_min;
    for (const auto& row : stability_map::rate) {
        if (row.nx != r.nx) continue;
        if (row.friction <= F) r.f_below = std::max(r.f_below, row.friction);
        if (row.friction >= F) r.f_above = std::min(r.f_above, row.friction);
        if (row.slope <= dF) r.slope = std::max(r.slope, row.slope);
    }
    for (size_t b = 0; b < std::size(stability_map::rate_betas); ++b)
        if (stability_map::rate_betas[b] <= beta && !std::isnan(rate_growth(r.nx, r.f_below, r.slope, b)) &&
            !std::isnan(rate_growth(r.nx, r.f_above, r.slope, b)))
            r.beta = b;
    r.covered = !std::isnan(rate_growth(r.nx, r.f_below, r.slope, r.beta)) &&
                !std::isnan(rate_growth(r.nx, r.f_above, r.slope, r.beta));
    return r;
}

double rate_map_growth(const RatePlace& r, double slope, size_t beta) {
    return std::max(rate_growth(r.nx, r.f_below, slope, beta), rate_growth(r.nx, r.f_above, slope, beta));
}

// The largest measured dF/dv < 0 at which every measured point of the rate map grows (0: none).
double every_point_grows() {
    double largest = 0;
    for (const auto& row : stability_map::rate) {
        if (!(row.slope < 0)) continue;
        bool all = true;
        for (const auto& other : stability_map::rate)
            if (other.slope == row.slope)
                for (double g : other.growth) all = all && (std::isnan(g) || g > 0);
        if (all && (largest == 0 || row.slope > largest)) largest = row.slope;
    }
    return largest;
}

std::string rate_warning(const SceneParameters& p, double speed) {
    double dF = 0;
    const double F = rate_law(p).coefficient(p.friction_coefficient, speed, &dF);
    const double scale = beta_scale(p);
    Text law;
    law << "with the slip-rate law at the sliding speed |foundation_velocity| = " << speed
        << " m/s, F = " << F << " and dF/dv = " << dF << " s/m";
    const RatePlace r = place_on_rate_map(p, F, dF, p.damping_stiffness / scale);
    if (!r.covered) {
        // Outside the rate map: the constant-F map at F(V), which knows nothing of dF/dv.
        SceneParameters at_speed = p;
        at_speed.friction_coefficient = F;
        const std::string constant = friction_warning(at_speed);
        if (constant.empty() && dF >= 0) return "";  // dF/dv >= 0 only damps the interface
        double f_min = stability_map::inf, f_max = 0, s_min = stability_map::inf, s_max = -s_min;
        for (const auto& row : stability_map::rate) {
            f_min = std::min(f_min, row.friction), f_max = std::max(f_max, row.friction);
            s_min = std::min(s_min, row.slope), s_max = std::max(s_max, row.slope);
        }
        Text msg;
        msg << "settings outside the measured maps: " << law.str() << " lie outside the rate map (F " << f_min
            << " to " << f_max << ", dF/dv " << s_min << " to " << s_max
            << " s/m; examples/results/rate_stability.md), so this judges the "
               "map of constant F at F(V) alone, which ignores dF/dv";
        if (dF < 0) {
            msg << " (dF/dv < 0 destabilizes";
            if (const double s = every_point_grows(); s < 0)
                msg << ": on the rate map dF/dv = " << s << " s/m made every measured point grow, "
                    << "up to damping_stiffness = "
                    << stability_map::rate_betas[std::size(stability_map::rate_betas) - 1]
                    << " s on the paper's body";
            msg << ")";
        }
        msg << (constant.empty() ? ": that map sees no growth" : ": " + constant);
        return msg.str();
    }
    const double beta_grid = stability_map::rate_betas[r.beta];
    if (rate_map_growth(r, r.slope, r.beta) < 0) return "";
    Text msg;
    msg << law.str() << ", damping_stiffness = " << p.damping_stiffness
        << " s: steady sliding is unstable on the rate map (nx = " << r.nx
        << " cells across the height, measured F " << r.f_below;
    if (r.f_above != r.f_below) msg << " and " << r.f_above;
    msg << ", dF/dv " << r.slope << " s/m, beta " << beta_grid * scale << " s)";
    // What would do: a larger measured dF/dv at this beta, or a larger measured beta.
    double slope_needed = stability_map::inf;
    for (const auto& row : stability_map::rate)
        if (row.nx == r.nx && row.friction == r.f_below && row.slope > r.slope &&
            rate_map_growth(r, row.slope, r.beta) < 0)
            slope_needed = std::min(slope_needed, row.slope);
    double beta_needed = stability_map::inf;
    for (size_t b = r.beta + 1; b < std::size(stability_map::rate_betas); ++b)
        if (rate_map_growth(r, r.slope, b) < 0) {
            beta_needed = stability_map::rate_betas[b] * scale;
            break;
        }
    if (std::isfinite(slope_needed) || std::isfinite(beta_needed)) msg << ": stable with";
    if (std::isfinite(slope_needed)) msg << " dF/dv >= " << slope_needed << " s/m at this damping";
    if (std::isfinite(slope_needed) && std::isfinite(beta_needed)) msg << ", or";
    if (std::isfinite(beta_needed)) msg << " damping_stiffness >= " << beta_needed << " s at this dF/dv";
    if (!std::isfinite(slope_needed) && !std::isfinite(beta_needed))
        msg << ": no measured dF/dv or damping_stiffness stabilizes it";
    msg << " (measured on the paper's body, lambda/mu = 2; beta scaled by H / c_p";
    if (std::abs(p.lambda / p.mu - 2) > 0.5)
        msg << "; lambda/mu here = " << p.lambda / p.mu << ", not measured";
    msg << ")";
    return msg.str();
}

}  // namespace

double wedging_friction(const SceneParameters& p) {
    if (!p.mesh.empty()) return std::numeric_limits<double>::infinity();  // not measured
    return stability_map::damped_no_steady_state[nearest_column(p.ny)];
}

std::string massless_edge_warning(const SceneParameters& p) {
    if (p.modes == 0 || reduced_edge_has_tangential_mass(p) || p.friction_coefficient == 0) return "";
    const double c_over_b = (p.lambda + 3 * p.mu) / (p.lambda + p.mu);
    const bool weakening = p.stribeck_velocity > 0 && p.static_friction_ratio > 1;
    if (!weakening && p.friction_coefficient <= c_over_b) return "";
    Text msg;
    msg << "modes = " << p.modes << " with the massless contact edge: the edge has no tangential "
        << "mass, so with ";
    if (weakening)
        msg << "friction that drops with the slip rate (static_friction_ratio = " << p.static_friction_ratio
            << " over stribeck_velocity = " << p.stribeck_velocity << " m/s)";
    else
        msg << "F = " << p.friction_coefficient << " above c/b = (lambda+3mu)/(lambda+mu) = " << c_over_b;
    msg << " a substep can have several solutions, or none the solver reaches, at any substep "
           "size (as with mass_matrix = redistributed_both, paper section 6): reducing "
           "internal_step does not help. "
        << (p.mass_matrix == MassVariant::redistributed_both
                ? "mass_matrix = redistributed_normal with reduced_edge = tangential_mass, or modes = 0 with "
                  "mass_matrix = redistributed_normal, keeps the tangential mass"
                : "reduced_edge = tangential_mass keeps the edge's tangential mass (or modes = 0, the full "
                  "body)");
    return msg.str();
}

std::string long_reduced_edge_warning(const SceneParameters& p, long contact_unknowns, long unknowns) {
    const double m = static_cast<double>(contact_unknowns), ratio = m * m / static_cast<double>(unknowns);
    if (p.modes == 0 || !(ratio >= reduced_edge_ratio)) return "";
    Text msg;  // numbers as doubles: one formatting routine (the FMU's size, docs/building.md)
    msg << "modes > 0 on a long contact edge: the reduced body keeps the operators of its " << m
        << " contact unknowns dense, and where (contact unknowns)^2 reached " << reduced_edge_ratio
        << " times the full body's unknowns (here " << ratio << " times its " << static_cast<double>(unknowns)
        << ") the full body (modes = 0) was about as fast on the measured pad and faster beyond, in a "
           "fraction of the memory and start time (docs/meshes.md, \"A refined contact boundary\"): "
           "consider modes = 0";
    return msg.str();
}

std::string scheme_warning(const SceneParameters& p, double sliding_speed) {
    if (!p.mesh.empty()) {  // the maps place a body by the rectangle's cells: none for a mesh
        if (p.friction_coefficient > 0 && sliding_speed != 0 && !p.damped() && p.dimension == 3)
            return "settings not covered: the stability maps behind these warnings were measured "
                   "on 2D bodies, and no map covers a 3D body (the mesh " +
                   p.mesh +
                   "); on every "
                   "2D body measured, undamped steady sliding with friction was unstable for "
                   "every F > 0: consider damping_stiffness";
        if (p.friction_coefficient > 0 && sliding_speed != 0 && !p.damped())
            return "settings not covered: the stability maps behind these warnings were measured "
                   "on the rectangle, and say nothing of the mesh " +
                   p.mesh +
                   "; there, undamped "
                   "steady sliding with friction was unstable for every F > 0 on every mesh "
                   "measured: consider damping_stiffness";
        return "";
    }
    const bool rate = p.friction_coefficient > 0 && rate_law(p).active();
    const std::string why = rate                         ? rate_warning(p, sliding_speed)
                            : p.friction_coefficient > 0 ? friction_warning(p)
                                                         : frictionless_warning(p);
    if (why.empty() || why.rfind("settings ", 0) == 0) return why;
    return "settings in a measured unstable region: " + why;
}

}  // namespace contactbody
