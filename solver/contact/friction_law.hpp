// The contact and friction law, once for any number of tangents: one node's law (node_law),
// the loop that applies it at every node (apply_node_law, both contact solves' residual), and
// a scene's friction coefficients (rate_law).
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "assembly/discretization.hpp"
#include "contact/contact_solver.hpp"
#include "util/tangents.hpp"

namespace contactbody {

// One node's Alart-Curnier residual phi = (phi_N, phi_T), zero exactly where the node obeys the
// contact law, with augmentation parameters r_N, r_T > 0, for `tangents` tangents (0 without
// friction, 1 for a 2D body, 2 for a 3D body's isotropic friction): the tangential trial
// z = l_T - r_T (u_T - origin) projected onto the ball of radius F x the normal trial (the
// interval in 2D, the disc in 3D; GetFEM's ball_projection).
struct NodeLaw {
    NodeStatus status = NodeStatus::open;
    // 0 open, 1 stick (or active without friction), 2 slip; with one tangent +-2, z's sign.
    signed char pattern = 0;
    double phi[1 + max_tangents] = {0, 0, 0};  // N, then each tangent
    double trial = 0;                          // -l_N - r_N (gap - u_N): > 0 where active
    double coefficient = 0;                    // F (active with friction)
    double direction[max_tangents] = {0, 0};   // z / |z| (slip)
    double ratio = 0;                          // F trial / |z| (slip)
};

// |v| of the first k entries: exactly |v_0| for one.
inline double tangential_size(const double* v, int k) {
    if (k == 1) return std::abs(v[0]);
    double sum = 0;
    for (int t = 0; t < k; ++t) sum += v[t] * v[t];
    return std::sqrt(sum);  // not hypot: no libm in the FMUs
}

// l, u: the node's multipliers and displacements (N, then each tangent); coefficient(trial)
// gives its F (called for an active node with friction only).
template <class Coefficient>
NodeLaw node_law(int tangents, const double* l, const double* u, double rN, double rT, double gap,
                 const double* origin, Coefficient&& coefficient) {
    NodeLaw law;
    const double pressure = -l[0];
    law.trial = pressure - rN * (gap - u[0]);
    if (law.trial <= 0) {
        law.phi[0] = pressure;
        for (int t = 0; t < tangents; ++t) law.phi[1 + t] = l[1 + t];
        return law;
    }
    law.phi[0] = pressure - law.trial;
    law.status = NodeStatus::stick;
    law.pattern = 1;
    if (tangents == 0) return law;
    law.coefficient = coefficient(law.trial);
    const double bound = law.coefficient * law.trial;
    double z[max_tangents] = {0, 0};
    for (int t = 0; t < tangents; ++t) z[t] = l[1 + t] - rT * (u[1 + t] - origin[t]);
    const double size = tangential_size(z, tangents);
    if (size <= bound) {
        for (int t = 0; t < tangents; ++t) law.phi[1 + t] = l[1 + t] - z[t];
        return law;
    }
    for (int t = 0; t < tangents; ++t) {
        law.direction[t] = z[t] / size;  // +-1 exactly with one tangent
        law.phi[1 + t] = l[1 + t] - bound * law.direction[t];
    }
    law.ratio = bound / size;
    law.status = NodeStatus::slip;
    law.pattern = static_cast<signed char>(tangents == 1 && z[0] < 0 ? -2 : 2);
    return law;
}

// Applies node_law at every node of p (its tangents with friction, none without) and returns
// the residual's size relative to max |lambda| (infinity for a nonzero one at lambda = 0): the
// one loop of both contact solves. u(c, i): component c (0 normal, then each tangent) of node
// i's displacement B w; augmentation(c, i): r_N (c = 0) or r_T (c = 1, with friction only);
// coefficient(i, slip): F_i at the iterate's slip u_T - origin (tangents entries; for active
// nodes with friction only); record(i, law) keeps what the solve needs. phi[c n + i]: the
// residual's component c at node i.
template <class Displacement, class Augmentation, class Coefficient, class Record>
double apply_node_law(const ContactProblem& p, const Eigen::VectorXd& lambda, Displacement&& u,
                      Augmentation&& augmentation, Coefficient&& coefficient, Record&& record,
                      Eigen::VectorXd& phi) {
    const Eigen::Index n = p.gap_limit.size();
    const int tangents = p.has_friction() ? p.tangents : 0;
    phi.resize(lambda.size());
    for (Eigen::Index i = 0; i < n; ++i) {
        double l[1 + max_tangents] = {0, 0, 0}, x[1 + max_tangents] = {0, 0, 0};
        double origin[max_tangents] = {0, 0};
        for (int c = 0; c <= tangents; ++c) {
            l[c] = lambda[c * n + i];
            x[c] = u(c, i);
        }
        for (int t = 0; t < tangents; ++t) origin[t] = p.slip_origin[t * n + i];
        const double rT = tangents > 0 ? augmentation(1, i) : 0.0;
        const NodeLaw law =
            node_law(tangents, l, x, augmentation(0, i), rT, p.gap_limit[i], origin, [&](double) {
                double slip[max_tangents] = {0, 0};
                for (int t = 0; t < tangents; ++t) slip[t] = x[1 + t] - origin[t];
                return coefficient(i, static_cast<const double*>(slip));
            });
        for (int c = 0; c <= tangents; ++c) phi[c * n + i] = law.phi[c];
        record(i, law);
    }
    const double scale = lambda.lpNorm<Eigen::Infinity>();
    const double size = phi.lpNorm<Eigen::Infinity>();
    if (size == 0) return 0;
    return scale > 0 ? size / scale : std::numeric_limits<double>::infinity();
}

// The slip-rate law of p as the contact solver takes it, with slip_time 1 (so that its slip is
// a slip rate: coefficient(F_d, v, &dF) gives F(v) and dF/dv); the stepper sets the substep's.
ContactProblem::RateLaw rate_law(const SceneParameters& p);

}  // namespace contactbody
