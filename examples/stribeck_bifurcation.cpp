// Does one step of the full body have several solutions with velocity-
// weakening friction? Runs the body with one substep per step and, after each, solves that
// substep's contact problem (Stepper::last_contact_problem) again from a family of starting
// multipliers; counts the distinct converged solutions. At the first substep with several,
// it restarts that substep from each other solution as warm start (Newton stops at once on
// an exact solution) and runs on: how far the trajectories part.
// With MODES and EDGE the reduced body (modes, reduced_edge: 1 massless, 2 tangential_mass).
//   stribeck_bifurcation MASS_MATRIX NX DT STEPS F_D RATIO V_S V BETA [MODES EDGE]
// Prints JSON.
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "simulation/simulation.hpp"

using namespace contactbody;

namespace {

// Distinct solutions (relative 1e-7 of the largest multiplier) of p from the starts.
std::vector<Eigen::VectorXd> solutions(const ContactProblem& p, const Eigen::VectorXd& solved, int* failed) {
    const Eigen::Index n = p.gap_limit.size();
    const double scale = std::max(1e-300, solved.lpNorm<Eigen::Infinity>());
    std::vector<Eigen::VectorXd> starts = {solved, Eigen::VectorXd::Zero(2 * n)};
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (const double t : {-1.0, -0.5, 0.0, 0.5, 1.0}) {  // tangential parts of the cone
        Eigen::VectorXd s = solved;
        for (Eigen::Index i = 0; i < n; ++i) s[n + i] = t * p.coefficient(i, 0) * -solved[i];
        starts.push_back(s);
    }
    for (int k = 0; k < 20; ++k) {  // random starts around the solution's size
        Eigen::VectorXd s(2 * n);
        for (Eigen::Index i = 0; i < n; ++i) {
            s[i] = solved[i] * (1 + unit(rng));
            s[n + i] = unit(rng) * p.coefficient(i, 0) * -s[i];
        }
        starts.push_back(s);
    }
    std::vector<Eigen::VectorXd> found;
    ContactSolver solver;
    *failed = 0;
    for (Eigen::VectorXd lambda : starts) {
        try {
            solver.solve(p, ContactSolverOptions{1e-12, 200, 0}, lambda);
        } catch (const ContactSolveError&) {
            ++*failed;
            continue;
        }
        bool known = false;
        for (const Eigen::VectorXd& f : found)
            known = known || (f - lambda).lpNorm<Eigen::Infinity>() <= 1e-7 * scale;
        if (!known) found.push_back(lambda);
    }
    return found;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 10 && argc != 12) {
        std::fprintf(
            stderr,
            "usage: stribeck_bifurcation MASS_MATRIX NX DT STEPS F_D RATIO V_S V BETA [MODES EDGE]\n");
        return 2;
    }
    SceneParameters p;
    p.mass_matrix = static_cast<MassVariant>(std::atoi(argv[1]));
    p.nx = p.ny = std::atoi(argv[2]);
    const double dt = std::atof(argv[3]);
    const int steps = std::atoi(argv[4]);
    p.internal_step = dt;
    p.friction_coefficient = std::atof(argv[5]);
    p.static_friction_ratio = std::atof(argv[6]);
    p.stribeck_velocity = std::atof(argv[7]);
    p.damping_stiffness = std::atof(argv[9]);
    p.static_initial_state = true;
    p.max_energy_ratio = 0;
    if (argc == 12) {
        p.modes = std::atoi(argv[10]);
        p.reduced_edge = static_cast<ReducedEdge>(std::atoi(argv[11]));
    }
    StepInputs in;
    in.foundation_velocity[0] = std::atof(argv[8]);
    in.top_displacement = -2.5e-5;
    Simulation sim(p, in.top_displacement);

    int first = -1, most = 1, several = 0, failed_starts = 0;
    std::vector<Eigen::VectorXd> alternatives;
    SimulationSnapshot before_first;
    for (int k = 0; k < steps; ++k) {
        const SimulationSnapshot before = sim.snapshot();
        sim.do_step(dt, in);
        int failed = 0;
        const auto found = solutions(sim.body().last_contact_problem(), sim.state().lambda, &failed);
        failed_starts += failed;
        most = std::max(most, static_cast<int>(found.size()));
        if (found.size() > 1) {
            ++several;
            if (first < 0) {
                first = k;
                before_first = before;
                alternatives = found;
            }
        }
    }
    const double energy_end = sim.observables().energy;
    std::printf(
        "{\"mass_matrix\": %s, \"nx\": %d, \"dt\": %g, \"steps\": %d, \"most_solutions\": %d, "
        "\"substeps_with_several\": %d, \"first\": %d, \"failed_starts\": %d, \"energy_end\": %.17g, "
        "\"modes\": %d, \"reduced_edge\": %d",
        argv[1], p.nx, dt, steps, most, several, first, failed_starts, energy_end, p.modes,
        p.modes > 0 ? (reduced_edge_has_tangential_mass(p) ? 2 : 1) : 0);
    // The trajectories from each solution of the first ambiguous substep.
    std::printf(", \"branches\": [");
    for (size_t b = 0; b < alternatives.size(); ++b) {
        Simulation branch(p, in.top_displacement);
        SimulationSnapshot start = before_first;
        start.state.lambda = alternatives[b];  // the warm start: Newton stops on it at once
        branch.restore(start);
        branch.do_step(dt, in);
        const double chosen = (branch.state().lambda - alternatives[b]).lpNorm<Eigen::Infinity>();
        for (int k = first + 1; k < steps; ++k) branch.do_step(dt, in);
        const Observables& o = branch.observables();
        std::printf(
            "%s{\"took_it\": %s, \"energy_end\": %.17g, \"friction_force_end\": %.17g, "
            "\"slipping_end\": %d}",
            b ? ", " : "", chosen <= 1e-9 * alternatives[b].lpNorm<Eigen::Infinity>() ? "true" : "false",
            o.energy, o.friction_force[0], o.slipping_contact_nodes);
    }
    std::printf("]}\n");
    return 0;
}
