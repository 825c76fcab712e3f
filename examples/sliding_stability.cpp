// Linear stability of steady sliding: every contact node in
// contact (u_y = 0 on the bottom edge) and slipping against the foundation moving in +x, so
// the friction force on the body is F times the normal reaction p at each contact node.
// With p = (M u'' + A u) on the contact y rows, the x rows read M_x u'' + A_x u = F p, and on
// the remaining free dofs r
//   (M_rr - F E M_yr) u_r'' + (A_rr - F E A_yr) u_r = 0,
// E moving contact node i's y row onto its x row. Modes u = phi e^{s t} with
// s^2 = -eig(M_F^-1 K_F); for F = 0 the pencil is symmetric definite and every s is imaginary.
// For F > 0 it is not symmetric: a complex eigenvalue gives Re s > 0, a growing mode.
// Prints JSON: the largest growth rate Re s [1/s], its frequency |Im s| / 2 pi [Hz], and the
// number of growing modes.   sliding_stability NX FRICTION MASS_MATRIX [BETA ...]
// (Massless dofs, redistributed_both's contact x dofs, are condensed out first.)
//
// Rayleigh damping C = alpha M + beta A adds s C_F with the same friction row operation, so
// C_F = alpha M_F + beta K_F exactly and the damped pencil s^2 M_F + s C_F + K_F factors
// through the undamped eigenvalues omega^2 = eig(M_F^-1 K_F): each gives the two roots of
//   s^2 + (alpha + beta omega^2) s + omega^2 = 0.
// (Massless rows read (1 + beta s)(K_F phi) = 0, so their static condensation still holds.)
// For each BETA given (alpha = 0) the output's "damped" list has the largest Re s over all
// modes, negative when every mode decays.
//
// Slip-rate dependent friction (--slope=DFDV, s/m: F'(v) at the sliding speed):
// the x row's friction is F(v) p with v = V - u_x' the slip rate, so its first variation is
// F dp - F' p_i du_x': an interface damping D = diag(F' p_i) on the contact x dofs (velocity
// strengthening, F' > 0, damps). p_i is the steady sliding reaction under the clamp's
// displacement (--top=U, m, default the FMU's -2.5e-5): u_y = 0 at the contact nodes and
// K_F u_r = -(A_rC - F E A_yC) u_C. D is not proportional to M or A, so each BETA then solves
// the quadratic pencil s^2 M_F + s (beta K_F + D) + K_F through its companion matrix (2n
// unknowns; redistributed_both's massless x dofs are refused: D sits on them).
//
// Which nodes touch (--lift-off): by default every contact node is in contact, the
// linearization of the stability maps. With friction the steady reactions of that state are not
// all compressive (F = 0.3 already pulls on the last node), so --lift-off finds the steady
// sliding state's contact set by active sets: drop the nodes pulled on, add back the ones that
// penetrate, until the state is admissible; a lifted node's dofs are then free of contact and
// friction (its massless y dof, under redistributed_normal, is condensed out like the others).
#include <chrono>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "assembly/discretization.hpp"

using namespace contactbody;

// The largest Re s of the quadratic pencil s^2 M + s C + K (M invertible), and its |Im s|.
static std::pair<double, double> quadratic_growth(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C,
                                                  const Eigen::MatrixXd& K) {
    const Eigen::Index n = M.rows();
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(M);
    Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    companion.topRightCorner(n, n).setIdentity();
    companion.bottomLeftCorner(n, n) = -lu.solve(K);
    companion.bottomRightCorner(n, n) = -lu.solve(C);
    const Eigen::EigenSolver<Eigen::MatrixXd> eig(companion, false);
    if (eig.info() != Eigen::Success)
        throw std::runtime_error("the eigenvalue iteration of the companion matrix did not converge");
    double rate = -1e300, imag = 0;
    for (Eigen::Index k = 0; k < 2 * n; ++k)
        if (eig.eigenvalues()[k].real() > rate) {
            rate = eig.eigenvalues()[k].real();
            imag = std::abs(eig.eigenvalues()[k].imag());
        }
    return {rate, imag};
}

// The linearized steady sliding with the nodes in `touching` in contact (u_y = 0, friction
// F p on the x row): mass and stiffness on the free dofs r, the steady state under the clamp.
struct Linearization {
    std::vector<Eigen::Index> rows, position;  // r, and where a free dof lands in r (-1: none)
    Eigen::MatrixXd MF, KF;
    Eigen::VectorXd pressure;  // steady reaction p_i of every contact node (0 if lifted)
    Eigen::VectorXd lift;      // steady u_y of every contact node (0 if touching)
};

static Linearization linearize(const Discretization& d, const Eigen::MatrixXd& M, const Eigen::MatrixXd& A,
                               const std::vector<bool>& touching, double F, double top) {
    const Eigen::Index nf = M.rows();
    Linearization L;
    std::vector<bool> held(static_cast<size_t>(nf), false);
    for (size_t i = 0; i < d.contact_y.size(); ++i)
        if (touching[i]) held[static_cast<size_t>(d.contact_y[i])] = true;
    L.position.assign(static_cast<size_t>(nf), -1);
    for (Eigen::Index k = 0; k < nf; ++k)
        if (!held[static_cast<size_t>(k)]) {
            L.position[static_cast<size_t>(k)] = static_cast<Eigen::Index>(L.rows.size());
            L.rows.push_back(k);
        }
    L.MF = M(L.rows, L.rows);
    L.KF = A(L.rows, L.rows);
    for (size_t i = 0; i < d.contact_y.size(); ++i) {
        if (!touching[i]) continue;
        const Eigen::Index x = L.position[static_cast<size_t>(d.contact_tangential[0][i])];
        L.MF.row(x) -= F * M(d.contact_y[i], L.rows);
        L.KF.row(x) -= F * A(d.contact_y[i], L.rows);
    }
    // The steady state: K_F u_r = -(A_rC - F E A_yC) u_C, then p = A_yr u_r + A_yC u_C.
    Eigen::VectorXd clamped_u(static_cast<Eigen::Index>(d.clamped_dofs.size()));
    for (size_t k = 0; k < d.clamped_dofs.size(); ++k)
        clamped_u[static_cast<Eigen::Index>(k)] = d.clamped_dofs[k] % 2 == 1 ? top : 0.0;
    const Eigen::VectorXd clamp_force = d.A_free_clamped * clamped_u;
    Eigen::VectorXd rhs = -clamp_force(L.rows);
    for (size_t i = 0; i < d.contact_y.size(); ++i)
        if (touching[i])
            rhs[L.position[static_cast<size_t>(d.contact_tangential[0][i])]] +=
                F * clamp_force[d.contact_y[i]];
    const Eigen::VectorXd steady = L.KF.partialPivLu().solve(rhs);
    const Eigen::Index nc = static_cast<Eigen::Index>(d.contact_y.size());
    L.pressure = Eigen::VectorXd::Zero(nc);
    L.lift = Eigen::VectorXd::Zero(nc);
    for (Eigen::Index i = 0; i < nc; ++i) {
        const int y = d.contact_y[static_cast<size_t>(i)];
        if (touching[static_cast<size_t>(i)])
            L.pressure[i] = A(y, L.rows).dot(steady) + clamp_force[y];
        else
            L.lift[i] = steady[L.position[static_cast<size_t>(y)]];
    }
    return L;
}

int main(int argc, char** argv) {
    double slope = 0, top = -2.5e-5;
    bool lift_off = false;
    std::vector<const char*> args;
    for (int a = 1; a < argc; ++a) {
        if (std::strncmp(argv[a], "--slope=", 8) == 0)
            slope = std::atof(argv[a] + 8);
        else if (std::strncmp(argv[a], "--top=", 6) == 0)
            top = std::atof(argv[a] + 6);
        else if (std::strcmp(argv[a], "--lift-off") == 0)
            lift_off = true;
        else
            args.push_back(argv[a]);
    }
    if (args.size() < 3) {
        std::fprintf(stderr,
                     "usage: sliding_stability [--slope=DFDV] [--top=U] [--lift-off] NX "
                     "FRICTION MASS_MATRIX [BETA ...]\n");
        return 2;
    }
    SceneParameters p;
    p.nx = p.ny = std::atoi(args[0]);
    p.friction_coefficient = std::atof(args[1]);
    p.mass_matrix = static_cast<MassVariant>(std::atoi(args[2]));
    std::vector<double> betas;
    for (size_t a = 3; a < args.size(); ++a) betas.push_back(std::atof(args[a]));
    const auto t0 = std::chrono::steady_clock::now();
    const Discretization d = discretize(p);
    const Eigen::MatrixXd M(d.M_free), A(d.A_free);
    const double F = p.friction_coefficient;
    const size_t nc = d.contact_y.size();

    std::vector<bool> touching(nc, true);
    Linearization L = linearize(d, M, A, touching, F, top);
    int active_set_iterations = 0;
    // Active sets: each pass drops the pulled nodes and takes back the penetrating ones. A
    // contact set seen before means the passes cycle: no admissible set is found.
    std::set<std::vector<bool>> seen{touching};
    for (; lift_off; ++active_set_iterations) {
        bool changed = false;
        for (size_t i = 0; i < nc; ++i) {
            const Eigen::Index k = static_cast<Eigen::Index>(i);
            if (touching[i] && L.pressure[k] < 0)
                touching[i] = false, changed = true;
            else if (!touching[i] && L.lift[k] < 0)
                touching[i] = true, changed = true;
        }
        if (!changed) break;
        if (!seen.insert(touching).second) {
            std::fprintf(stderr,
                         "sliding_stability: no admissible steady contact set (the "
                         "active sets cycle after %d passes)\n",
                         active_set_iterations + 1);
            return 1;
        }
        L = linearize(d, M, A, touching, F, top);
    }
    const Eigen::Index n = static_cast<Eigen::Index>(L.rows.size());
    const Eigen::MatrixXd& MF = L.MF;
    const Eigen::MatrixXd& KF = L.KF;
    // Massless dofs (the contact x dofs of redistributed_both, a lifted node's y dof under
    // redistributed_normal: their rows of M_F vanish) are algebraic: condense them,
    // K_rr - K_rc K_cc^-1 K_cr, before the eigenvalues. Their columns of M_F vanish too.
    std::vector<Eigen::Index> massive, massless;
    for (Eigen::Index a = 0; a < n; ++a)
        (MF.row(a).cwiseAbs().maxCoeff() == 0 ? massless : massive).push_back(a);
    const Eigen::MatrixXd Mm = MF(massive, massive);
    Eigen::MatrixXd Km = KF(massive, massive);
    if (!massless.empty())
        Km -= KF(massive, massless) * KF(massless, massless).partialPivLu().solve(KF(massless, massive));
    const Eigen::EigenSolver<Eigen::MatrixXd> eig(Mm.partialPivLu().solve(Km), false);
    if (eig.info() != Eigen::Success) {
        std::fprintf(stderr, "sliding_stability: the eigenvalue iteration did not converge\n");
        return 1;
    }
    const Eigen::Index modes = static_cast<Eigen::Index>(massive.size());
    double growth = 0, frequency = 0, min_real = 1e300;
    int growing = 0;
    for (Eigen::Index k = 0; k < modes; ++k) {
        const std::complex<double> omega2 = eig.eigenvalues()[k];
        const std::complex<double> s = std::sqrt(-omega2);  // Re s >= 0 by the branch cut
        min_real = std::min(min_real, omega2.real());
        if (s.real() > 1e-6 * std::abs(s)) ++growing;
        if (s.real() > growth) {
            growth = s.real();
            frequency = std::abs(s.imag()) / (2 * 3.141592653589793);
        }
    }
    // The slip-rate damping D on the touching nodes' x dofs, in the condensed numbering.
    std::vector<Eigen::Index> condensed(static_cast<size_t>(n), -1);
    for (size_t a = 0; a < massive.size(); ++a)
        condensed[static_cast<size_t>(massive[a])] = static_cast<Eigen::Index>(a);
    Eigen::MatrixXd interface_damping = Eigen::MatrixXd::Zero(modes, modes);
    for (size_t i = 0; i < nc; ++i) {
        if (!touching[i] || slope == 0) continue;
        const Eigen::Index x =
            condensed[static_cast<size_t>(L.position[static_cast<size_t>(d.contact_tangential[0][i])])];
        if (x < 0) {
            std::fprintf(stderr,
                         "sliding_stability: --slope needs a mass on the contact x dofs "
                         "(mass_matrix %d has none)\n",
                         static_cast<int>(p.mass_matrix));
            return 2;
        }
        interface_damping(x, x) = slope * L.pressure[static_cast<Eigen::Index>(i)];
    }
    // Damped: with D = 0 the roots of s^2 + b s + omega^2, b = beta omega^2, in the
    // cancellation-free form; else the quadratic pencil itself.
    std::string damped = "[";
    for (size_t a = 0; a < betas.size(); ++a) {
        const double beta = betas[a];
        double rate = -1e300, freq = 0;
        if (slope != 0) {
            const auto [r, imag] = quadratic_growth(Mm, beta * Km + interface_damping, Km);
            rate = r;
            freq = imag / (2 * 3.141592653589793);
        }
        for (Eigen::Index k = 0; k < modes && slope == 0; ++k) {
            const std::complex<double> omega2 = eig.eigenvalues()[k], b = beta * omega2;
            const std::complex<double> root = std::sqrt(b * b - 4.0 * omega2);
            const std::complex<double> q = -0.5 * (b + (std::real(std::conj(b) * root) >= 0 ? root : -root));
            for (const std::complex<double> s : {q, omega2 / q})
                if (s.real() > rate) {
                    rate = s.real();
                    freq = std::abs(s.imag()) / (2 * 3.141592653589793);
                }
        }
        char item[128];
        std::snprintf(item, sizeof item,
                      "%s{\"beta\": %.6e, \"max_growth_rate\": %.6e, "
                      "\"frequency_hz\": %.6e}",
                      a > 0 ? ", " : "", beta, rate, freq);
        damped += item;
    }
    damped += "]";
    std::string pressures = "[", lifted = "[";
    for (size_t i = 0; i < nc; ++i) {
        char item[64];
        std::snprintf(item, sizeof item, "%s%.9e", i ? ", " : "", L.pressure[static_cast<Eigen::Index>(i)]);
        pressures += item;
        if (!touching[i]) lifted += (lifted.size() > 1 ? ", " : "") + std::to_string(i);
    }
    pressures += "]";
    lifted += "]";
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf(
        "{\"nx\": %d, \"h\": %g, \"friction\": %g, \"mass_matrix\": %d, \"dofs\": %ld, "
        "\"modes\": %ld, \"max_growth_rate\": %.6e, \"frequency_hz\": %.6e, \"growing_modes\": %d, "
        "\"min_real_omega2\": %.6e, \"slope\": %.6e, \"top_displacement\": %.6e, "
        "\"lift_off\": %s, \"active_set_iterations\": %d, \"lifted_nodes\": %s, "
        "\"normal_force\": %.9e, \"min_pressure\": %.6e, \"pressure\": %s, "
        "\"seconds\": %.2f, \"damped\": %s}\n",
        p.nx, p.width / p.nx, F, static_cast<int>(p.mass_matrix), static_cast<long>(n),
        static_cast<long>(modes), growth, frequency, growing, min_real, slope, top,
        lift_off ? "true" : "false", active_set_iterations, lifted.c_str(), L.pressure.sum(),
        L.pressure.minCoeff(), pressures.c_str(), seconds, damped.c_str());
    return 0;
}
