#include "reduced_stepper.hpp"

#include <cmath>
#include <stdexcept>

namespace contactbody {

ReducedStepper::ReducedStepper(const SceneParameters& params, int modes)
    : params_(params), disc_(discretize(params)), basis_(build_modal_basis(disc_, modes)) {
    const Discretization& d = disc_;
    const Eigen::Index m = basis_.modes.cols(), k = basis_.residual.cols(), n = m + k;
    omega2_.resize(n);
    omega2_ << basis_.omega2, Eigen::VectorXd::Ones(k);
    mass_.resize(n);
    mass_ << Eigen::VectorXd::Ones(m), Eigen::VectorXd::Zero(k);

    const int nc = num_contact_nodes();
    Bhat_.resize(2 * nc, n);
    Blift_.resize(2 * nc);
    for (int i = 0; i < nc; ++i) {  // N_i = -e_y(i), T_i = +e_x(i), as the stepper's B
        const int y = d.contact_y[static_cast<size_t>(i)], x = d.contact_x[static_cast<size_t>(i)];
        Bhat_.row(i) << -basis_.modes.row(y), -basis_.residual.row(y);
        Bhat_.row(nc + i) << basis_.modes.row(x), basis_.residual.row(x);
        Blift_[i] = -basis_.lift[y];
        Blift_[nc + i] = basis_.lift[x];
    }

    // The clamp: e = 1 on the clamped y dofs.
    const Eigen::Index ncl = static_cast<Eigen::Index>(d.clamped_dofs.size());
    Eigen::VectorXd e = Eigen::VectorXd::Zero(ncl);
    for (Eigen::Index j = 0; j < ncl; ++j) e[j] = d.clamped_dofs[static_cast<size_t>(j)] % 2 == 1;
    Eigen::VectorXd all_e = Eigen::VectorXd::Zero(d.mesh.num_dofs());
    for (Eigen::Index j = 0; j < ncl; ++j) all_e[d.clamped_dofs[static_cast<size_t>(j)]] = e[j];
    const Eigen::VectorXd& S = basis_.lift;
    const Eigen::VectorXd MS = d.M_free * S, Me = d.M_free_clamped * e, AS = d.A_free * S;
    m_s_ = Eigen::VectorXd::Zero(n);
    m_c_ = Eigen::VectorXd::Zero(n);
    m_s_.head(m) = basis_.modes.transpose() * MS;
    m_c_.head(m) = basis_.modes.transpose() * Me;
    a_s_.resize(n);
    a_s_ << basis_.modes.transpose() * AS, basis_.residual.transpose() * AS;
    m_t_ = m_s_ + m_c_;
    damping_ = params_.damping_mass * mass_ + params_.damping_stiffness * omega2_;
    mu_ss_ = S.dot(MS);
    mu_cs_ = S.dot(Me);
    mu_cc_ = all_e.dot(d.M * all_e);
    s_ss_ = S.dot(AS);
    e_cc_ = all_e.dot(d.A * all_e);

    options_.tolerance = params_.contact_tolerance;
    problem_.a.resize(2 * nc);
    problem_.gap_limit.resize(nc);
    problem_.slip_origin.resize(nc);
    rhs_.resize(n);
    w_.resize(n);
    contact_u_.resize(2 * nc);
    contact_v_.resize(2 * nc);
    bw_.resize(2 * nc);
    du_.resize(n);
    contact_force_.resize(n);
}

ReducedState ReducedStepper::reduce(const State& full) const {
    const Discretization& d = disc_;
    const int top_dof = d.clamped_dofs.back();  // a clamped y dof: the top's value
    ReducedState s;
    s.top = s.lift_at = full.u[top_dof];
    s.top_rate = s.lift_rate = full.v[top_dof];
    const Eigen::Index nf = static_cast<Eigen::Index>(d.free_dofs.size());
    Eigen::VectorXd u(nf), v(nf);
    for (Eigen::Index j = 0; j < nf; ++j) {
        u[j] = full.u[d.free_dofs[static_cast<size_t>(j)]] - basis_.lift[j] * s.lift_at;
        v[j] = full.v[d.free_dofs[static_cast<size_t>(j)]] - basis_.lift[j] * s.lift_rate;
    }
    const auto project = [&](const Eigen::VectorXd& x) {  // diag(A_hat)^-1 T^T A x
        const Eigen::VectorXd Ax = d.A_free * x;
        Eigen::VectorXd z(size());
        z << basis_.modes.transpose() * Ax, basis_.residual.transpose() * Ax;
        return Eigen::VectorXd(z.cwiseQuotient(omega2_));
    };
    s.z = project(u);
    s.zdot = project(v);
    s.lambda = full.lambda;
    s.sticking = full.sticking;
    s.time = full.time;
    return s;
}

void ReducedStepper::expand(const ReducedState& s, State& full) const {
    const Discretization& d = disc_;
    const Eigen::Index m = basis_.modes.cols();
    const Eigen::VectorXd u = basis_.modes * s.z.head(m) + basis_.residual * s.z.tail(size() - m) +
                              basis_.lift * s.lift_at;
    const Eigen::VectorXd v = basis_.modes * s.zdot.head(m) +
                              basis_.residual * s.zdot.tail(size() - m) + basis_.lift * s.lift_rate;
    full.u.setZero(d.mesh.num_dofs());
    full.v.setZero(d.mesh.num_dofs());
    for (size_t j = 0; j < d.free_dofs.size(); ++j) {
        full.u[d.free_dofs[j]] = u[static_cast<Eigen::Index>(j)];
        full.v[d.free_dofs[j]] = v[static_cast<Eigen::Index>(j)];
    }
    for (int dof : d.clamped_dofs) {
        full.u[dof] = dof % 2 == 1 ? s.top : 0.0;
        full.v[dof] = dof % 2 == 1 ? s.top_rate : 0.0;
    }
    full.lambda = s.lambda;
    full.sticking = s.sticking;
    full.time = s.time;
}

double ReducedStepper::energy(const ReducedState& s) const {
    const double tau = s.lift_rate, tc = s.top_rate, gap = s.lift_at - s.top;
    const double kinetic = 0.5 * s.zdot.cwiseAbs2().dot(mass_) + s.zdot.dot(m_s_ * tau + m_c_ * tc) +
                           0.5 * (mu_ss_ * tau * tau + 2 * mu_cs_ * tau * tc + mu_cc_ * tc * tc);
    // With A_fc e = -A_ff S: 1/2 z^T A_hat z + z^T a_s (lift - top) + 1/2 S^T A_ff S (lift - top)^2
    // + 1/2 (e^T A_cc e - S^T A_ff S) top^2.
    const double strain = 0.5 * s.z.cwiseAbs2().dot(omega2_) + s.z.dot(a_s_) * gap +
                          0.5 * s_ss_ * gap * gap + 0.5 * (e_cc_ - s_ss_) * s.top * s.top;
    return kinetic + strain;
}

void ReducedStepper::set_friction_coefficient(double friction) {
    params_.friction_coefficient = friction;
    problem_dt_ = -1;
}

const ReducedStepper::StepOperators& ReducedStepper::operators_for(double dt) {
    for (size_t j = 0; j < cache_.size(); ++j)
        if (cache_[j] && std::abs(cache_[j]->dt - dt) <= 1e-14 * dt) return *cache_[j];
    std::swap(cache_[0], cache_[1]);
    auto ops = std::make_unique<StepOperators>();
    ops->dt = dt;
    const double c1 = 4.0 / (dt * dt), c2 = 2.0 / dt;
    ops->inverse_stiffness = (c1 * mass_ + c2 * damping_ + omega2_).cwiseInverse();
    ops->delassus = Bhat_ * ops->inverse_stiffness.asDiagonal() * Bhat_.transpose();
    cache_[0] = std::move(ops);
    return *cache_[0];
}

SubstepReport ReducedStepper::substep(ReducedState& s, double dt, const SubstepLoad& load) {
    const StepOperators& ops = operators_for(dt);
    const int nc = num_contact_nodes();
    const bool friction = params_.friction_coefficient > 0;
    if (problem_dt_ != dt || problem_friction_ != friction) {
        problem_.W = friction ? ops.delassus : Eigen::MatrixXd(ops.delassus.topLeftCorner(nc, nc));
        problem_.a.resize(friction ? 2 * nc : nc);
        problem_.friction.setConstant(friction ? nc : 0, params_.friction_coefficient);
        problem_.revision = ContactProblem::next_revision();
        problem_dt_ = dt;
        problem_friction_ = friction;
    }
    const double c1 = 4.0 / (dt * dt), c2 = 2.0 / dt;
    const double alpha = params_.damping_mass, beta = params_.damping_stiffness;
    if (s.lambda.size() != problem_.W.rows()) s.lambda.setZero(problem_.W.rows());

    // The midpoint equation on z with the clamp's midpoint increment w_t (no stiffness
    // coupling: the lift is the clamp's static response):
    //   K_hat w = 2/dt (M_hat zdot + m_t top_rate) - A_hat z - (4/dt^2 + 2/dt alpha) m_t w_t + B_hat^T lambda.
    const double w_t = 0.5 * (load.top_start + load.top_end) - s.top;
    rhs_ = c2 * (mass_.cwiseProduct(s.zdot) + m_s_ * s.lift_rate + m_c_ * s.top_rate) -
           omega2_.cwiseProduct(s.z) - a_s_ * (s.lift_at - s.top) -
           (c1 + c2 * alpha) * w_t * m_t_;
    w_ = ops.inverse_stiffness.cwiseProduct(rhs_);
    contact_u_.noalias() = Bhat_ * s.z;
    contact_u_ += Blift_ * s.lift_at;  // B u^k: (-u_y, u_x) of the contact nodes
    contact_v_.noalias() = Bhat_ * s.zdot;
    contact_v_ += Blift_ * s.lift_rate;
    bw_.noalias() = Bhat_ * w_;
    bw_ += Blift_ * w_t;

    problem_.a = bw_.head(problem_.a.size());
    const bool touching = set_contact_conditions(
        problem_, params_, disc_.contact_at_end_of_step, dt, load.foundation_velocity, s.sticking,
        [&](int i) { return params_.initial_gap - contact_u_[i]; },
        [&](int i) { return contact_v_[nc + i]; });
    SubstepReport report;
    const Eigen::Index unknowns = problem_.W.rows();
    if (touching) {
        const ContactSolveInfo info = solver_.solve(problem_, options_, s.lambda);
        report.contact_iterations = info.iterations;
        report.contact_sweeps = info.sweeps;
        report.contact_solved = true;
        contact_force_.noalias() = Bhat_.topRows(unknowns).transpose() * s.lambda;
        w_ += ops.inverse_stiffness.cwiseProduct(contact_force_);
        bw_.noalias() = Bhat_ * w_;
        bw_ += Blift_ * w_t;
    } else {
        s.lambda.setZero();
    }

    // Damping work dt vbar^T C vbar, vbar = 2 w / dt on every dof: C = alpha M + beta A,
    // whose A part does not couple z with the lift and clamp (A_fc e = -A_ff S).
    const double du_t = 2 * w_t;
    du_ = 2 * w_;
    const double mass_tt = mu_ss_ + 2 * mu_cs_ + mu_cc_, stiffness_tt = e_cc_ - s_ss_;
    if (params_.damped())
        report.work.damping = (du_.cwiseAbs2().dot(damping_) + 2 * du_t * alpha * m_t_.dot(du_) +
                               (alpha * mass_tt + beta * stiffness_tt) * du_t * du_t) / dt;

    // The clamp's force on the body: the clamp moves the lift with it, so its force is the
    // residual of the reduced equations' rows of both (lift and clamp), less the contact
    // forces' share through the lift, (B S)^T lambda. Its work closes the reduced body's own
    // energy balance; with every finite mode the lift's row is zero and this is the clamped
    // rows' residual, as in the full body.
    double r = m_t_.dot(c1 * w_ - c2 * s.zdot) + (mu_ss_ + mu_cs_) * (c1 * w_t - c2 * s.lift_rate) +
               (mu_cs_ + mu_cc_) * (c1 * w_t - c2 * s.top_rate) + stiffness_tt * (s.top + w_t);
    if (params_.damped())
        r += 0.5 * c2 * (alpha * (m_t_.dot(du_) + mass_tt * du_t) + beta * stiffness_tt * du_t);
    r -= Blift_.head(unknowns).dot(s.lambda);
    report.top_reaction_y = r;
    report.work.clamp = r * du_t;

    for (int i = 0; i < nc; ++i)
        add_node_contact(report, s.sticking[i], s.lambda[i], friction ? s.lambda[nc + i] : 0.0,
                         contact_u_[i], 2 * bw_[i], 2 * bw_[nc + i], load.foundation_velocity * dt,
                         params_.initial_gap, friction, touching,
                         touching ? solver_.status()[i] : NodeStatus::open);
    report.corner_lambda_N = s.lambda[0];
    report.corner_lambda_T = friction ? s.lambda[nc] : 0.0;

    s.zdot = 2 * c2 * w_ - s.zdot;
    s.z += 2 * w_;
    s.lift_rate = 2 * c2 * w_t - s.lift_rate;
    s.lift_at += du_t;
    s.top = load.top_end;
    s.top_rate = load.top_rate;
    s.time += dt;
    return report;
}

}  // namespace contactbody
