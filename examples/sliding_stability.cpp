// Linear stability of steady sliding (issue 3's "what we already know"): every contact node in
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
#include <chrono>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "discretization.hpp"

using namespace contactbody;

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: sliding_stability NX FRICTION MASS_MATRIX [BETA ...]\n");
        return 2;
    }
    SceneParameters p;
    p.nx = p.ny = std::atoi(argv[1]);
    p.friction_coefficient = std::atof(argv[2]);
    p.mass_matrix = static_cast<MassVariant>(std::atoi(argv[3]));
    const auto t0 = std::chrono::steady_clock::now();
    const Discretization d = discretize(p);
    const Eigen::MatrixXd M(d.M_free), A(d.A_free);
    const Eigen::Index nf = M.rows();

    // r: the free dofs but the contact nodes' y dofs; position: where a free dof lands in r.
    std::vector<bool> contact_y(static_cast<size_t>(nf), false);
    for (int y : d.contact_y) contact_y[static_cast<size_t>(y)] = true;
    std::vector<Eigen::Index> rows, position(static_cast<size_t>(nf), -1);
    for (Eigen::Index k = 0; k < nf; ++k)
        if (!contact_y[static_cast<size_t>(k)]) {
            position[static_cast<size_t>(k)] = static_cast<Eigen::Index>(rows.size());
            rows.push_back(k);
        }
    const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
    Eigen::MatrixXd MF = M(rows, rows), KF = A(rows, rows);
    const double F = p.friction_coefficient;
    for (size_t i = 0; i < d.contact_y.size(); ++i) {
        const Eigen::Index x = position[static_cast<size_t>(d.contact_x[i])];
        MF.row(x) -= F * M(d.contact_y[i], rows);
        KF.row(x) -= F * A(d.contact_y[i], rows);
    }
    // Massless dofs (the contact x dofs of redistributed_both: their rows of M_F vanish)
    // are algebraic: condense them, K_rr - K_rc K_cc^-1 K_cr, before the eigenvalues.
    std::vector<Eigen::Index> massive, massless;
    for (Eigen::Index a = 0; a < n; ++a)
        (MF.row(a).cwiseAbs().maxCoeff() == 0 ? massless : massive).push_back(a);
    const Eigen::MatrixXd Mm = MF(massive, massive);
    Eigen::MatrixXd Km = KF(massive, massive);
    if (!massless.empty())
        Km -= KF(massive, massless) *
              KF(massless, massless).partialPivLu().solve(KF(massless, massive));
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
    // Damped: the roots of s^2 + b s + omega^2, b = beta omega^2, in the cancellation-free form.
    std::string damped = "[";
    for (int a = 4; a < argc; ++a) {
        const double beta = std::atof(argv[a]);
        double rate = -1e300, freq = 0;
        for (Eigen::Index k = 0; k < modes; ++k) {
            const std::complex<double> omega2 = eig.eigenvalues()[k], b = beta * omega2;
            const std::complex<double> root = std::sqrt(b * b - 4.0 * omega2);
            const std::complex<double> q =
                -0.5 * (b + (std::real(std::conj(b) * root) >= 0 ? root : -root));
            for (const std::complex<double> s : {q, omega2 / q})
                if (s.real() > rate) {
                    rate = s.real();
                    freq = std::abs(s.imag()) / (2 * 3.141592653589793);
                }
        }
        char item[128];
        std::snprintf(item, sizeof item, "%s{\"beta\": %.6e, \"max_growth_rate\": %.6e, "
                      "\"frequency_hz\": %.6e}", a > 4 ? ", " : "", beta, rate, freq);
        damped += item;
    }
    damped += "]";
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("{\"nx\": %d, \"h\": %g, \"friction\": %g, \"mass_matrix\": %d, \"dofs\": %ld, "
                "\"modes\": %ld, \"max_growth_rate\": %.6e, \"frequency_hz\": %.6e, \"growing_modes\": %d, "
                "\"min_real_omega2\": %.6e, \"seconds\": %.2f, \"damped\": %s}\n",
                p.nx, p.width / p.nx, F, static_cast<int>(p.mass_matrix), static_cast<long>(n),
                static_cast<long>(modes), growth, frequency, growing, min_real, seconds,
                damped.c_str());
    return 0;
}
