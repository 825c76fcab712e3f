// Where a reduced substep's time goes (issue 44): damped sliding from the static start (the
// paper's body, F = 0.3, beta = 4e-6 s, the foundation at 20 m/s, the top held) with one
// substep per step, after WARM unmeasured substeps. Per substep: wall microseconds pressed (the
// whole edge in contact) and lifted off (the same body with the top raised: no contact solve),
// Newton iterations, residual evaluations (each one product with the Delassus operator W),
// Newton factorizations and factorization updates (pattern changes), Gauss-Seidel sweeps, and the contact nodes whose
// state changed; and one product with the dense W alone, the unit of a substep's floor
// (issue 44). Pressed and lifted run in 5 alternating rounds of STEPS substeps each; the
// times are the rounds' medians, the counts their means. Prints one JSON object.
// With ONLY = pressed the lifted run is left out (for a profiler's window).
//   bench_contact_profile NX MODES DT STEPS [EDGE [ONLY]]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "reduced/reduced_stepper.hpp"
#include "simulation/simulation.hpp"

using namespace contactbody;
using namespace bench;

static double median(std::vector<double> x) {
    std::nth_element(x.begin(), x.begin() + x.size() / 2, x.end());
    return x[x.size() / 2];
}

int main(int argc, char** argv) {
    if (argc < 5) {
        std::fprintf(stderr, "usage: bench_contact_profile NX MODES DT STEPS [EDGE]\n");
        return 2;
    }
    SceneParameters p;
    p.nx = p.ny = std::atoi(argv[1]);
    p.modes = std::atoi(argv[2]);
    p.internal_step = std::atof(argv[3]);
    const int steps = std::atoi(argv[4]);
    if (argc > 5) p.reduced_edge = static_cast<ReducedEdge>(std::atoi(argv[5]));
    p.friction_coefficient = 0.3;
    p.damping_stiffness = 4e-6;
    p.static_initial_state = true;
    constexpr int warm = 50, rounds = 5;
    const double top = -2.5e-5;
    StepInputs in;
    in.foundation_velocity[0] = 20;
    in.top_displacement = top;

    auto t0 = Clock::now();
    Simulation sim(p, top);
    const double setup = seconds_since(t0);
    for (int k = 0; k < warm; ++k) sim.do_step(p.internal_step, in);
    // Lifted off: the same body with the top raised 1 mm, so that no node touches.
    const bool pressed_only = argc > 6 && std::string(argv[6]) == "pressed";
    StepInputs lifted = in;
    lifted.top_displacement = 1e-3;
    std::unique_ptr<Simulation> off;
    if (!pressed_only) {
        off = std::make_unique<Simulation>(p, top);
        for (int k = 0; k < warm; ++k) off->do_step(p.internal_step, lifted);
    }
    const ContactSolver& solver = sim.body().contact_solver();
    const long it0 = solver.newton_iterations(), res0 = solver.residual_evaluations(),
               fac0 = solver.factorizations(), upd0 = solver.factorization_updates();
    long sweeps = 0, changed = 0, active = 0;
    auto states = sim.body().last_contact().state;
    // Pressed and lifted in alternating rounds, the median of each: this machine's noise
    // moves single runs by 20 %.
    std::vector<double> pressed_us, lifted_us;
    for (int round = 0; round < rounds; ++round) {
        t0 = Clock::now();
        for (int k = 0; k < steps; ++k) {
            sim.do_step(p.internal_step, in);
            const Observables& o = sim.observables();
            sweeps += static_cast<long>(o.gauss_seidel_sweeps);
            active += static_cast<long>(o.active_contact_nodes);
            const auto& now = sim.body().last_contact().state;
            for (Eigen::Index i = 0; i < now.size(); ++i) changed += now[i] != states[i];
            states = now;
        }
        pressed_us.push_back(seconds_since(t0) / steps * 1e6);
        if (!off) continue;
        t0 = Clock::now();
        for (int k = 0; k < steps; ++k) off->do_step(p.internal_step, lifted);
        lifted_us.push_back(seconds_since(t0) / steps * 1e6);
        if (off->observables().active_contact_nodes != 0) {
            std::fprintf(stderr, "the lifted body still touches\n");
            return 1;
        }
    }
    const double pressed = median(pressed_us), lifted_median = off ? median(lifted_us) : 0;
    const double n = static_cast<double>(steps) * rounds;
    const double iterations = (solver.newton_iterations() - it0) / n;
    const double residuals = (solver.residual_evaluations() - res0) / n;
    const double factorizations = (solver.factorizations() - fac0) / n;
    const double updates = (solver.factorization_updates() - upd0) / n;
    const Eigen::MatrixXd& W = sim.body().last_contact_problem().W;
    const Eigen::Index unknowns = W.rows();
    // The unit the issue counts in: one product with the dense W (m x m), in this process.
    std::vector<double> product_us;
    Eigen::VectorXd x = sim.state().lambda, y(unknowns);
    for (int round = 0; round < rounds; ++round) {
        t0 = Clock::now();
        for (int k = 0; k < 1000; ++k) {
            y.noalias() = W * x;
            x[k % unknowns] += 1e-30 * y[0];  // a dependence, so that no product is skipped
        }
        product_us.push_back(seconds_since(t0) * 1e3);
    }
    // The residual's column count: with the sizes, it gives the matrices' reads (contact_profile.py).
    const auto* reduced = dynamic_cast<const ReducedStepper*>(&sim.body());
    const long residual_modes = reduced ? static_cast<long>(reduced->basis().residual.cols()) : 0;
    std::printf(
        "{\"nx\": %d, \"modes\": %d, \"residual_modes\": %ld, \"edge\": %d, \"dt\": %.6g, \"steps\": %d, "
        "\"setup_s\": %.6g, \"unknowns\": %ld, \"substep_us_pressed\": %.6g, "
        "\"substep_us_lifted\": %.6g, \"newton_iterations\": %.6g, "
        "\"residual_evaluations\": %.6g, \"factorizations\": %.6g, \"updates\": %.6g, \"sweeps\": %.6g, "
        "\"state_changes\": %.6g, \"active_nodes\": %.6g, \"w_product_us\": %.6g}\n",
        p.nx, p.modes, residual_modes, static_cast<int>(p.reduced_edge), p.internal_step, steps, setup,
        static_cast<long>(unknowns), pressed, lifted_median, iterations, residuals, factorizations, updates,
        sweeps / n, changed / n, active / n, median(product_us));
    return 0;
}
