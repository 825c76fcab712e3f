#include "reduced/clamp_rows.hpp"

namespace contactbody {

ClampXRows clamp_x_rows(const Discretization& d, int component) {
    const Eigen::Index ncl = static_cast<Eigen::Index>(d.clamped_dofs.size());
    Eigen::VectorXd all_e = Eigen::VectorXd::Zero(d.mesh.num_dofs());
    for (Eigen::Index j = 0; j < ncl; ++j) {
        const int dof = d.clamped_dofs[static_cast<size_t>(j)];
        all_e[dof] = d.mesh.component(dof) == Mesh::normal;
    }
    Eigen::VectorXd all_ex = Eigen::VectorXd::Zero(d.mesh.num_dofs());
    for (int dof : d.clamped_dofs) all_ex[dof] = d.mesh.component(dof) == component;
    const Eigen::VectorXd M_ex = d.M * all_ex, A_ex = d.A * all_ex;
    const Eigen::Index nf = static_cast<Eigen::Index>(d.free_dofs.size());
    ClampXRows rows;
    rows.mass_free.resize(nf);
    rows.stiffness_free.resize(nf);
    for (Eigen::Index j = 0; j < nf; ++j) {
        rows.mass_free[j] = M_ex[d.free_dofs[static_cast<size_t>(j)]];
        rows.stiffness_free[j] = A_ex[d.free_dofs[static_cast<size_t>(j)]];
    }
    rows.mass_top = all_e.dot(M_ex);
    rows.stiffness_top = all_e.dot(A_ex);
    return rows;
}

double ClampRows::residual(const Substep& k, const Eigen::Ref<const Eigen::VectorXd>& y,
                           const Eigen::Ref<const Eigen::VectorXd>& ydot, const Eigen::VectorXd& w,
                           const Eigen::VectorXd& du) const {
    const double c1 = k.c1, c2 = k.c2, w_t = k.w_t, du_t = 2 * w_t;
    const double mass_x = mass.dot(c1 * w - c2 * ydot) + mass_lift * (c1 * w_t - c2 * k.lift_rate) +
                          mass_top * (c1 * w_t - c2 * k.top_rate);
    double rx =
        mass_x + stiffness.dot(y + w) + stiffness_lift * (k.lift_at + w_t) + stiffness_top * (k.top + w_t);
    if (k.damped)
        rx += 0.5 * c2 *
              (k.alpha * (mass.dot(du) + (mass_lift + mass_top) * du_t) +
               k.beta * (stiffness.dot(du) + (stiffness_lift + stiffness_top) * du_t));
    return rx;
}

void split_off_lift(const Discretization& d, int top_dof, const Eigen::VectorXd& lift, const State& full,
                    Eigen::Index n, State& s, Eigen::VectorXd& u, Eigen::VectorXd& v) {
    s.u.resize(n + 2);
    s.v.resize(n + 2);
    s.u[n] = s.u[n + 1] = full.u[top_dof];
    s.v[n] = s.v[n + 1] = full.v[top_dof];
    const Eigen::Index nf = static_cast<Eigen::Index>(d.free_dofs.size());
    u.resize(nf);
    v.resize(nf);
    for (Eigen::Index j = 0; j < nf; ++j) {
        u[j] = full.u[d.free_dofs[static_cast<size_t>(j)]] - lift[j] * s.u[n];
        v[j] = full.v[d.free_dofs[static_cast<size_t>(j)]] - lift[j] * s.v[n];
    }
    s.lambda = full.lambda;
    s.sticking = full.sticking;
    s.time = full.time;
}

void expand_to_full(const Discretization& d, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                    const State& s, Eigen::Index n, State& full) {
    full.u.setZero(d.mesh.num_dofs());
    full.v.setZero(d.mesh.num_dofs());
    for (size_t j = 0; j < d.free_dofs.size(); ++j) {
        full.u[d.free_dofs[j]] = u[static_cast<Eigen::Index>(j)];
        full.v[d.free_dofs[j]] = v[static_cast<Eigen::Index>(j)];
    }
    for (int dof : d.clamped_dofs) {
        const bool normal = d.mesh.component(dof) == Mesh::normal;
        full.u[dof] = normal ? s.u[n + 1] : 0.0;
        full.v[dof] = normal ? s.v[n + 1] : 0.0;
    }
    full.lambda = s.lambda;
    full.sticking = s.sticking;
    full.time = s.time;
}

}  // namespace contactbody
